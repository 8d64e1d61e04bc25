//! The student's capstone, rendered live: what the terminal UI's student
//! mode runs in a thread of its own, here without any terminal so that
//! it can be tested. [`live_student`] builds the student's process as the
//! grader does ([`build_exercises_in`]), then grades the capstone with it
//! under a time limit (as `chN --student` does: the student's code runs
//! there, the picture is made here from its answers), and reads back the
//! student's image and the reference. Every
//! way this can go wrong (no cargo, a compile error, the stub's `todo!()`,
//! a panic, a loop that never ends) is a [`LiveError`] with a one-line
//! status, never a panic. [`exercise_stamp`] tells the UI when the
//! chapter's exercise files changed.

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::time::{Duration, SystemTime};

use crate::build::{build_exercises_in, Place};
use crate::core::film::Film;
use crate::core::warp_test::Drawn;
use crate::exercise::Outcome;
use crate::process::{capstone_images, in_student_process};
pub use crate::runner::capstone;
use crate::runner::{replay_warp, Request};

/// The student's capstone image beside the reference.
#[derive(Clone, Debug)]
pub struct StudentRender {
    /// The capstone, `chN/name`.
    pub id: String,
    /// The student's image.
    pub student: Film,
    /// The reference image.
    pub reference: Film,
    /// Whether the grader's check passes (exact up to a few silhouette
    /// pixels, or within the noise for a Monte Carlo chapter).
    pub matches: bool,
    /// The check's own words: all pixels match, or the worst pixel.
    pub detail: String,
}

impl StudentRender {
    /// Pixels whose 8-bit sRGB colours differ.
    pub fn differing_pixels(&self) -> usize {
        if (self.student.width, self.student.height)
            != (self.reference.width, self.reference.height)
        {
            return self.reference.pixels.len();
        }
        let (a, b) = (self.student.to_srgb8(), self.reference.to_srgb8());
        a.chunks(3).zip(b.chunks(3)).filter(|(a, b)| a != b).count()
    }

    /// The status line: "student matches reference" or "differs: N pixels
    /// / RMSE x".
    pub fn status(&self) -> String {
        if self.matches {
            return "student matches reference".into();
        }
        let rmse = if (self.student.width, self.student.height)
            == (self.reference.width, self.reference.height)
        {
            self.student.rmse(&self.reference)
        } else {
            f64::INFINITY
        };
        format!(
            "differs: {} pixels / RMSE {rmse:.4}",
            self.differing_pixels()
        )
    }
}

/// Why there is no student image.
#[derive(Clone, Debug, PartialEq)]
pub enum LiveError {
    /// The chapter has no capstone.
    NoCapstone(u32),
    /// The exercises crate could not be built for a reason other than an
    /// exercise file (no cargo, a broken repository, cancelled).
    Build(String),
    /// The capstone's file does not compile.
    DoesNotCompile {
        /// `chN/name`.
        id: String,
        /// The compiler's messages about it.
        message: String,
    },
    /// The capstone is still the shipped stub (`todo!()`).
    NotStarted {
        /// `chN/name`.
        id: String,
        /// The file to edit.
        file: String,
    },
    /// The student's code panicked or crashed.
    Panicked {
        /// `chN/name`.
        id: String,
        /// The panic message.
        message: String,
    },
    /// The render ran past the time limit and was stopped.
    TimedOut {
        /// `chN/name`.
        id: String,
        /// The limit, in seconds.
        seconds: f64,
        /// What it was doing last.
        doing: String,
    },
}

impl LiveError {
    /// One line for the status bar.
    pub fn status(&self) -> String {
        match self {
            LiveError::NoCapstone(n) => format!("chapter {n} has no capstone"),
            LiveError::Build(m) => format!(
                "cannot build the exercises: {}",
                m.lines().next().unwrap_or("")
            ),
            LiveError::DoesNotCompile { message, .. } => {
                format!("compile error: {}", first_compiler_line(message))
            }
            LiveError::NotStarted { id, .. } => format!("{id}: not started (todo!)"),
            LiveError::Panicked { id, message } => {
                format!("{id} panicked: {}", message.lines().next().unwrap_or(""))
            }
            LiveError::TimedOut { id, seconds, doing } => {
                let doing = if doing.is_empty() {
                    String::new()
                } else {
                    format!(" while {doing}")
                };
                format!("{id} timed out after {seconds:.0} s{doing}")
            }
        }
    }
}

