//! Exercise 6.2: Russian roulette that stays unbiased.
//!
//! A path tracer cannot follow every path forever. Russian roulette ends a
//! path at random, and lets the paths that survive carry more, so that on
//! average nothing is lost: ending paths adds noise, not bias.
//!
//! Contract (what the grader checks, on 10,000 evenly spaced u per case):
//! * the path survives with probability `q` (0 < q ≤ 1), decided by the
//!   uniform number `u` in [0, 1); a path that dies returns exactly 0.
//!   Which values of u survive is yours to choose, as long as they make
//!   up the share q of [0, 1) taken as real numbers;
//! * the fraction of paths that die is 1 − q (within 0.2%);
//! * the mean of the results is `value` (within 0.2%): a survivor
//!   carries value / q, however small q is (the grader asks down to
//!   q = 10⁻²⁰⁰);
//! * a small q is not zero: for every q down to 10⁻¹⁵ one of u = 0,
//!   q/2 and 1 − q/2 survives (the usual choices, u below q or u at or
//!   above 1 − q, do; the grader looks for survivors there). Below
//!   10⁻¹⁵, where 1 − q rounds to 1 in f64, none need;
//! * for q from 10⁻⁷ to 10⁻⁴ the survivors lie within 2q of 0 or of 1,
//!   and there they make up the share q (within 0.2 %): the grader
//!   measures it, where 10,000 evenly spaced u see no survivor at all.
//!
//! Hints: `cargo grade --hint ch6/russian_roulette`.
//! Grade it with: `cargo grade ch6`

/// The contribution after the roulette.
pub fn russian_roulette(value: f64, q: f64, u: f64) -> f64 {
    // TODO: survive with probability q, and keep the mean.
    todo!()
}
