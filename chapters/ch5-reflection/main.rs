//! Chapter 5: radiometry, lights, BRDFs and the reflection equation.
//! `cargo run --release --bin ch5 -- --help`
//!
//! Renders direct light (with shadow rays, mirrors followed a few bounces)
//! with one of four strategies for area lights and the environment. With
//! `--report` it also runs the strategy study (table, CSV and two log-log
//! plots, `ch5-error-time-area.png` and `ch5-error-time-environment.png`)
//! and the stiff cases.

use std::process::ExitCode;

use clap::{Parser, ValueEnum};
use raystep::ch5_reflection::direct::Strategy;
use raystep::ch5_reflection::shadowing::shadow_work_warning;
use raystep::ch5_reflection::stage::{Reflection, DEFAULT};
use raystep::core::error::Result;
use raystep::core::run::{exit_code, init_threads, run_on, CommonArgs, RunSummary};
use raystep::scene::{LightSampling, Scene};

#[derive(Clone, Copy, Debug, ValueEnum)]
enum StrategyArg {
    /// Uniform hemisphere directions.
    Uniform,
    /// BRDF sampling (cosine-weighted on Lambertian surfaces); also
    /// `bsdf`, chapter 6's name for the same rung.
    #[value(alias = "bsdf")]
    Cosine,
    /// Light sampling with shadow rays.
    Light,
    /// Light and BRDF sampling combined by the power heuristic.
    Mis,
}

#[derive(Parser)]
#[command(name = "ch5", about = "Chapter 5: the reflection equation")]
struct Cli {
    #[command(flatten)]
    common: CommonArgs,
    /// How area lights and the environment are sampled.
    #[arg(long, value_enum, default_value = "mis")]
    strategy: StrategyArg,
    /// Mirror bounces followed before a mirror shows black.
    #[arg(long, default_value_t = DEFAULT.max_mirror_bounces)]
    max_mirror_bounces: u32,
    /// How area lights are sampled: a point by area, or a direction by the
    /// solid angle the light covers.
    #[arg(long, value_enum, default_value = "area")]
    light_sampling: LightSampling,
}

fn main() -> ExitCode {
    // `--student`: the chapter's capstone rendered with your exercise.
    if std::env::args().any(|a| a == "--student") {
        return raystep::grading::process::student_main(5);
    }
    let cli: Cli = raystep::core::run::parse_args();
    let stage = Reflection {
        strategy: match cli.strategy {
            StrategyArg::Uniform => Strategy::Uniform,
            StrategyArg::Cosine => Strategy::Bsdf,
            StrategyArg::Light => Strategy::Light,
            StrategyArg::Mis => Strategy::Mis,
        },
        max_mirror_bounces: cli.max_mirror_bounces,
    };
    exit_code(run(&stage, &cli.common, cli.light_sampling))
}

/// Warns about a scene whose shadow rays cost lights x SDFs before the
/// render (it may take hours), then runs it.
fn run(stage: &Reflection, common: &CommonArgs, sampling: LightSampling) -> Result<RunSummary> {
    init_threads(common.threads)?;
    let scene = Scene {
        light_sampling: sampling,
        ..common.load_sized_scene()?
    };
    let samples = scene.camera.width as u64 * scene.camera.height as u64 * common.spp as u64;
    if let Some(warning) = shadow_work_warning(&scene, samples) {
        eprintln!("{warning}");
    }
    run_on(stage, scene, common)
}
