//! Chapter 2: rasterization. `cargo run --release --bin ch2 -- --help`
//!
//! Fills the triangles of any scene: coverage by edge functions with the
//! top-left rule, a depth buffer, barycentric interpolation (perspective-
//! correct beside affine), 1 to 64 samples per pixel. Prints the mesh
//! checks; with `--report` the anti-aliasing study and the stiff cases;
//! with `--bench` only the speed benchmark.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use raystep::raster::bench::run_bench;
use raystep::raster::Rasterization;
use raystep::run::{init_threads, run_headless, CommonArgs};
use raystep::scene::Scene;

#[derive(Parser)]
#[command(name = "ch2", about = "Chapter 2: rasterization")]
struct Cli {
    #[command(flatten)]
    common: CommonArgs,
    /// Drop triangles facing away from the camera.
    #[arg(long)]
    cull_back_faces: bool,
    /// Print the speed benchmark (bunny and a procedural mesh at 1920x1080
    /// on 1 and 2 threads) instead of rendering.
    #[arg(long)]
    bench: bool,
    /// Triangles of the benchmark's procedural mesh.
    #[arg(long, default_value_t = 1_000_000)]
    bench_triangles: usize,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = (|| {
        if cli.bench {
            let bunny = Scene::load(&PathBuf::from("scenes/bunny.toml")).ok();
            let table = run_bench(bunny, &[1, 2], cli.bench_triangles)?;
            print!("{}", table.to_text());
            return Ok(());
        }
        init_threads(cli.common.threads)?;
        let scene = cli.common.load_scene()?;
        let chapter = Rasterization {
            cull_back_faces: cli.cull_back_faces,
        };
        let mut stdout = std::io::stdout().lock();
        run_headless(
            &chapter,
            scene,
            &cli.common.settings(),
            &cli.common.out,
            cli.common.preview_width,
            &mut stdout,
        )
        .map(|_| ())
    })();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
