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
pub mod fresh_eighteenth;
pub mod fresh_eighth;
pub mod fresh_eleventh;
pub mod fresh_fifteenth;
pub mod fresh_fifth;
pub mod fresh_fortieth;
pub mod fresh_fourteenth;
pub mod fresh_fourth;
pub mod fresh_new;
pub mod fresh_nineteenth;
pub mod fresh_ninth;
pub mod fresh_seventeenth;
pub mod fresh_seventh;
pub mod fresh_sixteenth;
pub mod fresh_sixth;
pub mod fresh_tenth;
pub mod fresh_third;
pub mod fresh_thirteenth;
pub mod fresh_thirtieth;
pub mod fresh_thirtyeighth;
pub mod fresh_thirtyfifth;
pub mod fresh_thirtyfirst;
pub mod fresh_thirtyfourth;
pub mod fresh_thirtyninth;
pub mod fresh_thirtysecond;
pub mod fresh_thirtyseventh;
pub mod fresh_thirtysixth;
pub mod fresh_thirtythird;
pub mod fresh_twelfth;
pub mod fresh_twentieth;
pub mod fresh_twentyeighth;
pub mod fresh_twentyfifth;
pub mod fresh_twentyfirst;
pub mod fresh_twentyfourth;
pub mod fresh_twentyninth;
pub mod fresh_twentysecond;
pub mod fresh_twentyseventh;
pub mod fresh_twentysixth;
pub mod fresh_twentythird;
pub mod knobs;
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

/// The seeds the newer exercises' mutants and alternatives are tried
/// under.
pub const SEEDS: [u64; 5] = [0, 1, 0x5eed, 977, 31337];

/// Checks `check` fails under every one of [`SEEDS`], naming `symptom`
/// (when given); what went otherwise is added to `wrong`.
pub fn fails_under(
    wrong: &mut Vec<String>,
    what: &str,
    symptom: Option<Symptom>,
    check: impl Fn() -> Check,
) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        if c.passed() {
            wrong.push(format!("{what} passed under seed {seed}: {}", c.detail));
        } else if symptom.is_some_and(|s| c.symptom != Some(s)) {
            wrong.push(format!(
                "{what}, seed {seed}, named {:?}: {}",
                c.symptom, c.detail
            ));
        }
    }
}

/// Checks `check` passes under every one of [`SEEDS`]; what did not is
/// added to `wrong`.
pub fn passes_under(wrong: &mut Vec<String>, what: &str, check: impl Fn() -> Check) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        if !c.passed() {
            wrong.push(format!("{what} failed under seed {seed}: {}", c.detail));
        }
    }
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

/// `check` fails under every one of `seeds`, naming the symptom called
/// `symptom` when one is given (the fresh sets' assertion).
pub fn fails_every(seeds: &[u64], what: &str, symptom: Option<&str>, check: impl Fn() -> Check) {
    for (seed, c) in under_seeds(seeds, check) {
        assert!(!c.passed(), "{what} passed under seed {seed}: {}", c.detail);
        if let Some(name) = symptom {
            assert_eq!(
                c.symptom.map(|s| s.name),
                Some(name),
                "{what}, seed {seed}: {}",
                c.detail
            );
        }
    }
}

/// `check` passes under every one of `seeds`.
pub fn passes_every(seeds: &[u64], what: &str, check: impl Fn() -> Check) {
    for (seed, c) in under_seeds(seeds, check) {
        assert!(c.passed(), "{what} failed under seed {seed}: {}", c.detail);
    }
}
