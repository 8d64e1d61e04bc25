//! The tests of single library files, one file here per file in `src/`
//! (they live outside the library so that `cargo test` compiles it once).

mod clip;
mod depth;
mod edge;
mod exact;
