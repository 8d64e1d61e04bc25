//! Chapter 6's graders: the references pass, the shipped stubs fail
//! cleanly, and typical wrong answers (a missing factor, a biased
//! roulette, the balance heuristic) fail.

use crate::common;
use glam::{Vec2, Vec3};
use raystep::grading::exercises::ch6;
use raystep::grading::exercises::paths::{check_path_radiance, PathScene};

#[test]
fn chapter_6_references_pass() {
    common::references_pass(6, 6);
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

/// The capstone as a student writes it from its contract: roulette from
/// the first bounce with q the throughput's largest channel (at most 1).
/// `fixed` survives with a fixed 0.8 instead (unbiased, but a survivor's
/// throughput grows where the albedo is above 0.8); `biased` forgets to
/// divide by q;
/// `twice` also adds the emission a bounce finds (counted twice, since the
/// light sample already counted it).
fn contract_path(
    scene: &PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
    fixed: bool,
    biased: bool,
    twice: bool,
) -> Vec3 {
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    let mut l = hit.emitted;
    let mut beta = Vec3::ONE;
    loop {
        let f = hit.albedo / std::f32::consts::PI;
        if let Some(ls) = scene.sample_light(&hit, Vec2::new(rng(), rng())) {
            let cos = hit.n.dot(ls.wi);
            if cos > 0.0 && scene.unoccluded(&hit, ls.wi, ls.dist) {
                l += beta * f * ls.li * cos / ls.pdf;
            }
        }
        let (wi, pdf) = scene.sample_cosine(&hit, Vec2::new(rng(), rng()));
        if pdf <= 0.0 {
            break; // a direction in the tangent plane (rng() may give 0)
        }
        beta *= f * hit.n.dot(wi) / pdf;
        let q = if fixed {
            0.8
        } else {
            beta.max_element().min(1.0)
        };
        if rng() >= q {
            break;
        }
        if !biased {
            beta /= q;
        }
        let Some(next) = scene.next_hit(&hit, wi) else {
            break;
        };
        hit = next;
        if twice {
            l += beta * hit.emitted;
        }
    }
    l
}

#[test]
fn the_path_capstone_passes_as_its_contract_reads_and_catches_mistakes() {
    let check = check_path_radiance(|s, o, d, r| contract_path(s, o, d, r, false, false, false));
    assert!(check.passed(), "{}", check.detail);
    // Roulette that does not divide by q: too dark.
    let check = check_path_radiance(|s, o, d, r| contract_path(s, o, d, r, false, true, false));
    assert!(!check.passed(), "{}", check.detail);
    assert!(
        check.detail.contains("z = ") && check.detail.contains("closed furnace"),
        "{}",
        check.detail
    );
    assert!(check.images.is_some());
    // Emission counted by the light sample and again by the bounce.
    let check = check_path_radiance(|s, o, d, r| contract_path(s, o, d, r, false, false, true));
    assert!(!check.passed(), "{}", check.detail);
    // A fixed survival probability: right on average, but not bounded.
    let check = check_path_radiance(|s, o, d, r| contract_path(s, o, d, r, true, false, false));
    assert!(!check.passed(), "{}", check.detail);
    assert_eq!(
        check.symptom.map(|s| s.name),
        Some("survival not taken from the throughput"),
        "{}",
        check.detail
    );
}
