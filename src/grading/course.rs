//! How far along the course a student is, and what to try next. Every
//! grading of the student's own solutions remembers each graded exercise's
//! state in `<out>/progress.txt` (one `chN/name state` per line), so that
//! `cargo grade ch3` still shows the whole course: per chapter the
//! exercises passed, overall, and the first exercise in lecture order
//! that has not passed, with the command that helps next.

use std::collections::BTreeMap;
use std::path::Path;

use crate::exercise::{Exercise, Outcome};

/// The file that remembers the states, inside the grader's output dir.
pub const FILE: &str = "progress.txt";

/// Where an exercise stood when it was last graded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    /// Within tolerance.
    Passed,
    /// Graded and not passed: wrong, panicked, too slow or not compiling.
    Failed,
    /// Its `todo!()` was still there.
    NotStarted,
}

impl State {
    /// The state an outcome leaves.
    pub fn of(outcome: &Outcome) -> State {
        match outcome {
            Outcome::Passed(_) => State::Passed,
            Outcome::NotImplemented => State::NotStarted,
            _ => State::Failed,
        }
    }

    fn word(self) -> &'static str {
        match self {
            State::Passed => "passed",
            State::Failed => "failed",
            State::NotStarted => "not-started",
        }
    }

    fn from_word(w: &str) -> Option<State> {
        [State::Passed, State::Failed, State::NotStarted]
            .into_iter()
            .find(|s| s.word() == w)
    }
}

/// The states remembered in `out`, by exercise id (an unreadable or
/// missing file: none; a line it cannot read is skipped).
pub fn load(out: &Path) -> BTreeMap<String, State> {
    let text = std::fs::read_to_string(out.join(FILE)).unwrap_or_default();
    text.lines()
        .filter_map(|l| {
            let (id, w) = l.split_once(' ')?;
            Some((id.to_string(), State::from_word(w.trim())?))
        })
        .collect()
}

/// Remembers the states `results` leave, beside those of the exercises
/// not graded this time; returns them all.
pub fn update(out: &Path, results: &[(Exercise, Outcome, String)]) -> BTreeMap<String, State> {
    let mut states = load(out);
    for (ex, outcome, _) in results {
        states.insert(ex.id(), State::of(outcome));
    }
    let text: String = states
        .iter()
        .map(|(id, s)| format!("{id} {}\n", s.word()))
        .collect();
    // Progress is a convenience: a folder that cannot take it does not
    // fail the grading.
    let _ = crate::safe_out::write(&out.join(FILE), text.as_bytes());
    states
}

/// The course as `states` know it: per chapter the exercises passed (`-`
/// for a chapter never graded), the total, and what to try next.
pub fn summary(catalog: &[Exercise], states: &BTreeMap<String, State>) -> String {
    let mut chapters: Vec<u32> = catalog.iter().map(|e| e.chapter).collect();
    chapters.dedup();
    let passed = |e: &Exercise| states.get(&e.id()) == Some(&State::Passed);
    let mut parts = Vec::new();
    let mut ungraded = false;
    for c in &chapters {
        let of: Vec<&Exercise> = catalog.iter().filter(|e| e.chapter == *c).collect();
        let done = of.iter().filter(|e| passed(e)).count();
        if of.iter().any(|e| states.contains_key(&e.id())) {
            parts.push(format!("ch{c} {done}/{}", of.len()));
        } else {
            ungraded = true;
            parts.push(format!("ch{c} -/{}", of.len()));
        }
    }
    let total = catalog.iter().filter(|e| passed(e)).count();
    let mut s = format!(
        "course: {}; {total} of {} passed\n",
        parts.join(", "),
        catalog.len()
    );
    if ungraded {
        s += "        (-: a chapter not graded yet)\n";
    }
    s += &match catalog.iter().find(|e| !passed(e)) {
        None => "all passed: the whole course runs on your code\n".to_string(),
        Some(e) => {
            let id = e.id();
            match states.get(&id) {
                Some(State::Failed) => format!(
                    "next: {id} failed: `cargo grade --hint {id}`, then `cargo grade ch{}`\n",
                    e.chapter
                ),
                Some(State::NotStarted) => format!("next: start {id} in {}\n", e.file),
                _ => format!(
                    "next: {id} has not been graded: `cargo grade ch{}`\n",
                    e.chapter
                ),
            }
        }
    };
    s
}
