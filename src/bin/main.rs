//! `cargo run --release`: the front door.
//!
//! In a terminal (stdout is a TTY, and the default `tui` feature is on) this
//! opens the terminal UI, on the chapter and scene the flags name. Piped,
//! in CI, or with `--headless` it renders every chapter on the scene and
//! prints one line per chapter, then chapter 6's Cornell box rendered clean
//! with its preview ([`raystep::summary`]); `--report` prints every
//! chapter's full report and studies instead, and `--chapter N` runs one
//! chapter with its full report. `raystep --help` lists every flag.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;

use raystep::core::run::run_headless;
use raystep::core::stage::Settings;
use raystep::scene::Scene;
use raystep::summary::{summarise, NoProgress, Progress, CLEAN_SPP};
use raystep::{Error, Result};

/// Rendering, step by step: the lecture's six chapters, from a pinhole
/// camera to Monte Carlo global illumination.
#[derive(Parser, Debug)]
#[command(name = "raystep", version)]
struct Cli {
    /// Open (or, headless, run only) chapter N, 1 to 6.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=6))]
    chapter: Option<u32>,
    /// Scene file (TOML); the built-in Cornell box when omitted.
    #[arg(long, value_name = "FILE")]
    scene: Option<PathBuf>,
    /// Samples per pixel: the budget of the terminal UI's progressive
    /// render (default 1024), the clean chapter 6 render of the headless
    /// summary (default 32), or every sampling chapter with --report or
    /// --chapter.
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u32).range(1..=raystep::core::run::MAX_SPP as i64))]
    spp: Option<u32>,
    /// Never open the terminal UI: render and print a summary.
    #[arg(long)]
    headless: bool,
    /// Headless: every chapter's full report, with its error-against-time
    /// and stability studies (slow), instead of the summary.
    #[arg(long)]
    report: bool,
    /// Where images and CSV files go (and the UI's `s` saves).
    #[arg(long, value_name = "DIR", default_value = "out")]
    out: PathBuf,
    /// The folder of scene files the UI lists (given, it must exist).
    #[arg(long, value_name = "DIR", default_value = "scenes", value_parser = scenes_folder)]
    scenes: PathBuf,
    /// How the UI draws its preview: `auto` asks the terminal (kitty
    /// graphics, sixel, its cell size) and falls back on the environment;
    /// `kitty`, `sixel`, `iterm2` force a protocol (half blocks, with a
    /// note, where it cannot work); `halfblocks` works everywhere.
    #[arg(long, value_name = "HOW", default_value = "auto",
          value_parser = ["auto", "kitty", "sixel", "iterm2", "halfblocks"])]
    graphics: String,
    /// Which engine traces chapter 6's paths in the UI and with
    /// `--chapter`/`--report`: `fast` (an eight-wide BVH with SIMD chosen at
    /// run time, and a wavefront path loop on triangle scenes) or `readable`
    /// (the lesson's code); both trace the same paths, to the last bits of a
    /// sine.
    #[arg(long, value_name = "ENGINE", default_value = "fast", value_parser = ["fast", "readable"])]
    engine: String,
    /// The same as `--graphics halfblocks`.
    #[arg(long)]
    halfblocks: bool,
    /// On quit, print the bytes the UI wrote to the terminal per second,
    /// idle and while rendering.
    #[arg(long)]
    stats: bool,
    /// Time the UI's start-up and redraws and print a table (needs the
    /// `tui` feature).
    #[arg(long)]
    bench_ui: bool,
}

/// `--scenes DIR`: a folder that exists, unless it is the default (a
/// checkout without `scenes/` just lists none).
fn scenes_folder(s: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(s);
    if s != "scenes" && !path.is_dir() {
        return Err("no such folder".into());
    }
    Ok(path)
}

fn main() -> ExitCode {
    #[cfg(feature = "tui")]
    let started = std::time::Instant::now();
    let cli: Cli = raystep::core::run::parse_args();
    if cli.bench_ui {
        #[cfg(feature = "tui")]
        {
            let mut stdout = std::io::stdout().lock();
            return match raystep::tui::bench::run(started, &cli.scenes, &mut stdout) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: {e}");
                    ExitCode::from(2)
                }
            };
        }
        #[cfg(not(feature = "tui"))]
        {
            eprintln!("error: --bench-ui needs the `tui` feature");
            return ExitCode::from(2);
        }
    }
    #[cfg(feature = "tui")]
    if !cli.headless && !cli.report && raystep::tui::should_open() {
        let launch = raystep::tui::Launch {
            scenes_dir: cli.scenes.clone(),
            out_dir: cli.out.clone(),
            chapter: cli.chapter,
            scene: cli.scene.clone(),
            spp: cli.spp,
            graphics: if cli.halfblocks {
                "halfblocks"
            } else {
                &cli.graphics
            }
            .parse()
            .unwrap_or_default(),
            stats: cli.stats,
            readable: cli.engine == "readable",
            remember: raystep::tui::last::path(&|k| std::env::var(k).ok()),
        };
        return match raystep::tui::run(&launch) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: terminal UI: {e}");
                ExitCode::from(2)
            }
        };
    }
    raystep::core::run::exit_code(headless(&cli))
}

fn headless(cli: &Cli) -> Result<()> {
    // An interrupted run leaves no temporaries and no half set of outputs,
    // as the chapter binaries do.
    raystep::core::run::clean_up_on_signals();
    let scene = match &cli.scene {
        Some(path) => Scene::load(path)?,
        None => Scene::builtin(),
    };
    let mut stdout = std::io::stdout().lock();
    if cli.report || cli.chapter.is_some() {
        let settings = Settings {
            spp: cli.spp.unwrap_or(1),
            studies: cli.report,
            ..Settings::default()
        };
        for chapter in raystep::chapters::with_engine(cli.engine == "readable") {
            if cli.chapter.is_some_and(|n| n != chapter.info().number) {
                continue;
            }
            run_headless(chapter, scene.clone(), &settings, &cli.out, 64, &mut stdout)
                .map_err(|e| Error::Usage(format!("ch{}: {e}", chapter.info().number)))?;
        }
        return Ok(());
    }
    summarise(
        &scene,
        &cli.out,
        cli.spp.unwrap_or(CLEAN_SPP),
        64,
        &mut stdout,
        &mut *progress_bar(),
    )?;
    Ok(())
}

/// A progress bar on stderr when stderr is a terminal (and the `tui`
/// feature brings indicatif); nothing otherwise.
fn progress_bar() -> Box<dyn Progress> {
    #[cfg(feature = "tui")]
    if std::io::IsTerminal::is_terminal(&std::io::stderr()) {
        return Box::new(Bar(None));
    }
    Box::new(NoProgress)
}

#[cfg(feature = "tui")]
struct Bar(Option<indicatif::ProgressBar>);

#[cfg(feature = "tui")]
impl Progress for Bar {
    fn begin(&mut self, what: &str, total: u64) {
        let bar = indicatif::ProgressBar::new(total);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{msg} [{bar:40}] {pos}/{len} · {elapsed} · about {eta} left",
        ) {
            bar.set_style(style.progress_chars("=> "));
        }
        bar.set_message(what.to_string());
        self.0 = Some(bar);
    }
    fn advance(&mut self, done: u64) {
        if let Some(b) = &self.0 {
            b.set_position(done);
        }
    }
    fn end(&mut self) {
        if let Some(b) = self.0.take() {
            b.finish_and_clear();
        }
    }
}
