//! Chapter 6: global illumination by Monte Carlo path tracing.
//! `cargo run --release --bin ch6 -- --help`
//!
//! Path-traces a scene and writes the image (PNG and EXR), its noise, the
//! bounce strip (direct, 1, 2, 4, 8, 16 bounces) and every bounce layer as
//! EXR; prints the report. Flags add the spp-doubling figure, the
//! strategy study (`--report`), the benchmark (`--bench`) and the stored
//! Cornell-box reference (`--make-reference`).

use std::process::ExitCode;

use clap::{Parser, ValueEnum};
use raystep::ch6_global_illumination::annotate::annotate_references;
use raystep::ch6_global_illumination::engine::EngineChoice;
use raystep::ch6_global_illumination::integrator::{roulette_cannot_end, Strategy, SAFETY_BOUNCES};
use raystep::ch6_global_illumination::reference::{make_reference, reference_dir};
use raystep::ch6_global_illumination::sampler::SamplerKind;
use raystep::ch6_global_illumination::stage::{GlobalIllumination, DEFAULT};
use raystep::core::run::{exit_code, init_threads, run_on, CommonArgs};
use raystep::fast::bench;
use raystep::scene::{LightSampling, Scene};
use raystep::{Error, Result};

#[derive(Clone, Copy, Debug, ValueEnum)]
enum EstimatorArg {
    /// Uniform hemisphere random walk.
    Uniform,
    /// BSDF (cosine) sampling only.
    Bsdf,
    /// Light sampling without MIS.
    Light,
    /// Light and BSDF sampling, power heuristic.
    Mis,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum SamplerArg {
    /// Independent random numbers.
    Independent,
    /// Owen-scrambled Sobol.
    Sobol,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum EngineArg {
    /// The eight-wide BVH with SIMD chosen at run time, and on triangle
    /// scenes a wavefront path loop (diffuse hits with MIS shaded eight at
    /// once).
    Fast,
    /// The lesson's four-wide BVH and path loop.
    Readable,
}

#[derive(Parser)]
#[command(
    name = "ch6",
    about = "Chapter 6: global illumination, bounce by bounce"
)]
struct Cli {
    #[command(flatten)]
    common: CommonArgs,
    /// The estimator.
    #[arg(long, value_enum, default_value = "mis")]
    estimator: EstimatorArg,
    /// Where the random numbers come from.
    #[arg(long, value_enum, default_value = "sobol")]
    sampler: SamplerArg,
    /// How area lights are sampled: a point by area, or a direction by the
    /// solid angle the light covers (the fast engine's lanes then leave
    /// every hit to the lesson's steps).
    #[arg(long, value_enum, default_value = "area")]
    light_sampling: LightSampling,
    /// Largest bounce count k (k + 1 scatterings); paths end there.
    #[arg(long, default_value_t = 16)]
    max_bounces: u32,
    /// No bounce limit: Russian roulette alone ends paths.
    #[arg(long)]
    unlimited: bool,
    /// Russian roulette starts after this many scatterings: it may end a
    /// path before it gathers light of this bounce count k or more.
    #[arg(long, default_value_t = 1)]
    rr_after: u32,
    /// Russian roulette's scale s: a path survives with probability
    /// min(1, s · max β), so roulette plays once β falls below 1/s
    /// (default: the sampler's own, 1 for independent numbers and 2 for
    /// Sobol points).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    rr_scale: Option<u32>,
    /// Which engine traces the paths; both trace the same paths, to the
    /// last bits of a sine (see the book's appendix "Making it fast").
    #[arg(long, value_enum, default_value = "fast")]
    engine: EngineArg,
    /// Samples per pixel in one progressive pass.
    #[arg(long, default_value_t = 4)]
    spp_per_pass: u32,
    /// Only the final image: no per-bounce layers, strip or layer EXRs.
    #[arg(long)]
    final_only: bool,
    /// Also write the spp-doubling figure: 1, 2, 4, ... up to N spp
    /// (at most the sample limit, as --spp).
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u32).range(1..=raystep::core::run::MAX_SPP as i64))]
    spp_figure: Option<u32>,
    /// Run the benchmark instead: both engines and samplers on the Cornell
    /// box (or --scene) at 256x256 (or --width/--height), 64 spp (or
    /// --spp), 16 bounces, with the RMSE against its stored reference.
    #[arg(long)]
    bench: bool,
    /// Paths per second of both engines on the Cornell box, the bunny and a
    /// 524,288-triangle mesh (128x128, 32 spp or --spp) instead.
    #[arg(long)]
    bench_scenes: bool,
    /// Render the stored Cornell-box reference into scenes/references
    /// (use with --width/--height/--spp/--seed).
    #[arg(long)]
    make_reference: bool,
    /// Record the content hash of its scene (scenes/<scene>.toml) in every
    /// stored reference's text file in scenes/references, after a change
    /// of what the hash covers that left the pictures as they were.
    #[arg(long)]
    annotate_references: bool,
}

