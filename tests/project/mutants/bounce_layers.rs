//! Exercise 6.6's mutants: plausible wrong filings of a path's light,
//! written from the stub's contract alone, each of which the check must
//! fail under every seed (naming its symptom where one fits); and correct
//! alternatives, written differently, that must pass under every seed.

use glam::Vec3;
use raystep::ch6_global_illumination::layers::{
    LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND, SLOT_EMITTED,
};
use raystep::grading::exercises::bounce_layers::{self as b, check_bounce_layers, Gathered, How};
use raystep::grading::{Check, Symptom};

use super::under_seeds;

const SEEDS: [u64; 5] = [0, 1, 0x5eed, 977, 31337];

/// What a mutant gets wrong.
#[derive(Clone, Copy, PartialEq)]
enum Bug {
    None,
    /// A light sample at vertex j in slot j (k = j − 1).
    LightOneLow,
    /// Emission found at vertex i ≥ 1 in slot i + 1 (k = i).
    FoundOneHigh,
    /// What the camera sees directly in slot 1 (layer 0).
    EmittedInLayerZero,
    /// Bounce counts past the last slot dropped instead of capped.
    BeyondDropped,
    /// Layers only up to k = LAYERS_SHOWN − 1; k = LAYERS_SHOWN beyond.
    CapOneEarly,
    /// value, not value · weight.
    NoWeight,
    /// No test for NaN or infinity.
    NoFiniteTest,
    /// Everything in slot E (the pixel's total in one layer).
    AllInOne,
    /// The finite test on the contribution's length, which overflows for
    /// finite values above about 1e19 (fourth fresh set).
    LengthFilter,
    /// A test for NaN and +inf only, which lets -inf through (fourth
    /// fresh set).
    PositiveInfOnly,
    /// The finite test on the value alone, before the weight (a NaN or
    /// infinite weight let through; sixth fresh set).
    ValueOnly,
}

fn layers(path: &[Gathered], bug: Bug) -> [Vec3; LAYER_SLOTS] {
    let mut out = [Vec3::ZERO; LAYER_SLOTS];
    for g in path {
        let k = match g.how {
            How::Found if g.vertex == 0 && bug != Bug::EmittedInLayerZero => None,
            How::Found if g.vertex == 0 => Some(0),
            How::Found if bug == Bug::FoundOneHigh => Some(g.vertex),
            How::Found => Some(g.vertex - 1),
            How::LightSample if bug == Bug::LightOneLow && g.vertex > 0 => Some(g.vertex - 1),
            How::LightSample if bug == Bug::LightOneLow => None,
            How::LightSample => Some(g.vertex),
        };
        let shown = if bug == Bug::CapOneEarly {
            LAYERS_SHOWN - 1
        } else {
            LAYERS_SHOWN
        };
        let slot = match k {
            _ if bug == Bug::AllInOne => SLOT_EMITTED,
            None => SLOT_EMITTED,
            Some(k) if k <= shown => k as usize + 1,
            Some(k) if bug == Bug::BeyondDropped && k as usize + 1 > SLOT_BEYOND => continue,
            Some(_) => SLOT_BEYOND,
        };
        let c = if bug == Bug::NoWeight {
            g.value
        } else {
            g.value * g.weight
        };
        let kept = match bug {
            Bug::NoFiniteTest => true,
            Bug::LengthFilter => c.length().is_finite(),
            Bug::PositiveInfOnly => !c.is_nan() && c.max_element() < f32::INFINITY,
            Bug::ValueOnly => g.value.is_finite(),
            _ => c.is_finite(),
        };
        if kept {
            out[slot] += c;
        }
    }
    out
}

macro_rules! with_bug {
    ($bug:expr) => {
        |p: &[Gathered]| layers(p, $bug)
    };
}

fn fails_naming(what: &str, check: impl Fn() -> Check, symptom: Option<Symptom>) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        assert!(!c.passed(), "{what} passed under seed {seed}: {}", c.detail);
        if let Some(s) = symptom {
            assert_eq!(
                c.symptom.map(|s| s.name),
                Some(s.name),
                "{what} under seed {seed}: {}",
                c.detail
            );
        }
    }
}

fn passes(what: &str, check: impl Fn() -> Check) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        assert!(c.passed(), "{what} failed under seed {seed}: {}", c.detail);
    }
}

