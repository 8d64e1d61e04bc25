//! Attribute interpolation with barycentric coordinates: the lecture's
//! colour(x) = colour(x_i)·φi + colour(x_j)·φj + colour(x_k)·φk.
//!
//! On the screen, φ computed from pixel positions are *screen-space*
//! barycentrics. Using them directly (affine interpolation) is right for a
//! triangle parallel to the image plane and wrong for any other: a
//! perspective projection does not keep ratios of lengths. What it does
//! keep linear on the screen is 1/w and a/w for any attribute a, so the
//! perspective-correct value is Σ φn·an/wn divided by Σ φn/wn. Both are
//! here; the chapter shows them side by side.

use glam::I64Vec2;

use super::clip::Attributes;
use super::edge::edge_fixed;
use super::setup::ScreenTriangle;

/// Which interpolation to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    /// Divide by w: what the eye sees on a slanted triangle.
    Perspective,
    /// Screen-space barycentrics used directly (the textbook mistake).
    Affine,
}

/// Screen-space barycentrics (φ0, φ1, φ2) of fixed-point `p` in `tri`.
pub fn screen_barycentrics(tri: &ScreenTriangle, p: I64Vec2) -> [f64; 3] {
    let [v0, v1, v2] = tri.v;
    let a = tri.area as f64;
    [
        edge_fixed(v1, v2, p) as f64 / a,
        edge_fixed(v2, v0, p) as f64 / a,
        edge_fixed(v0, v1, p) as f64 / a,
    ]
}

/// The attributes of `tri` at sample `p`, and the depth w there.
// ANCHOR: interpolate
pub fn interpolate(tri: &ScreenTriangle, p: I64Vec2, mode: Interpolation) -> (Attributes, f64) {
    interpolate_phi(tri, screen_barycentrics(tri, p), mode)
}

/// [`interpolate`] from screen-space barycentrics φ already computed.
pub fn interpolate_phi(
    tri: &ScreenTriangle,
    phi: [f64; 3],
    mode: Interpolation,
) -> (Attributes, f64) {
    // 1/w is linear on the screen in both modes: that gives the depth.
    let inv_w: f64 = (0..3).map(|n| phi[n] * tri.inv_w[n]).sum();
    let mut out = [0.0; 6];
    for (c, value) in out.iter_mut().enumerate() {
        *value = match mode {
            Interpolation::Affine => (0..3).map(|n| phi[n] * tri.attr[n][c]).sum(),
            Interpolation::Perspective => {
                (0..3)
                    .map(|n| phi[n] * tri.attr[n][c] * tri.inv_w[n])
                    .sum::<f64>()
                    / inv_w
            }
        };
    }
    (out, 1.0 / inv_w)
}
// ANCHOR_END: interpolate
