//! Grading students' solutions.
//!
//! Each chapter ships exercise files (`chapters/chN-…/exercises/*.rs`) whose
//! bodies are `todo!()` with `// TODO` notes. The grader copies them into
//! `target/raystep-grade/<hash>/` and builds them into crates of its own
//! (`src/grading/crates/`: `student` holds the files and sees raystep only
//! through `blocks`, the building blocks the stubs name; `child` is the
//! process that runs them). A file that breaks the rules
//! ([`source_rules`]) or does not compile is replaced by its stub and
//! reported, while the others are graded. A chapter's list
//! ([`exercises`]) gives, for each file, a check that measures a candidate
//! against raystep's own reference with a tolerance and the symptoms it
//! recognises; the hints (three tiers per exercise, one per symptom) are
//! data a teacher edits, `chapters/hints.toml` ([`manifest`]), and so are
//! the predict questions, `chapters/questions.toml`, which the student
//! answers in `chapters/predictions.toml` ([`predict`]).
//!
//! `cargo grade` ([`driver`]) runs each check in the student's process,
//! which records every call of the student's code ([`bridge`]); the verdict
//! is made in the grader's own process, which replays that record
//! ([`process`], [`runner`]). A `todo!()`, a panic, a crash or a loop that
//! never ends are reported: the grader never crashes and never hangs. When
//! a check compares images and fails, the student's image, the reference
//! and their difference are written to `out/grade/`.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

// The lessons under their own names, so that paths read as in them
// (`crate::ch3_ray_triangle::…`).
use raystep_lessons::{
    ch1_projection, ch2_rasterization, ch3_ray_triangle, ch4_implicit_surfaces, ch5_reflection,
    ch6_global_illumination, core, scene,
};

pub mod bridge;
pub mod build;
pub mod cases;
pub mod child;
pub mod counted;
pub mod course;
pub mod driver;
pub mod exercise;
pub mod exercises;
pub mod hints;
pub mod kept;
pub mod live;
pub mod manifest;
pub mod predict;
pub mod process;
pub mod runner;
pub mod safe_out;
pub mod sandbox;
pub mod seccomp;
pub mod shipped;
pub mod solutions;
pub mod source_rules;
pub mod stream;
pub mod students;
pub mod wire;
pub mod work;

pub use driver::grade_main;
pub use exercise::{Check, Exercise, Outcome, Symptom};

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use glam::Vec3;

use crate::core::difference::signed_colour;
use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::strip::write_captioned_strip;

/// Every exercise of every chapter, in order.
pub fn all() -> Vec<Exercise> {
    crate::exercises::all()
}

/// Only one grading at a time swaps the panic hook.
static HOOK: Mutex<()> = Mutex::new(());

/// Grades raystep's reference solution of one exercise, in this process
/// (the student's code runs in a process of its own: see [`driver`]).
pub fn run(ex: &Exercise) -> Outcome {
    run_check(ex.reference)
}

/// Where the first panic of a check happened (`file:line:column`).
static PANIC_AT: Mutex<Option<String>> = Mutex::new(None);

thread_local! {
    /// The seed of the inputs a check draws, new for every grading run
    /// (see [`run_seed`]).
    static RUN_SEED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// Sets the seed of the inputs this thread's checks draw: the grader
/// draws one per run, and the student's process and the grader's replay
/// use the same one.
pub fn set_run_seed(seed: u64) {
    RUN_SEED.with(|s| s.set(seed));
}

/// The seed of the inputs this thread's checks draw (0 unless set: raystep's
/// own tests are reproducible).
pub fn run_seed() -> u64 {
    RUN_SEED.with(|s| s.get())
}

/// Records `at` as where the first panic of the running check happened,
/// unless one is recorded already (a replayed panic of the student's code
/// happened in the student's file, not where the replay raises it).
pub(crate) fn note_panic_at(at: String) {
    let alone = ALONE.with(|a| match a.borrow_mut().as_mut() {
        Some(first) => {
            first.get_or_insert(at.clone());
            true
        }
        None => false,
    });
    if !alone {
        PANIC_AT
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .get_or_insert(at);
    }
}

thread_local! {
    /// Inside [`run_check_alone`] on this thread: where its first panic
    /// happened, once one did.
    static ALONE: std::cell::RefCell<Option<Option<String>>> =
        const { std::cell::RefCell::new(None) };
}

/// Installs, once, the panic hook of [`run_check_alone`]: silent on a
/// thread running a check alone (it notes where the first panic
/// happened), the hook that was there before everywhere else.
fn install_alone_hook() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            let noted = ALONE.with(|a| match a.borrow_mut().as_mut() {
                Some(first) => {
                    if let Some(at) = info.location() {
                        first.get_or_insert_with(|| {
                            format!("{}:{}:{}", short_path(at.file()), at.line(), at.column())
                        });
                    }
                    true
                }
                None => false,
            });
            if !noted {
                previous(info);
            }
        }));
    });
}