/// A mutant: its name, its check, and the symptom it must be named by.
type Case = (&'static str, fn() -> Check, Option<Symptom>);

#[test]
fn wrong_filings_fail_and_are_named() {
    let cases: [Case; 11] = [
        (
            "light sample one low",
            || check_bounce_layers(with_bug!(Bug::LightOneLow)),
            Some(b::LAYERS_OFF_BY_ONE),
        ),
        (
            "emission one high",
            || check_bounce_layers(with_bug!(Bug::FoundOneHigh)),
            Some(b::LAYERS_OFF_BY_ONE),
        ),
        (
            "emitters in layer 0",
            || check_bounce_layers(with_bug!(Bug::EmittedInLayerZero)),
            Some(b::LAYERS_EMITTED),
        ),
        (
            "beyond dropped",
            || check_bounce_layers(with_bug!(Bug::BeyondDropped)),
            Some(b::LAYERS_CAP),
        ),
        (
            "cap one early",
            || check_bounce_layers(with_bug!(Bug::CapOneEarly)),
            Some(b::LAYERS_CAP),
        ),
        (
            "no weight",
            || check_bounce_layers(with_bug!(Bug::NoWeight)),
            Some(b::LAYERS_WEIGHT),
        ),
        (
            "no finite test",
            || check_bounce_layers(with_bug!(Bug::NoFiniteTest)),
            Some(b::LAYERS_NOT_FINITE),
        ),
        (
            "all in one layer",
            || check_bounce_layers(with_bug!(Bug::AllInOne)),
            None,
        ),
        (
            "finite test on the length",
            || check_bounce_layers(with_bug!(Bug::LengthFilter)),
            None,
        ),
        (
            "no test for -inf",
            || check_bounce_layers(with_bug!(Bug::PositiveInfOnly)),
            Some(b::LAYERS_NOT_FINITE),
        ),
        (
            "the finite test on the value alone",
            || check_bounce_layers(with_bug!(Bug::ValueOnly)),
            None,
        ),
    ];
    for (what, check, symptom) in cases {
        fails_naming(what, check, symptom);
    }
}

/// No cap at all: `layers[k + 1]` runs past the array and panics, which
/// the grader reports as a failure.
#[test]
fn no_cap_panics() {
    let uncapped = |path: &[Gathered]| {
        let mut out = [Vec3::ZERO; LAYER_SLOTS];
        for g in path {
            let slot = match g.how {
                How::Found => g.vertex as usize,
                How::LightSample => g.vertex as usize + 1,
            };
            let c = g.value * g.weight;
            if c.is_finite() {
                out[slot] += c;
            }
        }
        out
    };
    let run = std::panic::catch_unwind(|| check_bounce_layers(uncapped));
    assert!(run.is_err(), "an index past the last slot did not panic");
}

/// Correct: the bounce count from a helper, a match on how.
fn with_helper(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    fn bounce_count(g: &Gathered) -> Option<u32> {
        match (g.how, g.vertex) {
            (How::Found, 0) => None,
            (How::Found, i) => Some(i - 1),
            (How::LightSample, j) => Some(j),
        }
    }
    let mut out = [Vec3::ZERO; LAYER_SLOTS];
    for g in path {
        let slot = bounce_count(g).map_or(SLOT_EMITTED, |k| (k as usize + 1).min(SLOT_BEYOND));
        let c = g.value * g.weight;
        if c.is_finite() {
            out[slot] += c;
        }
    }
    out
}

/// Correct: accumulate by the number of scatterings (0 for what the
/// camera sees), in f64, then shift everything past the last shown layer
/// into the last slot.
fn accumulate_then_shift(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    let mut by_scatterings: Vec<glam::DVec3> = Vec::new();
    for g in path {
        let s = match g.how {
            How::Found => g.vertex as usize,
            How::LightSample => g.vertex as usize + 1,
        };
        // Left out where the product as f32 forms it is not finite (the
        // stub's clause), then summed in f64.
        if !(g.value * g.weight).is_finite() {
            continue;
        }
        let c = g.value.as_dvec3() * g.weight as f64;
        if by_scatterings.len() <= s {
            by_scatterings.resize(s + 1, glam::DVec3::ZERO);
        }
        by_scatterings[s] += c;
    }
    let mut out = [glam::DVec3::ZERO; LAYER_SLOTS];
    for (s, c) in by_scatterings.into_iter().enumerate() {
        out[s.min(SLOT_BEYOND)] += c;
    }
    out.map(|c| c.as_vec3())
}

#[test]
fn right_filings_pass() {
    passes("the stub's convention", || {
        check_bounce_layers(with_bug!(Bug::None))
    });
    passes("a helper for k", || check_bounce_layers(with_helper));
    passes("accumulate, then shift", || {
        check_bounce_layers(accumulate_then_shift)
    });
    passes("raystep's", || check_bounce_layers(b::reference_layers));
}
