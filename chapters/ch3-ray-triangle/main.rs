//! Chapter 3: ray-triangle intersection and a BVH.
//! `cargo run --release --bin ch3 -- --help`
//!
//! Traces the first hit of every primary ray and writes four views (depth,
//! normal, barycentrics, triangle id); `--report` adds the anti-aliasing and
//! naive-vs-BVH studies, the leak counts and the stiff cases. `ch3 --bench`
//! instead prints the throughput benchmark (BVH build, Mrays/s on 1 and 2
//! threads, raystep's stage against obvhs alone); `ch3 --bench bunny` only
//! the bunny's rows.

use std::process::ExitCode;

use clap::Parser;
use raystep::ch3_ray_triangle::bench::benchmark;
use raystep::ch3_ray_triangle::hostile::hostile_builds;
use raystep::ch3_ray_triangle::stage::DEFAULT;
use raystep::core::run::{exit_code, run_with, CommonArgs};

#[derive(Parser)]
#[command(name = "ch3", about = "Chapter 3: ray-triangle intersection and a BVH")]
struct Cli {
    #[command(flatten)]
    common: CommonArgs,
    /// Print the throughput benchmark (BVH build, Mrays/s on 1 and 2
    /// threads, the stage against obvhs alone) instead of rendering; an
    /// optional MESH keeps only the rows whose mesh name contains it;
    /// `--bench hostile` times the BVH builds on hostile geometry instead.
    #[arg(long, value_name = "MESH", num_args = 0..=1, default_missing_value = "")]
    bench: Option<String>,
}

fn main() -> ExitCode {
    // `--student`: the chapter's capstone rendered with your exercise.
    if std::env::args().any(|a| a == "--student") {
        return raystep::grading::process::student_main(3);
    }
    let cli: Cli = raystep::core::run::parse_args();
    if let Some(only) = cli.bench {
        if only == "hostile" {
            print!(
                "{}",
                hostile_builds(&[10_000, 100_000, 1_000_000]).to_text()
            );
            return ExitCode::SUCCESS;
        }
        let only = (!only.is_empty()).then_some(only.as_str());
        print!("{}", benchmark(only).to_text());
        return ExitCode::SUCCESS;
    }
    exit_code(run_with(&DEFAULT, &cli.common))
}
