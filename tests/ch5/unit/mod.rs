//! The tests of single library files, one file here per file in `src/`
//! (they live outside the library so that `cargo test` compiles it once).

mod light_area;
mod light_sky;
mod light_spherical;
mod light_spot;
mod light_terms;
mod material_dielectric;
mod material_frame;
mod mis;
mod radiometry;
mod warp;
