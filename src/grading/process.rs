//! The grader's side of running a student's code: each exercise's
//! [`Request`] answered by the student's process (`raystep-grade-child`)
//! under a time limit, its transcript replayed in this process, where the
//! verdict is made ([`crate::runner::replay_check`]); and
//! `chN --student`, which renders a chapter's capstone with the student's
//! code.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::sync::atomic::AtomicBool;
use std::time::Duration;

use crate::build::{build_exercises, exercises_dir};
use crate::child::{crash_message, last_progress, run_limited, Limit, Ran, OUTPUT_LIMIT};
use crate::exercise::{Check, Exercise, Outcome};
use crate::runner::{replay_check, Request};
use crate::{run, write_failure_images, PROGRESS_ENV};

/// A seed for one grading run's drawn inputs, different every run (not
/// printed: a student cannot learn the inputs in advance).
pub fn fresh_seed() -> u64 {
    use std::hash::{BuildHasher, Hasher};
    let mut h = std::collections::hash_map::RandomState::new().build_hasher();
    h.write_u128(
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos()),
    );
    h.write_u32(std::process::id());
    h.finish()
}

/// Runs `request` in the student's process `runner` under `timeout` (or
/// until `cancel` is set): its transcript, or the outcome that ended it
/// (a crash, the time limit, too much output).
pub fn in_student_process(
    runner: &Path,
    request: &Request,
    timeout: Duration,
    cancel: Option<&AtomicBool>,
) -> Result<Vec<u8>, Box<Outcome>> {
    let mut cmd = Command::new(runner);
    // Nothing of the grader's environment reaches the student's code.
    cmd.env_clear().env(PROGRESS_ENV, "1");
    let ran = run_limited(
        &mut cmd,
        request.line().as_bytes(),
        Some(Limit::Cpu(timeout)),
        cancel,
    );
    let outcome = match ran {
        Err(e) => Outcome::Panicked(format!("could not start {}: {e}", runner.display())),
        Ok(Ran::TimedOut { stderr }) => Outcome::TimedOut {
            seconds: timeout.as_secs_f64(),
            doing: last_progress(&stderr),
        },
        Ok(Ran::TooMuchOutput) => Outcome::Panicked(too_much_output()),
        Ok(Ran::Cancelled) => Outcome::Panicked("cancelled".into()),
        Ok(Ran::Exited {
            status,
            raw,
            stderr,
            ..
        }) => {
            if status.success() && !raw.is_empty() {
                return Ok(raw);
            }
            Outcome::Panicked(crash_message(&status, &stderr))
        }
    };
    Err(Box::new(outcome))
}

/// Exercise `ex`'s check: its calls answered by the student's process
/// `runner` (stopped after `timeout` or when `cancel` is set), the verdict
/// made here on the inputs drawn from `seed`.
fn graded(
    runner: &Path,
    ex: &Exercise,
    timeout: Duration,
    seed: u64,
    cancel: Option<&AtomicBool>,
) -> Outcome {
    let request = Request::Check { id: ex.id(), seed };
    let timeout = timeout * ex.time_factor();
    match in_student_process(runner, &request, timeout, cancel) {
        Ok(transcript) => replay_check(&ex.id(), transcript, seed),
        Err(outcome) => *outcome,
    }
}

/// `chN --student`: builds the exercises, then renders chapter N's
/// capstone scene with the student's code beside the reference and their
/// difference, into `out/student/` (under a one-minute limit).
pub fn student_main(chapter: u32) -> ExitCode {
    let Some(ex) = crate::runner::capstone(chapter) else {
        eprintln!("chapter {chapter} has no capstone to render yet");
        return ExitCode::from(2);
    };
    eprintln!("building your exercises...");
    let built = match build_exercises(&exercises_dir()) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error: could not build the exercises: {e}");
            return ExitCode::from(2);
        }
    };
    let id = ex.id();
    if let Some(m) = built.broken.get(&id) {
        eprintln!("{id} does not compile:\n{m}");
        return ExitCode::from(1);
    }
    let out = PathBuf::from("out/student");
    let (outcome, files) = capstone_images(&built.runner, &ex, &out, Duration::from_secs(60), None);
    match outcome {
        Outcome::Passed(c) | Outcome::Failed(c) => {
            let verdict = if c.passed() {
                "matches the reference"
            } else {
                "differs from the reference"
            };
            println!("your {id} {verdict}: {}", c.detail);
            for f in &files {
                println!("wrote {}", f.display());
            }
            ExitCode::SUCCESS
        }
        Outcome::NotImplemented => {
            println!("{id} is not started: replace the todo!() in {}", ex.file);
            ExitCode::from(1)
        }
        other => {
            println!("{id}: {other:?}");
            ExitCode::from(1)
        }
    }
}

