//! Chapter 5's exercises and how each is graded.

use std::f32::consts::FRAC_1_PI;

use glam::{Vec2, Vec3};

use super::{images, worst_of};
use crate::ch1_projection::camera::Camera;
use crate::ch5_reflection::light::area::solid_angle_pdf;
use crate::ch5_reflection::material::lambert::Lambertian;
use crate::ch5_reflection::warp::{cosine_hemisphere as warp_cosine, cosine_hemisphere_pdf};
use crate::core::sampling::random;
use crate::grading::exercise::{Check, Exercise};

type BrdfFn = fn(Vec3, Vec3, Vec3) -> Vec3;
type CosineFn = fn(Vec2) -> (Vec3, f32);
type PointFn = fn(Vec3, Vec3, Vec3, Vec3) -> Vec3;
type AreaPdfFn = fn(f32, Vec3, Vec3, Vec3) -> f32;

/// Chapter 5's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 5,
            name: "lambert_brdf",
            file: "chapters/ch5-reflection/exercises/lambert_brdf.rs",
            hints: [
                "slide \"the BRDF: ideal diffuse\": a Lambertian surface reflects the same radiance in every direction; energy conservation fixes the constant.",
                "∫ f cos θ dω over the hemisphere must equal the albedo ρ; ∫ cos θ dω = π. Directions on opposite sides of the surface reflect nothing.",
                "same side when wo.z * wi.z > 0; then rho / PI, else Vec3::ZERO",
            ],
            symptoms: &[],
            reference: || check_lambert_brdf(|rho, wo, wi| Lambertian { rho }.f(wo, wi)),
        },
        Exercise {
            chapter: 5,
            name: "cosine_hemisphere",
            file: "chapters/ch5-reflection/exercises/cosine_hemisphere.rs",
            hints: [
                "slide \"turning uniform numbers into directions\": sample a disk uniformly, then lift the point onto the hemisphere (Malley's method).",
                "a uniform disk needs r = sqrt(u) (area grows with r²); lift with z = sqrt(1 - r²). The density of the direction is proportional to cos θ.",
                "r = sqrt(u.x), phi = 2π u.y, (x, y) = r (cos phi, sin phi), z = sqrt(1 - r²), pdf = z / π",
            ],
            symptoms: &[],
            reference: || check_cosine_hemisphere(|u| {
                        let w = warp_cosine(u);
                        (w, cosine_hemisphere_pdf(w.z))
                    }),
        },
        Exercise {
            chapter: 5,
            name: "point_light",
            file: "chapters/ch5-reflection/exercises/point_light.rs",
            hints: [
                "slide \"radiometry: irradiance, Lambert's law\": intensity spreads over the sphere of radius r, and a tilted surface catches less.",
                "the inverse-square law divides by r², Lambert's law multiplies by cos θ (clamped at zero: light behind the surface does nothing).",
                "to = light - p; r² = to.length_squared(); cos = max(0, n · to/|to|); I cos / r²",
            ],
            symptoms: &[],
            reference: || check_point_light(|i, light, p, n| {
                        let to = light - p;
                        i * crate::ch5_reflection::radiometry::point_irradiance(
                            1.0,
                            to.length() as f64,
                            n.dot(to.normalize()) as f64,
                        ) as f32
                    }),
        },
        Exercise {
            chapter: 5,
            name: "area_pdf",
            file: "chapters/ch5-reflection/exercises/area_pdf.rs",
            hints: [
                "slide \"solid angle\": a small patch dA at distance d, seen at angle θ, subtends dω = dA cos θ / d².",
                "a density per area becomes a density per solid angle by the Jacobian dA/dω = d² / |cos θ_light|; edge-on (cos = 0) the light covers no solid angle.",
                "d² = (y - x).length_squared(); cos = |n_light · (x - y)/d|; 0 if cos == 0, else pdf_area d² / cos",
            ],
            symptoms: &[],
            reference: || check_area_pdf(|pdf, x, y, n| {
                        let to = y - x;
                        solid_angle_pdf(pdf, to.length(), n.dot(to.normalize()))
                    }),
        },
        Exercise {
            chapter: 5,
            name: "direct_light",
            file: "chapters/ch5-reflection/exercises/direct_light.rs",
            hints: [
                "slides \"the reflection equation, estimated at one point\" (light sampling) and \"solid angle\": L = f · Le · cos θ / pdf_ω, and a point drawn uniformly on the light has pdf_A = 1/A per area, not per solid angle.",
                "turn pdf_A into pdf_ω with dω = dA cos θl / d²: the estimate becomes f · Le · cos θ · cos θl / d² · A. Both cosines must be positive (the light faces p, p faces the light) and the segment p→y unblocked.",
                "wi = (y - p) / d; cos = n·wi; cos_l = n_light·(-wi); if cos <= 0 || cos_l <= 0 || !visible(p, y) { 0 } else { rho / π · le · cos · cos_l / d² · area }",
            ],
            symptoms: &[],
            reference: || check_direct_light(reference_direct),
        },
    ]
}

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
    rho * FRAC_1_PI * le * cos * cos_l / d2 * area
}

