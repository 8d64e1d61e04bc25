//! Edge functions: which side of a triangle's edge a point lies on.
//!
//! For an edge from a to b, E_ab(p) = (b - a) × (p - a) is the signed
//! (doubled) area of the triangle (a, b, p). It is zero on the line through
//! a and b, positive on one side and negative on the other, and it is an
//! affine function of p. A point is inside a triangle when it is on the
//! inner side of all three edges; the three values divided by the
//! triangle's own doubled area are its barycentric coordinates φi, φj, φk.
//!
//! Two versions live here. The readable one works in `f32` and is what the
//! book and the exercises use. The one the rasterizer uses snaps vertices
//! and samples to a grid of 1/256 pixel and evaluates the edge functions in
//! `i64`, where they are exact: a sample is never inside both of two
//! triangles that share an edge, and never inside neither (with the
//! top-left rule below for samples exactly on the edge).

use glam::{I64Vec2, Vec2, Vec3};

/// Bits of sub-pixel precision of snapped vertex and sample positions.
pub const SUBPIXEL_BITS: u32 = 8;
/// One pixel in fixed-point units (256).
pub const SUBPIXEL: i64 = 1 << SUBPIXEL_BITS;

/// The edge function E_ab(p) in floating point: positive when p is to the
/// left of a→b in a y-up frame (to the right on a y-down raster).
// ANCHOR: edge_function
pub fn edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)
}
// ANCHOR_END: edge_function

/// Barycentric coordinates (φi, φj, φk) of `p` in the triangle (pi, pj, pk):
/// p = φi·pi + φj·pj + φk·pk with φi + φj + φk = 1. `None` when the triangle
/// has no area (then no such coordinates exist).
// ANCHOR: barycentric
pub fn barycentric(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    let area = edge_function(pi, pj, pk);
    if area == 0.0 || !area.is_finite() {
        return None;
    }
    // Each φ is the area of the sub-triangle opposite its vertex.
    let phi_i = edge_function(pj, pk, p) / area;
    let phi_j = edge_function(pk, pi, p) / area;
    let phi_k = edge_function(pi, pj, p) / area;
    Some(Vec3::new(phi_i, phi_j, phi_k))
}
// ANCHOR_END: barycentric

/// A raster position snapped to 1/256 pixel; `None` if it is not finite or
/// too far out for exact `i64` edge functions (2^22 pixels or more: then
/// fixed-point coordinates stay below 2^30, differences below 2^31 and each
/// product in an edge function below 2^62).
pub fn to_fixed(x: f64, y: f64) -> Option<I64Vec2> {
    let limit = (1u64 << 22) as f64;
    if !(x.abs() < limit && y.abs() < limit) {
        return None;
    }
    let s = SUBPIXEL as f64;
    Some(I64Vec2::new((x * s).round() as i64, (y * s).round() as i64))
}

/// A fixed-point position back to pixels.
pub fn from_fixed(p: I64Vec2) -> glam::DVec2 {
    p.as_dvec2() / SUBPIXEL as f64
}

/// The exact edge function on fixed-point positions, in 1/65536 pixel².
/// Exact as long as coordinates stay below 2^22 pixels in magnitude, which the
/// guard band guarantees (see [`super::clip`]).
// ANCHOR: edge_fixed
#[inline]
pub fn edge_fixed(a: I64Vec2, b: I64Vec2, p: I64Vec2) -> i64 {
    (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)
}
// ANCHOR_END: edge_fixed

/// The top-left fill rule for an edge a→b of a triangle whose inside has
/// positive edge functions (raster coordinates, y down). A sample exactly
/// on an edge belongs to the triangle only if the edge is a *left* edge
/// (the inside lies to its right) or a *top* edge (horizontal, inside
/// below). A shared edge is a left or top edge of exactly one of its two
/// triangles, since they walk it in opposite directions.
// ANCHOR: top_left
#[inline]
pub fn is_top_left(a: I64Vec2, b: I64Vec2) -> bool {
    let d = b - a;
    d.y < 0 || (d.y == 0 && d.x > 0)
}
// ANCHOR_END: top_left

/// The amount added to an edge function before testing `>= 0`: 0 for
/// top-left edges (a sample on them counts), -1 for the others (it does not).
#[inline]
pub fn fill_bias(a: I64Vec2, b: I64Vec2) -> i64 {
    if is_top_left(a, b) {
        0
    } else {
        -1
    }
}
