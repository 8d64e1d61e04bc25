//! The sixth fresh set (2026-11-29): plausible wrong solutions written by
//! two testers from the stubs' contracts before reading the checks, each
//! the course's solution (`tests/project/solutions/`) with one change. The
//! ones the grader let through until this set, now caught: a clause's
//! domain the checks did not draw (an `up` 1° to 8° from the view, a point
//! near a long edge, a NaN on an empty sample, a u32::MAX index, a sample
//! 10⁻⁵ pixels inside an edge, a hit 10⁻⁷ to 10⁻⁴ away, an origin within ε
//! of a surface, a ray leaving a surface at a grazing angle, a z of 10⁻³⁰,
//! a cosine along an exact axis, a scene 10⁴ times its size from the
//! origin, a narrow spike, q near 1, a value of 10⁻³⁰) or a statistic they
//! did not take (the numbers a bounce is drawn from). Each must fail under
//! every seed tried; where one copies a long solution, it is that solution
//! written once with knobs ([`super::knobs`]), one knob turned.

use std::f32::consts::PI;

use glam::{Mat4, Vec2, Vec3};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::grading::counted::{Hit, ReadableBvh};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch2::manifold;
use raystep::grading::exercises::paths::{self, PathScene};
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5, ch6};

use super::fails_every;
use super::knobs::{
    self, BvhKnobs, DirectKnobs, Knobs, LookKnobs, MarchKnobs, MollerKnobs, PathKnobs, RasterKnobs,
    SceneKnobs,
};

/// The seeds every mutant must fail under: the testers' three and one
/// more.
const SEEDS: [u64; 4] = [81, 82, 83, 0x2026_1129];

/// The path loop's check traces 200,000 paths per seed: two seeds.
const PATH_SEEDS: &[u64] = &[81, 82];

fn fails(what: &str, symptom: Option<&str>, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, symptom, check);
}

// ---- 1.2 look_at ---------------------------------------------------------------

/// Swaps `up` for a world axis when it is within 8° of the view: up is
/// not parallel there, and the picture comes out rolled.
fn look_at_axis_near_parallel(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    knobs::look_at(
        LookKnobs::with(|k| k.axis_near_parallel = true),
        eye,
        target,
        up,
    )
}

#[test]
fn look_at_axis_near_parallel_fails() {
    fails(
        "up swapped for an axis within 8° of the view",
        None,
        || ch1::check_look_at(look_at_axis_near_parallel),
    );
}

// ---- 2.1 edge_function ---------------------------------------------------------

/// "On the line gives exactly 0" with a tolerance relative to the squared
/// lengths: a point near a, beside a long edge, comes back 0.
fn edge_relative_zero(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    let (e, q) = (b - a, p - a);
    let value = e.perp_dot(q);
    if value.abs() <= f32::EPSILON * (e.length_squared() + q.length_squared()) {
        return 0.0;
    }
    value
}

#[test]
fn edge_function_relative_zero_fails() {
    fails("0 within ε (|e|² + |q|²)", None, || {
        ch2::check_edge_function(edge_relative_zero)
    });
}

// ---- 2.3 depth_test ------------------------------------------------------------

/// A shortcut for an empty sample that stores z before testing it: a NaN
/// returns false but is stored.
fn depth_empty_stores(depth: &mut [f32], index: usize, z: f32) -> bool {
    if depth[index] == f32::INFINITY {
        depth[index] = z;
        return z < f32::INFINITY;
    }
    let nearer = z < depth[index];
    if nearer {
        depth[index] = z;
    }
    nearer
}

#[test]
fn depth_test_empty_stores_fails() {
    fails("an empty sample's z stored untested", None, || {
        ch2::check_depth_test(depth_empty_stores)
    });
}

// ---- 2.4 rasterize_triangle and 2.5 manifold -----------------------------------

/// A sample inside an edge that is neither top nor left only where its
/// edge function exceeds 10⁻⁵.
fn raster_edge_slack(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    let k = RasterKnobs::with(|k| k.edge_slack = 1e-5);
    knobs::rasterize(k, v, c, (w, h), d, i);
}

/// u32::MAX taken as a marker for "no triangle": a real triangle whose
/// first index is u32::MAX is left out.
fn manifold_marker(tris: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    let kept: Vec<[u32; 3]> = tris.iter().copied().filter(|t| t[0] != u32::MAX).collect();
    manifold::reference_counts(&kept)
}

#[test]
fn rasterize_and_manifold_mistakes_fail() {
    fails("a slack of 10⁻⁵ on the other edges", None, || {
        ch2::check_rasterize_triangle(raster_edge_slack)
    });
    fails("u32::MAX as a marker", None, || {
        ch2::check_manifold(manifold_marker)
    });
}

// ---- 3.3 moller_trumbore and 3.4 bvh_traversal ---------------------------------

/// Hits at t up to 10⁻⁴ refused ("self-intersection").
fn moller_t_floor(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    knobs::moller(MollerKnobs::with(|k| k.t_floor = 1e-4), o, d, tri)
}

/// A later hit kept only where it is nearer than the best by more than
/// 10⁻⁴ ("z-fighting").
fn bvh_improve_by(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    knobs::closest_hit(BvhKnobs::with(|k| k.improve_by = 1e-4), bvh, ray, t_max)
}

