//! The thirty-second fresh set (2026-11-30), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: random numbers reused or correlated (M, 66 wrong), the
//! plural case, right with one of something and wrong with several (N,
//! 50), and incremental computation that drifts over many steps (O, 46);
//! 84 right alternatives, all of which pass. With the grader of 500a738,
//! 5 of the 162 wrong ones passed under seeds 51 and 52. The three here
//! now fail under seeds 51 to 53: two cosine samplers that never reach a
//! thin band of directions (z floored at 0.01, leaving out the 10⁻⁴ of
//! them nearest the rim; 6.28 for 2π, leaving out a wedge of 5·10⁻⁴),
//! and a sphere trace that advances its point by p += d·dir instead of
//! forming o + t·d, so that after a thousand steps the point it evaluates
//! has left the ray. Of the other two, one decides roulette in f32, right
//! by the contract down to q = 10⁻¹⁵ (below it no survivor is asked
//! for), and one lifts the disk without max(0), right in f32 as the
//! twenty-fifth set found (none of 2²⁴ azimuths at each of the 64
//! largest u.x gives x² + y² past 1).

use glam::{Vec2, Vec3};
use std::f32::consts::{FRAC_1_PI, PI};

use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch4, ch5};

use super::fails_every;
use super::knobs::{self, MarchKnobs};

/// A student's 2π (clippy's lint against it is the point).
#[allow(clippy::approx_constant)]
const SIX_28: f32 = 6.28;

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// The course's polar map with the azimuth's full turn `turn` and z
/// floored at `floor`.
fn polar(u: Vec2, turn: f32, floor: f32) -> (Vec3, f32) {
    let r = u.x.sqrt();
    let phi = turn * u.y;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt().max(floor);
    (Vec3::new(x, y, z), z * FRAC_1_PI)
}

#[test]
fn cosine_samplers_that_never_reach_a_thin_band_fail() {
    let gap = Some("a band of directions never drawn");
    fails_every(
        &SEEDS,
        "cosine_hemisphere: z floored at 0.01 (the 10⁻⁴ of directions nearest the rim never drawn)",
        gap,
        || ch5::check_cosine_hemisphere(|u| polar(u, 2.0 * PI, 0.01)),
    );
    fails_every(
        &SEEDS,
        "cosine_hemisphere: 6.28 for 2π (a wedge of 5·10⁻⁴ of the azimuths never drawn)",
        gap,
        || ch5::check_cosine_hemisphere(|u| polar(u, SIX_28, 0.0)),
    );
}

#[test]
fn a_march_that_advances_its_point_fails() {
    fails(
        "sphere_trace: the point advanced by p += d·dir, not formed as o + t·d",
        || {
            ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
                let k = MarchKnobs {
                    advanced_point: true,
                    ..Default::default()
                };
                knobs::sphere_trace(k, sdf, (o, d), eps, steps, max)
            })
        },
    );
}
