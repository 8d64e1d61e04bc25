//! Running a chapter without a terminal UI: parse the common flags, load the
//! scene, render every pass, write the images and the report's CSV, print a
//! preview and the report. Every chapter binary's `main` is one call to
//! [`chapter_main`].

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;

use clap::Parser;

use crate::core::error::{Error, Result};
use crate::core::film::OutputSet;
use crate::core::preview::{preview, PreviewStyle};
use crate::core::report::{Report, Times};
use crate::core::stage::{Chapter, ChapterInfo, Settings, Snapshot};
use crate::core::text::{escape, escape_keep_newlines};
use crate::scene::camera::MAX_RESOLUTION;
use crate::scene::obj::DEFAULT_MAX_TRIANGLES;
use crate::scene::{Limits, Scene, DEFAULT_MAX_FILE_BYTES};

/// Flags every chapter binary takes.
#[derive(Clone, Debug, clap::Args)]
pub struct CommonArgs {
    /// Scene file (TOML); the built-in Cornell box when omitted.
    #[arg(long, value_name = "FILE")]
    pub scene: Option<PathBuf>,
    /// Image width in pixels (overrides the scene).
    #[arg(long, allow_negative_numbers = true, value_parser = pixels)]
    pub width: Option<u32>,
    /// Image height in pixels (overrides the scene).
    #[arg(long, allow_negative_numbers = true, value_parser = pixels)]
    pub height: Option<u32>,
    /// Samples per pixel, for chapters that sample (1 to 1,000,000).
    #[arg(long, default_value_t = 1, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=MAX_SPP as i64))]
    pub spp: u32,
    /// Seed for every random number.
    #[arg(long, default_value_t = 0, allow_negative_numbers = true)]
    pub seed: u64,
    /// Output folder for images and CSV files.
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// Also run the error-against-time and stability studies.
    #[arg(long)]
    pub report: bool,
    /// Worker threads (default: all cores; at most 4 per core). Output does
    /// not depend on it.
    #[arg(long, allow_negative_numbers = true)]
    pub threads: Option<usize>,
    /// Width of the printed preview in characters (1 to 4096).
    #[arg(long, default_value_t = 64, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub preview_width: u32,
    /// Largest scene or OBJ file read, in MiB (1 to 1024: a file is read
    /// whole, in one piece).
    #[arg(long, value_name = "MIB", default_value_t = DEFAULT_MAX_FILE_BYTES >> 20,
          allow_negative_numbers = true, value_parser = clap::value_parser!(u64).range(1..=1 << 10))]
    pub max_file_mib: u64,
    /// Most triangles a scene may hold.
    #[arg(long, default_value_t = DEFAULT_MAX_TRIANGLES, allow_negative_numbers = true)]
    pub max_triangles: usize,
}

/// An image size from the command line, 1 to [`MAX_RESOLUTION`] pixels.
fn pixels(s: &str) -> std::result::Result<u32, String> {
    match s.parse::<i64>() {
        Ok(v) if (1..=MAX_RESOLUTION as i64).contains(&v) => Ok(v as u32),
        _ => Err(format!("must be between 1 and {MAX_RESOLUTION} pixels")),
    }
}

/// The most samples per pixel a run may ask for.
pub const MAX_SPP: u32 = 1_000_000;
/// Runs of more samples (samples per pixel × pixels) than this are refused.
pub const MAX_SAMPLES: u64 = 1 << 40;
/// Runs of more samples than this get a warning with a time estimate.
pub const WARN_SAMPLES: u64 = 1 << 30;
/// A rough rate for the warning's estimate: path samples per second per
/// core on a laptop (chapter 6, Cornell box).
const SAMPLES_PER_CORE_SECOND: f64 = 2e6;

#[derive(Parser)]
struct ChapterCli {
    #[command(flatten)]
    common: CommonArgs,
}

impl CommonArgs {
    /// The stage settings these flags ask for.
    pub fn settings(&self) -> Settings {
        Settings {
            width: self.width,
            height: self.height,
            spp: self.spp,
            seed: self.seed,
            studies: self.report,
            variant: None,
            rows: None,
            scale: None,
        }
    }

