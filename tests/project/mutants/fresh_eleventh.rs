//! The eleventh fresh set (2026-11-29): plausible wrong solutions written
//! by two more testers before reading the checks, from the pitfalls of
//! the language and of glam (conventions, casts, `is_normal`, `signum` of
//! ±0, iterator adapters) and from reading a contract too quickly. Of 91
//! wrong ones, three passed; the two now caught: a light well behind the
//! surface must bring exactly 0 (a cosine clamped at f32::EPSILON brings
//! a little), and a triangle with a corner on the image's border must be
//! drawn (`is_normal` is false for 0). Each must fail under every seed
//! tried.

use glam::Vec3;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch2, ch5};

use super::fails_every;
use super::knobs::{self, RasterKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [101, 102, 107, 0x2026_1129];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// The cosine clamped at f32::EPSILON, not at 0: a light behind brings a
/// little.
fn point_cos_epsilon(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let r2 = to.length_squared();
    intensity * n.dot(to / r2.sqrt()).max(f32::EPSILON) / r2
}

#[test]
fn library_pitfalls_fail() {
    fails("a cosine clamped at f32::EPSILON", || {
        ch5::check_point_light(point_cos_epsilon)
    });
    // "Not finite" corners refused with `is_normal`, which 0 is not.
    fails("corners refused by is_normal", || {
        ch2::check_rasterize_triangle(|v, colors, w, h, depth, image| {
            if v.iter().all(|p| p.to_array().iter().all(|c| c.is_normal())) {
                knobs::rasterize(RasterKnobs::default(), v, colors, (w, h), depth, image);
            }
        })
    });
}
