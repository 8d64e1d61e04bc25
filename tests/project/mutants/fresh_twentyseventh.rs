//! The twenty-seventh fresh set (2026-11-30), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: casts, integers and indices (X, 41 wrong), early exits
//! and short-circuits (Y, 55), and assumptions the contract does not make
//! (Z, 64); 80 right alternatives, all of which pass. With the grader of
//! 27a50f8, 10 of the 160 wrong ones passed under seed 51 or 52. The four
//! that now fail under seeds 51 to 55 are here: a colour judged by its
//! first channel (a light with no red, a surface black in red), a small q
//! treated as zero, and the reflectance at normal incidence used within
//! 8° of the normal. Of the other six, four decide roulette's survival in
//! f32 or by u ≥ 1 − q (right, as the earlier sets rule: the grader
//! cannot ask for survivors where rounding leaves none), one lifts the
//! disk without max(0) (right in f32, as the twenty-fifth set found),
//! one sends every u with u.x = 1/2 of a concentric map to the pole (a
//! set of measure zero, with its own right pdf), and one projects a NaN z,
//! which the contract's three cases (z < 0, z = 0, z > 0) leave out.

use glam::Vec3;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch5::{reference_direct, reference_point};
use raystep::grading::exercises::refraction::{check_refraction, reference_refract};
use raystep::grading::exercises::{ch5, ch6};

use super::fails_every;

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn a_light_without_red_fails() {
    fails(
        "point_light: nothing arrives where the intensity's red is 0",
        || {
            ch5::check_point_light(|i, light, p, n| match i.x == 0.0 {
                true => Vec3::ZERO,
                false => reference_point(i, light, p, n),
            })
        },
    );
}

#[test]
fn a_surface_black_in_red_fails() {
    fails(
        "direct_light: nothing reflected where ρ's or Le's red is 0",
        || {
            ch5::check_direct_light(|p, n, rho, y, n_light, area, le, visible| {
                match rho.x == 0.0 || le.x == 0.0 {
                    true => Vec3::ZERO,
                    false => reference_direct(p, n, rho, y, n_light, area, le, visible),
                }
            })
        },
    );
}

#[test]
fn a_small_q_taken_for_zero_fails() {
    fails(
        "russian_roulette: every path with q below 10⁻¹² dies",
        || {
            ch6::check_russian_roulette(|value, q, u| match q < 1e-12 || u >= q {
                true => 0.0,
                false => value / q,
            })
        },
    );
}

#[test]
fn the_normal_reflectance_near_the_normal_fails() {
    fails(
        "refraction: F at normal incidence for cos θ above 0.99",
        || {
            check_refraction(|d, n, outside, inside| {
                let (t, f) = reference_refract(d, n, outside, inside)?;
                let (eta_i, eta_t) = match d.dot(n) < 0.0 {
                    true => (outside, inside),
                    false => (inside, outside),
                };
                let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
                Some((t, if d.dot(n).abs() > 0.99 { r0 } else { f }))
            })
        },
    );
}
