//! Chapter 5's sampling routines as warp tests
//! ([`crate::core::warp_test`]): uniform and cosine-weighted hemisphere
//! directions, directions towards a square area light (by area and by
//! solid angle), and the glossy and semi-gloss lobes' directions for light
//! arriving at 45°. The terminal
//! UI's warp view (`w`) lists them.

use std::sync::OnceLock;

use glam::{Vec2, Vec3};

use crate::core::warp_test::{StudentWarp, WarpRoutine};
use crate::scene::mesh::Mesh;
use crate::scene::LightSampling;

use super::light::area::AreaLight;
use super::material::glossy::Glossy;
use super::material::semigloss::SemiGloss;
use super::warp::{
    cosine_hemisphere, cosine_hemisphere_pdf, uniform_hemisphere, UNIFORM_HEMISPHERE_PDF,
};

/// The routines, in the order the warp view shows them.
pub const ROUTINES: [WarpRoutine; 6] = [
    WarpRoutine {
        name: "uniform hemisphere",
        sample: |u| Some(uniform_hemisphere(u)),
        pdf: |w| {
            if w.z > 0.0 {
                UNIFORM_HEMISPHERE_PDF
            } else {
                0.0
            }
        },
    },
    WarpRoutine {
        name: "cosine hemisphere",
        sample: |u| Some(cosine_hemisphere(u)),
        pdf: |w| cosine_hemisphere_pdf(w.z).max(0.0),
    },
    WarpRoutine {
        name: "area light",
        sample: |u| test_light().sample_li(Vec3::ZERO, u).map(|s| s.wi),
        pdf: |w| light_pdf(test_light(), w),
    },
    WarpRoutine {
        name: "glossy lobe (n = 20, light at 45°)",
        sample: |u| GLOSSY.sample(WO, u).map(|s| s.wi),
        pdf: |w| GLOSSY.pdf(WO, w),
    },
    WarpRoutine {
        name: "semi-gloss paint (ks = 0.3, n = 50, light at 45°)",
        // The lobe is picked by u.x, which is then rescaled to be uniform
        // again: the two numbers stay independent and uniform.
        sample: |u| {
            let p = SEMIGLOSS.coat_probability();
            let (x, lobe) = if u.x < p {
                (u.x / p, 0.0)
            } else {
                ((u.x - p) / (1.0 - p), 1.0)
            };
            SEMIGLOSS
                .sample(WO, Vec2::new(x.min(1.0 - f32::EPSILON), u.y), lobe)
                .map(|s| s.wi)
        },
        pdf: |w| SEMIGLOSS.pdf(WO, w),
    },
    WarpRoutine {
        name: "area light, by solid angle",
        sample: |u| solid_angle_light().sample_li(Vec3::ZERO, u).map(|s| s.wi),
        pdf: |w| light_pdf(solid_angle_light(), w),
    },
];

/// The outgoing direction the two lobes are tested for: 45° from the
/// normal.
const WO: Vec3 = Vec3::new(
    std::f32::consts::FRAC_1_SQRT_2,
    0.0,
    std::f32::consts::FRAC_1_SQRT_2,
);

/// The glossy lobe the warp view tests.
const GLOSSY: Glossy = Glossy {
    rs: Vec3::ONE,
    n: 20.0,
};

/// The semi-gloss paint the warp view tests: the lecture's red paint.
const SEMIGLOSS: SemiGloss = SemiGloss {
    rho: Vec3::new(0.8, 0.1, 0.1),
    ks: 0.3,
    n: 50.0,
};

/// Exercise 5.2's routine, which the warp view can test with the
/// student's code: the directions must have density cos θ / π.
pub const STUDENT: StudentWarp = StudentWarp {
    id: "ch5/cosine_hemisphere",
    name: "your cosine_hemisphere (exercise 5.2)",
    pdf: |w| cosine_hemisphere_pdf(w.z).max(0.0),
};

/// The square area light of the test: 1 × 1, at height 1 above the
/// origin, facing down, seen from the origin (built once).
pub fn test_light() -> &'static AreaLight {
    static LIGHT: OnceLock<AreaLight> = OnceLock::new();
    LIGHT.get_or_init(|| {
        let mesh = Mesh {
            name: "test light".into(),
            positions: vec![
                Vec3::new(-0.5, -0.5, 1.0),
                Vec3::new(0.5, -0.5, 1.0),
                Vec3::new(0.5, 0.5, 1.0),
                Vec3::new(-0.5, 0.5, 1.0),
            ],
            // Clockwise seen from above: the front faces down, to the origin.
            triangles: vec![[0, 2, 1], [0, 3, 2]],
            colors: None,
            material: 0,
        };
        AreaLight::new(&mesh, 0, Vec3::ONE, false).expect("the test light has an area")
    })
}

/// [`test_light`] sampled by the solid angle it subtends.
pub fn solid_angle_light() -> &'static AreaLight {
    static LIGHT: OnceLock<AreaLight> = OnceLock::new();
    LIGHT.get_or_init(|| test_light().clone().sampled_by(LightSampling::SolidAngle))
}

/// The density per steradian with which `light.sample_li` from the origin
/// returns direction `w`: where the ray along `w` meets the light's plane
/// (z = 1) inside the square, its `pdf_li`; else 0.
fn light_pdf(light: &AreaLight, w: Vec3) -> f32 {
    if w.z <= 0.0 {
        return 0.0;
    }
    let y = w / w.z;
    if y.x.abs() > 0.5 || y.y.abs() > 0.5 {
        return 0.0;
    }
    light.pdf_li(Vec3::ZERO, y, Vec3::NEG_Z)
}
