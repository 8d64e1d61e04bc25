//! The eighth fresh set (2026-11-29): plausible wrong solutions written
//! by two more testers from the stubs' contracts before reading the
//! checks, as a student restructuring or optimising the course's solution
//! would: guards, caches, early exits, a helper for one case reused for
//! another. The ones the grader let through until this set, now caught: a
//! near plane from 10⁻⁶, a ray parallel to a box's side just inside it, a
//! gradient a quarter long, a cosine of -0, a density repeated with
//! another beside it, a light from 10³ to 10⁸ bright, and every light
//! sample's shadow ray counted. Each must fail under every seed tried.

use std::cell::Cell;

use glam::{Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::grading::counted::{Hit, ReadableBvh};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::paths::{self, PathScene};
use raystep::grading::exercises::{ch1, ch3, ch4, ch5, ch6};

use super::fails_every;
use super::knobs::{self, BvhKnobs, DirectKnobs, EdgeKnobs, Knobs, PathKnobs, SceneKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [61, 62, 91, 0x2026_1129];

/// The path loop's check traces 200,000 paths per seed: two seeds.
const PATH_SEEDS: &[u64] = &[61, 91];

fn fails(what: &str, symptom: Option<&str>, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, symptom, check);
}

thread_local! {
    static LAST_WEIGHT: Cell<Option<(f64, f64)>> = const { Cell::new(None) };
}

/// An end nearer the pinhole than 10⁻⁴ after the clip gives None ("no
/// division by a tiny z"): wrong for a near plane under 10⁻⁴.
fn edges_depth_guard(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    knobs::draw_edges(
        EdgeKnobs::with(|k| k.min_depth = Some(1e-4)),
        camera,
        a,
        b,
        near,
    )
}

/// A direction's zero components made ε before 1/d ("no division by
/// zero"): a ray parallel to a box's side, just inside it, leaves it.
fn bvh_nudged(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    knobs::closest_hit(BvhKnobs::with(|k| k.nudge_zero_dir = true), bvh, ray, t_max)
}

/// -dir as the normal wherever the gradient is shorter than 1/2.
fn scene_short_gradient(
    sdf: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    m: &March,
) -> Option<(f32, Vec3)> {
    knobs::trace_scene(
        SceneKnobs::with(|k| k.fallback_below = Some(0.5)),
        sdf,
        o,
        d,
        m,
    )
}

#[test]
fn geometry_mistakes_fail() {
    fails("ends within 10⁻⁴ of the pinhole refused", None, || {
        ch1::check_draw_edges(edges_depth_guard)
    });
    fails("zero direction components nudged", None, || {
        ch3::check_bvh_traversal(bvh_nudged)
    });
    fails("-dir below a gradient of 1/2", None, || {
        ch4::check_trace_scene(scene_short_gradient)
    });
}

/// Edge-on tested by the cosine's bits being 0: a -0 slips through.
fn pdf_zero_bits(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    let to = x - y;
    let d2 = to.length_squared();
    let cos = n_light.dot(to / d2.sqrt());
    if cos.to_bits() == 0 {
        0.0
    } else {
        pdf_area * d2 / cos.abs()
    }
}

/// The weight remembered by pdf_f alone.
fn weight_remembered(pdf_f: f64, pdf_g: f64) -> f64 {
    if pdf_f <= 0.0 {
        return 0.0;
    }
    if let Some((f, w)) = LAST_WEIGHT.with(|c| c.get()).filter(|(f, _)| *f == pdf_f) {
        let _ = f;
        return w;
    }
    let r = pdf_g / pdf_f;
    let w = 1.0 / (1.0 + r * r);
    LAST_WEIGHT.with(|c| c.set(Some((pdf_f, w))));
    w
}

#[test]
fn light_mistakes_fail() {
    fails("edge-on by the cosine's bits", None, || {
        ch5::check_area_pdf(pdf_zero_bits)
    });
    // Clamped to 100 per channel ("fireflies").
    fails("clamped to 100", None, || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
            let k = DirectKnobs::with(|k| k.clamp = Some(100.0));
            knobs::direct(k, (p, n, rho), (y, nl, a, le), v)
        })
    });
    fails("the weight remembered by pdf_f", None, || {
        LAST_WEIGHT.with(|c| c.set(None));
        ch6::check_mis_weight(weight_remembered)
    });
}

/// A light sample that brings under 10⁻³ counted without its shadow ray.
fn path_lazy_shadow(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    knobs::path(
        PathKnobs::with(|k| k.lazy_below = Some(1e-3)),
        scene,
        o,
        d,
        rng,
    )
}

#[test]
fn path_radiance_lazy_shadow_fails() {
    fails_every(
        PATH_SEEDS,
        "small light samples without a shadow ray",
        None,
        || paths::check_path_radiance(path_lazy_shadow),
    );
}
