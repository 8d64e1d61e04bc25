//! The lane tests of the fast engine's eight-wide tree, written once in
//! plain Rust over `[f32; 8]` arrays: the slab test of a node's eight
//! boxes and the watertight test of a leaf's eight triangles. Each lane's
//! arithmetic is chapter 3's in the order
//! [`WatertightRay::intersect4`](crate::ch3_ray_triangle::watertight_fast::WatertightRay::intersect4) uses, so every hit (t, u, v) is bit for
//! bit what the readable engine finds. [`super::simd`] holds the same two
//! tests in AVX2 instructions. And the last steps
//! of a Sobol point (the Owen scramble), in integer lanes.

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::gamma;
use crate::ch3_ray_triangle::watertight_fast::WatertightRay;
use crate::ch3_ray_triangle::wide_bvh::BoxRay;

use super::sobol8::owen_dim;

/// Children per node and triangles per leaf.
pub const W: usize = 8;
/// Most triangles in a leaf.
pub(super) const LEAF_SIZE: usize = 8;
/// A child reference with this bit set is a leaf.
pub(super) const LEAF: u32 = 1 << 31;
/// How much a box's far distance is stretched: the readable tree's.
pub(super) use crate::ch3_ray_triangle::wide_bvh::FAR_STRETCH;

/// Eight children's boxes by axis; an unused slot has an empty box.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
pub(super) struct Node8 {
    pub(super) min: [[f32; W]; 3],
    pub(super) max: [[f32; W]; 3],
    pub(super) child: [u32; W],
}

/// Eight triangles: `p[axis][vertex][lane]`. Unused lanes and zero-area
/// triangles hold NaN, which every test rejects.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
pub(super) struct Leaf8 {
    pub(super) p: [[[f32; W]; 3]; 3],
}

/// What the box and triangle tests need of a ray, computed once per ray
/// by the readable tree's own per-ray steps (chapter 3's `BoxRay` and
/// `WatertightRay`), in the scalar form the lane loops read.
pub struct RayData<'a> {
    /// The watertight test's per-ray part, also for the rare lanes the
    /// one-triangle test decides.
    pub(super) wt: WatertightRay<'a>,
    /// Origin, 1/direction (tiny components kept finite), and per axis
    /// whether the direction is negative.
    pub(super) o: [f32; 3],
    pub(super) inv: [f32; 3],
    pub(super) negative: [bool; 3],
    /// Watertight permutation, permuted origin and shear.
    pub(super) k: [usize; 3],
    pub(super) ko: [f32; 3],
    pub(super) s: [f32; 3],
}

