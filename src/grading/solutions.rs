//! Solutions a student may read once an exercise passes (`cargo grade
//! --solution chN/name`), as rustlings shows its own after a pass: one way
//! a student might solve each exercise, with the idea behind it (the
//! exercise's second hint). They are the solved files the project's tests
//! grade (`tests/project/solutions/`: every one must pass), embedded here.

use std::path::Path;

use super::course::{load, State};
use super::exercise::Exercise;
use super::shipped::{exercise_files, Stub};

macro_rules! solution {
    ($folder:literal, $name:literal) => {
        Stub {
            folder: $folder,
            name: $name,
            text: include_str!(concat!(
                "../../tests/project/solutions/",
                $folder,
                "/exercises/",
                $name,
                ".rs"
            )),
        }
    };
}

/// Every exercise's solution, in the order of the shipped stubs.
pub const SOLUTIONS: &[Stub] = exercise_files!(solution);

/// The solution of exercise `id` (`chN/name`).
pub fn find(id: &str) -> Option<&'static Stub> {
    SOLUTIONS.iter().find(|s| s.id() == id)
}

/// The text `--solution` prints for `ex` once it has passed (as the
/// grader last graded it, remembered in `out`); before, why not and what
/// helps instead.
pub fn show(ex: &Exercise, out: &Path) -> Result<String, String> {
    let id = ex.id();
    if load(out).get(&id) != Some(&State::Passed) {
        return Err(format!(
            "{id} has not passed yet (as last graded): its solution opens once it does. \
             For the next hint: cargo grade --hint {id}"
        ));
    }
    let Some(solution) = find(&id) else {
        return Err(format!("{id} has no solution to show"));
    };
    Ok(format!(
        "{id}: one way to solve it (yours may differ and be as right)\n\n{}\nthe idea: {}\n",
        solution.text,
        ex.hints()[1]
    ))
}
