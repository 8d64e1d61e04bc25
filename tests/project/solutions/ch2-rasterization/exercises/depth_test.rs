//! A student's solution of exercise 2.3 (the grader's tests run it).

/// Tests `z` against `depth[index]`; stores it and returns `true` if nearer.
pub fn depth_test(depth: &mut [f32], index: usize, z: f32) -> bool {
    let nearer = z < depth[index];
    if nearer {
        depth[index] = z;
    }
    nearer
}
