//! `cargo run --release --bin fuzz -- --cases 1000000 [--seed S] [--start N]
//! [--threads T]`: runs that many fuzz cases (see `raystep::fuzz`) in
//! chunks, printing the counts as it goes and at the end: clean errors,
//! successes, panics, and cases slower than one second. On a shared,
//! loaded machine wall-clock time inflates, so every slow case is run again
//! alone, after its chunk, and counted as "slow alone" if it still takes
//! over a second. Exit status 1 if any case panicked or was slow alone;
//! re-run one case with `--case N`.
//!
//! `--structured` runs the structure-aware fuzzer instead (see
//! `raystep::fuzz::tree` and `raystep::fuzz::process`): every case in a
//! child process under `--timeout SECONDS` (default 10) and `--memory-mib
//! M` (default 1024), `--jobs J` at a time; it counts clean errors,
//! successes, panics, hangs, out-of-memory ends, signals and odd exits,
//! prints every finding with the command that replays it, and exits with
//! status 1 if there was one. `--structured --case N` shows case N and
//! runs it the same way. The hidden `--run-case SEED INDEX` is the child.

use std::process::ExitCode;
use std::time::Instant;

/// `println!` that never panics: when stdout is closed (`fuzz | head`),
/// the program ends quietly with 141, the status of a process a broken
/// pipe ends.
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        if writeln!(std::io::stdout(), $($arg)*).is_err() {
            std::process::exit(141);
        }
    }};
}

use raystep::fuzz::process::{child_main, run_one, CaseLimits, Report};
use raystep::fuzz::tree::structured_case;
use raystep::fuzz::{case, run_case, run_index, run_range, Tally, SLOW_SECONDS};

fn main() -> ExitCode {
    let (mut cases, mut seed, mut start, mut threads, mut one) =
        (10_000u64, 0u64, 0u64, 0usize, None);
    let (mut structured, mut timeout, mut memory_mib) = (false, 10u64, 1024u64);
    let (mut child, mut self_test) = (None, None::<String>);
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = |name: &str| -> u64 {
            match args.next().and_then(|v| v.parse().ok()) {
                Some(v) => v,
                None => {
                    eprintln!("error: `{name}` needs a non-negative integer");
                    std::process::exit(2)
                }
            }
        };
        match a.as_str() {
            "--cases" => cases = value("--cases"),
            "--seed" => seed = value("--seed"),
            "--start" => start = value("--start"),
            "--threads" => threads = value("--threads") as usize,
            "--case" => one = Some(value("--case")),
            "--structured" => structured = true,
            "--jobs" => threads = value("--jobs") as usize,
            "--timeout" => timeout = value("--timeout"),
            "--memory-mib" => memory_mib = value("--memory-mib"),
            "--run-case" => child = Some((value("--run-case"), value("--run-case"))),
            "--self-test" => self_test = args.next(),
            _ => {
                eprintln!(
                    "usage: fuzz [--structured] [--cases N] [--seed S] [--start N] \
                     [--threads T | --jobs J] [--case N] [--timeout SECONDS] [--memory-mib M]"
                );
                return ExitCode::from(2);
            }
        }
    }
    if let Some((seed, index)) = child {
        child_main(seed, index, memory_mib << 20, self_test.as_deref());
        return ExitCode::SUCCESS;
    }
    if structured {
        let limits = CaseLimits {
            timeout: std::time::Duration::from_secs(timeout.max(1)),
            memory: memory_mib << 20,
        };
        return run_structured(seed, start, cases, one, threads, &limits);
    }
    if let Some(i) = one {
        let c = case(seed, i);
        let head = |t: &str| -> String { t.chars().take(4000).collect() };
        say!(
            "--- scene ({} bytes; chapter index {}) ---\n{}\n--- obj ({} bytes) ---\n{}",
            c.scene.len(),
            c.chapter,
            head(&c.scene),
            c.obj.len(),
            head(&c.obj)
        );
        let t = Instant::now();
        let result = run_case(&c);
        say!(
            "--- {:?} in {:.3} s",
            result.map(|_| "rendered"),
            t.elapsed().as_secs_f64()
        );
        return ExitCode::SUCCESS;
    }
    if threads > 0 {
        let _ = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build_global();
    }
    let began = Instant::now();
    let mut total = Tally::default();
    let (mut slow_alone, mut slowest_alone) = (Vec::new(), (0.0f64, 0u64));
    let chunk = 10_000u64;
    let mut at = start;
    while at < start + cases {
        let end = (at + chunk).min(start + cases);
        let tally = run_range(seed, at..end);
        for &i in &tally.slow_cases {
            let (_, seconds) = run_index(seed, i);
            if seconds > slowest_alone.0 {
                slowest_alone = (seconds, i);
            }
            if seconds > SLOW_SECONDS {
                slow_alone.push(i);
            }
        }
        total = total.merge(tally);
        at = end;
        let secs = began.elapsed().as_secs_f64();
        eprintln!(
            "{} cases in {secs:.0} s ({:.0}/s): {} errors, {} successes, {} panics, {} slow under load ({} slow alone, slowest re-run {:.3} s); slowest {:.3} s (case {})",
            total.cases, total.cases as f64 / secs, total.errors, total.successes, total.panics, total.slow, slow_alone.len(), slowest_alone.0, total.slowest.0, total.slowest.1
        );
    }
    let secs = began.elapsed().as_secs_f64();
    say!(
        "fuzz: seed {seed}, cases {start}..{}: {} clean errors, {} successes, {} panics, {} slow (> 1 s) under load, {} still slow run alone (slowest re-run {:.3} s, case {}); slowest under load {:.3} s (case {}); {secs:.0} s, {:.0} cases/s",
        start + cases, total.errors, total.successes, total.panics, total.slow, slow_alone.len(), slowest_alone.0, slowest_alone.1, total.slowest.0, total.slowest.1, total.cases as f64 / secs
    );
    if !slow_alone.is_empty() {
        say!("slow even alone: {slow_alone:?}");
    }
    if !total.bad.is_empty() {
        say!(
            "panicking or slow cases (re-run with --case N): {:?}",
            total.bad
        );
    }
    if total.panics > 0 || !slow_alone.is_empty() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// The command that replays case `index` of `seed`.
