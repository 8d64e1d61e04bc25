//! Chapter 3: where a ray meets a triangle.
//!
//! The lecture takes two routes to the same answer, and both are kept here as
//! separate functions, next to a third that a production renderer uses:
//!
//! 1. [`ray_plane`] then [`barycentric_inside`]: intersect the ray with the
//!    triangle's plane, t = (c - Nᵀo)/(Nᵀd), then ask whether the point is
//!    inside by its barycentric coordinates ([`intersect_plane_inside`]).
//! 2. The 3x3 system [p1 - p0, p2 - p0, -d] (u, v, t)ᵀ = o - p0, solved by
//!    Cramer's rule: the Möller–Trumbore algorithm
//!    ([`intersect_moller_trumbore`]).
//! 3. A *watertight* test (Woop, Benthin and Wald 2013, as in pbrt-v4):
//!    move the ray to the origin and along +z, so that the inside test is
//!    three 2D edge functions whose value on a shared edge is bit-for-bit the
//!    same for both triangles. A ray through an edge or a vertex of a closed
//!    mesh therefore always hits at least one triangle
//!    ([`intersect_watertight`]).
//!
//! All three take the ray's interval [t_min, t_max] and return a [`Hit`]
//! with the lecture's (u, v): the hit point is p0 + u (p1 - p0) + v (p2 - p0).

use glam::{DVec3, Vec3};

use crate::ch3_ray_triangle::ray::Ray;

/// Where a ray met a triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter: the hit point is o + t d.
    pub t: f32,
    /// Barycentric u: the weight of p1.
    pub u: f32,
    /// Barycentric v: the weight of p2 (p0 gets 1 - u - v).
    pub v: f32,
    /// Which triangle (an index into the triangle list that was searched).
    pub triangle: u32,
}

impl Hit {
    /// The three barycentric weights (of p0, p1, p2).
    pub fn barycentrics(&self) -> Vec3 {
        Vec3::new(1.0 - self.u - self.v, self.u, self.v)
    }

    /// The hit point from the barycentrics: more accurate than o + t d far
    /// from the ray's origin, since it does not multiply the error of t by
    /// the length of d.
    pub fn point(&self, [p0, p1, p2]: [Vec3; 3]) -> Vec3 {
        let b = self.barycentrics();
        b.x * p0 + b.y * p1 + b.z * p2
    }
}

/// The unit normal of triangle `[p0, p1, p2]` (its front is the side from
/// which the corners run counter-clockwise), at any size: the cross product
/// is scaled to its largest component before it is normalised, because
/// its squared length overflows f32 once edges pass about 1e9 (and
/// underflows below about 1e-10). `None` for a triangle with no area.
pub fn unit_normal([p0, p1, p2]: [Vec3; 3]) -> Option<Vec3> {
    let n = (p1 - p0).cross(p2 - p0);
    let largest = n.abs().max_element();
    if largest > 0.0 && largest.is_finite() {
        (n / largest).try_normalize()
    } else {
        None
    }
}

/// Ray-plane intersection for the plane Nᵀx = c: t = (c - Nᵀo)/(Nᵀd).
/// `None` when the ray is parallel to the plane (Nᵀd = 0) or t is not finite.
// ANCHOR: ray_plane
pub fn ray_plane(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let n_dot_d = n.dot(d);
    if n_dot_d == 0.0 {
        return None; // parallel: no point, or every point, of the plane
    }
    let t = (c - n.dot(o)) / n_dot_d;
    t.is_finite().then_some(t)
}
// ANCHOR_END: ray_plane

/// The barycentric coordinates (u, v) of a point `p` in the plane of the
/// triangle (p0, p1, p2), if it lies inside (edges included):
/// p - p0 = u (p1 - p0) + v (p2 - p0) with u ≥ 0, v ≥ 0, u + v ≤ 1.
// ANCHOR: barycentric_inside
pub fn barycentric_inside(p: Vec3, [p0, p1, p2]: [Vec3; 3]) -> Option<(f32, f32)> {
    let (e1, e2, q) = (p1 - p0, p2 - p0, p - p0);
    // N = e1 x e2 is twice the triangle's area times its unit normal.
    let n = e1.cross(e2);
    let nn = n.length_squared();
    if nn == 0.0 || !nn.is_finite() {
        return None; // degenerate (zero area) triangle
    }
    // Crossing q = u e1 + v e2 with e2 leaves u (e1 x e2); with e1, v.
    let u = n.dot(q.cross(e2)) / nn;
    let v = n.dot(e1.cross(q)) / nn;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0).then_some((u, v))
}
// ANCHOR_END: barycentric_inside

