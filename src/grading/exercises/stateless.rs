//! The same question gets the same answer, whatever was asked before: a
//! probe for the exercises whose answer is a function of their arguments
//! alone. A cache or memo keyed on some of the arguments (the last eye and
//! target without up, a point without its sphere), a table kept from the
//! first call, or a counter of calls, all answer a question again
//! differently once something else was asked in between.
//!
//! The probe draws questions in the exercise's domain, asks each once,
//! then asks it again right after a decoy: the same question with one
//! argument, or one number of an argument, taken from another question
//! (a whole argument where the contract constrains it as a whole, such as
//! a unit direction). The second answer must be the first, bit for bit.

use std::fmt::Debug;
use std::ops::Range;

use glam::{Vec2, Vec3};

use crate::exercise::Check;

/// A question as its numbers (f64 holds every f32 exactly), and the
/// groups of numbers a decoy takes together from another question.
pub struct Questions {
    /// The drawn questions.
    pub cases: Vec<Vec<f64>>,
    /// The groups: each a range of a question's numbers.
    pub groups: Vec<Range<usize>>,
}

impl Questions {
    /// `count` questions drawn by `draw`, with one group per number but
    /// for the ranges in `whole`, each a group of its own.
    pub fn drawn(count: usize, whole: &[Range<usize>], mut draw: impl FnMut() -> Vec<f64>) -> Self {
        let cases: Vec<Vec<f64>> = (0..count).map(|_| draw()).collect();
        let n = cases.first().map_or(0, Vec::len);
        let mut groups: Vec<Range<usize>> = whole.to_vec();
        groups.extend(
            (0..n)
                .filter(|i| !whole.iter().any(|r| r.contains(i)))
                .map(|i| i..i + 1),
        );
        Questions { cases, groups }
    }
}

/// The numbers of a `Vec3`.
pub fn nums3(v: Vec3) -> [f64; 3] {
    v.as_dvec3().to_array()
}

/// The numbers of a `Vec2`.
pub fn nums2(v: Vec2) -> [f64; 2] {
    v.as_dvec2().to_array()
}

/// The `Vec3` at numbers `at..at + 3`.
pub fn vec3_at(n: &[f64], at: usize) -> Vec3 {
    Vec3::new(n[at] as f32, n[at + 1] as f32, n[at + 2] as f32)
}

/// The `Vec2` at numbers `at..at + 2`.
pub fn vec2_at(n: &[f64], at: usize) -> Vec2 {
    Vec2::new(n[at] as f32, n[at + 1] as f32)
}

/// A question's numbers as the f32 values they are, in order.
pub fn show(numbers: &[f64]) -> String {
    format!(
        "{:?}",
        numbers.iter().map(|x| *x as f32).collect::<Vec<f32>>()
    )
}

/// Asks every question, then each again right after each of its decoys,
/// and each decoy once after an unrelated question and once right after
/// its question: `None` if every answer came back the same, else what
/// changed. (A memo keyed on part of the arguments answers whichever of
/// the two comes second with the other's answer.)
pub fn changed_answer<R: Debug>(q: &Questions, ask: impl Fn(&[f64]) -> R) -> Option<String> {
    let first: Vec<String> = q.cases.iter().map(|c| format!("{:?}", ask(c))).collect();
    let n = q.cases.len();
    let changed = |what: &[f64], before: &str, then: &str, after: &[f64]| {
        format!(
            "the arguments {}: answered {before} the first time, and {then} when asked \
             again right after {}: an answer must depend on its arguments alone, never on \
             what was asked before",
            show(what),
            show(after)
        )
    };
    for (k, decoy) in decoys(q) {
        let (case, unrelated) = (&q.cases[k], &q.cases[(k + 2) % n]);
        ask(unrelated);
        let cold = format!("{:?}", ask(&decoy));
        let again = format!("{:?}", ask(case));
        if again != first[k] {
            return Some(changed(case, &first[k], &again, &decoy));
        }
        let warm = format!("{:?}", ask(&decoy));
        if warm != cold {
            return Some(changed(&decoy, &cold, &warm, case));
        }
    }
    None
}

/// Each question's decoys, with the question's index: the question with
/// one group of its numbers taken from the next question (each group in
/// turn; none equal to its question).
pub fn decoys(q: &Questions) -> Vec<(usize, Vec<f64>)> {
    let n = q.cases.len();
    let mut out = Vec::new();
    for (k, case) in q.cases.iter().enumerate() {
        let other = &q.cases[(k + 1) % n];
        for g in &q.groups {
            let mut decoy = case.clone();
            decoy[g.clone()].copy_from_slice(&other[g.clone()]);
            if decoy != *case {
                out.push((k, decoy));
            }
        }
    }
    out
}

/// `check`, failed with the probe's finding if it passed and an answer
/// changed.
pub fn unless_changed(check: Check, found: impl FnOnce() -> Option<String>) -> Check {
    if !check.passed() {
        return check;
    }
    match found() {
        Some(detail) => Check {
            error: f64::INFINITY,
            detail,
            symptom: None,
            ..check
        },
        None => check,
    }
}

pub mod probes;
