//! What an exercise is and what grading it finds: the types the exercise
//! files of every chapter use, apart from the grader that runs them.

use crate::core::film::Film;

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
    /// What went wrong, when the check recognised it: picks the hint shown
    /// with the failure (one of the exercise's [`Exercise::symptoms`]).
    pub symptom: Option<Symptom>,
}

/// A failure a check recognises: a mirrored image, which points at the
/// projection's sign; a picture dark by a constant factor, at a missing
/// 1/pdf. The hint it calls for is data, in `chapters/hints.toml`
/// ([`Exercise::symptom_hint`], [`super::manifest`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Symptom {
    /// What the check saw, in a few words ("mirrored", "no pruning"): its
    /// key in the hints file.
    pub name: &'static str,
}

impl Check {
    /// The same check, naming what went wrong.
    pub fn with_symptom(mut self, symptom: Symptom) -> Check {
        self.symptom = Some(symptom);
        self
    }

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
    /// The check ran past the time limit (seconds) and was stopped; what it
    /// was doing last.
    TimedOut {
        /// The limit, in seconds.
        seconds: f64,
        /// The last progress line the check printed (which case).
        doing: String,
    },
    /// The exercise file does not compile; the compiler's messages about it.
    DoesNotCompile(String),
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
    /// The failures its check recognises, each with its own hint (shown
    /// instead of the first tier when the check names it). Its hints, in
    /// tiers and per symptom, are in `chapters/hints.toml`
    /// ([`Exercise::hints`], [`Exercise::symptom_hint`]).
    pub symptoms: &'static [Symptom],
    /// Runs the check on raystep's reference code (the student's code is
    /// checked by the same function, from the exercises crate).
    pub reference: fn() -> Check,
}

impl Exercise {
    /// `chN/name`.
    pub fn id(&self) -> String {
        format!("ch{}/{}", self.chapter, self.name)
    }

    /// How many times the time limit its check may take: 3 for the path
    /// capstone, whose check traces over a million paths (the course's
    /// solution takes about 3.5 s of the 5 s default, and a right solution
    /// that plays roulette only after 16 bounces over 5 s); 1 for the
    /// others.
    pub fn time_factor(&self) -> u32 {
        match (self.chapter, self.name) {
            (6, "path_radiance") => 3,
            _ => 1,
        }
    }
}
