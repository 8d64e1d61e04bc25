//! What `cargo run --release` prints without the terminal UI: one line per
//! chapter (what it rendered, how long it took, its error against its
//! reference where it has one, the image written), then chapter 6's Cornell
//! box rendered clean with the best estimator, with its preview. The full
//! reports and studies are behind `--report` and the chapter binaries.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use crate::ch6_global_illumination::stage::DEFAULT as CH6;
use crate::core::error::{Error, Result};
use crate::core::format::{format_number, format_seconds};
use crate::core::preview::{preview, PreviewStyle};
use crate::core::run::run_headless;
use crate::core::stage::{Chapter, Settings};
use crate::scene::Scene;

/// Samples per pixel of the clean chapter 6 render unless `--spp` says
/// otherwise: on the 256x256 Cornell box an RMSE below two hundredths
/// per pixel against the stored 16,384-spp reference, in seconds on 2 cores.
pub const CLEAN_SPP: u32 = 32;

/// Where long work reports how far it is (the main binary draws a
/// progress bar on a terminal; the default does nothing).
pub trait Progress {
    /// Work of `total` steps called `what` begins.
    fn begin(&mut self, what: &str, total: u64) {
        let _ = (what, total);
    }
    /// `done` of the steps are done.
    fn advance(&mut self, done: u64) {
        let _ = done;
    }
    /// The work is over.
    fn end(&mut self) {}
}

/// Reports nothing.
pub struct NoProgress;

impl Progress for NoProgress {}

/// What the clean render came to.
#[derive(Clone, Debug)]
pub struct Clean {
    /// Samples per pixel.
    pub spp: u32,
    /// Seconds of rendering.
    pub seconds: f64,
    /// RMSE against the stored reference, when there is one at this size.
    pub rmse: Option<f64>,
    /// The render's own noise estimate.
    pub noise: Option<f64>,
    /// The PNG and EXR written.
    pub files: Vec<PathBuf>,
    /// The image.
    pub image: crate::core::film::Film,
}

fn io(e: std::io::Error) -> Error {
    Error::io(Path::new("<stdout>"), e)
}

/// One line per chapter on `scene`, then the clean chapter 6 render of it
/// (`clean_spp` samples per pixel), written to `w`; images into `out`.
pub fn summarise(
    scene: &Scene,
    out: &Path,
    clean_spp: u32,
    preview_width: u32,
    w: &mut dyn Write,
    progress: &mut dyn Progress,
) -> Result<Option<Clean>> {
    let (width, height) = (scene.camera.width, scene.camera.height);
    writeln!(
        w,
        "raystep: every chapter on {} ({width}x{height}); images in {}\n\
         (RMSE: against the stored reference, where there is one)",
        scene.name,
        out.display()
    )
    .map_err(io)?;
    for chapter in crate::chapters::all() {
        writeln!(w, "{}", chapter_line(chapter, scene, out)?).map_err(io)?;
    }
    let clean = match clean_render(scene, out, clean_spp, progress) {
        // A scene chapter 6 cannot render (no meshes): said, not failed.
        Err(Error::Usage(why)) => {
            writeln!(w, "\nch6 clean: refused: {why}").map_err(io)?;
            return Ok(None);
        }
        other => other?,
    };
    let rmse = clean
        .rmse
        .map_or("no stored reference at this size".into(), |e| {
            format!("RMSE {} against the stored reference", format_number(e))
        });
    writeln!(
        w,
        "\nch6 clean: {} spp, MIS + low-discrepancy (Sobol) numbers, 16 bounces, {}\n  \
         {rmse}, noise estimate {}",
        clean.spp,
        format_seconds(clean.seconds),
        clean.noise.map_or("-".into(), format_number),
    )
    .map_err(io)?;
    write!(
        w,
        "{}",
        preview(&clean.image, preview_width, PreviewStyle::for_stdout())
    )
    .map_err(io)?;
    writeln!(
        w,
        "wrote: {}\nfull reports and studies: --report (or cargo run --release --bin chN)\n\
         the terminal UI: run raystep in a terminal",
        clean
            .files
            .iter()
            .map(|f| f.display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    )
    .map_err(io)?;
    Ok(Some(clean))
}

/// "ch3 ray-triangle  depth + 3 views  34.1 ms  -  out/…png": name, views,
/// time, RMSE against the stored reference (or "-" without one), image.
fn chapter_line(chapter: &dyn Chapter, scene: &Scene, out: &Path) -> Result<String> {
    let info = chapter.info();
    let name = format!("ch{} {}", info.number, info.slug);
    let settings = Settings::default();
    let summary = match run_headless(
        chapter,
        scene.clone(),
        &settings,
        out,
        16,
        &mut std::io::sink(),
    ) {
        // With default settings, a usage error is the stage refusing the
        // scene (`Chapter::start`): a line saying why, and on to the next.
        Err(Error::Usage(why)) => return Ok(format!("{name:<23} refused: {why}")),
        other => other?,
    };
    let views = info.views;
    let what = match views.len() {
        0 | 1 => views.first().map_or("image", |v| v.name).to_string(),
        2 => format!("{} + 1 view", views[0].name),
        n => format!("{} + {} views", views[0].name, n - 1),
    };
    let error = match summary.rmse {
        Some(e) => format!("RMSE {}", format_number(e)),
        None => "-".into(),
    };
    let sampled = if info.progressive {
        format!(", {} spp", settings.spp)
    } else {
        String::new()
    };
    Ok(format!(
        "{name:<23} {:<24} {:>9}  {error:<12} {}",
        format!("{what}{sampled}"),
        format_seconds(summary.seconds),
        summary
            .files
            .first()
            .map(|f| f.display().to_string())
            .unwrap_or_default(),
    ))
}

/// Chapter 6 with its defaults (MIS, Sobol, 16 bounces) to `spp` samples
/// per pixel; writes `ch6-<scene>-clean.png` and `.exr`.
pub fn clean_render(
    scene: &Scene,
    out: &Path,
    spp: u32,
    progress: &mut dyn Progress,
) -> Result<Clean> {
    let mut stage = CH6;
    stage.layers = false;
    let settings = Settings {
        spp: spp.max(1),
        ..Settings::default()
    };
    let t = Instant::now();
    let mut render = stage.start(Arc::new(scene.clone()), &settings)?;
    progress.begin("ch6 clean render (spp)", settings.spp as u64);
    loop {
        let pass = render.pass();
        progress.advance(pass.samples as u64);
        if pass.complete {
            break;
        }
    }
    progress.end();
    let seconds = t.elapsed().as_secs_f64();
    let snapshot = render.snapshot();
    let image = snapshot.views[0].clone();
    let stem = format!("ch6-{}-clean", scene.name);
    let files = vec![
        out.join(format!("{stem}.png")),
        out.join(format!("{stem}.exr")),
    ];
    image.write_png(&files[0])?;
    image.write_exr(&files[1])?;
    Ok(Clean {
        spp: snapshot.pass.samples,
        seconds,
        rmse: snapshot.error_series.last().map(|p| p.1),
        noise: snapshot.pass.noise.map(|(n, _)| n),
        files,
        image,
    })
}
