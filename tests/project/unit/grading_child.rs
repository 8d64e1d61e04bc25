//! `grading::child::run_limited`: a CPU-time limit stops a loop that never
//! ends, and does not stop a child that waits without computing until four
//! times the limit; a wall-clock limit stops both at the limit; a program
//! file still open for writing somewhere is waited for, not refused.

use std::process::Command;
use std::time::{Duration, Instant};

use raystep::grading::child::{run_limited, Limit, Ran};

fn run(script: &str, limit: Limit) -> (Ran, Duration) {
    let start = Instant::now();
    let ran = run_limited(
        Command::new("sh").args(["-c", script]),
        b"",
        Some(limit),
        None,
    )
    .unwrap();
    (ran, start.elapsed())
}

#[test]
#[cfg(target_os = "linux")]
fn a_cpu_limit_stops_a_loop_and_lets_a_waiting_child_finish() {
    let half = Duration::from_millis(500);
    // A loop uses up the half second of CPU time and is stopped (on a
    // loaded machine it gets less than a core, so allow the backstop).
    let (ran, took) = run("while :; do :; done", Limit::Cpu(half));
    assert!(matches!(ran, Ran::TimedOut { .. }), "{ran:?}");
    assert!(
        took >= half && took < 4 * half + Duration::from_millis(500),
        "{took:?}"
    );
    // A child that sleeps 1 s computes for almost none of it: it is not
    // stopped at half a second, only at the backstop (2 s), which it beats.
    let (ran, took) = run("sleep 1; echo done", Limit::Cpu(half));
    match ran {
        Ran::Exited { status, stdout, .. } => {
            assert!(status.success() && stdout.trim() == "done", "{stdout}")
        }
        other => panic!("stopped after {took:?}: {other:?}"),
    }
    // One that sleeps past the backstop is stopped there.
    let (ran, took) = run("sleep 30", Limit::Cpu(Duration::from_millis(250)));
    assert!(matches!(ran, Ran::TimedOut { .. }), "{ran:?}");
    assert!(took < Duration::from_secs(10), "{took:?}");
}

#[test]
fn a_wall_clock_limit_stops_a_waiting_child_at_the_limit() {
    let (ran, took) = run("sleep 30", Limit::Wall(Duration::from_millis(300)));
    assert!(matches!(ran, Ran::TimedOut { .. }), "{ran:?}");
    assert!(took < Duration::from_secs(10), "{took:?}");
}

/// A program file that something still holds open for writing cannot be
/// started ("text file busy"): a child another thread is starting holds the
/// descriptor of a file just written until it runs its own program.
/// `run_limited` waits that out instead of failing the grade.
#[test]
#[cfg(target_os = "linux")]
fn a_program_file_briefly_open_for_writing_is_waited_for() {
    let dir = crate::common::temp_dir("busy-program");
    let program = dir.join("true");
    std::fs::copy("/bin/true", &program).unwrap();
    let writer = std::fs::File::options().write(true).open(&program).unwrap();
    let held = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(200));
        drop(writer);
    });
    let ran = run_limited(&mut Command::new(&program), b"", None, None);
    held.join().unwrap();
    assert!(
        matches!(ran, Ok(Ran::Exited { ref status, .. }) if status.success()),
        "{ran:?}"
    );
}
