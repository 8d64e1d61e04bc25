//! Chapter 5's capstone, `direct_light`: one light-sampling estimate of
//! the radiance reflected at p from a point y drawn uniformly by area on
//! an area light. Its check, clause by clause of the stub's contract:
//!
//! 1. Hand-worked cases (exact: the function is deterministic), each
//!    changing one factor of f · Le · cos θ · cos θl / d² · A at a time:
//!    the BRDF ρ/π, cos θ at p, cos θl at the light, d², the area A; and
//!    the cases that must give exactly 0: the light's back face (it emits
//!    from its front face only), a light below p's surface, a light in
//!    p's plane, and a blocked segment. The visibility callback answers
//!    for the segment (p, y) and records any other endpoints it is asked
//!    about. Relative tolerance 10⁻⁴: f32 rounding of these cases is below
//!    10⁻⁶ (measured with the two correct alternatives of the mutant
//!    tests: largest 1·10⁻⁷).
//! 2. The Cornell box (`cornell-box.toml`, 48 × 48, 32 light samples per
//!    pixel), the candidate and the reference fed the same points on the
//!    light: each pixel's mean must agree within 10⁻⁴ relative (of the
//!    pixel, or of the image's mean level for darker pixels). Correct
//!    formulations differ by f32 rounding: measured with the two
//!    alternatives of the mutant tests, at most 2.3·10⁻⁷ (in f64) and
//!    1.2·10⁻⁷ (through the pdf). Its images are the check's images.

use std::cell::RefCell;
use std::f32::consts::{FRAC_1_PI, PI};

use glam::{Vec2, Vec3};

use super::super::images;
use super::symptoms::*;
use crate::ch1_projection::camera::Camera;
use crate::core::film::Film;
use crate::core::sampling::random;
use crate::exercise::{Check, Symptom};
use crate::exercises::AbsMax;

/// The capstone's candidate: (p, n, ρ, y, n_light, A, Le, visible) to one
/// sample of the reflected radiance.
pub type DirectFn =
    fn(Vec3, Vec3, Vec3, Vec3, Vec3, f32, Vec3, &dyn Fn(Vec3, Vec3) -> bool) -> Vec3;

/// raystep's answer to the capstone.
#[allow(clippy::too_many_arguments)]
pub fn reference_direct(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: &dyn Fn(Vec3, Vec3) -> bool,
) -> Vec3 {
    let to = y - p;
    let d2 = to.length_squared();
    let wi = to / d2.sqrt();
    let (cos, cos_l) = (n.dot(wi), n_light.dot(-wi));
    if !(cos > 0.0 && cos_l > 0.0 && d2 > 0.0 && visible(p, y)) {
        return Vec3::ZERO;
    }
    // A / d² first: each alone may leave f32's range at the drawn scales
    // (10⁻¹⁵ to 10¹⁵), their ratio does not, and dividing a dim light's
    // product by d² before multiplying by A underflows to 0.
    rho * FRAC_1_PI * le * (cos * cos_l * (area / d2))
}

/// One hand-worked case.
struct Case {
    what: &'static str,
    n: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    blocked: bool,
    /// The answer, from the closed form.
    want: Vec3,
}

const RHO: Vec3 = Vec3::new(0.8, 0.5, 0.2);
const LE: Vec3 = Vec3::new(4.0, 3.0, 2.0);

fn cases() -> Vec<Case> {
    let f = RHO / PI * LE;
    let (s60, c60) = (60f32.to_radians().sin(), 0.5);
    let case = |what, n, y, n_light, area, blocked, want| Case {
        what,
        n,
        y,
        n_light,
        area,
        blocked,
        want,
    };
    let up = Vec3::new(0.0, 0.0, 2.0);
    vec![
        // cos θ = cos θl = 1, d² = 4, A = 0.5.
        case(
            "straight above",
            Vec3::Z,
            up,
            -Vec3::Z,
            0.5,
            false,
            f * 0.5 / 4.0,
        ),
        case(
            "the surface tilted by 60°",
            Vec3::new(s60, 0.0, c60),
            up,
            -Vec3::Z,
            0.5,
            false,
            f * 0.5 * 0.5 / 4.0,
        ),
        case(
            "the light tilted by 60°",
            Vec3::Z,
            up,
            -Vec3::new(s60, 0.0, c60),
            0.5,
            false,
            f * 0.5 * 0.5 / 4.0,
        ),
        case(
            "twice as far",
            Vec3::Z,
            2.0 * up,
            -Vec3::Z,
            0.5,
            false,
            f * 0.5 / 16.0,
        ),
        case(
            "four times the area",
            Vec3::Z,
            up,
            -Vec3::Z,
            2.0,
            false,
            f * 2.0 / 4.0,
        ),
        // wi = (0.6, 0, 0.8): cos θ = cos θl = 0.8, d² = 25.
        case(
            "oblique, 5 m away",
            Vec3::Z,
            Vec3::new(3.0, 0.0, 4.0),
            -Vec3::Z,
            1.0,
            false,
            f * 0.64 / 25.0,
        ),
        case(
            "the light's back face",
            Vec3::Z,
            up,
            Vec3::Z,
            0.5,
            false,
            Vec3::ZERO,
        ),
        case(
            "a light below the surface",
            Vec3::Z,
            -up,
            Vec3::Z,
            0.5,
            false,
            Vec3::ZERO,
        ),
        case(
            "a light in the surface's plane",
            Vec3::Z,
            Vec3::new(2.0, 0.0, 0.0),
            -Vec3::X,
            0.5,
            false,
            Vec3::ZERO,
        ),
        case(
            "a blocked light",
            Vec3::Z,
            up,
            -Vec3::Z,
            0.5,
            true,
            Vec3::ZERO,
        ),
    ]
}

