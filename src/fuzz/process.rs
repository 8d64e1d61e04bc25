//! The structure-aware fuzzer's runs: every case in a child process of
//! its own (the `fuzz` binary's hidden `--run-case SEED INDEX`), under a
//! wall-clock limit and an address-space limit (`RLIMIT_AS`, set by the
//! child on itself through `nix`), through the grader's
//! [`run_limited`]. So a hang, a memory blow-up and a signal are outcomes
//! like a panic, not the end of the fuzzer:
//!
//! | outcome | how the parent sees it |
//! | --- | --- |
//! | clean error, success | the child's last line on standard output |
//! | panic | exit status 101 (Rust's panic exit) |
//! | hang | still running at the time limit: the group is killed |
//! | out of memory | "memory allocation of N bytes failed" on standard error, or killed by SIGKILL (the kernel's OOM killer) |
//! | signal | any other signal (SIGSEGV, SIGABRT, SIGBUS…) |
//! | odd exit | any other exit status, or too much output |
//!
//! The child reads nothing but its arguments; the case is rebuilt from
//! (seed, index) by [`structured_case`].

use std::path::Path;
use std::process::Command;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use super::tree::structured_case;
use crate::grading::child::{run_limited, Limit, Ran};

/// How one case ended, seen from outside its process.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Class {
    /// Loading or rendering returned an error.
    Error,
    /// It loaded and rendered.
    Success,
    /// It panicked.
    Panic,
    /// It ran past the time limit.
    Hang,
    /// It ran out of memory (allocation failure, or killed).
    OutOfMemory,
    /// It was ended by a signal.
    Signal,
    /// Any other end (an unexpected exit status, too much output).
    OddExit,
}

impl Class {
    /// Every class, in report order.
    pub const ALL: [Class; 7] = [
        Class::Error,
        Class::Success,
        Class::Panic,
        Class::Hang,
        Class::OutOfMemory,
        Class::Signal,
        Class::OddExit,
    ];

    /// Whether this outcome is a finding (a bug to report).
    pub fn is_finding(self) -> bool {
        !matches!(self, Class::Error | Class::Success)
    }

    /// Its name in reports.
    pub fn label(self) -> &'static str {
        match self {
            Class::Error => "clean errors",
            Class::Success => "successes",
            Class::Panic => "panics",
            Class::Hang => "hangs",
            Class::OutOfMemory => "out of memory",
            Class::Signal => "signals",
            Class::OddExit => "odd exits",
        }
    }
}

/// The limits of one case's process.
#[derive(Clone, Copy, Debug)]
pub struct CaseLimits {
    /// Wall-clock time before the case counts as a hang.
    pub timeout: Duration,
    /// Address space, bytes.
    pub memory: u64,
}

/// A deliberate failure the child produces instead of running its case,
/// to prove the harness classifies each kind (`--self-test KIND`).
pub const SELF_TESTS: &[&str] = &["hang", "oom", "panic", "abort"];

/// What the child prints as its last line on standard output.
const SAYS: &str = "fuzz-case: ";

// ANCHOR: child
/// The child's side (`fuzz --run-case SEED INDEX --memory-mib M
/// [--self-test KIND]`): limits itself, runs the case, prints the outcome.
/// Returns only for a clean error or a success.
pub fn child_main(seed: u64, index: u64, memory: u64, self_test: Option<&str>) {
    #[cfg(unix)]
    {
        use nix::sys::resource::{setrlimit, Resource};
        // No core files from aborts; the address space capped.
        let _ = setrlimit(Resource::RLIMIT_CORE, 0, 0);
        if setrlimit(Resource::RLIMIT_AS, memory, memory).is_err() {
            eprintln!("fuzz: could not set the memory limit");
        }
    }
    match self_test {
        Some("hang") => loop {
            std::thread::sleep(Duration::from_secs(1));
        },
        Some("oom") => {
            let mut hoard: Vec<Vec<u8>> = Vec::new();
            loop {
                hoard.push(vec![1u8; 16 << 20]);
            }
        }
        Some("panic") => panic!("fuzz self-test: a deliberate panic"),
        Some("abort") => std::process::abort(),
        _ => {}
    }
    let c = structured_case(seed, index);
    match super::render(&c.case, c.width, c.height, c.spp) {
        Ok(()) => println!("{SAYS}success"),
        Err(e) => println!("{SAYS}error: {}", e.replace('\n', " ")),
    }
}
// ANCHOR_END: child

/// The first line of a panic's message (or of standard error).
fn gist(stderr: &str) -> String {
    let line = stderr
        .lines()
        .skip_while(|l| !l.contains("panicked at") && !l.contains("memory allocation"))
        .take(2)
        .collect::<Vec<_>>()
        .join(" ");
    let line = if line.is_empty() {
        stderr.lines().last().unwrap_or("").to_string()
    } else {
        line
    };
    line.chars().take(300).collect()
}

