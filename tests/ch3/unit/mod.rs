//! The tests of single library files, one file here per file in `src/`
//! (they live outside the library so that `cargo test` compiles it once).

mod bvh_robust;
mod ray;
mod readable_bvh;
mod render;
mod spawn;
mod wide_bvh;
