//! The watertight test, rearranged for speed: the same arithmetic as
//! [`intersect_watertight`](crate::triangle::intersect_watertight), bit for
//! bit, with the work that depends only on the ray done once per ray.
//!
//! The readable version recomputes, for every triangle a ray meets, which
//! axis is the ray's largest, the shear (sx, sy, sz), and whether the
//! triangle has zero area. None of that changes from one triangle to the
//! next, so a BVH query computes the first two once in [`WatertightRay::new`]
//! (pbrt-v3 does the same), and the BVH stores zero-area triangles collapsed
//! to a point, which the edge functions reject exactly (all three are 0, so
//! det = 0), so the per-triangle area test disappears.
//!
//! Each triangle is stored by coordinate: the x of its three vertices, then
//! their y, then their z ([`SoaTriangle`]). The axis permutation is then a
//! choice of row, and the translation, the shear and the three edge
//! functions are each one 4-wide SIMD operation over the three vertices.
//! The rare paths (an edge function exactly zero, a t too small to trust
//! the error bound) go to the same f64 tie-breakers as the readable version.

use glam::{Vec3, Vec3A, Vec3Swizzles};

use crate::ray::Ray;
use crate::triangle::{ahead_in_f64, gamma, Hit};

/// One triangle stored by coordinate: `rows[0]` holds the x of (p0, p1,
/// p2), `rows[1]` their y, `rows[2]` their z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SoaTriangle {
    /// Rows x, y and z, each over the three vertices.
    pub rows: [Vec3A; 3],
}

impl SoaTriangle {
    /// Stores `tri`; a zero-area triangle (the readable test's check) is
    /// collapsed to its first vertex, which no test can hit.
    pub fn new(tri: [Vec3; 3]) -> SoaTriangle {
        let [p0, p1, p2] = tri;
        let [p0, p1, p2] = if (p2 - p0).cross(p1 - p0).length_squared() == 0.0 {
            [p0; 3]
        } else {
            tri
        };
        SoaTriangle {
            rows: [
                Vec3A::new(p0.x, p1.x, p2.x),
                Vec3A::new(p0.y, p1.y, p2.y),
                Vec3A::new(p0.z, p1.z, p2.z),
            ],
        }
    }

    /// The three vertices again (zero-area triangles come back collapsed).
    pub fn vertices(&self) -> [Vec3; 3] {
        let [x, y, z] = self.rows;
        [
            Vec3::new(x.x, y.x, z.x),
            Vec3::new(x.y, y.y, z.y),
            Vec3::new(x.z, y.z, z.z),
        ]
    }
}

/// The part of the watertight test that depends only on the ray.
#[derive(Clone, Copy, Debug)]
pub struct WatertightRay<'a> {
    ray: &'a Ray,
    /// Which axes become x, y and z (z is the ray's largest component).
    k: [usize; 3],
    /// The origin's coordinates in that order, one per SIMD row.
    o: [Vec3A; 3],
    /// The shear: x += sx z, y += sy z, z *= sz.
    sx: f32,
    sy: f32,
    sz: f32,
}

// ANCHOR: watertight_ray
impl<'a> WatertightRay<'a> {
    /// Permutation and shear for `ray`, exactly as the readable test
    /// computes them for every triangle.
    pub fn new(ray: &'a Ray) -> WatertightRay<'a> {
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
        // (kz + 1) % 3, (kz + 2) % 3, kz, without the divisions.
        const PERMUTATION: [[usize; 3]; 3] = [[1, 2, 0], [2, 0, 1], [0, 1, 2]];
        let k = PERMUTATION[kz];
        let (dir, origin) = (ray.dir.to_array(), ray.origin.to_array());
        let d = Vec3::new(dir[k[0]], dir[k[1]], dir[k[2]]);
        WatertightRay {
            ray,
            k,
            o: k.map(|i| Vec3A::splat(origin[i])),
            sx: -d.x / d.z,
            sy: -d.y / d.z,
            sz: 1.0 / d.z,
        }
    }

    /// The watertight test of `tri` in (t_min, t_max): the same hits, t, u
    /// and v as [`intersect_watertight`](crate::triangle::intersect_watertight)
    /// on the triangle's vertices (`triangle` is left 0).
    #[inline(always)]
    pub fn intersect(&self, tri: &SoaTriangle, t_min: f32, t_max: f32) -> Option<Hit> {
        // Translate and permute: x = (a.x, b.x, c.x) and so on.
        let x = tri.rows[self.k[0]] - self.o[0];
        let y = tri.rows[self.k[1]] - self.o[1];
        let z = tri.rows[self.k[2]] - self.o[2];
        // Shear so the ray points along +z.
        let x = x + self.sx * z;
        let y = y + self.sy * z;
        // The three edge functions at once: (b.x c.y - b.y c.x, ...).
        let mut e = x.yzx() * y.zxy() - y.yzx() * x.zxy();
        if e.cmpeq(Vec3A::ZERO).any() {
            e = edges_in_f64(x, y);
        }
        if e.cmplt(Vec3A::ZERO).any() && e.cmpgt(Vec3A::ZERO).any() {
            return None;
        }
        let det = e.x + e.y + e.z;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let z = z * self.sz;
        let ez = e * z;
        let t_scaled = ez.x + ez.y + ez.z;
        if det < 0.0 && (t_scaled >= t_min * det || t_scaled < t_max * det) {
            return None;
        }
        if det > 0.0 && (t_scaled <= t_min * det || t_scaled > t_max * det) {
            return None;
        }
        let inv_det = 1.0 / det;
        let t = t_scaled * inv_det;
        if t <= delta_t(x, y, z, e, inv_det) && !ahead_in_f64(self.ray, tri.vertices(), t_min) {
            return None;
        }
        Some(Hit {
            t,
            u: e.y * inv_det,
            v: e.z * inv_det,
            triangle: 0,
        })
    }
}
// ANCHOR_END: watertight_ray

/// The edge functions in f64, where the products of f32 values are exact.
#[cold]
#[inline(never)]
fn edges_in_f64(x: Vec3A, y: Vec3A) -> Vec3A {
    let f = |p: f32, q: f32, r: f32, s: f32| (p as f64 * q as f64 - r as f64 * s as f64) as f32;
    Vec3A::new(
        f(x.y, y.z, y.y, x.z),
        f(x.z, y.x, y.z, x.x),
        f(x.x, y.y, y.x, x.y),
    )
}

/// pbrt-v4's bound on the rounding error of t (see the readable version).
#[inline(always)]
fn delta_t(x: Vec3A, y: Vec3A, z: Vec3A, e: Vec3A, inv_det: f32) -> f32 {
    let max_zt = z.abs().max_element();
    let max_xt = x.abs().max_element();
    let max_yt = y.abs().max_element();
    let delta_z = gamma(3) * max_zt;
    let delta_x = gamma(5) * (max_xt + max_zt);
    let delta_y = gamma(5) * (max_yt + max_zt);
    let delta_e = 2.0 * (gamma(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
    let max_e = e.abs().max_element();
    3.0 * (gamma(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * inv_det.abs()
}