fn replay(seed: u64, index: u64, limits: &CaseLimits) -> String {
    format!(
        "cargo run --release --bin fuzz -- --structured --seed {seed} --case {index} \
         --timeout {} --memory-mib {}",
        limits.timeout.as_secs(),
        limits.memory >> 20
    )
}

/// `--structured`: one case shown and run (`one`), or `cases` cases from
/// `start` in child processes, `jobs` at a time.
fn run_structured(
    seed: u64,
    start: u64,
    cases: u64,
    one: Option<u64>,
    jobs: usize,
    limits: &CaseLimits,
) -> ExitCode {
    let exe = match std::env::current_exe() {
        Ok(exe) => exe,
        Err(e) => {
            eprintln!("error: cannot find this program to run its cases: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(i) = one {
        let c = structured_case(seed, i);
        let head = |t: &str| -> String { t.chars().take(4000).collect() };
        say!(
            "--- edits: {}\n--- chapter index {}, {}x{}, {} spp\n--- scene ({} bytes) ---\n{}\n--- obj ({} bytes) ---\n{}",
            c.edits.join("; "),
            c.case.chapter,
            c.width,
            c.height,
            c.spp,
            c.case.scene.len(),
            head(&c.case.scene),
            c.case.obj.len(),
            head(&c.case.obj)
        );
        let t = Instant::now();
        let (class, detail) = run_one(&exe, seed, i, limits, None);
        say!(
            "--- {} in {:.3} s: {detail}",
            class.label(),
            t.elapsed().as_secs_f64()
        );
        return if class.is_finding() {
            ExitCode::from(1)
        } else {
            ExitCode::SUCCESS
        };
    }
    let jobs = if jobs > 0 {
        jobs
    } else {
        std::thread::available_parallelism().map_or(1, |n| n.get())
    };
    let progress = |r: &Report| eprintln!("{}", r.summary());
    let r = raystep::fuzz::process::run_range(
        &exe,
        seed,
        start..start + cases,
        jobs,
        limits,
        1000,
        &progress,
    );
    say!(
        "fuzz --structured: seed {seed}, cases {start}..{}, {jobs} at a time, limits {:?} and {} MiB: {}",
        start + cases,
        limits.timeout,
        limits.memory >> 20,
        r.summary()
    );
    for (i, class, detail) in &r.findings {
        say!(
            "{}: case {i}: {detail}\n  replay: {}",
            class.label(),
            replay(seed, *i, limits)
        );
    }
    if r.findings.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
