//! `cargo run --release --bin fuzz -- --cases 1000000 [--seed S] [--start N]
//! [--threads T]`: runs that many fuzz cases (see `raystep::fuzz`) in
//! chunks, printing the counts as it goes and at the end: clean errors,
//! successes, panics, and cases slower than one second. Exit status 1 if any
//! case panicked or was slow; re-run one case with `--case N`.

use std::process::ExitCode;
use std::time::Instant;

use raystep::fuzz::{case, run_case, run_range, Tally};

fn main() -> ExitCode {
    let (mut cases, mut seed, mut start, mut threads, mut one) =
        (10_000u64, 0u64, 0u64, 0usize, None);
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
            _ => {
                eprintln!(
                    "usage: fuzz [--cases N] [--seed S] [--start N] [--threads T] [--case N]"
                );
                return ExitCode::from(2);
            }
        }
    }
    if let Some(i) = one {
        let c = case(seed, i);
        let head = |t: &str| -> String { t.chars().take(4000).collect() };
        println!(
            "--- scene ({} bytes; chapter index {}) ---\n{}\n--- obj ({} bytes) ---\n{}",
            c.scene.len(),
            c.chapter,
            head(&c.scene),
            c.obj.len(),
            head(&c.obj)
        );
        let t = Instant::now();
        let result = run_case(&c);
        println!(
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
    let chunk = 10_000u64;
    let mut at = start;
    while at < start + cases {
        let end = (at + chunk).min(start + cases);
        total = total.merge(run_range(seed, at..end));
        at = end;
        let secs = began.elapsed().as_secs_f64();
        eprintln!(
            "{} cases in {secs:.0} s ({:.0}/s): {} errors, {} successes, {} panics, {} slow; slowest {:.3} s (case {})",
            total.cases, total.cases as f64 / secs, total.errors, total.successes, total.panics, total.slow, total.slowest.0, total.slowest.1
        );
    }
    let secs = began.elapsed().as_secs_f64();
    println!(
        "fuzz: seed {seed}, cases {start}..{}: {} clean errors, {} successes, {} panics, {} slow (> 1 s); slowest {:.3} s (case {}); {secs:.0} s, {:.0} cases/s",
        start + cases, total.errors, total.successes, total.panics, total.slow, total.slowest.0, total.slowest.1, total.cases as f64 / secs
    );
    if !total.bad.is_empty() {
        println!(
            "panicking or slow cases (re-run with --case N): {:?}",
            total.bad
        );
    }
    if total.panics > 0 || total.slow > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
