//! Plausible wrong solutions of the capstones (and common mistakes of the
//! other exercises) that the grader must fail, naming the symptom, and
//! correct alternatives it must pass.

use raystep::grading::{Check, Exercise, Symptom};

pub mod bounce_layers;
pub mod ch1;
pub mod ch2;
pub mod ch2_manifold;
pub mod ch3;
pub mod ch3_sah;
pub mod ch4;
pub mod ch5;
pub mod ch6;
pub mod fresh;
pub mod fresh_new;
pub mod refraction;

/// Runs `check` once under each of `seeds` (the seed of the inputs the
/// checks draw, as a grading run sets it), on this thread; each seed with
/// what the check found.
pub fn under_seeds(seeds: &[u64], check: impl Fn() -> Check) -> Vec<(u64, Check)> {
    let found = seeds
        .iter()
        .map(|&seed| {
            raystep::grading::set_run_seed(seed);
            (seed, check())
        })
        .collect();
    raystep::grading::set_run_seed(0);
    found
}

/// `check` failed, naming `symptom`, which its chapter's `exercises` list;
/// returns the check's detail. `what` names the mistake in a failure.
pub fn fails_naming(check: Check, symptom: Symptom, exercises: &[Exercise], what: &str) -> String {
    assert!(!check.passed(), "{what} passed: {}", check.detail);
    assert_eq!(check.symptom, Some(symptom), "{what}: {}", check.detail);
    assert!(
        exercises.iter().any(|e| e.symptoms.contains(&symptom)),
        "{what}: {} is not listed",
        symptom.name
    );
    check.detail
}