/// Route 1: the plane first, then the inside test.
// ANCHOR: plane_inside
pub fn intersect_plane_inside(ray: &Ray, tri: [Vec3; 3], t_min: f32, t_max: f32) -> Option<Hit> {
    let [p0, p1, p2] = tri;
    // The plane through the triangle: normal N, offset c = Nᵀp0.
    let n = (p1 - p0).cross(p2 - p0);
    let t = ray_plane(ray.origin, ray.dir, n, n.dot(p0))?;
    if !(t > t_min && t < t_max) {
        return None;
    }
    // The point on the plane, then: is it inside?
    let (u, v) = barycentric_inside(ray.at(t), tri)?;
    Some(Hit {
        t,
        u,
        v,
        triangle: 0,
    })
}
// ANCHOR_END: plane_inside

/// Route 2: the lecture's 3x3 system [e1, e2, -d] (u, v, t)ᵀ = o - p0 with
/// e1 = p1 - p0, e2 = p2 - p0, solved by Cramer's rule (Möller–Trumbore).
// ANCHOR: moller_trumbore
// ANCHOR: moller_trumbore_u
pub fn intersect_moller_trumbore(
    ray: &Ray,
    [p0, p1, p2]: [Vec3; 3],
    t_min: f32,
    t_max: f32,
) -> Option<Hit> {
    let (e1, e2, d) = (p1 - p0, p2 - p0, ray.dir);
    let s = ray.origin - p0;
    // det[e1, e2, -d] = e1 · (e2 x -d) = e1 · (d x e2).
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 || !det.is_finite() {
        return None; // d lies in the triangle's plane, or the triangle is degenerate
    }
    let inv_det = 1.0 / det;
    // u = det[s, e2, -d] / det = s · (d x e2) / det.
    let u = s.dot(p) * inv_det;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    // ANCHOR_END: moller_trumbore_u
    // ANCHOR: moller_trumbore_vt
    // v = det[e1, s, -d] / det = d · (s x e1) / det.
    let q = s.cross(e1);
    let v = d.dot(q) * inv_det;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    // t = det[e1, e2, s] / det = e2 · (s x e1) / det.
    let t = e2.dot(q) * inv_det;
    (t > t_min && t < t_max).then_some(Hit {
        t,
        u,
        v,
        triangle: 0,
    })
}
// ANCHOR_END: moller_trumbore_vt
// ANCHOR_END: moller_trumbore

pub(crate) use super::rounding::gamma;

/// Route 3: the watertight test of Woop, Benthin and Wald (2013), following
/// pbrt-v4's `IntersectTriangle`, with its conservative check that t > 0.
// ANCHOR: watertight
// ANCHOR: watertight_frame
pub fn intersect_watertight(ray: &Ray, tri: [Vec3; 3], t_min: f32, t_max: f32) -> Option<Hit> {
    let [p0, p1, p2] = tri;
    // A zero-area triangle has no inside.
    if (p2 - p0).cross(p1 - p0).length_squared() == 0.0 {
        return None;
    }
    // Translate the vertices so the ray starts at the origin...
    let (a, b, c) = (p0 - ray.origin, p1 - ray.origin, p2 - ray.origin);
    // ... permute the axes so the ray's largest component becomes z ...
    let d_abs = ray.dir.abs();
    let kz = if d_abs.x > d_abs.y {
        if d_abs.x > d_abs.z {
            0
        } else {
            2
        }
    } else if d_abs.y > d_abs.z {
        1
    } else {
        2
    };
    let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
    let perm = |v: Vec3| Vec3::new(v[kx], v[ky], v[kz]);
    let (d, mut a, mut b, mut c) = (perm(ray.dir), perm(a), perm(b), perm(c));
    // ANCHOR_END: watertight_frame
    // ANCHOR: watertight_edges
    // ... and shear so the ray points along +z: x and y now measure the
    // distance from the ray in its own 2D frame.
    let (sx, sy, sz) = (-d.x / d.z, -d.y / d.z, 1.0 / d.z);
    for p in [&mut a, &mut b, &mut c] {
        p.x += sx * p.z;
        p.y += sy * p.z;
    }
    // Edge functions: twice the signed areas of (origin, edge). A shared
    // edge gives the same products in both triangles, only negated.
    let mut e0 = b.x * c.y - b.y * c.x;
    let mut e1 = c.x * a.y - c.y * a.x;
    let mut e2 = a.x * b.y - a.y * b.x;
    // Exactly on an edge in f32? Decide it in f64, where the products are exact.
    if e0 == 0.0 || e1 == 0.0 || e2 == 0.0 {
        let f = |p: f32, q: f32, r: f32, s: f32| (p as f64 * q as f64 - r as f64 * s as f64) as f32;
        e0 = f(b.x, c.y, b.y, c.x);
        e1 = f(c.x, a.y, c.y, a.x);
        e2 = f(a.x, b.y, a.y, b.x);
    }
    // Inside when the three signs agree (zeros count as either).
    if (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0) {
        return None;
    }
    let det = e0 + e1 + e2;
    if det == 0.0 || !det.is_finite() {
        return None; // the ray lies in the triangle's plane
    }
    // ANCHOR_END: watertight_edges
    // ANCHOR: watertight_distance
    // The scaled distance, compared with the interval before dividing.
    a.z *= sz;
    b.z *= sz;
    c.z *= sz;
    let t_scaled = e0 * a.z + e1 * b.z + e2 * c.z;
    if det < 0.0 && (t_scaled >= t_min * det || t_scaled < t_max * det) {
        return None;
    }
    if det > 0.0 && (t_scaled <= t_min * det || t_scaled > t_max * det) {
        return None;
    }
    let inv_det = 1.0 / det;
    let t = t_scaled * inv_det;
    // Is t certainly > 0, given the rounding error of everything above?
    let delta_t = t_rounding_bound([a, b, c], [e0, e1, e2], inv_det);
    // pbrt-v4 rejects the hit here. Its bound is very loose for triangles
    // tiny compared with their distance (an edge of 1e-6 seen from 1 unit
    // is rejected), so where it cannot decide, decide in f64 instead.
    if t <= delta_t && !ahead_in_f64(ray, tri, t_min) {
        return None;
    }
    Some(Hit {
        t,
        u: e1 * inv_det,
        v: e2 * inv_det,
        triangle: 0,
    })
}
// ANCHOR_END: watertight_distance
// ANCHOR_END: watertight

