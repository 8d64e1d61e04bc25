//! The grader's side of running a student's code: each check in a
//! `grade-student` process of its own, stopped at a time limit, its
//! verdict read back; and `chN --student`, which renders a chapter's
//! capstone with the student's code.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use crate::grading::build::{build_exercises, root};
use crate::grading::exercise::{Exercise, Outcome};
use crate::grading::runner::parse_verdict;
use crate::grading::{run, write_failure_images, PROGRESS, PROGRESS_ENV};

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
    let built = match build_exercises(&root().join("chapters")) {
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
    let mut child = match Command::new(&built.runner)
        .args(["render", &format!("ch{chapter}")])
        .arg(&out)
        .stdin(Stdio::null())
        .spawn()
    {
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
                return ExitCode::from(u8::try_from(status.code().unwrap_or(1)).unwrap_or(1))
            }
            Ok(None) if start.elapsed() > Duration::from_secs(60) => {
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
    let none = Vec::new;
    let mut child = match Command::new(runner)
        .arg(ex.id())
        .arg(out)
        .env(PROGRESS_ENV, "1")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
    {
        Ok(c) => c,
        Err(e) => {
            let m = format!("could not start {}: {e}", runner.display());
            return (Outcome::Panicked(m), none());
        }
    };
    let read = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            let _ = r.read_to_end(&mut buf);
            String::from_utf8_lossy(&buf).into_owned()
        })
    };
    let stdout = read(Box::new(child.stdout.take().expect("piped")));
    let stderr = read(Box::new(child.stderr.take().expect("piped")));
    let start = Instant::now();
    let mut timed_out = false;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if start.elapsed() >= timeout => {
                let _ = child.kill();
                let _ = child.wait();
                timed_out = true;
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => {
                return (
                    Outcome::Panicked(format!("lost the check's process: {e}")),
                    none(),
                )
            }
        }
    };
    let stdout = stdout.join().unwrap_or_default();
    let stderr = stderr.join().unwrap_or_default();
    let doing = stderr
        .lines()
        .filter_map(|l| l.strip_prefix(PROGRESS))
        .next_back()
        .unwrap_or_default()
        .to_string();
    if timed_out {
        let seconds = timeout.as_secs_f64();
        return (Outcome::TimedOut { seconds, doing }, none());
    }
    match parse_verdict(&stdout) {
        Some(v) => (v.outcome(), v.images),
        None => {
            let tail: Vec<&str> = stderr
                .lines()
                .filter(|l| !l.starts_with(PROGRESS))
                .collect();
            let tail = tail[tail.len().saturating_sub(3)..].join(" / ");
            let m = format!(
                "the check's process crashed ({}){}{}",
                status.map(|s| s.to_string()).unwrap_or_default(),
                if doing.is_empty() {
                    String::new()
                } else {
                    format!(" while {doing}")
                },
                if tail.is_empty() {
                    String::new()
                } else {
                    format!(": {tail}")
                }
            );
            (Outcome::Panicked(m), none())
        }
    }
}
