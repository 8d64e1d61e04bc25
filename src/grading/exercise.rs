//! What an exercise is and what grading it finds: the types the exercise
//! files of every chapter use, apart from the grader that runs them.

use crate::core::film::Film;

/// Whose code a check runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Solution {
    /// The exercise file as the student left it.
    Student,
    /// raystep's reference implementation.
    Reference,
}

/// What a check measured.
#[derive(Clone, Debug)]
pub struct Check {
    /// The measured error (largest over all cases, or an image RMSE).
    pub error: f64,
    /// The largest error that passes.
    pub tolerance: f64,
    /// What was compared, and the worst case when it failed.
    pub detail: String,
    /// For image checks: (candidate, reference).
    pub images: Option<(Film, Film)>,
}

impl Check {
    /// Passes when the error is within tolerance (a NaN error never passes).
    pub fn passed(&self) -> bool {
        self.error <= self.tolerance
    }
}

/// The result of grading one exercise.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// Within tolerance.
    Passed(Check),
    /// Outside tolerance.
    Failed(Check),
    /// The stub's `todo!()` is still there.
    NotImplemented,
    /// The code panicked; the panic message.
    Panicked(String),
}

impl Outcome {
    /// Whether this is a pass.
    pub fn is_pass(&self) -> bool {
        matches!(self, Outcome::Passed(_))
    }
}

/// One exercise.
#[derive(Clone, Copy, Debug)]
pub struct Exercise {
    /// The chapter it belongs to.
    pub chapter: u32,
    /// Its name (the file stem).
    pub name: &'static str,
    /// The file a student edits, relative to the repository root.
    pub file: &'static str,
    /// Printed when it does not pass.
    pub hint: &'static str,
    /// Runs the check on the student's or the reference code.
    pub grade: fn(Solution) -> Check,
}

impl Exercise {
    /// `chN/name`.
    pub fn id(&self) -> String {
        format!("ch{}/{}", self.chapter, self.name)
    }
}
