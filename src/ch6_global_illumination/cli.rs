//! The body of `ch6`'s `main`: a headless run like every chapter's
//! ([`crate::core::run`]) plus what only chapter 6 writes.

use std::io::Write;
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

use crate::core::error::{Error, Result};
use crate::core::preview::{preview, PreviewStyle};
use crate::core::report::{Report, Times};
use crate::core::run::{init_threads, CommonArgs};
use crate::core::stage::Render;
use crate::scene::Scene;

use super::accumulate::Accumulator;
use super::bench;
use super::figures::{plot_error_time, side_by_side, write_layers};
use super::reference::{reference_dir, StoredReference};
use super::stage::{GlobalIllumination, PathTracingRender};

/// What `ch6` was asked to do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Render the scene (and the spp figure up to this many spp).
    Render {
        /// The spp-doubling figure's largest spp.
        spp_figure: Option<u32>,
    },
    /// The benchmark table.
    Bench,
    /// Regenerate the stored Cornell-box reference.
    MakeReference,
}

fn stdout_err(e: std::io::Error) -> Error {
    Error::io(Path::new("<stdout>"), e)
}

/// Runs `ch6`.
pub fn run(stage: &GlobalIllumination, common: &CommonArgs, mode: Mode) -> Result<()> {
    stage.check()?;
    init_threads(common.threads)?;
    let mut out = std::io::stdout().lock();
    match mode {
        Mode::Bench => {
            let spp = if common.spp > 1 { common.spp } else { 64 };
            let t = bench::bench(spp, &stage.path)?;
            write!(out, "{}", t.to_text()).map_err(stdout_err)?;
            writeln!(out).map_err(stdout_err)?;
            write!(out, "{}", bench::query_bench().to_text()).map_err(stdout_err)?;
            Ok(())
        }
        Mode::MakeReference => make_reference(stage, common, &mut out),
        Mode::Render { spp_figure } => render(stage, common, spp_figure, &mut out),
    }
}

fn sized(common: &CommonArgs) -> Result<Scene> {
    let scene = common.load_scene()?;
    match (common.width, common.height) {
        (None, None) => Ok(scene),
        (w, h) => {
            let (w0, h0) = (scene.camera.width, scene.camera.height);
            scene.with_resolution(w.unwrap_or(w0), h.unwrap_or(h0))
        }
    }
}