/// [`run_check`] for a check that runs wholly on this thread (a replay:
/// see [`bridge::sequential`]): several can run at once on other threads,
/// since nothing of it is shared between threads.
pub fn run_check_alone(check: fn() -> Check) -> Outcome {
    install_alone_hook();
    ALONE.with(|a| *a.borrow_mut() = Some(None));
    let result = catch_unwind(AssertUnwindSafe(check));
    let at = ALONE.with(|a| a.borrow_mut().take()).flatten();
    outcome_of(result, at)
}

/// A panic's message (`"panicked"` when it carries no text).
pub fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "panicked".into())
}

/// Runs a check, catching `todo!()` and any other panic; a panic's
/// message names the file and line it happened at (the student's file,
/// from its chapter folder, when it was there).
pub fn run_check(check: fn() -> Check) -> Outcome {
    let _guard = HOOK.lock().unwrap_or_else(|e| e.into_inner());
    *PANIC_AT.lock().unwrap_or_else(|e| e.into_inner()) = None;
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(|info| {
        if let Some(at) = info.location() {
            let mut first = PANIC_AT.lock().unwrap_or_else(|e| e.into_inner());
            first.get_or_insert_with(|| {
                format!("{}:{}:{}", short_path(at.file()), at.line(), at.column())
            });
        }
    }));
    let result = catch_unwind(AssertUnwindSafe(check));
    std::panic::set_hook(previous);
    let at = PANIC_AT.lock().unwrap_or_else(|e| e.into_inner()).take();
    outcome_of(result, at)
}

/// The outcome of a check that returned or panicked (`at`: where).
fn outcome_of(result: std::thread::Result<Check>, at: Option<String>) -> Outcome {
    match result {
        Ok(check) if check.passed() => Outcome::Passed(check),
        Ok(check) => Outcome::Failed(check),
        Err(payload) => {
            let message = panic_text(&*payload);
            if message.starts_with("not yet implemented") {
                return Outcome::NotImplemented;
            }
            match at {
                Some(at) => Outcome::Panicked(format!("{message} (at {at})")),
                None => Outcome::Panicked(message),
            }
        }
    }
}

/// A source path from its chapter folder (`ch3-ray-triangle/exercises/…`)
/// or from `src/`, whichever it is under; else as it is.
pub(crate) fn short_path(file: &str) -> String {
    let file = file.replace('\\', "/");
    let parts: Vec<&str> = file.split('/').collect();
    match parts.iter().rposition(|p| *p == "exercises" || *p == "src") {
        Some(i) if parts[i] == "exercises" && i > 0 => parts[i - 1..].join("/"),
        Some(i) => parts[i..].join("/"),
        None => file.clone(),
    }
}

/// Writes `<id>-student.png`, `-reference.png` and `-diff.png` for a failed
/// image check into `dir`; returns the files written.
pub fn write_failure_images(ex: &Exercise, check: &Check, dir: &Path) -> Result<Vec<PathBuf>> {
    let Some((candidate, reference)) = &check.images else {
        return Ok(Vec::new());
    };
    let stem = format!("ch{}-{}", ex.chapter, ex.name);
    let files = vec![
        dir.join(format!("{stem}-student.png")),
        dir.join(format!("{stem}-reference.png")),
        dir.join(format!("{stem}-diff.png")),
    ];
    safe_out::ensure_dir(dir).map_err(crate::core::error::Error::Usage)?;
    for f in &files {
        safe_out::refuse_in_way(f).map_err(crate::core::error::Error::Usage)?;
    }
    candidate.write_png(&files[0])?;
    reference.write_png(&files[1])?;
    let legend = format!(
        "student - reference: blue -{DIFF_SCALE}, black 0, red +{DIFF_SCALE}, green NaN or Inf"
    );
    write_captioned_strip(
        &[(
            &with_legend(&signed_difference(candidate, reference)),
            &legend,
        )],
        &files[2],
    )?;
    Ok(files)
}

