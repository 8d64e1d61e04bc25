//! Exercise 2.3: the depth test.
//!
//! A depth buffer holds, for every sample, the depth of the nearest surface
//! drawn so far (it starts at infinity). A new surface at depth `z` is
//! visible at that sample only if it is nearer: then its depth is stored and
//! the test passes. A tie keeps what was drawn first, and a NaN depth never
//! passes.
//!
//! Grade it with: `cargo run --release --bin grade -- ch2`

/// Tests `z` against `depth[index]`; stores it and returns `true` if nearer.
pub fn depth_test(depth: &mut [f32], index: usize, z: f32) -> bool {
    // TODO: compare with the stored depth (think about ties and NaN).
    // TODO: on success, store z.
    todo!()
}
