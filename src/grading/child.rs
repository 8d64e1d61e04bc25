//! Running a child process under a time limit, with its output captured:
//! `cargo build` for the exercises crate and every `grade-student`
//! process. The caller never waits past the limit, and can cancel.

use std::io::{Read, Write};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use std::time::{Duration, Instant};

use crate::sandbox::{kill_group, own_group, Limits};
use crate::PROGRESS;

/// How a child process run by [`run_limited`] ended.
#[derive(Debug)]
pub enum Ran {
    /// It exited by itself.
    Exited {
        /// Its exit status.
        status: ExitStatus,
        /// What it wrote to standard output.
        stdout: String,
        /// The same, as bytes (the student's process writes its transcript
        /// there).
        raw: Vec<u8>,
        /// What it wrote to standard error.
        stderr: String,
    },
    /// It ran past the time limit and was stopped.
    TimedOut {
        /// What it wrote to standard error before.
        stderr: String,
    },
    /// It wrote more than [`OUTPUT_LIMIT`] bytes and was stopped.
    TooMuchOutput,
    /// `cancel` was set, and it was stopped.
    Cancelled,
}

/// When [`run_limited`] stops a child that has not exited.
#[derive(Debug, Clone, Copy)]
pub enum Limit {
    /// After this much wall-clock time.
    Wall(Duration),
    /// After this much CPU time, what a loop that never ends uses up
    /// however busy the machine is, while a correct check is not cut
    /// short because other work slows it; or after four times as much
    /// wall-clock time, for a child that waits without computing. Where
    /// the CPU time cannot be read (no Linux `/proc`), after this much
    /// wall-clock time.
    Cpu(Duration),
}

impl Limit {
    /// Whether process `pid`, started `wall` ago, has reached the limit.
    fn reached(self, pid: u32, wall: Duration) -> bool {
        match self {
            Limit::Wall(t) => wall >= t,
            Limit::Cpu(t) => match cpu_time(pid) {
                Some(cpu) => cpu >= t || wall >= 4 * t,
                None => wall >= t,
            },
        }
    }
}

/// The CPU time (user and system) process `pid` has used so far, from
/// `/proc/<pid>/stat`; `None` where that cannot be read.
fn cpu_time(pid: u32) -> Option<Duration> {
    #[cfg(target_os = "linux")]
    {
        let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
        // After the command name (in parentheses, and it may hold
        // anything) come the fields from the third on: utime and stime
        // are the 14th and 15th, in clock ticks.
        let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
        let ticks = fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?;
        let per_second = nix::unistd::sysconf(nix::unistd::SysconfVar::CLK_TCK).ok()??;
        (per_second > 0).then(|| Duration::from_secs_f64(ticks as f64 / per_second as f64))
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = pid;
        None
    }
}

/// The most a child may write to standard error before it is stopped:
/// 4 MiB (a check's own output is a few hundred bytes; a student's
/// debugging prints rarely reach this).
pub const OUTPUT_LIMIT: usize = 4 << 20;

/// The most a child may write to standard output: 256 MiB (the student's
/// process writes the transcript of its calls there: 18 MiB for chapter
/// 6's capstone, the largest; a student's code that calls its callbacks
/// without end is stopped here or at the time limit).
pub const TRANSCRIPT_LIMIT: usize = 256 << 20;

/// Both outputs of a child, read on two threads into one budget.
struct Outputs {
    stdout: Arc<Mutex<Vec<u8>>>,
    stderr: Arc<Mutex<Vec<u8>>>,
    out_total: Arc<AtomicUsize>,
    err_total: Arc<AtomicUsize>,
    done: mpsc::Receiver<()>,
}

impl Outputs {
    fn start(child: &mut Child) -> Outputs {
        let (tx, done) = mpsc::channel();
        let read = |mut r: Box<dyn Read + Send>, total: &Arc<AtomicUsize>, limit: usize| {
            let buf = Arc::new(Mutex::new(Vec::new()));
            let (into, total, tx) = (Arc::clone(&buf), Arc::clone(total), tx.clone());
            std::thread::spawn(move || {
                let mut chunk = [0u8; 8192];
                while let Ok(n) = r.read(&mut chunk) {
                    if n == 0 {
                        break;
                    }
                    // Past the limit, keep draining (so the writer is not
                    // blocked before it is stopped) but store nothing.
                    if total.fetch_add(n, Ordering::Relaxed) + n <= limit {
                        lock(&into).extend_from_slice(&chunk[..n]);
                    }
                }
                let _ = tx.send(());
            });
            buf
        };
        let (out_total, err_total) = (Arc::new(AtomicUsize::new(0)), Arc::new(AtomicUsize::new(0)));
        let stdout = read(
            Box::new(child.stdout.take().expect("piped")),
            &out_total,
            TRANSCRIPT_LIMIT,
        );
        let stderr = read(
            Box::new(child.stderr.take().expect("piped")),
            &err_total,
            OUTPUT_LIMIT,
        );
        Outputs {
            stdout,
            stderr,
            out_total,
            err_total,
            done,
        }
    }