/// "file:line:col: message" from cargo's messages about one exercise: the
/// first error's text and where it points (from the chapter folder on);
/// a changed signature says so.
pub fn first_compiler_line(message: &str) -> String {
    if message.starts_with("the signature") {
        return "the signature changed: keep the shipped one".into();
    }
    let text = message
        .lines()
        .find_map(|l| l.strip_prefix("error"))
        .map(|rest| rest.split_once(": ").map_or(rest, |(_, m)| m).trim())
        .unwrap_or("");
    let at = message
        .lines()
        .find_map(|l| l.trim_start().strip_prefix("--> "))
        .map(|path| {
            let path = path.replace('\\', "/");
            let parts: Vec<&str> = path.split('/').collect();
            // From the chapter folder: `ch1-projection/exercises/x.rs:3:5`.
            match parts.iter().rposition(|p| *p == "exercises") {
                Some(i) if i > 0 => parts[i - 1..].join("/"),
                _ => parts.last().copied().unwrap_or("").to_string(),
            }
        });
    match at {
        Some(at) => format!("{at}: {text}"),
        None => text.to_string(),
    }
}

/// Where and how [`live_student`] works.
#[derive(Clone, Debug)]
pub struct LiveOptions {
    /// The folder holding the chapters' exercise folders (`chapters/`).
    pub exercises: PathBuf,
    /// Where the exercises crate is built.
    pub place: Place,
    /// Where the three images are written (`out/student`).
    pub out: PathBuf,
    /// The render's time limit.
    pub timeout: Duration,
}

impl LiveOptions {
    /// The repository's `chapters/`, built beside the running program, the
    /// images in `<out>/student`, and 20 s for the render.
    pub fn for_out_dir(out: &Path) -> Result<LiveOptions, String> {
        Ok(LiveOptions {
            exercises: crate::build::exercises_dir(),
            place: Place::current()?,
            out: out.join("student"),
            timeout: Duration::from_secs(20),
        })
    }
}

/// Builds the exercises and renders chapter `chapter`'s capstone with the
/// student's code, as `chN --student` does; the two images, or why not.
/// Setting `cancel` stops the build or the render soon after.
pub fn live_student(
    chapter: u32,
    opts: &LiveOptions,
    cancel: Option<&AtomicBool>,
) -> Result<StudentRender, LiveError> {
    live_student_with(chapter, opts, cancel, &|| {})
}

/// [`live_student`], calling `rendering` once the build is done and the
/// student's code starts rendering.
pub fn live_student_with(
    chapter: u32,
    opts: &LiveOptions,
    cancel: Option<&AtomicBool>,
    rendering: &dyn Fn(),
) -> Result<StudentRender, LiveError> {
    let ex = capstone(chapter).ok_or(LiveError::NoCapstone(chapter))?;
    let id = ex.id();
    let built =
        build_exercises_in(&opts.exercises, &opts.place, cancel).map_err(LiveError::Build)?;
    if let Some(message) = built.broken.get(&id) {
        let message = message.clone();
        return Err(LiveError::DoesNotCompile { id, message });
    }
    rendering();
    let (outcome, files) = capstone_images(&built.runner, &ex, &opts.out, opts.timeout, cancel);
    let check = match outcome {
        Outcome::Passed(c) | Outcome::Failed(c) => c,
        Outcome::NotImplemented => {
            let file = ex.file.to_string();
            return Err(LiveError::NotStarted { id, file });
        }
        Outcome::TimedOut { seconds, doing } => {
            return Err(LiveError::TimedOut { id, seconds, doing })
        }
        Outcome::Panicked(m) if m == "cancelled" => return Err(LiveError::Build(m)),
        Outcome::Panicked(message) | Outcome::DoesNotCompile(message) => {
            return Err(LiveError::Panicked { id, message })
        }
    };
    let read = |i: usize| {
        let path = files.get(i).ok_or("the render wrote no images")?;
        Film::read_png(path).map_err(|e| e.to_string())
    };
    match (read(0), read(1)) {
        (Ok(student), Ok(reference)) => Ok(StudentRender {
            matches: check.passed(),
            detail: check.detail,
            id,
            student,
            reference,
        }),
        (Err(e), _) | (_, Err(e)) => Err(LiveError::Panicked {
            id,
            message: format!("cannot read the images: {e}"),
        }),
    }
}

