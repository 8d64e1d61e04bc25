//! The book's diagrams and wrong pictures, drawn from the real functions
//! that compute each idea, so that they cannot drift from the code.
//! `book/figures.sh` runs it; `tests/project/figures.rs` checks that the
//! SVGs in `book/src/figures` are what it draws now.
//!
//! ```text
//! diagrams --out DIR           every diagram as DIR/<name>.svg
//! diagrams --wrong --out DIR   each plausible bug's picture (<name>-wrong.png)
//!                              beside the right one, rendered by the project
//! diagrams --list              one line per diagram: its file and what it shows
//! ```
//!
//! | module | draws |
//! |---|---|
//! | [`svg`] | the SVG writer every diagram uses |
//! | [`ch1`] | chapter 1's diagrams (projection) |
//! | [`ch2`] | chapter 2's diagrams (rasterization) |
//! | [`ch2_top_left`] | chapter 2's top-left rule diagram (a pixel grid) |
//! | [`ch3`] | chapter 3's diagrams (rays, triangles, boxes) |
//! | [`ch3_bvh`] | chapter 3's BVH diagram (a real tree's boxes) |
//! | [`ch4`] | chapter 4's diagrams (sphere tracing) |
//! | [`ch5`] | chapter 5's diagrams (radiometry, lights, BRDFs) |
//! | [`ch6`] | chapter 6's diagrams (paths) |
//! | [`contour`] | level sets of a function of the plane (chapter 4's slices) |
//! | [`wrong`] | the wrong pictures and their right partners (chapters 1 and 2) |
//! | [`wrong_rays`] | chapters 3 and 4's wrong pictures (a leaking triangle test, an implicit sphere that is not a distance) |
//! | [`wrong_pair`] | what the wrong pictures' modules share (a pair, the scenes, magnifying) |
//! | [`wrong_light`] | chapters 5 and 6's wrong pictures (shadow acne, the BRDF without 1/π, roulette without 1/q) |

mod ch1;
mod ch2;
mod ch2_top_left;
mod ch3;
mod ch3_bvh;
mod ch4;
mod ch5;
mod ch6;
mod contour;
mod svg;
mod wrong;
mod wrong_light;
mod wrong_pair;
mod wrong_rays;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use raystep::core::error::{Error, Result};

/// One diagram: its file name (without `.svg`; it ends in `-diagram`),
/// what it shows, and the drawing.
pub struct Diagram {
    /// `chN-what-diagram`.
    pub name: &'static str,
    /// One line: what it shows and which function computes it.
    pub what: &'static str,
    /// The drawing.
    pub svg: svg::Svg,
}

/// The book's diagrams and wrong pictures.
#[derive(Parser)]
#[command(
    version,
    about = "Draws the book's diagrams (SVG) and wrong pictures (PNG)"
)]
struct Cli {
    /// The folder to write into.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Render the wrong pictures and their right partners instead.
    #[arg(long)]
    wrong: bool,
    /// List the diagrams instead of writing them.
    #[arg(long)]
    list: bool,
}

/// Every diagram, chapter by chapter.
fn all() -> Result<Vec<Diagram>> {
    let mut all = Vec::new();
    all.extend(ch1::diagrams()?);
    all.extend(ch2::diagrams()?);
    all.extend(ch3::diagrams()?);
    all.extend(ch4::diagrams()?);
    all.extend(ch5::diagrams()?);
    all.extend(ch6::diagrams()?);
    Ok(all)
}

fn run(cli: &Cli) -> Result<()> {
    if cli.list {
        for d in all()? {
            println!("{}.svg: {}", d.name, d.what);
        }
        for (file, what) in wrong::list() {
            println!("{file}: {what}");
        }
        return Ok(());
    }
    let Some(out) = &cli.out else {
        return Err(Error::Usage("diagrams: give --out DIR (or --list)".into()));
    };
    raystep::core::film::create_folder(out)?;
    if cli.wrong {
        for name in wrong::render_all(out)? {
            println!("wrote {}", out.join(name).display());
        }
        return Ok(());
    }
    for d in all()? {
        assert!(
            d.name.ends_with("-diagram"),
            "{}: name must end in -diagram",
            d.name
        );
        let path = out.join(format!("{}.svg", d.name));
        let text = d.svg.finish();
        raystep::core::film::write_atomically(&path, |tmp| {
            raystep::core::film::write_all_synced(tmp, text.as_bytes())
        })?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

fn main() -> ExitCode {
    let cli: Cli = raystep::core::run::parse_args();
    raystep::core::run::exit_code(run(&cli))
}