/// The difference of a failure image at which its colour is full: a
/// difference of 0.25 (linear, in the channel that differs most) is full red
/// or blue. Fixed, so that images of two attempts compare.
pub const DIFF_SCALE: f32 = 0.25;

/// The signed difference of two images on the fixed scale [`DIFF_SCALE`]
/// ([`Film::signed_difference`]): red where the student's image is
/// brighter, blue where it is darker, black where they match, green
/// where the student's value is not a number or infinite.
pub fn signed_difference(candidate: &Film, reference: &Film) -> Film {
    candidate.signed_difference(reference, DIFF_SCALE)
}

/// `diff` above a colour bar from -[`DIFF_SCALE`] (blue) through 0
/// (black) to +[`DIFF_SCALE`] (red), at least 320 pixels wide so that its
/// caption fits (a narrower image sits on grey at the left).
fn with_legend(diff: &Film) -> Film {
    let width = diff.width.max(320);
    let bar = 10;
    let mut out = Film::new(width, diff.height + 2 + bar);
    out.pixels.iter_mut().for_each(|p| *p = Vec3::splat(0.2));
    for y in 0..diff.height {
        for x in 0..diff.width {
            *out.get_mut(x, y) = diff.get(x, y);
        }
    }
    for x in 0..width {
        let c = signed_colour(2.0 * (x as f32 + 0.5) / width as f32 - 1.0);
        for y in diff.height + 2..out.height {
            *out.get_mut(x, y) = c;
        }
    }
    out
}

/// Removes the failure images of `ex` from `dir` (after it passes, so that
/// an old failure is not shown as the newest).
pub fn remove_failure_images(ex: &Exercise, dir: &Path) {
    let stem = format!("ch{}-{}", ex.chapter, ex.name);
    for kind in ["student", "reference", "diff"] {
        let _ = std::fs::remove_file(dir.join(format!("{stem}-{kind}.png")));
    }
}

/// A student's image and the reference from a failed image check, read back
/// from the files [`write_failure_images`] wrote (the TUI's `g` shows them).
#[derive(Clone, Debug)]
pub struct FailureImages {
    /// The common stem, `chN-name` (the exercise).
    pub stem: String,
    /// `<stem>-student.png`.
    pub student: Film,
    /// `<stem>-reference.png`.
    pub reference: Film,
}

/// The newest pair of failure images in `dir` (by the student image's
/// modification time; the stem decides ties), or `None` when there is none
/// or `dir` does not exist.
pub fn latest_failure_images(dir: &Path) -> Result<Option<FailureImages>> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Ok(None);
    };
    let mut newest: Option<(std::time::SystemTime, String)> = None;
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(stem) = name.strip_suffix("-student.png") else {
            continue;
        };
        if !dir.join(format!("{stem}-reference.png")).is_file() {
            continue;
        }
        let time = entry
            .metadata()
            .and_then(|m| m.modified())
            .unwrap_or(std::time::UNIX_EPOCH);
        let candidate = (time, stem.to_string());
        if newest.as_ref().is_none_or(|n| candidate > *n) {
            newest = Some(candidate);
        }
    }
    let Some((_, stem)) = newest else {
        return Ok(None);
    };
    Ok(Some(FailureImages {
        student: Film::read_png(&dir.join(format!("{stem}-student.png")))?,
        reference: Film::read_png(&dir.join(format!("{stem}-reference.png")))?,
        stem,
    }))
}

/// The prefix of a progress line on a check's standard error.
pub const PROGRESS: &str = "@@raystep-progress@@ ";

/// The variable the grader sets for the checks it runs in a process of
/// their own; [`progress`] is silent without it.
pub const PROGRESS_ENV: &str = "RAYSTEP_GRADE_PROGRESS";

/// Tells the grader what a check is doing now (which case, which pixel):
/// if the student's code never returns, the timeout names it.
pub fn progress(what: impl std::fmt::Display) {
    use std::io::Write;
    if std::env::var_os(PROGRESS_ENV).is_none() {
        return;
    }
    let mut err = std::io::stderr().lock();
    let _ = writeln!(err, "{PROGRESS}{what}");
    let _ = err.flush();
}
