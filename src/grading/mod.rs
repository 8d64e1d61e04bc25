//! Grading students' solutions.
//!
//! Each chapter ships exercise files (`chapters/chN-…/exercises/*.rs`) whose
//! bodies are `todo!()` with `// TODO` notes; they are compiled into the
//! library as [`crate::grading::exercises`], so they always build. A chapter's
//! exercise manifest lists, for each file, a hint and a check that measures
//! a candidate against raystep's own reference with a tolerance.
//!
//! `cargo run --release --bin grade` runs every check on the student's code
//! and prints pass or fail, the measured error and the hint. A `todo!()` or
//! any other panic is caught and reported: the grader never crashes. When a
//! check compares images and fails, the student's image, the reference and
//! their difference are written to `out/grade/`.

pub mod exercise;
pub mod exercises;

pub use exercise::{Check, Exercise, Outcome, Solution};

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Mutex;

use clap::Parser;

use crate::core::error::Result;
use crate::core::film::Film;

/// Every exercise of every chapter, in order.
pub fn all() -> Vec<Exercise> {
    crate::grading::exercises::all()
}

/// Only one grading at a time swaps the panic hook.
static HOOK: Mutex<()> = Mutex::new(());

/// Grades one exercise, catching `todo!()` and any other panic.
pub fn run(ex: &Exercise, who: Solution) -> Outcome {
    let _guard = HOOK.lock().unwrap_or_else(|e| e.into_inner());
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let result = catch_unwind(AssertUnwindSafe(|| (ex.grade)(who)));
    std::panic::set_hook(previous);
    match result {
        Ok(check) if check.passed() => Outcome::Passed(check),
        Ok(check) => Outcome::Failed(check),
        Err(payload) => {
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "panicked".into());
            if message.starts_with("not yet implemented") {
                Outcome::NotImplemented
            } else {
                Outcome::Panicked(message)
            }
        }
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
    candidate.write_png(&files[0])?;
    reference.write_png(&files[1])?;
    candidate.difference(reference).write_png(&files[2])?;
    Ok(files)
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

/// Grade your solutions to the exercises against raystep's reference.
#[derive(Parser, Debug)]
#[command(name = "grade")]
struct GradeCli {
    /// Chapters to grade (`ch1` or `1`); all when omitted.
    chapters: Vec<String>,
    /// Grade raystep's reference solutions instead (they must all pass).
    #[arg(long)]
    reference: bool,
    /// Where images of failed image checks go.
    #[arg(long, value_name = "DIR", default_value = "out/grade")]
    out: PathBuf,
}

/// The whole `main` of the `grade` binary.
pub fn grade_main() -> ExitCode {
    let cli = GradeCli::parse();
    let mut wanted = Vec::new();
    for c in &cli.chapters {
        match c.trim_start_matches("ch").parse::<u32>() {
            Ok(n) => wanted.push(n),
            Err(_) => {
                eprintln!("error: `{c}` is not a chapter; expected e.g. `ch1` or `1`");
                return ExitCode::from(2);
            }
        }
    }
    let exercises: Vec<Exercise> = all()
        .into_iter()
        .filter(|e| wanted.is_empty() || wanted.contains(&e.chapter))
        .collect();
    if exercises.is_empty() {
        eprintln!("error: no exercises for chapters {:?}", cli.chapters);
        return ExitCode::from(2);
    }
    let who = if cli.reference {
        Solution::Reference
    } else {
        Solution::Student
    };
    let (text, passed) = grade_report(&exercises, who, &cli.out);
    print!("{text}");
    if passed == exercises.len() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// Grades `exercises` and returns the printed report and the number passed.
pub fn grade_report(exercises: &[Exercise], who: Solution, out: &Path) -> (String, usize) {
    let width = exercises.iter().map(|e| e.id().len()).max().unwrap_or(0);
    let mut text = format!(
        "grading {} exercises ({})\n",
        exercises.len(),
        match who {
            Solution::Student => "your solutions",
            Solution::Reference => "reference solutions",
        }
    );
    let mut passed = 0;
    let mut wrote_images = false;
    for ex in exercises {
        let outcome = run(ex, who);
        let id = format!("{:width$}", ex.id());
        let line = match &outcome {
            Outcome::Passed(c) => {
                passed += 1;
                format!(
                    "  {id}  PASS  error {:.3e} within {:.0e}\n",
                    c.error, c.tolerance
                )
            }
            Outcome::Failed(c) => {
                let mut s = format!(
                    "  {id}  FAIL  error {:.3e} exceeds {:.0e}: {}\n",
                    c.error, c.tolerance, c.detail
                );
                match write_failure_images(ex, c, out) {
                    Ok(files) if !files.is_empty() => {
                        wrote_images = true;
                        let names: Vec<String> =
                            files.iter().map(|f| f.display().to_string()).collect();
                        s += &format!("  {:width$}        images: {}\n", "", names.join(", "));
                    }
                    Ok(_) => {}
                    Err(e) => s += &format!("  {:width$}        could not write images: {e}\n", ""),
                }
                s
            }
            Outcome::NotImplemented => {
                format!(
                    "  {id}  FAIL  not implemented yet: replace the todo!() in {}\n",
                    ex.file
                )
            }
            Outcome::Panicked(m) => format!("  {id}  FAIL  panicked: {m}\n"),
        };
        text += &line;
        if !outcome.is_pass() {
            text += &format!("  {:width$}        hint: {}\n", "", ex.hint);
        }
    }
    text += &format!("{passed} of {} passed\n", exercises.len());
    if wrote_images {
        text += "to compare the newest images side by side: open the terminal UI \
                 (`cargo run --release`) and press `g`\n";
    }
    (text, passed)
}