/// What the hand-worked cases found: (worst relative error, its detail,
/// the symptom).
fn hand_cases(f: DirectFn) -> (f64, String, Option<Symptom>) {
    let p = Vec3::new(0.25, -0.5, 0.0);
    let asked: RefCell<Vec<(Vec3, Vec3)>> = RefCell::new(Vec::new());
    let mut ratios = Vec::new();
    let mut worst = (0.0f64, String::from("every hand-worked case matches"), None);
    let facing = (RHO / PI * LE * 0.5 / 4.0).max_element() as f64;
    for c in cases() {
        let y = p + c.y;
        let visible = |a: Vec3, b: Vec3| {
            let same = (a - p).length() < 1e-5 && (b - y).length() < 1e-5;
            if !same {
                asked.borrow_mut().push((a, b));
            }
            // A blocker sits between p and y: a segment that reaches
            // neither point's neighbourhood misses it.
            !(c.blocked && same)
        };
        let got = f(p, c.n, RHO, y, c.n_light, c.area, LE, &visible);
        let (err, symptom) = if c.want == Vec3::ZERO {
            let s = match c.what {
                "the light's back face" => TWO_SIDED,
                "a light below the surface" => BEHIND,
                "a blocked light" => NO_SHADOW,
                _ => COS_SURFACE,
            };
            // Relative to what the same light would bring facing p.
            (got.abs_max() as f64 / facing, s)
        } else {
            ratios.push((c.what, (got / c.want).element_sum() as f64 / 3.0));
            (((got - c.want) / c.want).abs_max() as f64, CONSTANT_FACTOR)
        };
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            let detail = format!(
                "{}: p {p}, n {:.3}, y {y}, n_light {:.3}, A {}, Le {LE}, ρ {RHO}{}: got {got}, expected {}",
                c.what, c.n, c.n_light, c.area,
                if c.blocked { ", blocked" } else { "" },
                c.want
            );
            worst = (err, detail, Some(symptom));
        }
    }
    let (error, mut detail, symptom) = worst;
    if error <= 1e-4 {
        let detail = format!("every hand-worked case matches (worst {error:.1e} relative)");
        return (error, detail, None);
    }
    if let Some((a, b)) = asked.borrow().first() {
        detail = format!("visible was asked about the segment {a} → {b}, not p → y; {detail}");
        return (error, detail, Some(WRONG_SEGMENT));
    }
    // Which factor: each case differs from "straight above" by one.
    let base = ratios[0].1;
    let differs = |what: &str| {
        ratios
            .iter()
            .any(|(w, r)| *w == what && ((r - base) / base).abs() > 1e-4)
    };
    let symptom = if differs("the surface tilted by 60°") {
        Some(COS_SURFACE)
    } else if differs("the light tilted by 60°") || differs("twice as far") {
        Some(JACOBIAN)
    } else if differs("four times the area") {
        Some(AREA)
    } else if [PI as f64, 1.0 / PI as f64]
        .iter()
        .any(|k| ((base - k) / k).abs() < 1e-3)
    {
        Some(BRDF_PI)
    } else if symptom == Some(CONSTANT_FACTOR) || !(base.is_finite()) {
        Some(CONSTANT_FACTOR)
    } else {
        symptom
    };
    (error, detail, symptom)
}

