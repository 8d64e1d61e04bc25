//! Clipping a triangle against a plane: the near plane in camera space
//! (chapter 1's z = -NEAR, see [`crate::ch1_projection::wireframe::NEAR`]), and the guard
//! band, a rectangle far outside the screen, in raster space.
//!
//! A triangle that crosses the near plane is not dropped: the part in front
//! is kept, a polygon of three or four vertices, and cut into triangles.
//! Attributes are linear in camera space, so the new vertices get them by
//! plain linear interpolation along the cut edge. In raster space the
//! quantities that are linear are x, y, 1/w and attribute/w, so the guard
//! band clip interpolates those.
//!
//! Each cut point is computed from the edge's inside end towards its outside
//! end, whichever triangle the edge belongs to. Two triangles sharing a cut
//! edge therefore get bit-identical cut points, and stay watertight.

/// Per-vertex attributes carried through the pipeline: linear RGB colour,
/// then the vertex's barycentric identity (1,0,0), (0,1,0) or (0,0,1) in the
/// original triangle (so the barycentric view shows the triangle's φ even
/// after clipping).
pub type Attributes = [f64; 6];

/// A vertex being clipped: a position in 3D (camera space, or raster
/// (x, y, 1/w)) and attributes (or attributes/w in raster space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// Position.
    pub p: glam::DVec3,
    /// Attributes.
    pub attr: Attributes,
}

impl ClipVertex {
    /// The point `t` of the way from `self` to `other`.
    pub fn lerp(&self, other: &ClipVertex, t: f64) -> ClipVertex {
        let mut attr = self.attr;
        for (a, b) in attr.iter_mut().zip(&other.attr) {
            *a += (b - *a) * t;
        }
        ClipVertex {
            p: self.p.lerp(other.p, t),
            attr,
        }
    }
}

/// Sutherland–Hodgman against one plane: keeps the part of the convex
/// polygon where `distance(v) <= 0`. A NaN distance counts as outside.
// ANCHOR: clip_polygon
pub fn clip_polygon(
    polygon: &[ClipVertex],
    distance: impl Fn(&ClipVertex) -> f64,
) -> Vec<ClipVertex> {
    let d: Vec<f64> = polygon.iter().map(&distance).collect();
    let inside = |i: usize| d[i] <= 0.0;
    let mut out = Vec::with_capacity(polygon.len() + 1);
    for i in 0..polygon.len() {
        let j = (i + 1) % polygon.len();
        if inside(i) {
            out.push(polygon[i]);
        }
        if inside(i) != inside(j) && !d[i].is_nan() && !d[j].is_nan() {
            // Always from the inside end, so shared edges cut identically.
            let (a, b) = if inside(i) { (i, j) } else { (j, i) };
            let t = d[a] / (d[a] - d[b]);
            out.push(polygon[a].lerp(&polygon[b], t));
        }
    }
    out
}
// ANCHOR_END: clip_polygon

/// Keeps the part of a camera-space polygon in front of the near plane
/// z = -near.
// ANCHOR: clip_near_polygon
pub fn clip_near(polygon: &[ClipVertex], near: f64) -> Vec<ClipVertex> {
    if polygon.iter().all(|v| v.p.z <= -near) {
        return polygon.to_vec();
    }
    let mut out = clip_polygon(polygon, |v| v.p.z + near);
    // Cut points lie exactly on the plane.
    for v in &mut out {
        if v.p.z > -near {
            v.p.z = -near;
        }
    }
    out
}
// ANCHOR_END: clip_near_polygon

/// How far beyond the screen's edges the guard band lies, in pixels. Raster
/// positions inside it fit the exact fixed-point edge functions with room
/// to spare; triangles reaching beyond it are clipped to it. Cut edges lie
/// far off screen, so they never change which samples are covered.
pub const GUARD_BAND: f64 = (1u64 << 21) as f64;

/// Clips a raster-space polygon (x, y, 1/w; attributes/w) to the guard band
/// around a `width` x `height` screen. Returns the polygon unchanged when
/// it is already inside.
pub fn clip_guard_band(polygon: Vec<ClipVertex>, width: u32, height: u32) -> Vec<ClipVertex> {
    let (lo, hx, hy) = (
        -GUARD_BAND,
        width as f64 + GUARD_BAND,
        height as f64 + GUARD_BAND,
    );
    let inside = |v: &ClipVertex| v.p.x >= lo && v.p.x <= hx && v.p.y >= lo && v.p.y <= hy;
    if polygon.iter().all(inside) {
        return polygon;
    }
    let mut poly = polygon;
    poly = clip_polygon(&poly, |v| lo - v.p.x);
    poly = clip_polygon(&poly, |v| v.p.x - hx);
    poly = clip_polygon(&poly, |v| lo - v.p.y);
    clip_polygon(&poly, |v| v.p.y - hy)
}