fn render(
    stage: &GlobalIllumination,
    common: &CommonArgs,
    spp_figure: Option<u32>,
    out: &mut dyn Write,
) -> Result<()> {
    let scene = sized(common)?;
    let stem = format!("ch6-{}", scene.name);
    let dir = &common.out;
    let settings = common.settings();
    let scene = Arc::new(scene);
    let mut r = PathTracingRender::new(*stage, scene.clone(), &settings);
    while !r.pass() {}
    let mut files = Vec::new();
    let image = r.view(0);
    for (name, film) in [
        (stem.clone(), &image),
        (format!("{stem}-stderr"), &r.view(1)),
    ] {
        let png = dir.join(format!("{name}.png"));
        film.write_png(&png)?;
        files.push(png);
    }
    let exr = dir.join(format!("{stem}.exr"));
    image.write_exr(&exr)?;
    files.push(exr);
    files.extend(write_layers(&r.acc, dir, &stem)?);
    if let Some(n) = spp_figure {
        files.push(spp_strip(stage, &scene, settings.seed, n, dir, &stem)?);
    }
    let report = r.report();
    if let Some(et) = &report.error_vs_time {
        for (prefix, name) in [("cornell", "cornell"), ("furnace", "furnace")] {
            let path = dir.join(format!("{stem}-strategies-{name}.png"));
            plot_error_time(et, prefix, 480, 320).write_png(&path)?;
            files.push(path);
        }
    }
    report.write_csv(dir, &stem)?;
    if report.error_vs_time.is_some() {
        files.push(dir.join(format!("{stem}.csv")));
    }
    if !report.stability.is_empty() {
        files.push(dir.join(format!("{stem}-stability.csv")));
    }
    print_report(out, &report, &image, common.preview_width)?;
    writeln!(
        out,
        "  wrote: {}\n",
        files
            .iter()
            .map(|f| f.display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    )
    .map_err(stdout_err)?;
    if !report.all_stable() {
        return Err(Error::Usage(
            "a stiff case did not come out as expected".into(),
        ));
    }
    Ok(())
}

fn print_report(
    out: &mut dyn Write,
    report: &Report,
    image: &crate::core::film::Film,
    width: u32,
) -> Result<()> {
    write!(out, "{}", preview(image, width, PreviewStyle::for_stdout())).map_err(stdout_err)?;
    write!(out, "{}", report.to_text(Times::Show)).map_err(stdout_err)
}

/// The spp-doubling figure: one render, its image after 1, 2, 4, … `max`
/// samples per pixel side by side.
pub fn spp_strip(
    stage: &GlobalIllumination,
    scene: &Scene,
    seed: u64,
    max: u32,
    dir: &Path,
    stem: &str,
) -> Result<std::path::PathBuf> {
    let world = crate::ch5_reflection::world::World::new(scene);
    let mut acc = Accumulator::new(scene.camera.width, scene.camera.height, false);
    let mut films = Vec::new();
    let mut spp = 1;
    while spp <= max.max(1) {
        let count = spp - acc.samples;
        acc.add_samples(
            &world,
            &scene.camera,
            &stage.path,
            stage.sampler,
            seed,
            count,
        );
        let mut f = acc.mean();
        f.scrub_nonfinite();
        films.push(f);
        spp *= 2;
    }
    let path = dir.join(format!("{stem}-spp.png"));
    side_by_side(&films).write_png(&path)?;
    Ok(path)
}

fn make_reference(
    stage: &GlobalIllumination,
    common: &CommonArgs,
    out: &mut dyn Write,
) -> Result<()> {
    let scene = sized(common)?;
    let spp = common.spp.max(1);
    let t = Instant::now();
    let mut acc = Accumulator::new(scene.camera.width, scene.camera.height, false);
    let world = crate::ch5_reflection::world::World::new(&scene);
    let chunk = 256;
    while acc.samples < spp {
        let count = chunk.min(spp - acc.samples);
        acc.add_samples(
            &world,
            &scene.camera,
            &stage.path,
            stage.sampler,
            common.seed,
            count,
        );
        eprint!("\rreference: {}/{spp} spp", acc.samples);
    }
    eprintln!();
    let secs = t.elapsed().as_secs_f64();
    let meta = format!(
        "scene = {}\ntriangles = {}\nwidth = {}\nheight = {}\nspp = {spp}\nseed = {}\n\
         estimator = {}\nsampler = {}\nmax_bounces = {}\nrr_after = {}\npaths = {}\nseconds = {secs:.1}\n\
         threads = {}\ncommand = cargo run --release --bin ch6 -- --make-reference --width {} --height {} --spp {spp} --seed {} \
         --estimator {} --sampler {} {} --rr-after {}\n",
        scene.name,
        scene.triangle_count(),
        acc.width,
        acc.height,
        common.seed,
        stage.path.estimator.name(),
        stage.sampler.name(),
        stage.path.max_bounces.map_or("unlimited".into(), |k| k.to_string()),
        stage.path.rr_min_scatterings,
        acc.stats.paths,
        rayon::current_num_threads(),
        acc.width,
        acc.height,
        common.seed,
        stage.path.estimator.name(),
        stage.sampler.name(),
        stage
            .path
            .max_bounces
            .map_or("--unlimited".into(), |k| format!("--max-bounces {k}")),
        stage.path.rr_min_scatterings,
    );
    let name = super::reference::stem(&scene.name, acc.width, acc.height);
    let files = StoredReference::save(&acc, &reference_dir(), &name, &meta)?;
    writeln!(out, "{meta}wrote: {files:?}").map_err(stdout_err)?;
    Ok(())
}