impl<'a> RayData<'a> {
    /// The per-ray data of `ray`.
    #[inline(always)]
    pub fn new(ray: &'a Ray) -> RayData<'a> {
        let wt = WatertightRay::new(ray);
        let (k, ko, s) = wt.setup();
        let b = BoxRay::new(ray);
        RayData {
            wt,
            o: b.o.map(|v| v.x),
            inv: b.inv.map(|v| v.x),
            negative: b.negative,
            k,
            ko,
            s,
        }
    }
}

/// Bit i set where lane i is true.
#[inline(always)]
fn mask(b: [bool; W]) -> u32 {
    let mut bits = [0u32; W];
    for i in 0..W {
        bits[i] = (b[i] as u32) << i;
    }
    bits.iter().fold(0, |m, x| m | x)
}

/// The slab test of a node's eight boxes against (0, t_max): the mask of
/// children entered and where the ray enters each.
// ANCHOR: slab8
#[inline(always)]
pub(super) fn enter(r: &RayData, node: &Node8, t_max: f32) -> (u32, [f32; W]) {
    let mut t_near = [0.0f32; W];
    let mut t_far = [t_max; W];
    for axis in 0..3 {
        let (near, far) = match r.negative[axis] {
            true => (&node.max[axis], &node.min[axis]),
            false => (&node.min[axis], &node.max[axis]),
        };
        for i in 0..W {
            t_near[i] = t_near[i].max((near[i] - r.o[axis]) * r.inv[axis]);
            t_far[i] = t_far[i].min((far[i] - r.o[axis]) * r.inv[axis]);
        }
    }
    let mut entered = [false; W];
    for i in 0..W {
        entered[i] = t_near[i] <= t_far[i] * FAR_STRETCH;
    }
    (mask(entered), t_near)
}
// ANCHOR_END: slab8

/// What [`leaf_test`] found: hit and check masks, and t, u, v per lane.
pub(super) struct Hits8 {
    pub(super) hit: u32,
    pub(super) check: u32,
    pub(super) t: [f32; W],
    pub(super) u: [f32; W],
    pub(super) v: [f32; W],
}

/// The watertight test on a leaf's eight triangles in (0, t_max), lane
/// by lane in the order of the four-wide test. One loop without branches
/// (bitwise `&` and `|` on the comparisons, no early exit), which the
/// compiler turns into vector instructions.
// ANCHOR: leaf8
#[inline(always)]
pub(super) fn leaf_test(r: &RayData, leaf: &Leaf8, t_max: f32) -> Hits8 {
    let (px, py, pz) = (&leaf.p[r.k[0]], &leaf.p[r.k[1]], &leaf.p[r.k[2]]);
    let [ox, oy, oz] = r.ko;
    let [sx, sy, sz] = r.s;
    let mut h = Hits8 {
        hit: 0,
        check: 0,
        t: [0.0; W],
        u: [0.0; W],
        v: [0.0; W],
    };
    // First the edge functions and which lanes can hit at all; the
    // division and the error bound only when one can (most leaves a ray
    // enters hold no hit).
    let mut e = [[0.0f32; W]; 3];
    let (mut xs, mut ys, mut zs) = ([[0.0f32; W]; 3], [[0.0f32; W]; 3], [[0.0f32; W]; 3]);
    let (mut det, mut ts) = ([0.0f32; W], [0.0f32; W]);
    let (mut candidate, mut any_zero) = ([false; W], [false; W]);
    for i in 0..W {
        // Translate, permute and shear each vertex (a, b, c).
        let (z0, z1, z2) = (pz[0][i] - oz, pz[1][i] - oz, pz[2][i] - oz);
        let (x0, x1, x2) = (
            (px[0][i] - ox) + sx * z0,
            (px[1][i] - ox) + sx * z1,
            (px[2][i] - ox) + sx * z2,
        );
        let (y0, y1, y2) = (
            (py[0][i] - oy) + sy * z0,
            (py[1][i] - oy) + sy * z1,
            (py[2][i] - oy) + sy * z2,
        );
        // The edge functions.
        let e0 = x1 * y2 - y1 * x2;
        let e1 = x2 * y0 - y2 * x0;
        let e2 = x0 * y1 - y0 * x1;
        any_zero[i] = (e0 == 0.0) | (e1 == 0.0) | (e2 == 0.0);
        let neg = (e0 < 0.0) | (e1 < 0.0) | (e2 < 0.0);
        let pos = (e0 > 0.0) | (e1 > 0.0) | (e2 > 0.0);
        let d = e0 + e1 + e2;
        let (z0, z1, z2) = (z0 * sz, z1 * sz, z2 * sz);
        let t_scaled = e0 * z0 + e1 * z1 + e2 * z2;
        let (lo, hi) = (0.0 * d, t_max * d);
        let in_neg = (d < 0.0) & (t_scaled < lo) & (t_scaled >= hi);
        let in_pos = (d > 0.0) & (t_scaled > lo) & (t_scaled <= hi);
        let finite = d.abs() < f32::INFINITY;
        candidate[i] = !(neg & pos) & finite & (in_neg | in_pos);
        (e[0][i], e[1][i], e[2][i]) = (e0, e1, e2);
        (xs[0][i], xs[1][i], xs[2][i]) = (x0, x1, x2);
        (ys[0][i], ys[1][i], ys[2][i]) = (y0, y1, y2);
        (zs[0][i], zs[1][i], zs[2][i]) = (z0, z1, z2);
        (det[i], ts[i]) = (d, t_scaled);
    }
    let (candidates, zeros) = (mask(candidate), mask(any_zero));
    if candidates == 0 {
        h.check = zeros;
        return h;
    }
    let g = gamma;
    let mut trusted = [false; W];
    let max3 = |v: &[[f32; W]; 3], i: usize| v[0][i].abs().max(v[1][i].abs()).max(v[2][i].abs());
    for i in 0..W {
        let inv_det = 1.0 / det[i];
        let t = ts[i] * inv_det;
        // pbrt-v4's bound on the rounding error of t.
        let (max_zt, max_xt, max_yt) = (max3(&zs, i), max3(&xs, i), max3(&ys, i));
        let delta_z = g(3) * max_zt;
        let delta_x = g(5) * (max_xt + max_zt);
        let delta_y = g(5) * (max_yt + max_zt);
        let delta_e = 2.0 * (g(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
        let max_e = max3(&e, i);
        let delta_t =
            3.0 * (g(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * inv_det.abs();
        trusted[i] = t > delta_t;
        h.t[i] = t;
        h.u[i] = e[1][i] * inv_det;
        h.v[i] = e[2][i] * inv_det;
    }
    let trusted = mask(trusted);
    h.hit = candidates & trusted & !zeros;
    h.check = zeros | (candidates & !trusted);
    h
}
// ANCHOR_END: leaf8

/// The last steps of the crate's `sample_4d` on a Sobol point's four
/// dimensions (reversed bits): the Owen scramble with a seed per dimension,
/// the bits put back in order, the conversion to [0, 1). Written lane by
/// lane in integers, so that the compiler can run the four lanes in one
/// vector register, and any width gives the same bits.
#[inline(always)]
pub fn owen_finish_lanes(sobol: [u32; 4], seed: u32) -> [f32; 4] {
    let s = seed.wrapping_mul(0x9c8f2d3b);
    std::array::from_fn(|d| owen_dim(sobol[d], s, d))
}
