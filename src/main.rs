//! `cargo run --release`: every chapter on the built-in default scene.
//!
//! Renders each chapter that exists on the built-in Cornell box into `out/`
//! and prints its preview and report. (In a terminal this will open the
//! terminal UI once it lands; piped or in CI it stays headless.)

use std::process::ExitCode;

use raystep::run::run_headless;
use raystep::scene::Scene;
use raystep::stage::Settings;

fn main() -> ExitCode {
    let out = std::path::PathBuf::from("out");
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
