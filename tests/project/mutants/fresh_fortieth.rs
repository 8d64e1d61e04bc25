//! The fortieth fresh set (2026-12-01), three testers who read the stubs,
//! the book and the course's solutions but not the grader: K, misread
//! units and conventions (143 wrong, 35 right); L, solutions fitted to the
//! demo scene (117 wrong, 35 right); M, slips made while refactoring (136
//! wrong, 60 right). With the grader of 8cb2aea, under seed 51, one wrong
//! file passed for a reason inside its contract: the running mean below,
//! which never counts the first number. One right file failed for a reason
//! of ours: a ray-plane hit by the reciprocal of Nᵀd, where a hand-worked
//! case had d shorter than the contract allows (Nᵀd = 2^-140, whose
//! reciprocal overflows). The contract now says in so many words that Nᵀd
//! is 0 or a normal number, so a solution that takes a subnormal Nᵀd as
//! parallel (a mutant of the twenty-second set) is right too. (Fresnel's
//! s and p terms with cos θi and cos θt exchanged in both passes, and
//! rightly: each becomes minus the other, and their squares' mean is the
//! same.)

use glam::Vec3;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch3, ch6};

use super::{fails_every, passes_every};

/// The seeds every mutant must fail, and every right one pass, under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1201];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// A running mean m += (x − m) / i.max(1): the second number overwrites
/// the first, so the answer is the mean of all but the first number. It
/// is still unbiased, with a plain estimator's spread, and exact on a
/// constant; only the weights are wrong.
fn mc_running_mean_skips_the_first(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    let mut mean = 0.0;
    for (i, u) in u.iter().enumerate() {
        let sample = f(a + u * (b - a)) * (b - a);
        mean += (sample - mean) / i.max(1) as f64;
    }
    mean
}

#[test]
fn a_running_mean_that_skips_the_first_number_fails() {
    fails("mc_integral: a running mean divided by i.max(1)", || {
        ch6::check_mc_integral(mc_running_mean_skips_the_first)
    });
}

/// t by the reciprocal of Nᵀd, which is finite for every normal Nᵀd the
/// contract allows.
fn plane_by_reciprocal(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let nd = n.dot(d);
    if nd == 0.0 {
        return None;
    }
    let inv = 1.0 / nd;
    Some((c - n.dot(o)) * inv)
}

#[test]
fn a_plane_hit_by_the_reciprocal_of_n_dot_d_passes() {
    passes_every(&SEEDS, "ray_plane: t = (c − N·o) · (1 / N·d)", || {
        ch3::check_ray_plane(plane_by_reciprocal)
    });
}

#[test]
fn a_subnormal_n_dot_d_taken_as_parallel_passes() {
    passes_every(
        &SEEDS,
        "ray_plane: Nᵀd not normal taken as parallel",
        || {
            ch3::check_ray_plane(|o, d, n, c| {
                let denom = n.dot(d);
                denom.is_normal().then(|| (c - n.dot(o)) / denom)
            })
        },
    );
}
