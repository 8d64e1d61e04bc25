//! The lane tests of the fast engine's eight-wide tree, written once in
//! plain Rust over `[f32; 8]` arrays: the slab test of a node's eight
//! boxes and the watertight test of a leaf's eight triangles. Each lane's
//! arithmetic is chapter 3's in the order
//! [`WatertightRay::intersect4`](crate::ch3_ray_triangle::watertight_fast::WatertightRay::intersect4) uses, so every hit (t, u, v) is bit for
//! bit what the readable engine finds. [`super::kernels`] holds the same
//! two tests over a vector type, which the queries run. And the last steps
//! of a Sobol point (the Owen scramble), in integer lanes.

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::rounding::t_error_bound;
use crate::ch3_ray_triangle::watertight_fast::WatertightRay;
use crate::ch3_ray_triangle::wide_bvh::BoxRay;

/// The lane width: children per node, triangles per leaf, paths shaded
/// together.
pub const W: usize = 8;
/// Most triangles in a leaf.
pub(super) const LEAF_SIZE: usize = 8;
/// A child reference with this bit set is a leaf.
pub(super) use crate::ch3_ray_triangle::wide_build::LEAF;
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

/// Bit i set where lane i is true. The eight lanes as the bytes of one
/// number (each 0 or 1, lane i at byte i), gathered into its top byte by
/// one multiplication: byte i times 2^(56 − 7i) lands on bit 56 + i, and
/// every other product lands below bit 56 or beyond bit 63, no two on the
/// same bit, so nothing carries. (Eight shifts and ors, without AVX's
/// instruction that does this, cost several times more.)
#[inline(always)]
pub fn mask(b: [bool; W]) -> u32 {
    const GATHER: u64 = 0x0102_0408_1020_4080;
    let bytes = u64::from_le_bytes(b.map(u8::from));
    (bytes.wrapping_mul(GATHER) >> 56) as u32
}

/// The larger of `x` and `y` as a select: `y` where it is larger, else
/// `x`, the rule of the vector max instruction (which the kernels
/// use). `f32::max` asks for more without AVX, to treat a NaN, which never
/// comes where the lane loops call this.
#[inline(always)]
pub(super) fn larger(x: f32, y: f32) -> f32 {
    if y > x {
        y
    } else {
        x
    }
}

/// The smaller of `x` and `y`, likewise: `y` where it is smaller, else `x`.
#[inline(always)]
pub(super) fn smaller(x: f32, y: f32) -> f32 {
    if y < x {
        y
    } else {
        x
    }
}

