//! The grader's side of running a student's code: each check in a
//! `grade-student` process of its own, stopped at a time limit, its
//! verdict read back; and `chN --student`, which renders a chapter's
//! capstone with the student's code.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use crate::grading::build::{build_exercises, exercises_dir};
use crate::grading::child::{crash_message, last_progress, run_limited, Ran, OUTPUT_LIMIT};
use crate::grading::exercise::{Exercise, Outcome};
use crate::grading::runner::Handshake;
use crate::grading::sandbox::{kill_group, own_group};
use crate::grading::{run, write_failure_images, PROGRESS_ENV};

/// `chN --student`: builds the exercises, then renders chapter N's
/// capstone scene with the student's code beside the reference and their
/// difference, into `out/student/` (under a one-minute limit).
pub fn student_main(chapter: u32) -> ExitCode {
    let Some((_, name)) = crate::grading::runner::CAPSTONES
        .iter()
        .find(|(c, _)| *c == chapter)
    else {
        eprintln!("chapter {chapter} has no capstone to render yet");
        return ExitCode::from(2);
    };
    eprintln!("building your exercises (the raystep-exercises crate)...");
    let built = match build_exercises(&exercises_dir()) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error: could not build the exercises: {e}");
            return ExitCode::from(2);
        }
    };
    let id = format!("ch{chapter}/{name}");
    if let Some(m) = built.broken.get(&id) {
        eprintln!("{id} does not compile:\n{m}");
        return ExitCode::from(1);
    }
    let out = PathBuf::from("out/student");
    let mut cmd = Command::new(&built.runner);
    cmd.args(["render", &format!("ch{chapter}")])
        .arg(&out)
        .stdin(Stdio::null());
    own_group(&mut cmd);
    let mut child = match cmd.spawn() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: could not start {}: {e}", built.runner.display());
            return ExitCode::from(2);
        }
    };
    let start = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(status)) => {
                kill_group(child.id());
                return ExitCode::from(u8::try_from(status.code().unwrap_or(1)).unwrap_or(1));
            }
            Ok(None) if start.elapsed() > Duration::from_secs(60) => {
                kill_group(child.id());
                let _ = child.kill();
                let _ = child.wait();
                eprintln!("your {id} ran for a minute and was stopped: does a loop never end?");
                return ExitCode::from(1);
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
}

/// Grades raystep's reference solution of `ex` in this process; images of
/// a failed image check go to `out`.
pub fn reference(ex: &Exercise, out: &Path) -> (Outcome, Vec<PathBuf>) {
    let outcome = run(ex);
    let images = match &outcome {
        Outcome::Failed(c) => write_failure_images(ex, c, out).unwrap_or_default(),
        _ => Vec::new(),
    };
    (outcome, images)
}

/// Runs the student's check of `ex` in a `grade-student` process, stopping
/// it after `timeout`; the outcome and the images the check wrote.
pub fn run_student(
    runner: &Path,
    ex: &Exercise,
    out: &Path,
    timeout: Duration,
) -> (Outcome, Vec<PathBuf>) {
    let mut cmd = Command::new(runner);
    cmd.arg(ex.id()).arg(out).env(PROGRESS_ENV, "1");
    let handshake = Handshake::new(timeout);
    match run_limited(&mut cmd, &handshake.line(), Some(timeout), None) {
        Err(e) => {
            let m = format!("could not start {}: {e}", runner.display());
            (Outcome::Panicked(m), Vec::new())
        }
        Ok(Ran::TimedOut { stderr }) => {
            let seconds = timeout.as_secs_f64();
            let doing = last_progress(&stderr);
            (Outcome::TimedOut { seconds, doing }, Vec::new())
        }
        Ok(Ran::TooMuchOutput) => (Outcome::Panicked(too_much_output()), Vec::new()),
        Ok(Ran::Cancelled) => (Outcome::Panicked("cancelled".into()), Vec::new()),
        Ok(Ran::Exited {
            status,
            stdout,
            stderr,
        }) => match handshake.verdict_in(&stdout) {
            Some(v) => (v.outcome(ex), v.images),
            None => (
                Outcome::Panicked(crash_message(&status, &stderr)),
                Vec::new(),
            ),
        },
    }
}

/// Why a check that printed too much was stopped.
pub fn too_much_output() -> String {
    format!(
        "printed more than {} MiB and was stopped: remove the prints in loops",
        OUTPUT_LIMIT >> 20
    )
}

/// What the sandbox of `grade-student` (built at `runner`) cannot enforce
/// on this system, one phrase each: empty where everything holds. Asked
/// of a `grade-student` process of its own, since the limits, once set,
/// stay with the process that set them.
pub fn sandbox_gaps(runner: &Path, scratch: &Path) -> Vec<String> {
    let mut cmd = Command::new(runner);
    cmd.arg(crate::grading::runner::SANDBOX_CHECK).arg(scratch);
    match run_limited(&mut cmd, b"", Some(Duration::from_secs(10)), None) {
        Ok(Ran::Exited { stdout, .. }) => stdout.lines().map(str::to_string).collect(),
        _ => vec!["its check did not run".into()],
    }
}
