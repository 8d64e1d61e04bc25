//! `cargo run --release`: every chapter on the built-in default scene.
//!
//! In a terminal (stdout is a TTY, and the default `tui` feature is on) this
//! opens the terminal UI on the built-in Cornell box, with the scenes of
//! `scenes/` in its scene list. Piped, in CI, or with `--headless` it
//! renders each chapter that exists on the built-in scene into `out/` and
//! prints its preview and report.
//!
//! Flags: `--headless` (never open the UI), `--bench-ui` (time the UI's
//! start-up and redraws; needs the `tui` feature), `--scenes DIR` (the
//! folder the UI lists, default `scenes`), `--out DIR` (where the UI's `s`
//! saves, default `out`).

use std::path::PathBuf;
use std::process::ExitCode;

use raystep::core::run::run_headless;
use raystep::core::stage::Settings;
use raystep::scene::Scene;

struct Args {
    headless: bool,
    bench_ui: bool,
    scenes: PathBuf,
    out: PathBuf,
}

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        headless: false,
        bench_ui: false,
        scenes: PathBuf::from("scenes"),
        out: PathBuf::from("out"),
    };
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        match a.as_str() {
            "--headless" => args.headless = true,
            "--bench-ui" => args.bench_ui = true,
            "--scenes" | "--out" => {
                let v = it.next().ok_or(format!("`{a}` needs a folder"))?;
                if a == "--scenes" {
                    args.scenes = v.into();
                } else {
                    args.out = v.into();
                }
            }
            "-h" | "--help" => {
                return Err(
                    "usage: raystep [--headless] [--bench-ui] [--scenes DIR] [--out DIR]".into(),
                )
            }
            other => return Err(format!("unknown argument `{other}` (try --help)")),
        }
    }
    Ok(args)
}

fn main() -> ExitCode {
    #[cfg(feature = "tui")]
    let started = std::time::Instant::now();
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    if args.bench_ui {
        #[cfg(feature = "tui")]
        {
            let mut stdout = std::io::stdout().lock();
            return match raystep::tui::bench::run(started, &args.scenes, &mut stdout) {
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
    if !args.headless && raystep::tui::should_open() {
        return match raystep::tui::run(&args.scenes, &args.out) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: terminal UI: {e}");
                ExitCode::from(2)
            }
        };
    }
    let out = args.out;
    let settings = Settings {
        studies: true,
        ..Settings::default()
    };
    let mut stdout = std::io::stdout().lock();
    for chapter in raystep::chapters::all() {
        if let Err(e) = run_headless(chapter, Scene::builtin(), &settings, &out, 64, &mut stdout) {
            eprintln!("error: ch{}: {e}", chapter.number());
            return ExitCode::from(2);
        }
    }
    ExitCode::SUCCESS
}