    /// The limits `--max-file-mib` and `--max-triangles` set.
    pub fn limits(&self) -> Limits {
        Limits {
            max_file_bytes: self.max_file_mib << 20,
            max_triangles: self.max_triangles,
        }
    }

    /// The scene the flags name, or the built-in one.
    pub fn load_scene(&self) -> Result<Scene> {
        match &self.scene {
            Some(path) => Scene::load_with(path, &self.limits()),
            None => Ok(Scene::builtin()),
        }
    }

    /// [`CommonArgs::load_scene`] at the size `--width` and `--height` ask
    /// for (the scene's own where they are missing).
    pub fn load_sized_scene(&self) -> Result<Scene> {
        sized(self.load_scene()?, self.width, self.height)
    }
}

/// The most worker threads a run may ask for: 4 per core (at least 8).
pub fn max_threads() -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    (4 * cores).max(8)
}

/// Sets the size of rayon's global pool (once per process), and installs
/// the signal clean-up ([`clean_up_on_signals`]): every headless
/// entry point calls this first.
pub fn init_threads(threads: Option<usize>) -> Result<()> {
    if let Some(n) = threads {
        let max = max_threads();
        if n == 0 || n > max {
            return Err(Error::Usage(format!(
                "`--threads` must be between 1 and {max} (4 per core, at least 8), got {n}"
            )));
        }
        // A second call in the same process keeps the first pool; fine.
        let _ = rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global();
    }
    // Every worker allocates once now (the signal thread does before
    // `clean_up_on_signals` returns), so the allocator's per-thread arenas
    // (address space reserved on a first allocation) are mapped before any
    // memory check reads what is left, however fast the threads started.
    rayon::broadcast(|_| drop(std::hint::black_box(Box::new(0u8))));
    clean_up_on_signals();
    Ok(())
}

/// What one headless run produced.
#[derive(Clone, Debug)]
pub struct RunSummary {
    /// Images and CSV files written.
    pub files: Vec<PathBuf>,
    /// Wall-clock seconds of the render (not the studies).
    pub seconds: f64,
    /// Whether every stiff case came out as expected.
    pub stable: bool,
    /// The main image's error against the stage's reference, where it has
    /// one: the last point of its error series (at the reference's
    /// resolution), else the RMSE pixel by pixel.
    pub rmse: Option<f64>,
}

/// Renders `scene` with `chapter` to completion, writes its outputs into
/// `out`, and prints preview and report to `w`.
pub fn run_headless(
    chapter: &dyn Chapter,
    scene: Scene,
    settings: &Settings,
    out: &Path,
    preview_width: u32,
    w: &mut dyn Write,
) -> Result<RunSummary> {
    let info = chapter.info();
    let scene = sized(scene, settings.width, settings.height)?;
    check_samples(
        &scene,
        settings.spp.saturating_add(info.extra_spp),
        info.radiance,
    )?;
    if let Some(rows) = crate::core::bands::plan(&info, &scene) {
        return run_banded(chapter, scene, settings, out, preview_width, rows, w);
    }
    info.check_memory(&scene)?;
    let stem = output_stem(info.number, &scene.name);
    let start = Instant::now();
    let mut render = chapter.start(Arc::new(scene), settings)?;
    let show_progress = std::io::stderr().is_terminal();
    let mut shown = false;
    loop {
        let pass = render.pass();
        if show_progress && start.elapsed().as_secs_f64() > 1.0 {
            eprint!("\r{}: pass {}/{}  ", escape(&stem), pass.done, pass.planned);
            shown = true;
        }
        if pass.complete {
            break;
        }
    }
    if shown {
        eprintln!();
    }
    let seconds = start.elapsed().as_secs_f64();

    // Every output of the run appears together or not at all.
    let snapshot = render.snapshot();
    let report = render.report();
    let set = OutputSet::begin();
    let files = write_outputs(&info, &snapshot, &report, out, &stem)?;
    set.commit()?;
    print_run(w, &snapshot.views[0], preview_width, &report, &files)?;
    Ok(RunSummary {
        rmse: snapshot.rmse(),
        files,
        seconds,
        stable: report.all_stable(),
    })
}

