//! Running a child process under a time limit, with its output captured:
//! `cargo build` for the exercises crate and every `grade-student`
//! process. The caller never waits past the limit, and can cancel.

use std::io::Read;
use std::process::{Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::grading::PROGRESS;

/// How a child process run by [`run_limited`] ended.
#[derive(Debug)]
pub enum Ran {
    /// It exited by itself.
    Exited {
        /// Its exit status.
        status: ExitStatus,
        /// What it wrote to standard output.
        stdout: String,
        /// What it wrote to standard error.
        stderr: String,
    },
    /// It ran past the time limit and was stopped.
    TimedOut {
        /// What it wrote to standard error before.
        stderr: String,
    },
    /// `cancel` was set, and it was stopped.
    Cancelled,
}

/// Runs `cmd` (standard input closed, both outputs captured) until it
/// exits, stopping it after `timeout` or as soon as `cancel` is set; the
/// caller never waits longer than that. Used for `cargo build` and for
/// every `grade-student` process.
pub fn run_limited(
    cmd: &mut Command,
    timeout: Option<Duration>,
    cancel: Option<&AtomicBool>,
) -> std::io::Result<Ran> {
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()?;
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
    loop {
        if let Some(status) = child.try_wait()? {
            return Ok(Ran::Exited {
                status,
                stdout: stdout.join().unwrap_or_default(),
                stderr: stderr.join().unwrap_or_default(),
            });
        }
        if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
            let _ = child.kill();
            let _ = child.wait();
            // The readers are left to finish by themselves: a grandchild
            // (cargo's rustc) may hold the pipes open a while longer.
            return Ok(Ran::Cancelled);
        }
        if timeout.is_some_and(|t| start.elapsed() >= t) {
            let _ = child.kill();
            let _ = child.wait();
            return Ok(Ran::TimedOut {
                stderr: stderr.join().unwrap_or_default(),
            });
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// The last progress line a check printed on standard error.
pub fn last_progress(stderr: &str) -> String {
    stderr
        .lines()
        .filter_map(|l| l.strip_prefix(PROGRESS))
        .next_back()
        .unwrap_or_default()
        .to_string()
}

/// What a check's process that printed no verdict left behind: its exit
/// status, what it was doing, and the last lines of its standard error.
pub fn crash_message(status: &ExitStatus, stderr: &str) -> String {
    let doing = last_progress(stderr);
    let tail: Vec<&str> = stderr
        .lines()
        .filter(|l| !l.starts_with(PROGRESS))
        .collect();
    let tail = tail[tail.len().saturating_sub(3)..].join(" / ");
    format!(
        "the check's process crashed ({status}){}{}",
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
    )
}