    fn too_much(&self) -> bool {
        self.out_total.load(Ordering::Relaxed) > TRANSCRIPT_LIMIT
            || self.err_total.load(Ordering::Relaxed) > OUTPUT_LIMIT
    }

    /// What was read so far, after waiting up to `wait` for both pipes to
    /// close (a grandchild that left the process group may hold them open
    /// for ever: we do not wait for it).
    fn collect(&self, wait: Duration) -> (Vec<u8>, String) {
        let until = Instant::now() + wait;
        for _ in 0..2 {
            let left = until.saturating_duration_since(Instant::now());
            if self.done.recv_timeout(left).is_err() {
                break;
            }
        }
        let err = String::from_utf8_lossy(&lock(&self.stderr)).into_owned();
        (std::mem::take(&mut *lock(&self.stdout)), err)
    }
}

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// Runs `cmd` in a process group of its own, with `input` on its standard
/// input (then closed) and both outputs captured, until it exits; stops
/// the whole group at `limit`, as soon as `cancel` is set, or when it
/// writes more than [`OUTPUT_LIMIT`] to standard error or
/// [`TRANSCRIPT_LIMIT`] to standard output. The caller never waits longer than
/// that, nor for pipes that something the child started keeps open. Used
/// for `cargo build` and for every `grade-student` process.
pub fn run_limited(
    cmd: &mut Command,
    input: &[u8],
    limit: Option<Limit>,
    cancel: Option<&AtomicBool>,
) -> std::io::Result<Ran> {
    own_group(cmd);
    cmd.stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // A program file just written is "busy" while a child another thread
    // is starting still holds the writer's descriptor: wait it out, as
    // cargo does for build scripts.
    let mut busy = 0;
    let mut child = loop {
        match cmd.spawn() {
            Err(e) if e.kind() == std::io::ErrorKind::ExecutableFileBusy && busy < 100 => {
                busy += 1;
                std::thread::sleep(Duration::from_millis(10));
            }
            spawned => break spawned?,
        }
    };
    if let Some(mut stdin) = child.stdin.take() {
        // A child that exits without reading its input is not an error.
        let _ = stdin.write_all(input);
    }
    let outputs = Outputs::start(&mut child);
    let start = Instant::now();
    let stop = |child: &mut Child| {
        kill_group(child.id());
        let _ = child.kill();
        let _ = child.wait();
    };
    loop {
        if let Some(status) = child.try_wait()? {
            // Whatever the child started and left in its group goes too.
            kill_group(child.id());
            let (raw, stderr) = outputs.collect(Duration::from_millis(500));
            if outputs.too_much() {
                return Ok(Ran::TooMuchOutput);
            }
            return Ok(Ran::Exited {
                status,
                stdout: String::from_utf8_lossy(&raw).into_owned(),
                raw,
                stderr,
            });
        }
        if cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
            stop(&mut child);
            return Ok(Ran::Cancelled);
        }
        if outputs.too_much() {
            stop(&mut child);
            return Ok(Ran::TooMuchOutput);
        }
        if limit.is_some_and(|l| l.reached(child.id(), start.elapsed())) {
            stop(&mut child);
            let (_, stderr) = outputs.collect(Duration::from_millis(200));
            return Ok(Ran::TimedOut { stderr });
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
    // A backtrace (RUST_BACKTRACE) is the grader's, not the student's story.
    let tail: Vec<&str> = stderr
        .lines()
        .take_while(|l| !l.starts_with("stack backtrace:"))
        .filter(|l| !l.starts_with(PROGRESS) && !l.starts_with("note: "))
        .collect();
    let tail = tail[tail.len().saturating_sub(3)..].join(" / ");
    let what = if stderr.contains("memory allocation of") {
        format!(
            "ran out of memory and was stopped (a check may use {} GiB)",
            Limits::for_timeout(1.0).memory >> 30
        )
    } else if status.success() {
        "the check's process exited before the check gave its verdict (does your code \
         call process::exit?)"
            .to_string()
    } else {
        format!("the check's process crashed ({status})")
    };
    format!(
        "{what}{}{}",
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
