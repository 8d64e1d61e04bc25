//! The thirty-fourth fresh set (2026-12-01), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: two mistakes that cancel on the usual inputs (S, 59
//! wrong), the outputs a student checks least (T, 68), and IEEE special
//! values arising inside valid inputs (U, 56); 84 right alternatives,
//! all of which pass. With the grader of f89259d, 6 of the 183 wrong
//! ones passed under seeds 51 to 53. The three here now fail under seeds
//! 51 to 55. Of the other three, one is right (a Fresnel term with the
//! indices in a fixed order swaps r_s and r_p, whose mean is the same),
//! and two are right under the contracts as they now say what was
//! checked all along: barycentric's φ far outside, to 1e-5 of the largest
//! |φ|, and barycentric_inside on triangles 10⁻³·⁵ to 10³ across (1/|n|²
//! is infinite only below 10⁻¹⁰, where |n|² is subnormal and the course's
//! own quotient has lost its digits).

use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch3, ch5, ch6};

use super::fails_every;
use super::knobs::{self, BvhKnobs, DirectKnobs, Knobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1202];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn a_traversal_that_asks_t_max_of_the_root_alone_fails() {
    fails("bvh_traversal: t_max asked of the root's box alone", || {
        ch3::check_bvh_traversal(|bvh, ray, t_max| {
            let k = BvhKnobs::with(|k| k.t_max_at_root_only = true);
            knobs::closest_hit(k, bvh, ray, t_max)
        })
    });
}

/// The solution of direct_light with its pdf per steradian raised to at
/// least `floor`.
macro_rules! pdf_floored {
    ($floor:expr) => {
        fails(
            concat!("direct_light: the pdf floored at ", stringify!($floor)),
            || {
                ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
                    let k = DirectKnobs::with(|k| k.pdf_floor = Some($floor));
                    knobs::direct(k, (p, n, rho), (y, nl, a, le), v)
                })
            },
        )
    };
}

#[test]
fn a_light_pdf_with_a_floor_fails() {
    pdf_floored!(1e-4);
    pdf_floored!(1e-6);
}

/// Survives where u ≥ 1 − q and carries value over 1 − (1 − q), which
/// rounds away from q in f64 below about 10⁻¹³.
fn roulette_over_rounded_q(value: f64, q: f64, u: f64) -> f64 {
    let p_die = 1.0 - q;
    if u < p_die {
        0.0
    } else {
        value / (1.0 - p_die)
    }
}

#[test]
fn roulette_over_a_rounded_q_fails() {
    fails("russian_roulette: value / (1 − (1 − q))", || {
        ch6::check_russian_roulette(roulette_over_rounded_q)
    });
}
