//! `cargo run --release --bin fuzz -- --cases 1000000 [--seed S] [--start N]
//! [--threads T]`: runs that many fuzz cases (see `raystep::fuzz`) in
//! chunks, printing the counts as it goes and at the end: clean errors,
//! successes, panics, and cases slower than one second. On a shared,
//! loaded machine wall-clock time inflates, so every slow case is run again
//! alone, after its chunk, and counted as "slow alone" if it still takes
//! over a second. Exit status 1 if any case panicked or was slow alone;
//! re-run one case with `--case N`.

use std::process::ExitCode;
use std::time::Instant;

use raystep::fuzz::{case, run_case, run_index, run_range, Tally, SLOW_SECONDS};

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
    println!(
        "fuzz: seed {seed}, cases {start}..{}: {} clean errors, {} successes, {} panics, {} slow (> 1 s) under load, {} still slow run alone (slowest re-run {:.3} s, case {}); slowest under load {:.3} s (case {}); {secs:.0} s, {:.0} cases/s",
        start + cases, total.errors, total.successes, total.panics, total.slow, slow_alone.len(), slowest_alone.0, slowest_alone.1, total.slowest.0, total.slowest.1, total.cases as f64 / secs
    );
    if !slow_alone.is_empty() {
        println!("slow even alone: {slow_alone:?}");
    }
    if !total.bad.is_empty() {
        println!(
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