/// The capstone: the Cornell box (`cornell-box.toml`, 48 × 48, one ray
/// through each pixel centre) lit only directly by its ceiling light,
/// 32 light samples per pixel with the candidate and, with other random
/// numbers, with the reference; 8 × 8-pixel blocks must agree within 5
/// standard errors (a z-test: Monte Carlo answers are never exact).
pub fn check_direct_light(f: DirectFn) -> Check {
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
    let (world, camera) = (&world, &camera);
    let shade = |g: DirectFn, seed: u64| {
        move |x: u32, y: u32, s: u32| -> Vec3 {
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
            let u = Vec2::new(
                random(seed, pixel, s as u64, 0),
                random(seed, pixel, s as u64, 1),
            );
            // A point uniform by area: a triangle by area, then a point in it.
            let k = light
                .cdf
                .partition_point(|c| *c <= u.x * light.area)
                .min(light.cdf.len() - 1);
            let [a, b, c] = light.triangles[k];
            let bary = uniform_triangle(Vec2::new(random(seed, pixel, s as u64, 2), u.y));
            let point = bary.x * a + bary.y * b + bary.z * c;
            let visible = |p: Vec3, q: Vec3| {
                let to = q - p;
                let d = to.length();
                d > 0.0 && world.unoccluded(p, n, to / d, d)
            };
            if x == 0 && s == 0 {
                crate::grading::progress(format_args!(
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
        }
    };
    let student = images::Estimate::gather(w, h, 32, &shade(f, 501));
    let reference = images::Estimate::gather(w, h, 32, &shade(reference_direct, 502));
    images::z_test(student, reference, 8, 5.0, "reflected radiance")
}

fn rel(got: Vec3, want: Vec3) -> f64 {
    ((got - want).abs().max_element() / want.abs().max_element().max(1e-6)) as f64
}

/// ρ/π on the same side, 0 across, for hand-picked directions.
pub fn check_lambert_brdf(f: BrdfFn) -> Check {
    let rho = Vec3::new(0.9, 0.5, 0.1);
    let d = |x: f32, y: f32, z: f32| Vec3::new(x, y, z).normalize();
    let same = rho * FRAC_1_PI;
    let cases = [
        (d(0.0, 0.0, 1.0), d(0.0, 0.0, 1.0), same),
        (d(1.0, 0.0, 1.0), d(-0.3, 0.2, 0.5), same),
        (d(0.0, 1.0, 0.01), d(0.9, 0.0, 0.05), same),
        // Both below: still the same side (two-sided).
        (d(0.2, 0.0, -1.0), d(0.0, 0.4, -1.0), same),
        // Opposite sides: nothing.
        (d(0.0, 0.0, 1.0), d(0.0, 0.0, -1.0), Vec3::ZERO),
        (d(1.0, 0.0, -0.2), d(0.3, 0.3, 0.8), Vec3::ZERO),
    ];
    let (error, detail) = worst_of(cases.into_iter().map(|(wo, wi, want)| {
        let got = f(rho, wo, wi);
        let err = if want == Vec3::ZERO {
            got.abs().max_element() as f64
        } else {
            rel(got, want)
        };
        (err, format!("ωo {wo}, ωi {wi}: got {got}, expected {want}"))
    }));
    Check {
        error,
        tolerance: 1e-5,
        detail,
        images: None,
        symptom: None,
    }
}

/// Statistical: every sample is a unit direction with z ≥ 0 whose pdf is
/// z/π; over 40,000 samples, E(z) = 2/3, E(x) = E(y) = 0 and P(z < 1/2)
/// = 1/4 (for cos θ/π, P(cos θ < c) = c²). The error is the worst
/// deviation in standard errors (5 passes), or a large number when a
/// sample is not even a direction on the hemisphere.
pub fn check_cosine_hemisphere(f: CosineFn) -> Check {
    let n = 40_000u64;
    let (mut sx, mut sy, mut sz, mut low) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for i in 0..n {
        let u = Vec2::new(random(55, i, 0, 0), random(55, i, 0, 1));
        let (w, pdf) = f(u);
        if !((w.length() - 1.0).abs() < 1e-4 && w.z >= -1e-6) {
            return Check {
                error: 1e9,
                tolerance: 5.0,
                detail: format!("u = {u}: {w} is not a unit direction with z ≥ 0"),
                images: None,
                symptom: None,
            };
        }
        let want = w.z.max(0.0) * FRAC_1_PI;
        if (pdf - want).abs() > 1e-4 * want.max(1e-3) {
            return Check {
                error: 1e9,
                tolerance: 5.0,
                detail: format!("u = {u}: direction {w} has pdf {pdf}, expected z/π = {want}"),
                images: None,
                symptom: None,
            };
        }
        sx += w.x as f64;
        sy += w.y as f64;
        sz += w.z as f64;
        low += f64::from(w.z < 0.5);
    }
    let m = n as f64;
    // Standard deviations under cos θ/π: x and y have variance 1/4, z has
    // 1/2 − 4/9, the indicator 1/4 · 3/4.
    let stats = [
        ("mean x", sx / m, 0.0, 0.25f64),
        ("mean y", sy / m, 0.0, 0.25),
        ("mean z", sz / m, 2.0 / 3.0, 0.5 - 4.0 / 9.0),
        ("P(z < 1/2)", low / m, 0.25, 0.1875),
    ];
    let (error, detail) = worst_of(stats.into_iter().map(|(what, got, want, var)| {
        let z = (got - want).abs() / (var / m).sqrt();
        (
            z,
            format!("{what} = {got:.4}, expected {want:.4} ({z:.1} standard errors off)"),
        )
    }));
    Check {
        error,
        tolerance: 5.0,
        detail,
        images: None,
        symptom: None,
    }
}

/// E = I cos θ / r² for hand-worked cases.
pub fn check_point_light(f: PointFn) -> Check {
    let i = Vec3::new(4.0, 2.0, 1.0);
    let cases = [
        // Straight above at 2 m: I/4.
        (Vec3::new(0.0, 0.0, 2.0), Vec3::ZERO, Vec3::Z, i / 4.0),
        // 5 m away along (3, 0, 4): cos θ = 4/5, r² = 25.
        (
            Vec3::new(3.0, 0.0, 4.0),
            Vec3::ZERO,
            Vec3::Z,
            i * 0.8 / 25.0,
        ),
        // Off the origin and a tilted normal: to = (0, 1, 1), cos = 1.
        (
            Vec3::new(1.0, 2.0, 3.0),
            Vec3::new(1.0, 1.0, 2.0),
            Vec3::new(0.0, 1.0, 1.0).normalize(),
            i / 2.0,
        ),
        // Behind the surface: nothing.
        (Vec3::new(0.0, 0.0, -1.0), Vec3::ZERO, Vec3::Z, Vec3::ZERO),
    ];
    let (error, detail) = worst_of(cases.into_iter().map(|(light, p, n, want)| {
        let got = f(i, light, p, n);
        let err = if want == Vec3::ZERO {
            got.abs().max_element() as f64
        } else {
            rel(got, want)
        };
        (
            err,
            format!("light at {light}, p {p}, n {n}: got {got}, expected {want}"),
        )
    }));
    Check {
        error,
        tolerance: 1e-4,
        detail,
        images: None,
        symptom: None,
    }
}

/// pdf_A d²/|cos θl| for hand-worked cases, and 0 edge-on.
pub fn check_area_pdf(f: AreaPdfFn) -> Check {
    let cases = [
        // Light 2 m straight above, facing down: 1/A · 4 / 1.
        (0.5, Vec3::ZERO, Vec3::new(0.0, 0.0, 2.0), -Vec3::Z, 2.0),
        // Facing up (seen from behind): |cos| is still 1.
        (0.5, Vec3::ZERO, Vec3::new(0.0, 0.0, 2.0), Vec3::Z, 2.0),
        // 5 m away along (3, 0, 4), light normal -z: cos θl = 4/5.
        (
            1.0,
            Vec3::ZERO,
            Vec3::new(3.0, 0.0, 4.0),
            -Vec3::Z,
            25.0 / 0.8,
        ),
        // Edge-on: no area shows.
        (1.0, Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::Z, 0.0),
    ];
    let (error, detail) = worst_of(cases.into_iter().map(|(pdf, x, y, n, want)| {
        let got = f(pdf, x, y, n);
        let err = if want == 0.0 {
            got.abs() as f64
        } else {
            ((got - want) / want).abs() as f64
        };
        (
            err,
            format!("pdf_A {pdf}, x {x}, y {y}, n_light {n}: got {got}, expected {want}"),
        )
    }));
    Check {
        error,
        tolerance: 1e-4,
        detail,
        images: None,
        symptom: None,
    }
}
