//! The tenth fresh set (2026-11-29): plausible wrong solutions written by
//! two more testers before reading the checks, as a student who has read
//! other renderers or who optimises would write them (other conventions,
//! bit-trick reciprocals and square roots, loops unrolled, padding
//! against cracks, weights too small to matter). The ones the grader let
//! through until this set, now caught: a disk radius a few percent off
//! (a grid of u spread over the hemisphere), an ε added to cos θl (a light
//! exactly edge-on but for a hair), an inside test padded by 10⁻³, a slab
//! test with an approximate 1/d (rays aimed just inside triangles' edges),
//! an odd step budget, and MIS weights under 10⁻⁴ dropped. Each must fail
//! under every seed tried.

use glam::{Vec2, Vec3};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::ch6_global_illumination::layers::LAYER_SLOTS;
use raystep::grading::counted::{Hit, ReadableBvh};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::bounce_layers::{check_bounce_layers, Gathered};
use raystep::grading::exercises::{ch3, ch4, ch5};

use super::fails_every;
use super::knobs::{self, BvhKnobs, DirectKnobs, Knobs, LayersKnobs, MarchKnobs, SceneKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [81, 82, 97, 0x2026_1129];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// Malley's method with r = √u.x from the exponent-halving bit trick
/// (up to 4% off).
fn cosine_bit_sqrt(u: Vec2) -> (Vec3, f32) {
    let r = f32::from_bits((u.x.to_bits() >> 1) + 0x1fbd_1df5);
    let phi = std::f32::consts::TAU * u.y;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    (Vec3::new(x, y, z), z * std::f32::consts::FRAC_1_PI)
}

#[test]
fn light_mistakes_fail() {
    fails("a bit-trick √u.x", || {
        ch5::check_cosine_hemisphere(cosine_bit_sqrt)
    });
    // 10⁻⁶ added to cos θl "against division by 0".
    fails("10⁻⁶ added to cos θl", || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
            let k = DirectKnobs::with(|k| k.cos_light_plus = 1e-6);
            knobs::direct(k, (p, n, rho), (y, nl, a, le), v)
        })
    });
}

/// The inside test padded by 10⁻³ against cracks.
fn moller_padded(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
    let pvec = d.cross(e2);
    let det = e1.dot(pvec);
    if det == 0.0 {
        return None;
    }
    let tvec = o - tri[0];
    let qvec = tvec.cross(e1);
    let (u, v, t) = (tvec.dot(pvec) / det, d.dot(qvec) / det, e2.dot(qvec) / det);
    let pad = 1e-3;
    (u >= -pad && v >= -pad && u + v <= 1.0 + pad && t > 0.0).then_some((t, u, v))
}

/// 1/d from the bit trick in the slab test.
fn bvh_approximate_recip(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    knobs::closest_hit(BvhKnobs::with(|k| k.approx_recip = true), bvh, ray, t_max)
}

/// The capstone's march unrolled the same way.
fn scene_unrolled(
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    march: &March,
) -> Option<(f32, Vec3)> {
    knobs::trace_scene(
        SceneKnobs::with(|k| k.unrolled = true),
        sdf,
        origin,
        dir,
        march,
    )
}

#[test]
fn geometry_mistakes_fail() {
    fails("an inside test padded by 10⁻³", || {
        ch3::check_moller_trumbore(moller_padded)
    });
    fails("an approximate 1/d in the slab test", || {
        ch3::check_bvh_traversal(bvh_approximate_recip)
    });
    // Two evaluations a turn for max_steps / 2 turns: an odd budget loses
    // its last evaluation.
    fails("sphere tracing unrolled by two", || {
        ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
            let k = MarchKnobs::with(|k| k.unrolled = true);
            knobs::sphere_trace(k, sdf, (o, d), eps, steps, max)
        })
    });
    fails("the capstone's march unrolled by two", || {
        ch4::check_trace_scene(scene_unrolled)
    });
}

/// Contributions whose MIS weight is under 10⁻⁴ skipped.
fn layers_skip_small_weights(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    knobs::layers(
        LayersKnobs::with(|k| k.skip_weight_below = Some(1e-4)),
        path,
    )
}

#[test]
fn layer_mistakes_fail() {
    fails("MIS weights under 10⁻⁴ skipped", || {
        check_bounce_layers(layers_skip_small_weights)
    });
}