/// Builds the exercises and has the student's sampling routine `id`
/// (exercise 5.2, `ch5/cosine_hemisphere`) draw `draws` directions in its
/// sandboxed process under the time limit; the counts, or why not.
pub fn live_warp(
    id: &str,
    draws: usize,
    seed: u64,
    opts: &LiveOptions,
    cancel: Option<&AtomicBool>,
) -> Result<Drawn, LiveError> {
    let ex = crate::all()
        .into_iter()
        .find(|e| e.id() == id && id == "ch5/cosine_hemisphere")
        .ok_or_else(|| LiveError::Build(format!("no sampling routine {id}")))?;
    let built =
        build_exercises_in(&opts.exercises, &opts.place, cancel).map_err(LiveError::Build)?;
    if let Some(message) = built.broken.get(id) {
        let (id, message) = (id.to_string(), message.clone());
        return Err(LiveError::DoesNotCompile { id, message });
    }
    let request = Request::Warp { draws, seed };
    let panicked = |message: String| LiveError::Panicked {
        id: id.to_string(),
        message,
    };
    let transcript = match in_student_process(&built.runner, &request, opts.timeout, cancel)
        .map_err(|outcome| *outcome)
    {
        Ok(t) => t,
        Err(Outcome::TimedOut { seconds, .. }) => {
            return Err(LiveError::TimedOut {
                id: id.to_string(),
                seconds,
                doing: "drawing directions".into(),
            })
        }
        Err(Outcome::Panicked(m)) if m == "cancelled" => return Err(LiveError::Build(m)),
        Err(Outcome::Panicked(m)) => return Err(panicked(m)),
        Err(other) => return Err(panicked(format!("{other:?}"))),
    };
    match replay_warp(transcript, draws, seed) {
        Ok(drawn) => Ok(drawn),
        Err(m) if m == "not_implemented" => Err(LiveError::NotStarted {
            id: id.to_string(),
            file: ex.file.to_string(),
        }),
        Err(m) => Err(panicked(m.trim_start_matches("panicked: ").to_string())),
    }
}

/// The chapter's exercise files (`chN-*/exercises/*.rs` under
/// `exercises`) with their modification times and sizes, sorted: when
/// this changes, the student has saved a file.
pub fn exercise_stamp(exercises: &Path, chapter: u32) -> Vec<(PathBuf, Option<SystemTime>, u64)> {
    let prefix = format!("ch{chapter}-");
    let mut files = Vec::new();
    let Ok(entries) = std::fs::read_dir(exercises) else {
        return files;
    };
    for entry in entries.flatten() {
        if !entry.file_name().to_string_lossy().starts_with(&prefix) {
            continue;
        }
        let Ok(inner) = std::fs::read_dir(entry.path().join("exercises")) else {
            continue;
        };
        for f in inner.flatten() {
            let path = f.path();
            if path.extension().is_some_and(|e| e == "rs") {
                let meta = f.metadata().ok();
                let modified = meta.as_ref().and_then(|m| m.modified().ok());
                files.push((path, modified, meta.map_or(0, |m| m.len())));
            }
        }
    }
    files.sort();
    files
}
