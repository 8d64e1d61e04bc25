//! Exercise 2.3: the depth test.
//!
//! A depth buffer holds, for every sample, the depth of the nearest surface
//! drawn so far (it starts at infinity). A new surface at depth `z` is
//! visible at that sample only if it is nearer.
//!
//! The contract (checked on sequences of tests on buffers small and large,
//! and the buffers' contents after them):
//! * nearer (smaller z) passes: the buffer then holds z, and the function
//!   returns `true`;
//! * farther fails and leaves the buffer as it was (`false`);
//! * a tie fails: what was drawn first stays;
//! * a NaN depth never passes, and infinity never passes an empty sample.
//!
//! Grade it with: `cargo grade ch2`

/// Tests `z` against `depth[index]`; stores it and returns `true` if nearer.
pub fn depth_test(depth: &mut [f32], index: usize, z: f32) -> bool {
    // TODO: the test, and what a pass changes.
    todo!()
}