// ANCHOR: classify
/// Runs case `index` of `seed` in a child process of `exe` (the `fuzz`
/// binary) under `limits`: its class and a line of detail.
pub fn run_one(
    exe: &Path,
    seed: u64,
    index: u64,
    limits: &CaseLimits,
    self_test: Option<&str>,
) -> (Class, String) {
    let mut cmd = Command::new(exe);
    cmd.args(["--run-case", &seed.to_string(), &index.to_string()])
        .args(["--memory-mib", &(limits.memory >> 20).to_string()])
        .env("RAYON_NUM_THREADS", "1")
        .env("RUST_BACKTRACE", "0");
    if let Some(kind) = self_test {
        cmd.args(["--self-test", kind]);
    }
    let ran = match run_limited(&mut cmd, b"", Some(Limit::Wall(limits.timeout)), None) {
        Ok(ran) => ran,
        Err(e) => return (Class::OddExit, format!("could not start: {e}")),
    };
    let (status, stdout, stderr) = match ran {
        Ran::Exited {
            status,
            stdout,
            stderr,
            ..
        } => (status, stdout, stderr),
        Ran::TimedOut { .. } => {
            return (Class::Hang, format!("over {:?}", limits.timeout));
        }
        Ran::TooMuchOutput => return (Class::OddExit, "too much output".into()),
        Ran::Cancelled => return (Class::OddExit, "cancelled".into()),
    };
    if stderr.contains("memory allocation of") {
        return (Class::OutOfMemory, gist(&stderr));
    }
    if status.success() {
        let last = stdout.lines().last().unwrap_or("");
        return match last.strip_prefix(SAYS) {
            Some("success") => (Class::Success, String::new()),
            Some(e) => (Class::Error, e.trim_start_matches("error: ").to_string()),
            None => (Class::OddExit, "exit 0 without an outcome".into()),
        };
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(sig) = status.signal() {
            // SIGKILL that we did not send: the kernel's OOM killer.
            let class = if sig == 9 {
                Class::OutOfMemory
            } else {
                Class::Signal
            };
            return (class, format!("signal {sig}: {}", gist(&stderr)));
        }
    }
    match status.code() {
        Some(101) => (Class::Panic, gist(&stderr)),
        _ => (Class::OddExit, format!("{status}: {}", gist(&stderr))),
    }
}
// ANCHOR_END: classify

/// Counts over a structured run.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// Cases run, per class (in [`Class::ALL`]'s order).
    pub counts: [u64; 7],
    /// Every finding: index, class, detail.
    pub findings: Vec<(u64, Class, String)>,
    /// Wall-clock seconds.
    pub seconds: f64,
    /// The longest case, seconds, and its index.
    pub slowest: (f64, u64),
}

impl Report {
    /// Cases run.
    pub fn cases(&self) -> u64 {
        self.counts.iter().sum()
    }

    /// Cases of one class.
    pub fn count(&self, class: Class) -> u64 {
        self.counts[Class::ALL
            .iter()
            .position(|&c| c == class)
            .expect("a class")]
    }

    /// One line: cases, cases/s and the count per class.
    pub fn summary(&self) -> String {
        let per: Vec<String> = Class::ALL
            .iter()
            .map(|&c| format!("{} {}", self.count(c), c.label()))
            .collect();
        format!(
            "{} cases in {:.1} s ({:.1} cases/s): {}; slowest {:.2} s (case {})",
            self.cases(),
            self.seconds,
            self.cases() as f64 / self.seconds.max(1e-9),
            per.join(", "),
            self.slowest.0,
            self.slowest.1
        )
    }
}

/// Runs cases `range` of `seed`, `jobs` children at a time; `progress` is
/// called with the report so far after every `every` cases.
pub fn run_range(
    exe: &Path,
    seed: u64,
    range: std::ops::Range<u64>,
    jobs: usize,
    limits: &CaseLimits,
    every: u64,
    progress: &(dyn Fn(&Report) + Sync),
) -> Report {
    let began = Instant::now();
    let next = AtomicU64::new(range.start);
    let report = Mutex::new(Report::default());
    std::thread::scope(|s| {
        for _ in 0..jobs.max(1) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                if i >= range.end {
                    break;
                }
                let t = Instant::now();
                let (class, detail) = run_one(exe, seed, i, limits, None);
                let secs = t.elapsed().as_secs_f64();
                let mut r = report.lock().unwrap_or_else(|e| e.into_inner());
                let k = Class::ALL
                    .iter()
                    .position(|&c| c == class)
                    .expect("a class");
                r.counts[k] += 1;
                if class.is_finding() {
                    r.findings.push((i, class, detail));
                }
                if secs > r.slowest.0 {
                    r.slowest = (secs, i);
                }
                r.seconds = began.elapsed().as_secs_f64();
                if every > 0 && r.cases() % every == 0 {
                    progress(&r);
                }
            });
        }
    });
    let mut r = report.into_inner().unwrap_or_else(|e| e.into_inner());
    r.seconds = began.elapsed().as_secs_f64();
    r.findings.sort_by_key(|f| f.0);
    r
}