/// The Cornell box lit directly by its ceiling light, `g` at the first
/// surface of each pixel centre's ray, `spp` light points per pixel.
fn cornell(g: DirectFn, spp: u32) -> images::Estimate {
    use crate::ch5_reflection::light::Light;
    use crate::ch5_reflection::warp::uniform_triangle;
    use crate::ch5_reflection::world::World;
    let scene = images::scene("cornell-box.toml");
    let camera = Camera::of(&scene)
        .with_resolution(48, 48)
        .expect("a valid camera");
    let world = World::new(&scene);
    let light = world
        .lights
        .lights
        .iter()
        .find_map(|l| match l {
            Light::Area(a) => Some(a),
            _ => None,
        })
        .expect("the Cornell box has an area light");
    let (w, h) = (camera.width, camera.height);
    let sample = |x: u32, y: u32, s: u32| -> Vec3 {
        let ray = camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
        let Some(it) = world.intersect(&ray) else {
            return Vec3::ZERO;
        };
        let m = &world.materials[it.material];
        if m.is_emissive() {
            return m.emission;
        }
        let n = if it.n.dot(ray.dir) > 0.0 { -it.n } else { it.n };
        let pixel = (y * w + x) as u64;
        let r = |d: u64| random(502, pixel, s as u64, d);
        // A point uniform by area: a triangle by area, then a point in it.
        let k = light
            .cdf
            .partition_point(|c| *c <= r(0) * light.area)
            .min(light.cdf.len() - 1);
        let [a, b, c] = light.triangles[k];
        let bary = uniform_triangle(Vec2::new(r(2), r(1)));
        let point = bary.x * a + bary.y * b + bary.z * c;
        let visible = |p: Vec3, q: Vec3| {
            let to = q - p;
            let d = to.length();
            d > 0.0 && world.unoccluded(p, n, to / d, d)
        };
        if x == 0 && s == 0 {
            crate::progress(format_args!(
                "calling direct_light for row {y} of {h}: p = {:.3}, n = {:.3}, light point {point:.3}",
                it.p, n
            ));
        }
        g(
            it.p,
            n,
            m.reflectance,
            point,
            light.normals[k],
            light.area,
            light.le,
            &visible,
        )
    };
    images::Estimate::gather(w, h, spp, &sample)
}

/// Pixels whose means differ by more than 10⁻⁴ relative (of the pixel,
/// or of the image's mean level where the pixel is darker than that), as
/// a [`Check`] on the fraction that differ (0 passes) with both images.
fn same_picture(student: Film, reference: Film) -> Check {
    let n = reference.pixels.len();
    let level = reference
        .pixels
        .iter()
        .map(|p| p.max_element())
        .sum::<f32>()
        / n as f32;
    let mut differ = 0usize;
    let mut worst = (0.0f32, 0usize);
    for (i, (s, r)) in student.pixels.iter().zip(&reference.pixels).enumerate() {
        let d = (*s - *r).abs_max() / r.max_element().max(level);
        let d = if d.is_nan() { f32::INFINITY } else { d };
        if d > 1e-4 {
            differ += 1;
        }
        if d > worst.0 {
            worst = (d, i);
        }
    }
    let (x, y) = (
        worst.1 as u32 % reference.width,
        worst.1 as u32 / reference.width,
    );
    let detail = if differ == 0 {
        format!(
            "all {n} pixels match the reference's (same light points), to {:.1e} relative",
            worst.0
        )
    } else {
        format!(
            "{differ} of {n} pixels differ from the reference's (same light points); the worst, \
             pixel ({x}, {y}): yours {:.4}, the reference {:.4} W/(m²·sr)",
            student.pixels[worst.1], reference.pixels[worst.1]
        )
    };
    Check {
        error: differ as f64 / n as f64,
        tolerance: 0.0,
        detail,
        images: Some((student, reference)),
        symptom: None,
    }
}

/// The capstone (see the module's doc): the hand-worked cases, then the
/// Cornell box with the same light points as the reference.
pub fn check_direct_light(f: DirectFn) -> Check {
    // The hand cases name the mistake; the drawn ones count when those
    // all pass.
    let (mut error, mut detail, symptom) = hand_cases(f);
    if error <= 1e-4 {
        let drawn = super::drawn::drawn_cases(f);
        crate::exercises::draws::fold_drawn(&mut error, &mut detail, drawn);
        let skimming = super::drawn::skimming_cases(f);
        crate::exercises::draws::fold_drawn(&mut error, &mut detail, skimming);
        let vast = super::drawn::vast_cases(f);
        crate::exercises::draws::fold_drawn(&mut error, &mut detail, vast);
    }
    let student = cornell(f, 32);
    let reference = cornell(reference_direct, 32);
    let picture = same_picture(student.mean, reference.mean);
    if error > 1e-4 {
        return Check {
            error,
            tolerance: 1e-4,
            detail,
            images: picture.images,
            symptom,
        };
    }
    Check {
        // A picture that differs fails even when every hand case matched.
        error: if picture.passed() { error } else { 1.0 },
        tolerance: 1e-4,
        detail: if picture.passed() {
            format!("{detail}; Cornell box: {}", picture.detail)
        } else {
            format!(
                "every hand-worked case matches, but in the Cornell box {}",
                picture.detail
            )
        },
        images: picture.images,
        symptom: None,
    }
}