/// The slab test of a node's first `N` boxes (all eight, or the first
/// four where the others are empty) against (0, t_max): the mask of
/// children entered and where the ray enters each.
// ANCHOR: slab8
#[inline(always)]
pub(super) fn enter<const N: usize>(r: &RayData, node: &Node8, t_max: f32) -> (u32, [f32; W]) {
    let mut t_near = [0.0f32; W];
    let mut t_far = [t_max; W];
    for axis in 0..3 {
        let (near, far) = match r.negative[axis] {
            true => (&node.max[axis], &node.min[axis]),
            false => (&node.min[axis], &node.max[axis]),
        };
        for i in 0..N {
            let enters = (near[i] - r.o[axis]) * r.inv[axis];
            let leaves = (far[i] - r.o[axis]) * r.inv[axis];
            t_near[i] = larger(t_near[i], enters);
            t_far[i] = smaller(t_far[i], leaves);
        }
    }
    let mut entered = [false; W];
    for i in 0..N {
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

/// One lane of the watertight test's first half: a triangle's corners
/// (coordinates on the ray's permuted axes: `px[vertex]`, ...) moved into
/// the frame of a ray with permuted origin `ko` and shear `s`, the edge
/// functions, and whether the ray can hit it in (0, t_max). The one-ray
/// test's arithmetic in its order, so that a loop over lanes (triangles
/// or rays) gives the same bits whichever way it runs.
pub(super) struct FrontLane {
    pub(super) x: [f32; 3],
    pub(super) y: [f32; 3],
    /// The corners' z, sheared (times sz).
    pub(super) z: [f32; 3],
    pub(super) e: [f32; 3],
    pub(super) det: f32,
    /// t times det.
    pub(super) ts: f32,
    pub(super) candidate: bool,
    /// An edge function is exactly zero (the one-triangle test decides).
    pub(super) zero: bool,
}

/// Eight lanes' [`FrontLane`]s stored by field (`x[vertex][lane]`, ...),
/// the form whose lane loops become vector instructions.
#[derive(Default)]
pub(super) struct Fronts {
    pub(super) x: [[f32; W]; 3],
    pub(super) y: [[f32; W]; 3],
    pub(super) z: [[f32; W]; 3],
    pub(super) e: [[f32; W]; 3],
    pub(super) det: [f32; W],
    pub(super) ts: [f32; W],
    pub(super) candidate: [bool; W],
    pub(super) zero: [bool; W],
}

impl Fronts {
    /// Stores lane `j`.
    #[inline(always)]
    pub(super) fn set(&mut self, j: usize, f: &FrontLane) {
        for c in 0..3 {
            (self.x[c][j], self.y[c][j], self.z[c][j]) = (f.x[c], f.y[c], f.z[c]);
            self.e[c][j] = f.e[c];
        }
        (self.det[j], self.ts[j]) = (f.det, f.ts);
        (self.candidate[j], self.zero[j]) = (f.candidate, f.zero);
    }

    /// Lane `j` again.
    #[inline(always)]
    pub(super) fn get(&self, j: usize) -> FrontLane {
        let at = |v: &[[f32; W]; 3]| [v[0][j], v[1][j], v[2][j]];
        FrontLane {
            x: at(&self.x),
            y: at(&self.y),
            z: at(&self.z),
            e: at(&self.e),
            det: self.det[j],
            ts: self.ts[j],
            candidate: self.candidate[j],
            zero: self.zero[j],
        }
    }
}

// ANCHOR: front_lane
#[inline(always)]
pub(super) fn front_lane(
    (px, py, pz): ([f32; 3], [f32; 3], [f32; 3]),
    ([ox, oy, oz], [sx, sy, sz]): ([f32; 3], [f32; 3]),
    t_max: f32,
) -> FrontLane {
    // Translate, permute and shear each vertex (a, b, c).
    let (z0, z1, z2) = (pz[0] - oz, pz[1] - oz, pz[2] - oz);
    let (x0, x1, x2) = (
        (px[0] - ox) + sx * z0,
        (px[1] - ox) + sx * z1,
        (px[2] - ox) + sx * z2,
    );
    let (y0, y1, y2) = (
        (py[0] - oy) + sy * z0,
        (py[1] - oy) + sy * z1,
        (py[2] - oy) + sy * z2,
    );
    // The edge functions.
    let e0 = x1 * y2 - y1 * x2;
    let e1 = x2 * y0 - y2 * x0;
    let e2 = x0 * y1 - y0 * x1;
    let zero = (e0 == 0.0) | (e1 == 0.0) | (e2 == 0.0);
    let neg = (e0 < 0.0) | (e1 < 0.0) | (e2 < 0.0);
    let pos = (e0 > 0.0) | (e1 > 0.0) | (e2 > 0.0);
    let d = e0 + e1 + e2;
    let (z0, z1, z2) = (z0 * sz, z1 * sz, z2 * sz);
    let t_scaled = e0 * z0 + e1 * z1 + e2 * z2;
    let (lo, hi) = (0.0 * d, t_max * d);
    let in_neg = (d < 0.0) & (t_scaled < lo) & (t_scaled >= hi);
    let in_pos = (d > 0.0) & (t_scaled > lo) & (t_scaled <= hi);
    let finite = d.abs() < f32::INFINITY;
    FrontLane {
        x: [x0, x1, x2],
        y: [y0, y1, y2],
        z: [z0, z1, z2],
        e: [e0, e1, e2],
        det: d,
        ts: t_scaled,
        candidate: !(neg & pos) & finite & (in_neg | in_pos),
        zero,
    }
}
// ANCHOR_END: front_lane

/// One lane of the second half, for a lane that can hit ([`FrontLane`]'s
/// numbers, read back from wherever a lane loop keeps them): t, 1/det,
/// and whether pbrt-v4's bound on the rounding error of t trusts it.
// ANCHOR: trust_lane
#[inline(always)]
pub(super) fn trust_lane(f: &FrontLane) -> (f32, f32, bool) {
    let max3 = |v: &[f32; 3]| larger(larger(v[0].abs(), v[1].abs()), v[2].abs());
    let inv_det = 1.0 / f.det;
    let t = f.ts * inv_det;
    let delta_t = t_error_bound(max3(&f.x), max3(&f.y), max3(&f.z), max3(&f.e), inv_det);
    (t, inv_det, t > delta_t)
}
// ANCHOR_END: trust_lane

/// The watertight test on a leaf's first `N` triangles (all eight, or
/// the first four where the others are empty) in (0, t_max), lane by
/// lane ([`front_lane`], [`trust_lane`]) in the order of the four-wide
/// test. One loop without branches (bitwise `&` and `|` on the
/// comparisons, no early exit), which the compiler turns into vector
/// instructions.
// ANCHOR: leaf8
#[allow(clippy::needless_range_loop)] // lane loops, on purpose
#[inline(always)]
pub(super) fn leaf_test<const N: usize>(r: &RayData, leaf: &Leaf8, t_max: f32) -> Hits8 {
    let (px, py, pz) = (&leaf.p[r.k[0]], &leaf.p[r.k[1]], &leaf.p[r.k[2]]);
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
    let mut f = Fronts::default();
    for i in 0..N {
        let tri = (
            [px[0][i], px[1][i], px[2][i]],
            [py[0][i], py[1][i], py[2][i]],
            [pz[0][i], pz[1][i], pz[2][i]],
        );
        f.set(i, &front_lane(tri, (r.ko, r.s), t_max));
    }
    let (candidates, zeros) = (mask(f.candidate), mask(f.zero));
    if candidates == 0 {
        h.check = zeros;
        return h;
    }
    let mut trusted = [false; W];
    for i in 0..N {
        let (t, inv_det, trust) = trust_lane(&f.get(i));
        trusted[i] = trust;
        h.t[i] = t;
        h.u[i] = f.e[1][i] * inv_det;
        h.v[i] = f.e[2][i] * inv_det;
    }
    let trusted = mask(trusted);
    h.hit = candidates & trusted & !zeros;
    h.check = zeros | (candidates & !trusted);
    h
}
// ANCHOR_END: leaf8