/// [`run_headless`] in bands of `rows_per_band` rows
/// ([`crate::core::bands`]): for a `scene` at its final size whose pixels do
/// not fit in memory at once.
pub fn run_banded(
    chapter: &dyn Chapter,
    scene: Scene,
    settings: &Settings,
    out: &Path,
    preview_width: u32,
    rows_per_band: u32,
    w: &mut dyn Write,
) -> Result<RunSummary> {
    let stem = output_stem(chapter.info().number, &scene.name);
    let run =
        crate::core::bands::render_in_bands(chapter, scene, settings, out, &stem, rows_per_band)?;
    print_run(w, &run.preview, preview_width, &run.report, &run.files)?;
    Ok(RunSummary {
        stable: run.report.all_stable(),
        files: run.files,
        seconds: run.seconds,
        rmse: None,
    })
}

/// Prints a finished run: the preview of `image` `columns` wide, the
/// report and the files written.
fn print_run(
    w: &mut dyn Write,
    image: &crate::core::film::Film,
    columns: u32,
    report: &Report,
    files: &[PathBuf],
) -> Result<()> {
    let io = |e: std::io::Error| Error::io(Path::new("<stdout>"), e);
    let style = PreviewStyle::for_stdout();
    write!(w, "{}", preview(image, columns, style)).map_err(io)?;
    // Names in the report come from the scene file: no raw control codes.
    write!(w, "{}", escape_keep_newlines(&report.to_text(Times::Show))).map_err(io)?;
    writeln!(w, "  wrote {} files:", files.len()).map_err(io)?;
    for f in files {
        writeln!(w, "    {}", escape(&f.display().to_string())).map_err(io)?;
    }
    writeln!(w).map_err(io)
}

/// The stem of a run's file names: `ch<N>-<scene>`.
pub fn output_stem(chapter: u32, scene: &str) -> String {
    format!("ch{chapter}-{scene}")
}

/// Writes what a finished run shows into `out`: every view of the
/// snapshot as a PNG (`<stem>.png`, `<stem>-<view>.png`; the main image
/// also as EXR when it holds radiance), the report's CSV tables and its
/// figures. Returns the paths written, in that order.
pub fn write_outputs(
    info: &ChapterInfo,
    snapshot: &Snapshot,
    report: &Report,
    out: &Path,
    stem: &str,
) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for (i, (view, film)) in info.views.iter().zip(&snapshot.views).enumerate() {
        let name = if i == 0 {
            stem.to_string()
        } else {
            format!("{stem}-{}", view.name)
        };
        let png = out.join(format!("{name}.png"));
        film.write_png(&png)?;
        files.push(png);
        if i == 0 && info.radiance {
            let exr = out.join(format!("{name}.exr"));
            film.write_exr(&exr)?;
            files.push(exr);
        }
    }
    for figure in &report.figures {
        files.push(figure.write(out)?);
    }
    report.write_csv(out, stem)?;
    if report.error_vs_time.is_some() {
        files.push(out.join(format!("{stem}.csv")));
    }
    if !report.stability.is_empty() {
        files.push(out.join(format!("{stem}-stability.csv")));
    }
    Ok(files)
}

/// Refuses more than [`MAX_SAMPLES`] samples, and warns (on stderr, with a
/// rough time estimate) above [`WARN_SAMPLES`]; the pass counter shows the
/// progress. Only chapters that sample radiance take `spp` (the settings'
/// and the stage's [`ChapterInfo::extra_spp`] together).
fn check_samples(scene: &Scene, spp: u32, samples_radiance: bool) -> Result<()> {
    let pixels = scene.camera.width as u64 * scene.camera.height as u64;
    let spp = if samples_radiance { spp as u64 } else { 1 };
    let samples = pixels * spp;
    if samples > MAX_SAMPLES {
        return Err(Error::Usage(format!(
            "{spp} samples per pixel x {pixels} pixels = {samples} samples, more than the limit of {MAX_SAMPLES} (2^40); lower --spp or the size"
        )));
    }
    if samples > WARN_SAMPLES {
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        let seconds = samples as f64 / (SAMPLES_PER_CORE_SECOND * cores as f64);
        eprintln!(
            "warning: {samples} samples ({spp} per pixel x {pixels} pixels) may take about {:.0} minutes on {cores} cores; progress is shown per pass",
            seconds / 60.0
        );
    }
    Ok(())
}

