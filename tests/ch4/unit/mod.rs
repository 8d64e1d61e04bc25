//! The tests of single library files, one file here per file in `src/`
//! (they live outside the library so that `cargo test` compiles it once).

mod bounds;
mod distance;
mod hit;
mod normal;
mod operators;
mod primitives;
mod render;
