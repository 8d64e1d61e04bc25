//! Combining distance functions. Boolean operators keep the surface exact
//! but not always the distance: see the table in [`distance`](super::distance).

/// Union (either shape): the nearer surface. Exact outside; inside the
/// overlap it underestimates (a bound).
// ANCHOR: op_union
pub fn op_union(a: f32, b: f32) -> f32 {
    a.min(b)
}
// ANCHOR_END: op_union

/// Intersection (both shapes): the farther surface. Exact inside; outside
/// near the edges where the shapes meet it underestimates (a bound).
pub fn op_intersection(a: f32, b: f32) -> f32 {
    a.max(b)
}

/// Difference a − b: inside a and outside b. A bound.
pub fn op_difference(a: f32, b: f32) -> f32 {
    a.max(-b)
}

/// Smooth union with blend radius `k` (quadratic polynomial smooth
/// minimum): equal to `min(a, b)` where the two distances differ by more
/// than k, and below it in between, which fills a fillet. A bound:
/// ‖∇f‖ drops below 1 in the blend.
// ANCHOR: op_smooth_union
pub fn op_smooth_union(a: f32, b: f32, k: f32) -> f32 {
    if k <= 0.0 {
        return a.min(b);
    }
    let h = (k - (a - b).abs()).max(0.0) / k; // 1 where a = b, 0 beyond k
    a.min(b) - h * h * k * 0.25
}
// ANCHOR_END: op_smooth_union
