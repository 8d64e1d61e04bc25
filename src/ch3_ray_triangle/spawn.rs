//! Spawning a new ray from a surface without hitting that surface again.
//!
//! A hit point computed in f32 is off the true surface by an amount that
//! grows with its distance from the origin: at 1e5 the spacing of f32 values
//! is about 0.008. A fixed ε (start new rays 1e-4 away) is then far too
//! small, and near the origin it is needlessly large. Wächter and Binder
//! (Ray Tracing Gems, chapter 6, "A fast and robust method for avoiding
//! self-intersection") instead move the origin along the normal by a fixed
//! number of *units in the last place* of each coordinate, which scales with
//! the coordinate's magnitude; only very close to the origin, where ulps are
//! tiny, do they fall back to a small fixed offset.

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;

/// Below this magnitude a coordinate is offset by a fixed amount...
pub const ORIGIN: f32 = 1.0 / 32.0;
/// ... of this size times the normal.
pub const FLOAT_SCALE: f32 = 1.0 / 65536.0;
/// Elsewhere it moves by this many ulps times the normal. Wächter and
/// Binder use 256 for hit points computed as o + t·d; ours are interpolated
/// from the triangle's vertices (a few ulps of error), so 32 leaves a wide
/// margin, and the offset stays small next to the scene far from the
/// origin: at 1e4, 256 ulps are 0.25, an eighth of the Cornell box, and
/// the box came out 4 % too dark (tests/ch6/placement.rs).
pub const INT_SCALE: f32 = 32.0;

/// Moves `p` off the surface with normal `n` (pointing to the side the new
/// ray leaves into) by a distance that scales with `p`'s magnitude.
// ANCHOR: offset_origin
pub fn offset_origin(p: Vec3, n: Vec3) -> Vec3 {
    let step = |p: f32, n: f32| -> f32 {
        if p.abs() < ORIGIN {
            return p + FLOAT_SCALE * n;
        }
        // Step the bit pattern: each step is one ulp of p, away from zero
        // when n points away from zero and towards it otherwise.
        let ulps = (INT_SCALE * n) as i32;
        let ulps = if p < 0.0 { -ulps } else { ulps };
        f32::from_bits((p.to_bits() as i32).wrapping_add(ulps) as u32)
    };
    Vec3::new(step(p.x, n.x), step(p.y, n.y), step(p.z, n.z))
}
// ANCHOR_END: offset_origin

/// The largest distance [`offset_origin`] moves a point near `p`: the
/// fixed offset near the origin, else `INT_SCALE` ulps of `p`'s largest
/// coordinate.
pub fn offset_distance(p: Vec3) -> f32 {
    let m = p.abs().max_element();
    if m < ORIGIN {
        return FLOAT_SCALE;
    }
    let ulp = f32::from_bits(m.to_bits() + 1) - m;
    INT_SCALE * ulp
}

// ANCHOR: stop_distance
/// How many times [`offset_distance`] a shadow ray stops short of the
/// light's point.
pub const STOP_SCALE: f32 = 4.0;

/// How far short of the light's point `p` a shadow ray stops:
/// [`STOP_SCALE`] times [`offset_distance`], so that its far end, like its
/// origin, scales with where the scene sits. Four times, not once: the
/// trees pad their boxes by 2⁻²⁰ of the coordinates and the slab test
/// stretches far ends by a few rounding errors, which together reach about
/// as far as one offset; stopping at one offset, most shadow rays ended
/// inside the box around the light and tested the light's own leaf for
/// nothing. (An occluder closer to the light than this is not seen: 128
/// ulps of the point's largest coordinate, at most 1.5·10⁻⁵ of it.)
pub fn stop_distance(p: Vec3) -> f32 {
    STOP_SCALE * offset_distance(p)
}
// ANCHOR_END: stop_distance

/// A ray leaving the surface point `p` (geometric normal `n`, either side)
/// in direction `dir`, with its origin offset to the side `dir` points to.
/// `None` when `dir` is zero or not finite, or `p` is not finite.
pub fn spawn_ray(p: Vec3, n: Vec3, dir: Vec3) -> Option<Ray> {
    let n = n.try_normalize()?;
    let n = if n.dot(dir) < 0.0 { -n } else { n };
    Ray::new(offset_origin(p, n), dir).ok()
}
