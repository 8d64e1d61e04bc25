//! The foundation every chapter stands on, with no lecture content of its
//! own: errors, the film (an HDR image), drawing lines, terminal previews,
//! plots, reports, random numbers, the stage boundary between a chapter and
//! its front ends, and the headless runner.

pub mod band_files;
pub mod bands;
pub mod difference;
pub mod draw;
pub mod error;
pub mod figure;
pub mod film;
pub mod format;
pub mod memory;
pub mod outputs;
pub mod plot;
pub mod preview;
pub mod refuse;
pub mod report;
pub mod run;
pub mod sampling;
pub mod stage;
pub mod stale;
pub mod strip;
pub mod style;
pub mod table;
pub mod text;
pub mod warp_test;
pub mod zview;

/// The repository's root folder (where `Cargo.toml`, `scenes/` and
/// `chapters/` are), as the build saw it. This crate's manifest is
/// `src/Cargo.toml`, one folder below.
pub fn project_root() -> std::path::PathBuf {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    src.parent().unwrap_or(src).to_path_buf()
}
