//! The thirty-seventh fresh set (2026-12-01), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! taking two chapters clause by clause: a wrong solution for every
//! clause of every contract, breaking only that clause on a small part of
//! its domain (B: chapters 1 and 2, 47 wrong; C: 3 and 4, 51; D: 5 and 6,
//! 54); 45 right alternatives, all of which pass. With the grader of
//! a77efa6, 5 of the 152 wrong ones passed under at least one of seeds 51
//! to 53. The three here now fail under seeds 51 to 55 (the SAH by
//! volume under 51 to 57; roulette decided in f32, whose share of
//! survivors is off by more than 0.2 % only for q below 1.5·10⁻⁵, by a
//! new clause of the stub: for q up to 10⁻⁴ the survivors lie within 2q
//! of 0 or of 1, where the grader measures their share). The other two
//! are outside their contracts (a NaN depth for project_point; a
//! determinant below f32's normal numbers for Möller–Trumbore, whose stub
//! now says d is 10⁻²⁶ to 10²⁶ long).

use glam::Vec3;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch3, ch5, ch6};

use super::fails_every;
use super::knobs::{self, Measure, SahKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1205];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// The point light's irradiance, 0 only where cos θ < -10⁻⁴: a light just
/// behind the surface gives a small negative E.
fn point_light_cut_below_horizon(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let cos = n.dot(to.normalize());
    match cos < -1e-4 {
        true => Vec3::ZERO,
        false => intensity * cos / to.length_squared(),
    }
}

#[test]
fn a_light_just_behind_the_surface_that_still_lights_fails() {
    fails("point_light: 0 only below cos θ = -1e-4", || {
        ch5::check_point_light(point_light_cut_below_horizon)
    });
}

#[test]
fn a_surface_area_heuristic_by_volume_fails() {
    fails("sah: the boxes' volumes for their areas", || {
        ch3::check_sah(|b, c| {
            let k = SahKnobs {
                measure: Measure::Volume,
                ..SahKnobs::default()
            };
            knobs::sah_sweep(k, b, c)
        })
    });
}

/// Survives where u ≥ 1 − q with both rounded to f32: 1 − q keeps seven
/// digits, so for q below 10⁻⁵ the survivors' share is off by up to 3 %.
fn roulette_in_f32(value: f64, q: f64, u: f64) -> f64 {
    match u as f32 >= 1.0 - q as f32 {
        true => value / q,
        false => 0.0,
    }
}

#[test]
fn roulette_decided_in_f32_fails() {
    fails("russian_roulette: u >= 1 - q in f32", || {
        ch6::check_russian_roulette(roulette_in_f32)
    });
}
