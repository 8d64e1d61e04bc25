//! The thirty-eighth fresh set (2026-12-01), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle no earlier set had: E, a solution more general than the
//! exercise asks (50 wrong); F, debugging leftovers, a clamp, guard or
//! special case left in (60 wrong); G, another well-known algorithm for
//! the same task (62 wrong); and 74 right alternatives. With the grader
//! of bff5799, 6 of the 172 wrong ones passed under at least one of seeds
//! 51 to 53, and a seventh under seed 54 (a solid angle within 10⁻³ of
//! 2π snapped to 2π); all seven now fail under seeds 51 to 55. One right
//! alternative failed: ray_plane in Hessian form (N / |N|), whose |N|²
//! underflows for the grader's shortest N. It is wrong where the
//! contract's N lie, which the stub now says (10⁻²⁶ to 10²⁵ long), so it
//! is a wrong one here.

use glam::Vec3;
use raystep::ch2_rasterization::triangle::rasterize_triangle;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::ch5_reflection::radiometry::spot_flux;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::paths::check_path_radiance;
use raystep::grading::exercises::{ch2, ch3, ch4, ch5};

use super::fails_every;
use super::knobs::{self, PathKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1206];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// The lesson's rasterizer with a margin in its depth test: drawn only
/// where z < depth − 10⁻⁵ (run on a buffer 10⁻⁵ nearer, and only what it
/// wrote kept).
fn raster_depth_margin(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    let before: Vec<f32> = d.iter().map(|z| z - 1e-5).collect();
    let mut shifted = before.clone();
    rasterize_triangle(v, c, w, h, &mut shifted, i);
    for ((z, new), old) in d.iter_mut().zip(&shifted).zip(&before) {
        if new.to_bits() != old.to_bits() {
            *z = *new;
        }
    }
}

#[test]
fn a_depth_test_with_a_margin_fails() {
    fails("rasterize_triangle: z < depth - 1e-5", || {
        ch2::check_rasterize_triangle(raster_depth_margin)
    });
}

#[test]
fn a_march_with_a_step_cap_of_its_own_fails() {
    fails(
        "trace_scene: at most 512 steps, whatever the budget",
        || {
            ch4::check_trace_scene(|sdf, o, d, m| {
                let capped = March {
                    max_steps: m.max_steps.min(512),
                    ..*m
                };
                ch4::reference_trace_ray(sdf, o, d, &capped)
            })
        },
    );
}

/// The closed form, but no power at all for a cone narrower than 10⁻⁴
/// rad.
fn spot_nothing_below(i: Vec3, inner: f32, outer: f32) -> Vec3 {
    match outer < 1e-4 {
        true => Vec3::ZERO,
        false => (i.as_dvec3() * spot_flux(1.0, inner.into(), outer.into())).as_vec3(),
    }
}

#[test]
fn a_spot_too_narrow_to_shine_fails() {
    fails("spot: 0 below 1e-4 rad", || {
        ch5::check_spot(spot_nothing_below)
    });
}

#[test]
fn a_light_density_floored_at_one_hundredth_fails() {
    fails(
        "path_radiance: the light sample's pdf floored at 1e-2",
        || {
            check_path_radiance(|s, o, d, r| {
                let k = PathKnobs {
                    light_pdf_floor: Some(1e-2),
                    ..PathKnobs::default()
                };
                knobs::path(k, s, o, d, r)
            })
        },
    );
}

#[test]
fn a_light_sample_along_one_line_of_the_light_fails() {
    fails("path_radiance: the light sample's v fixed at 1/2", || {
        check_path_radiance(|s, o, d, r| {
            let k = PathKnobs {
                light_v_half: true,
                ..PathKnobs::default()
            };
            knobs::path(k, s, o, d, r)
        })
    });
}

/// The plane first, then the barycentrics of the hit point o + t d: that
/// point carries the rounding of its coordinates, so a small triangle far
/// from the world's origin gets u and v far off.
fn moller_plane_then_barycentric(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
    let n = e1.cross(e2);
    let denom = n.dot(d);
    if denom == 0.0 {
        return None;
    }
    let t = n.dot(tri[0] - o) / denom;
    let q = o + t * d - tri[0];
    let nn = n.dot(n);
    let (u, v) = (n.dot(q.cross(e2)) / nn, n.dot(e1.cross(q)) / nn);
    (t > 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.0).then_some((t, u, v))
}

#[test]
fn a_hit_point_rebuilt_from_t_fails() {
    fails(
        "moller_trumbore: the plane, then o + t d's barycentrics",
        || ch3::check_moller_trumbore(moller_plane_then_barycentric),
    );
}

/// The plane in Hessian form: N / |N| and c / |N|, where |N|² leaves
/// f32's range for the contract's shortest and longest N.
fn plane_hessian(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let len = n.length();
    let (m, dist) = (n / len, c / len);
    let denom = m.dot(d);
    (denom != 0.0 && n.dot(d) != 0.0).then(|| (dist - m.dot(o)) / denom)
}

/// The course's formula, but nearly a hemisphere taken as one: Ω within
/// 10⁻³ of 2π snapped to 2π (off by up to 1.6·10⁻⁴ of it).
fn solid_angle_snapped(p: Vec3, tri: [Vec3; 3]) -> f32 {
    let (a, b, c) = (tri[0] - p, tri[1] - p, tri[2] - p);
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let num = a.dot(b.cross(c)).abs();
    let den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    let omega = 2.0 * num.atan2(den);
    match omega > std::f32::consts::TAU - 1e-3 {
        true => std::f32::consts::TAU,
        false => omega,
    }
}

#[test]
fn nearly_a_hemisphere_snapped_to_one_fails() {
    fails("solid_angle: within 1e-3 of 2π taken as 2π", || {
        ch5::check_solid_angle(solid_angle_snapped)
    });
}

#[test]
fn a_plane_normalised_first_fails() {
    fails("ray_plane: N normalised first", || {
        ch3::check_ray_plane(plane_hessian)
    });
}