/// Grades capstone `ex` with the student's process `runner` and writes
/// the student's image, the reference and their difference into `out`
/// whether it passes or not (the live view and `chN --student` show them);
/// the outcome (its check without the images) and the files written.
pub fn capstone_images(
    runner: &Path,
    ex: &Exercise,
    out: &Path,
    timeout: Duration,
    cancel: Option<&AtomicBool>,
) -> (Outcome, Vec<PathBuf>) {
    let outcome = graded(runner, ex, timeout, fresh_seed(), cancel);
    let (Outcome::Passed(c) | Outcome::Failed(c)) = &outcome else {
        return (outcome, Vec::new());
    };
    let passed = c.passed();
    let written = crate::safe_out::ensure_dir(out)
        .and_then(|_| write_failure_images(ex, c, out).map_err(|e| e.to_string()));
    let strip = |c: &Check| Check {
        images: None,
        ..c.clone()
    };
    match written {
        Ok(files) => {
            let c = strip(c);
            let outcome = if passed {
                Outcome::Passed(c)
            } else {
                Outcome::Failed(c)
            };
            (outcome, files)
        }
        Err(e) => (
            Outcome::Panicked(format!("could not write the images: {e}")),
            Vec::new(),
        ),
    }
}

/// Grades raystep's reference solution of `ex` in this process; images of
/// a failed image check go to `out`.
pub fn reference(ex: &Exercise, out: &Path, seed: u64) -> (Outcome, Vec<PathBuf>) {
    crate::set_run_seed(seed);
    let outcome = run(ex);
    let images = match &outcome {
        Outcome::Failed(c) => write_failure_images(ex, c, out).unwrap_or_default(),
        _ => Vec::new(),
    };
    (outcome, images)
}

/// Grades the student's `ex`: its check's calls answered by the
/// student's process `runner` (stopped after `timeout`), the verdict
/// made here on the inputs drawn from `seed`; the outcome and the images
/// written for a failed image check (into `out`, never through a link).
pub fn run_student(
    runner: &Path,
    ex: &Exercise,
    out: &Path,
    timeout: Duration,
    seed: u64,
) -> (Outcome, Vec<PathBuf>) {
    match graded(runner, ex, timeout, seed, None) {
        Outcome::Failed(c) => {
            let (images, note) = match write_failure_images(ex, &c, out) {
                Ok(files) => (files, String::new()),
                Err(e) => (Vec::new(), format!(" (could not write images: {e})")),
            };
            let c = Check {
                images: None,
                detail: c.detail + &note,
                ..c
            };
            (Outcome::Failed(c), images)
        }
        Outcome::Passed(c) => (Outcome::Passed(Check { images: None, ..c }), Vec::new()),
        other => (other, Vec::new()),
    }
}

/// Why a check that printed too much was stopped.
pub fn too_much_output() -> String {
    format!(
        "printed more than {} MiB and was stopped: remove the prints in loops",
        OUTPUT_LIMIT >> 20
    )
}

/// What the sandbox of the student's process (built at `runner`) cannot
/// enforce on this system, one phrase each: empty where everything holds.
/// Asked of a process of its own, since the sandbox, once closed, stays
/// with the process that closed it.
pub fn sandbox_gaps(runner: &Path) -> Vec<String> {
    match in_student_process(
        runner,
        &Request::SandboxCheck,
        Duration::from_secs(10),
        None,
    ) {
        Ok(text) => String::from_utf8_lossy(&text)
            .lines()
            .skip(1)
            .filter(|l| !l.is_empty())
            .map(str::to_string)
            .collect(),
        Err(_) => vec!["its check did not run".into()],
    }
}