/// `scene` at `width` x `height`, each the scene's own where `None`.
fn sized(scene: Scene, width: Option<u32>, height: Option<u32>) -> Result<Scene> {
    match (width, height) {
        (None, None) => Ok(scene),
        (w, h) => {
            let (w0, h0) = (scene.camera.width, scene.camera.height);
            scene.with_resolution(w.unwrap_or(w0), h.unwrap_or(h0))
        }
    }
}

/// The command line as `T`, or the process ends with clap's message (a
/// bad flag or value, `--help`, `--version`) and its exit code. clap
/// quotes the arguments as given, and a file name may hold escape
/// sequences (`--scene dir/*.toml` picks up every name in a folder): the
/// message is printed without clap's colours and with every control
/// character escaped.
pub fn parse_args<T: Parser>() -> T {
    match T::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // The message of the same arguments with their control
            // characters written out (`\u{1b}`), so that they show instead
            // of acting on the terminal or vanishing with clap's colours.
            let shown = std::env::args_os().map(|a| escape(&a.to_string_lossy()).into_owned());
            let e = T::try_parse_from(shown).err().unwrap_or(e);
            let text = e.render().to_string();
            let text = escape_keep_newlines(&text);
            // A closed stream is no reason to panic: the exit code says it.
            let _ = if e.use_stderr() {
                std::io::stderr().lock().write_all(text.as_bytes())
            } else {
                std::io::stdout().lock().write_all(text.as_bytes())
            };
            std::process::exit(e.exit_code())
        }
    }
}

/// The whole `main` of a chapter binary.
pub fn chapter_main(chapter: &dyn Chapter) -> ExitCode {
    let cli: ChapterCli = parse_args();
    exit_code(run_with(chapter, &cli.common))
}

/// Sets the threads, loads the scene the flags name and runs `chapter` on
/// it headless, printing to stdout. The common part of every chapter's
/// `main`, including those with flags of their own.
pub fn run_with(chapter: &dyn Chapter, common: &CommonArgs) -> Result<RunSummary> {
    init_threads(common.threads)?;
    run_on(chapter, common.load_scene()?, common)
}

/// [`run_with`] on a scene the chapter's `main` has loaded already (to look
/// at it first); the threads are set up by then.
pub fn run_on(chapter: &dyn Chapter, scene: Scene, common: &CommonArgs) -> Result<RunSummary> {
    let mut stdout = std::io::stdout().lock();
    run_headless(
        chapter,
        scene,
        &common.settings(),
        &common.out,
        common.preview_width,
        &mut stdout,
    )
}

/// From now on SIGINT, SIGTERM and SIGHUP (the terminal closed) let the
/// file being written finish, remove every temporary file and exit with
/// 130, 143 or 129, so an interrupted run leaves no debris and no partial
/// set of outputs. Once per process; nothing on platforms without signals.
pub fn clean_up_on_signals() {
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        static ONCE: std::sync::Once = std::sync::Once::new();
        ONCE.call_once(|| {
            let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])
            else {
                return;
            };
            let (ready, started) = std::sync::mpsc::channel();
            std::thread::spawn(move || {
                let _ = ready.send(Box::new(0u8)); // its arena, mapped now
                if let Some(signal) = signals.forever().next() {
                    crate::core::film::remove_temporaries_and_exit(128 + signal);
                }
            });
            let _ = started.recv();
        });
    }
}

/// Success, or the error on stderr and exit status 2. When a signal is
/// stopping the run (its error is then "interrupted"), the signal's own
/// exit status wins: this waits for the handler's exit ([`stop_code`]).
pub fn exit_code<T>(result: Result<T>) -> ExitCode {
    match result {
        Ok(_) => ExitCode::SUCCESS,
        Err(_) if crate::core::film::stopping() => stop_code(),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// What a run that a signal interrupted returns: nothing, because the
/// signal's handler exits the process with 128 + the signal once it has removed
/// the temporaries ([`clean_up_on_signals`]); the main thread must not
/// return first with an exit status of its own.
pub fn stop_code() -> ExitCode {
    loop {
        std::thread::park();
    }
}