/// pbrt-v4's bound on the rounding error of the watertight test's t
/// ([`super::rounding`]): the sheared vertices `abc`, the edge functions
/// `e` and 1/det. A t at or below it cannot be told from 0.
fn t_rounding_bound(abc: [Vec3; 3], e: [f32; 3], inv_det: f32) -> f32 {
    let [a, b, c] = abc;
    let [e0, e1, e2] = e;
    let max_zt = a.z.abs().max(b.z.abs()).max(c.z.abs());
    let max_xt = a.x.abs().max(b.x.abs()).max(c.x.abs());
    let max_yt = a.y.abs().max(b.y.abs()).max(c.y.abs());
    let max_e = e0.abs().max(e1.abs()).max(e2.abs());
    super::rounding::t_error_bound(max_xt, max_yt, max_zt, max_e, inv_det)
}

/// Whether the plane of `tri` lies ahead of the ray's origin (t > t_min),
/// computed in f64 from the f32 inputs: the tie-breaker of
/// [`intersect_watertight`]'s conservative t > 0 check.
pub(crate) fn ahead_in_f64(ray: &Ray, [p0, p1, p2]: [Vec3; 3], t_min: f32) -> bool {
    let (p0, p1, p2) = (p0.as_dvec3(), p1.as_dvec3(), p2.as_dvec3());
    let n = (p1 - p0).cross(p2 - p0);
    let t = n.dot(p0 - ray.origin.as_dvec3()) / n.dot(ray.dir.as_dvec3());
    t > t_min as f64
}

/// The f64 reference: the 3x3 system solved by Cramer's rule in double
/// precision. Used by tests and the precision study, never for rendering.
pub fn intersect_f64(o: DVec3, d: DVec3, [p0, p1, p2]: [DVec3; 3]) -> Option<(f64, f64, f64)> {
    let (e1, e2, s) = (p1 - p0, p2 - p0, o - p0);
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 {
        return None;
    }
    let q = s.cross(e1);
    let (u, v, t) = (s.dot(p) / det, d.dot(q) / det, e2.dot(q) / det);
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0).then_some((t, u, v))
}

/// The three ray-triangle tests, as a value (for studies and the stage).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Intersector {
    /// [`intersect_plane_inside`].
    PlaneInside,
    /// [`intersect_moller_trumbore`].
    MollerTrumbore,
    /// [`intersect_watertight`] (the default).
    Watertight,
}

impl Intersector {
    /// All three, in the lecture's order.
    pub const ALL: [Intersector; 3] = [
        Intersector::PlaneInside,
        Intersector::MollerTrumbore,
        Intersector::Watertight,
    ];

    /// A short name for reports.
    pub fn name(self) -> &'static str {
        match self {
            Intersector::PlaneInside => "ray-plane + inside test",
            Intersector::MollerTrumbore => "Möller–Trumbore (3x3, Cramer)",
            Intersector::Watertight => "watertight (Woop et al.)",
        }
    }

    /// Runs the test on one triangle.
    #[inline]
    pub fn intersect(self, ray: &Ray, tri: [Vec3; 3], t_min: f32, t_max: f32) -> Option<Hit> {
        match self {
            Intersector::PlaneInside => intersect_plane_inside(ray, tri, t_min, t_max),
            Intersector::MollerTrumbore => intersect_moller_trumbore(ray, tri, t_min, t_max),
            Intersector::Watertight => intersect_watertight(ray, tri, t_min, t_max),
        }
    }
}