fn main() -> ExitCode {
    // `--student`: the chapter's capstone rendered with your exercise.
    if std::env::args().any(|a| a == "--student") {
        return raystep::grading::process::student_main(6);
    }
    let cli: Cli = raystep::core::run::parse_args();
    let mut stage = DEFAULT;
    stage.path.strategy = match cli.estimator {
        EstimatorArg::Uniform => Strategy::Uniform,
        EstimatorArg::Bsdf => Strategy::Bsdf,
        EstimatorArg::Light => Strategy::Light,
        EstimatorArg::Mis => Strategy::Mis,
    };
    stage.sampler = match cli.sampler {
        SamplerArg::Independent => SamplerKind::Independent,
        SamplerArg::Sobol => SamplerKind::Sobol,
    };
    stage.path.max_bounces = (!cli.unlimited).then_some(cli.max_bounces);
    stage.path.rr_min_bounce = cli.rr_after;
    stage.path.rr_scale = cli.rr_scale;
    stage.spp_per_pass = cli.spp_per_pass;
    stage.engine = match cli.engine {
        EngineArg::Fast => raystep::fast::FAST,
        EngineArg::Readable => EngineChoice::READABLE,
    };
    stage.layers = !cli.final_only;
    stage.spp_figure = cli.spp_figure;
    exit_code(run(&stage, &cli))
}

/// `scene` with `--light-sampling`.
fn sampled(cli: &Cli, scene: Scene) -> Scene {
    Scene {
        light_sampling: cli.light_sampling,
        ..scene
    }
}

fn run(stage: &GlobalIllumination, cli: &Cli) -> Result<()> {
    stage.check()?;
    let common = &cli.common;
    if cli.bench {
        init_threads(common.threads)?;
        let spp = if common.spp > 1 { common.spp } else { 64 };
        let (w, h) = bench::SIZE;
        let scene = sampled(cli, common.load_scene()?);
        let scene = scene.with_resolution(common.width.unwrap_or(w), common.height.unwrap_or(h))?;
        let text = format!(
            "{}\n{}",
            bench::bench(spp, &stage.path, &scene)?,
            bench::query_bench(&scene).to_text()
        );
        return print(&text);
    }
    if cli.bench_scenes {
        init_threads(common.threads)?;
        let spp = if common.spp > 1 { common.spp } else { 32 };
        return print(&bench::scenes_bench(spp, &stage.path)?.to_text());
    }
    if cli.annotate_references {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let done = annotate_references(&reference_dir(), &root.join("scenes"))?;
        let list: String = done
            .iter()
            .map(|(f, hash)| format!("{}: content = {hash}\n", f.display()))
            .collect();
        return print(&list);
    }
    if cli.make_reference {
        init_threads(common.threads)?;
        let scene = sampled(cli, common.load_sized_scene()?);
        let (meta, files) = make_reference(
            stage.engine,
            &stage.path,
            stage.sampler,
            &scene,
            common.spp,
            common.seed,
        )?;
        let list: String = files
            .iter()
            .map(|f| format!("    {}\n", f.display()))
            .collect();
        return print(&format!("{meta}wrote:\n{list}"));
    }
    init_threads(common.threads)?;
    let scene = sampled(cli, common.load_scene()?);
    // Said before the render, which may take hours.
    // (With --unlimited, or a --max-bounces at or past the safety limit.)
    if stage.path.bounce_limit() >= SAFETY_BOUNCES && roulette_cannot_end(&scene) {
        eprintln!(
            "warning: every surface of {} reflects all the light it receives \
             (reflectance 1 or glass): Russian roulette cannot end these paths, only \
             leaving the scene can; in a closed scene each runs to the safety limit \
             of {SAFETY_BOUNCES} bounces. Lower a reflectance, or drop --unlimited or \
             the large --max-bounces.",
            scene.name
        );
    }
    let summary = run_on(stage, scene, common)?;
    if !summary.stable {
        return Err(Error::Usage(
            "a stiff case did not come out as expected".into(),
        ));
    }
    Ok(())
}

fn print(text: &str) -> Result<()> {
    use std::io::Write;
    std::io::stdout()
        .lock()
        .write_all(text.as_bytes())
        .map_err(|e| Error::io(std::path::Path::new("<stdout>"), e))
}