#[test]
fn moller_and_bvh_mistakes_fail() {
    fails("t > 10⁻⁴", None, || {
        ch3::check_moller_trumbore(moller_t_floor)
    });
    fails("nearer by more than 10⁻⁴", None, || {
        ch3::check_bvh_traversal(bvh_improve_by)
    });
}

// ---- 4.2 sphere_trace and 4.4 trace_scene --------------------------------------

/// The evaluation at t = 0 not tested: an origin within ε of a surface
/// steps on.
fn trace_first_untested(
    f: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    e: f32,
    n: u32,
    m: f32,
) -> Option<f32> {
    knobs::sphere_trace(
        MarchKnobs::with(|k| k.first_untested = true),
        f,
        (o, d),
        e,
        n,
        m,
    )
}

/// The normal turned round only where n · d > 10⁻³.
fn scene_flip_above(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    knobs::trace_scene(SceneKnobs::with(|k| k.flip_above = 1e-3), f, o, d, m)
}

#[test]
fn sphere_tracing_mistakes_fail() {
    fails("the first evaluation untested", None, || {
        ch4::check_sphere_trace(trace_first_untested)
    });
    fails("turned round above n · d = 10⁻³", None, || {
        ch4::check_trace_scene(scene_flip_above)
    });
}

// ---- 5.1 lambert_brdf, 5.3 point_light, 5.5 direct_light -----------------------

/// "Same side" as |wo.z + wi.z| > |wo.z − wi.z|: a z of 10⁻⁹ beside one of
/// 1 is lost.
fn lambert_sum_difference(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    if (wo.z + wi.z).abs() > (wo.z - wi.z).abs() {
        rho / PI
    } else {
        Vec3::ZERO
    }
}

/// cos θ as cos(angle_between(n, to)): the round trip through acos loses
/// a small cosine.
fn point_through_angle(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let cos = n.angle_between(to).cos().max(0.0);
    intensity * cos / to.length_squared()
}

#[test]
fn reflection_mistakes_fail() {
    fails("same side by sum and difference", None, || {
        ch5::check_lambert_brdf(lambert_sum_difference)
    });
    fails("cos through the angle", None, || {
        ch5::check_point_light(point_through_angle)
    });
    fails("below the plane by its equation", None, || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
            let k = DirectKnobs::with(|k| k.plane_equation = true);
            knobs::direct(k, (p, n, rho), (y, nl, a, le), v)
        })
    });
}

// ---- 6.1 mc_integral and 6.2 russian_roulette ----------------------------------

/// The points kept 0.5% off each end of [a, b] ("the ends are singular").
fn integral_squeezed(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.is_empty() {
        return 0.0;
    }
    let sum: f64 = u.iter().map(|u| f(a + (0.005 + 0.99 * u) * (b - a))).sum();
    (b - a) * sum / u.len() as f64
}

/// The median of eight groups' means ("robust to outliers").
fn integral_median_of_means(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.len() < 8 {
        let sum: f64 = u.iter().map(|u| f(a + u * (b - a))).sum();
        return (b - a) * sum / u.len().max(1) as f64;
    }
    let mut means: Vec<f64> = u
        .chunks(u.len().div_ceil(8))
        .map(|c| (b - a) * c.iter().map(|u| f(a + u * (b - a))).sum::<f64>() / c.len() as f64)
        .collect();
    means.sort_by(f64::total_cmp);
    0.5 * (means[3] + means[4])
}

/// Above q = 0.99 the path always survives, undivided.
fn roulette_sure_near_one(value: f64, q: f64, u: f64) -> f64 {
    match (q > 0.99, u < q) {
        (true, _) => value,
        (false, true) => value / q,
        (false, false) => 0.0,
    }
}

/// A value under 10⁻⁶ always ends ("not worth tracing").
fn roulette_tiny_ends(value: f64, q: f64, u: f64) -> f64 {
    if value.abs() < 1e-6 || u >= q {
        0.0
    } else {
        value / q
    }
}

/// Divided by q + 10⁻⁶ ("no division by zero").
fn roulette_guarded(value: f64, q: f64, u: f64) -> f64 {
    if u < q {
        value / (q + 1e-6)
    } else {
        0.0
    }
}

#[test]
fn estimator_mistakes_fail() {
    fails("points squeezed off the ends", None, || {
        ch6::check_mc_integral(integral_squeezed)
    });
    fails("median of means", None, || {
        ch6::check_mc_integral(integral_median_of_means)
    });
    fails(
        "sure survival above 0.99",
        Some("the wrong fraction of paths ends"),
        || ch6::check_russian_roulette(roulette_sure_near_one),
    );
    fails("tiny values end", None, || {
        ch6::check_russian_roulette(roulette_tiny_ends)
    });
    fails(
        "divided by q + 10⁻⁶",
        Some("roulette changes the mean"),
        || ch6::check_russian_roulette(roulette_guarded),
    );
}

// ---- 6.4 path_radiance ---------------------------------------------------------

/// The roulette's number (known to be below q) used again as the next
/// bounce's u.x: that direction is not cosine distributed.
fn path_reused_number(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    knobs::path(
        PathKnobs::with(|k| k.reuse_roulette_u = true),
        scene,
        o,
        d,
        rng,
    )
}

#[test]
fn path_radiance_reused_number_fails() {
    fails_every(PATH_SEEDS, "the roulette's number reused", None, || {
        paths::check_path_radiance(path_reused_number)
    });
}
