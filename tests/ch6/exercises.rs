//! Chapter 6's graders: the references pass, the shipped stubs fail
//! cleanly, and typical wrong answers (a missing factor, a biased
//! roulette, the balance heuristic) fail.

use crate::common;
use raystep::grading::exercises::ch6;

#[test]
fn chapter_6_references_pass() {
    common::references_pass(6, 3);
}

#[test]
fn an_integral_without_the_interval_length_fails() {
    let check = ch6::check_mc_integral(|f, a, b, u| {
        u.iter().map(|u| f(a + u * (b - a))).sum::<f64>() / u.len() as f64
    });
    assert!(!check.passed(), "{check:?}");
    // Evaluating at the left end only is biased.
    let check =
        ch6::check_mc_integral(|f, a, b, u| (b - a) * f(a) * u.len() as f64 / u.len() as f64);
    assert!(!check.passed(), "{check:?}");
}

#[test]
fn a_roulette_that_forgets_to_divide_or_never_kills_fails() {
    let check = ch6::check_russian_roulette(|v, q, u| if u < q { v } else { 0.0 });
    assert!(!check.passed(), "{check:?}");
    let check = ch6::check_russian_roulette(|v, _, _| v);
    assert!(!check.passed(), "{check:?}");
    assert!(check.detail.contains("ended"), "{}", check.detail);
}

#[test]
fn the_balance_heuristic_or_an_overflowing_power_heuristic_fails() {
    let check = ch6::check_mis_weight(|f, g| if f + g > 0.0 { f / (f + g) } else { 0.0 });
    assert!(!check.passed(), "{check:?}");
    let check = ch6::check_mis_weight(|f, g| f * f / (f * f + g * g));
    assert!(!check.passed(), "{check:?}");
    // Weights that do not sum to one bias the MIS estimate.
    let check = ch6::check_mis_weight(|f, g| {
        if f == 0.0 {
            0.0
        } else {
            0.9 / (1.0 + (g / f).powi(2))
        }
    });
    assert!(!check.passed(), "{check:?}");
}
