//! The watertight test, rearranged for speed: the same arithmetic as
//! [`intersect_watertight`](crate::ch3_ray_triangle::triangle::intersect_watertight), bit for
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

use glam::{Vec3, Vec3A, Vec3Swizzles, Vec4};

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::rounding::t_error_bound;
use crate::ch3_ray_triangle::triangle::{ahead_in_f64, Hit};

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

/// Four triangles stored by coordinate and vertex, one triangle per SIMD
/// lane: `rows[axis][vertex]` holds that coordinate of that vertex of all
/// four. The wide BVH's leaves are tested four triangles at a time this
/// way ([`WatertightRay::intersect4`]), with no branch per triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tri4 {
    /// `rows[axis][vertex]`, lanes = triangles.
    pub rows: [[Vec4; 3]; 3],
}

impl Tri4 {
    /// Packs four triangles (as [`SoaTriangle`]s, so zero-area ones are
    /// already collapsed to a point).
    pub fn new(tris: [SoaTriangle; 4]) -> Tri4 {
        let lane = |axis: usize, vertex: usize| {
            Vec4::from_array(tris.map(|t| t.rows[axis].to_array()[vertex]))
        };
        Tri4 {
            rows: [0, 1, 2].map(|axis| [0, 1, 2].map(|vertex| lane(axis, vertex))),
        }
    }
}

/// What [`WatertightRay::intersect4`] found, lane by lane.
#[derive(Clone, Copy, Debug)]
pub struct Hits4 {
    /// Bit i: lane i is a hit, with `t`, `u` and `v` below (exactly what
    /// the one-triangle test returns).
    pub hit: u32,
    /// Bit i: lane i needs the one-triangle test to decide (an edge
    /// function exactly zero, or t too small to trust), which is rare.
    pub check: u32,
    /// t of each lane.
    pub t: Vec4,
    /// u of each lane.
    pub u: Vec4,
    /// v of each lane.
    pub v: Vec4,
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
    #[inline]
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
        // (-dx / dz, -dy / dz, 1 / dz) in one SIMD division.
        let s = Vec3A::new(-d.x, -d.y, 1.0) / Vec3A::splat(d.z);
        WatertightRay {
            ray,
            k,
            o: k.map(|i| Vec3A::splat(origin[i])),
            sx: s.x,
            sy: s.y,
            sz: s.z,
        }
    }

    /// The watertight test of `tri` in (t_min, t_max): the same hits, t, u
    /// and v as [`intersect_watertight`](crate::ch3_ray_triangle::triangle::intersect_watertight)
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

impl WatertightRay<'_> {
    /// The per-ray part of the test, for tests written elsewhere over more
    /// lanes (chapter 6's eight-wide tree): which axes become x, y and z,
    /// the origin's coordinates in that order, and the shear (sx, sy, sz).
    #[inline(always)]
    pub fn setup(&self) -> ([usize; 3], [f32; 3], [f32; 3]) {
        (self.k, self.o.map(|o| o.x), [self.sx, self.sy, self.sz])
    }

    /// [`WatertightRay::intersect`] on four triangles at once: the same
    /// arithmetic in the same order, one triangle per lane, so every lane's
    /// t, u and v are bit for bit what the one-triangle test gives. Lanes
    /// whose result depends on the test's rare exact paths are flagged in
    /// [`Hits4::check`] for the caller to run the one-triangle test on.
    #[inline(always)]
    pub fn intersect4(&self, tri: &Tri4, t_min: f32, t_max: f32) -> Hits4 {
        let [ox, oy, oz] = self.o.map(|o| Vec4::splat(o.x));
        let (sx, sy, sz) = (
            Vec4::splat(self.sx),
            Vec4::splat(self.sy),
            Vec4::splat(self.sz),
        );
        let [rx, ry, rz] = [
            tri.rows[self.k[0]],
            tri.rows[self.k[1]],
            tri.rows[self.k[2]],
        ];
        // Translate, permute and shear each vertex (a, b, c).
        let z = [rz[0] - oz, rz[1] - oz, rz[2] - oz];
        let x = [0, 1, 2].map(|j| (rx[j] - ox) + sx * z[j]);
        let y = [0, 1, 2].map(|j| (ry[j] - oy) + sy * z[j]);
        // Edge functions, as in the one-triangle test's swizzles:
        // e0 = b.x c.y - b.y c.x, e1 = c.x a.y - c.y a.x, e2 = a.x b.y - a.y b.x.
        let e0 = x[1] * y[2] - y[1] * x[2];
        let e1 = x[2] * y[0] - y[2] * x[0];
        let e2 = x[0] * y[1] - y[0] * x[1];
        let zero = Vec4::ZERO;
        let any_zero = e0.cmpeq(zero) | e1.cmpeq(zero) | e2.cmpeq(zero);
        let neg = e0.cmplt(zero) | e1.cmplt(zero) | e2.cmplt(zero);
        let pos = e0.cmpgt(zero) | e1.cmpgt(zero) | e2.cmpgt(zero);
        let det = e0 + e1 + e2;
        let z = z.map(|zj| zj * sz);
        let t_scaled = e0 * z[0] + e1 * z[1] + e2 * z[2];
        let (lo, hi) = (Vec4::splat(t_min) * det, Vec4::splat(t_max) * det);
        let in_range_neg = det.cmplt(zero) & t_scaled.cmplt(lo) & t_scaled.cmpge(hi);
        let in_range_pos = det.cmpgt(zero) & t_scaled.cmpgt(lo) & t_scaled.cmple(hi);
        let finite = det.is_finite_mask();
        let candidate = !(neg & pos) & finite & (in_range_neg | in_range_pos);
        if !candidate.any() {
            // No lane can hit: skip the division and the error bound.
            return Hits4 {
                hit: 0,
                check: any_zero.bitmask(),
                t: Vec4::ZERO,
                u: Vec4::ZERO,
                v: Vec4::ZERO,
            };
        }
        let inv_det = Vec4::ONE / det;
        let t = t_scaled * inv_det;
        let trusted = t.cmpgt(delta_t4(x, y, z, [e0, e1, e2], inv_det));
        let hit = candidate & trusted & !any_zero;
        let check = any_zero | (candidate & !trusted);
        Hits4 {
            hit: hit.bitmask(),
            check: check.bitmask(),
            t,
            u: e1 * inv_det,
            v: e2 * inv_det,
        }
    }
}

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

/// [`delta_t`] lane by lane, in the same order of operations.
#[inline(always)]
fn delta_t4(x: [Vec4; 3], y: [Vec4; 3], z: [Vec4; 3], e: [Vec4; 3], inv_det: Vec4) -> Vec4 {
    let max_abs = |v: [Vec4; 3]| v[0].abs().max(v[1].abs()).max(v[2].abs());
    t_error_bound(max_abs(x), max_abs(y), max_abs(z), max_abs(e), inv_det)
}

/// pbrt-v4's bound on the rounding error of t ([`super::rounding`]).
#[inline(always)]
fn delta_t(x: Vec3A, y: Vec3A, z: Vec3A, e: Vec3A, inv_det: f32) -> f32 {
    let max = |v: Vec3A| v.abs().max_element();
    t_error_bound(max(x), max(y), max(z), max(e), inv_det)
}
