//! The two lane tests written with AVX intrinsics, eight lanes in one
//! register, in exactly the operations and order of the portable loops in
//! [`lanes`](super::super::lanes) (so the same bits; `max`/`min` take the new value first,
//! so a NaN keeps the old one, as `f32::max` does).
//!
//! SAFETY (for every `unsafe` block below): these functions are only
//! reached from the `#[target_feature(enable = "avx2,...")]` entry points
//! in [`super`], which run only on CPUs that have AVX2 (`Level::available`); every
//! load reads a whole `[f32; 8]` that the reference proves is there.

use std::arch::x86_64::*;

use super::super::bvh8::Bvh8;
use super::super::lanes::{Leaf8, Node8, RayData, FAR_STRETCH, W};
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::rounding::{t_error_bound, Lanes};
use crate::ch3_ray_triangle::triangle::Hit;
use crate::ch3_ray_triangle::wide_build::{self, AnyHit, ClosestHit, Nearest, WideTree};

#[target_feature(enable = "avx2,fma")]
#[inline]
fn load(a: &[f32; W]) -> __m256 {
    // SAFETY: see the module.
    unsafe { _mm256_loadu_ps(a.as_ptr()) }
}

#[target_feature(enable = "avx2,fma")]
#[inline]
fn store(v: __m256) -> [f32; W] {
    let mut a = [0.0f32; W];
    // SAFETY: see the module.
    unsafe { _mm256_storeu_ps(a.as_mut_ptr(), v) };
    a
}

/// A ray's numbers as the tests use them, each in all eight lanes: built
/// once per query ([`splat!`]) so that the loop reads them from registers.
struct Splat {
    /// Origin and 1/direction per axis, and whether the direction is
    /// negative (the slab test).
    o: [__m256; 3],
    inv: [__m256; 3],
    negative: [bool; 3],
    /// The watertight permutation, the permuted origin and the shear.
    k: [usize; 3],
    ko: [__m256; 3],
    s: [__m256; 3],
}

/// The [`Splat`] of a [`RayData`] (a macro for the reason [`front!`] is).
macro_rules! splat {
    ($r:expr) => {{
        let r: &RayData = $r;
        Splat {
            o: r.o.map(|x| _mm256_set1_ps(x)),
            inv: r.inv.map(|x| _mm256_set1_ps(x)),
            negative: r.negative,
            k: r.k,
            ko: r.ko.map(|x| _mm256_set1_ps(x)),
            s: r.s.map(|x| _mm256_set1_ps(x)),
        }
    }};
}

#[target_feature(enable = "avx2,fma")]
#[inline]
fn enter_avx(r: &Splat, node: &Node8, t_max: f32) -> (u32, [f32; W]) {
    {
        let mut t_near = _mm256_setzero_ps();
        let mut t_far = _mm256_set1_ps(t_max);
        for axis in 0..3 {
            let (near, far) = match r.negative[axis] {
                true => (&node.max[axis], &node.min[axis]),
                false => (&node.min[axis], &node.max[axis]),
            };
            let (o, inv) = (r.o[axis], r.inv[axis]);
            t_near = _mm256_max_ps(_mm256_mul_ps(_mm256_sub_ps(load(near), o), inv), t_near);
            t_far = _mm256_min_ps(_mm256_mul_ps(_mm256_sub_ps(load(far), o), inv), t_far);
        }
        let stretched = _mm256_mul_ps(t_far, _mm256_set1_ps(FAR_STRETCH));
        let entered = _mm256_cmp_ps::<_CMP_LE_OQ>(t_near, stretched);
        (_mm256_movemask_ps(entered) as u32, store(t_near))
    }
}

/// The first half of the leaf test: each triangle's corners moved into
/// the ray's frame, the edge functions, and which lanes can hit at all
/// (`Front`). Written as a macro so that it expands inside the functions
/// that use it: a `#[target_feature]` helper returning registers is not
/// reliably inlined, and then its results go through memory.
macro_rules! front {
    ($r:expr, $leaf:expr, $t_max:expr) => {{
        let (r, leaf, t_max): (&Splat, &Leaf8, f32) = ($r, $leaf, $t_max);
        let (px, py, pz) = (&leaf.p[r.k[0]], &leaf.p[r.k[1]], &leaf.p[r.k[2]]);
        let [ox, oy, oz] = r.ko;
        let [sx, sy, sz] = r.s;
        let (add, sub, mul) = (_mm256_add_ps, _mm256_sub_ps, _mm256_mul_ps);
        let zero = _mm256_setzero_ps();
        // Three calls, not `[0, 1, 2].map(…)`: `map` is not inlined where
        // this expands outside a `#[target_feature]` function (the
        // traversals' `Kernels`), and its closure would then call every
        // intrinsic out of line.
        let zj = |j: usize| sub(load(&pz[j]), oz);
        let z = [zj(0), zj(1), zj(2)];
        let xj = |j: usize| add(sub(load(&px[j]), ox), mul(sx, z[j]));
        let yj = |j: usize| add(sub(load(&py[j]), oy), mul(sy, z[j]));
        let (x, y) = ([xj(0), xj(1), xj(2)], [yj(0), yj(1), yj(2)]);
        let e0 = sub(mul(x[1], y[2]), mul(y[1], x[2]));
        let e1 = sub(mul(x[2], y[0]), mul(y[2], x[0]));
        let e2 = sub(mul(x[0], y[1]), mul(y[0], x[1]));
        let or3 = |a, b, c| _mm256_or_ps(_mm256_or_ps(a, b), c);
        let any_zero = or3(
            _mm256_cmp_ps::<_CMP_EQ_OQ>(e0, zero),
            _mm256_cmp_ps::<_CMP_EQ_OQ>(e1, zero),
            _mm256_cmp_ps::<_CMP_EQ_OQ>(e2, zero),
        );
        // Edge functions of both signs: no hit. Where one is not finite,
        // det is not either and `finite` below rejects the lane, so the
        // minimum and maximum answer exactly as the six comparisons of
        // the lane loops do.
        let (min, max) = (_mm256_min_ps, _mm256_max_ps);
        let mixed = _mm256_and_ps(
            _mm256_cmp_ps::<_CMP_LT_OQ>(min(min(e0, e1), e2), zero),
            _mm256_cmp_ps::<_CMP_GT_OQ>(max(max(e0, e1), e2), zero),
        );
        let det = add(add(e0, e1), e2);
        let zs = [mul(z[0], sz), mul(z[1], sz), mul(z[2], sz)];
        let ts = add(add(mul(e0, zs[0]), mul(e1, zs[1])), mul(e2, zs[2]));
        // The lane loops' two cases (det < 0 and det > 0) as one: with
        // det's sign taken off det and ts (exact), 0 < ts <= t_max det.
        let sign = _mm256_and_ps(det, _mm256_set1_ps(-0.0));
        let (abs_det, ts_pos) = (_mm256_xor_ps(det, sign), _mm256_xor_ps(ts, sign));
        let and = _mm256_and_ps;
        let inside = and(
            and(
                _mm256_cmp_ps::<_CMP_GT_OQ>(abs_det, zero),
                _mm256_cmp_ps::<_CMP_GT_OQ>(ts_pos, zero),
            ),
            _mm256_cmp_ps::<_CMP_LE_OQ>(ts_pos, mul(_mm256_set1_ps(t_max), abs_det)),
        );
        let finite = _mm256_cmp_ps::<_CMP_LT_OQ>(abs_det, _mm256_set1_ps(f32::INFINITY));
        let candidate = _mm256_andnot_ps(mixed, and(finite, inside));
        Front {
            x,
            y,
            zs,
            e: [e0, e1, e2],
            det,
            ts,
            candidates: _mm256_movemask_ps(candidate) as u32,
            zeros: _mm256_movemask_ps(any_zero) as u32,
        }
    }};
}

/// Eight lanes in one register, for the bound on t's rounding error
/// written once over a lane type ([`t_error_bound`]). Its operations run
/// AVX instructions: a value exists only inside this module's functions,
/// which run only where the CPU has AVX2 (see the SAFETY note above).
#[derive(Clone, Copy)]
struct Eight(__m256);

impl std::ops::Add for Eight {
    type Output = Eight;
    #[inline(always)]
    fn add(self, o: Eight) -> Eight {
        // SAFETY: an `Eight` exists only where the CPU has AVX2.
        Eight(unsafe { _mm256_add_ps(self.0, o.0) })
    }
}

impl std::ops::Mul for Eight {
    type Output = Eight;
    #[inline(always)]
    fn mul(self, o: Eight) -> Eight {
        // SAFETY: as for `add`.
        Eight(unsafe { _mm256_mul_ps(self.0, o.0) })
    }
}

impl Lanes for Eight {
    #[inline(always)]
    fn splat(x: f32) -> Eight {
        // SAFETY: as for `add`.
        Eight(unsafe { _mm256_set1_ps(x) })
    }
    #[inline(always)]
    fn abs(self) -> Eight {
        // SAFETY: as for `add`.
        Eight(unsafe { abs(self.0) })
    }
}

/// The second half, for a leaf with candidates: t, 1/det, and which
/// candidates pbrt-v4's error bound trusts: `(t, inv_det, hit, check)`.
macro_rules! trust {
    ($f:expr) => {{
        let f: &Front = $f;
        let mul = _mm256_mul_ps;
        let max = |a, b| _mm256_max_ps(b, a);
        let max3 = |v: [__m256; 3]| max(max(abs(v[0]), abs(v[1])), abs(v[2]));
        let inv_det = _mm256_div_ps(_mm256_set1_ps(1.0), f.det);
        let t = mul(f.ts, inv_det);
        let m = |v| Eight(max3(v));
        let Eight(delta_t) = t_error_bound(m(f.x), m(f.y), m(f.zs), m(f.e), Eight(inv_det));
        let trusted = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_GT_OQ>(t, delta_t)) as u32;
        let (candidates, zeros) = (f.candidates, f.zeros);
        (
            t,
            inv_det,
            candidates & trusted & !zeros,
            zeros | (candidates & !trusted),
        )
    }};
}

/// What [`front!`] computes: the corners in the ray's frame (x, y and the
/// sheared z), the edge functions, det and the scaled t, and the masks of
/// candidates and of lanes with an edge function exactly zero.
struct Front {
    x: [__m256; 3],
    y: [__m256; 3],
    zs: [__m256; 3],
    e: [__m256; 3],
    det: __m256,
    ts: __m256,
    candidates: u32,
    zeros: u32,
}

/// |v|.
#[target_feature(enable = "avx2,fma")]
#[inline]
fn abs(v: __m256) -> __m256 {
    _mm256_andnot_ps(_mm256_set1_ps(-0.0), v)
}

/// The nearest of the lanes `hit` (at least one) and its lane: the
/// smallest t, and of equal ones the last lane.
#[target_feature(enable = "avx2,fma")]
#[inline]
fn nearest(t: __m256, inv_det: __m256, f: &Front, hit: u32) -> (Hit, usize) {
    let lanes = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    let bits = _mm256_set1_epi32(hit as i32);
    let on = _mm256_cmpeq_epi32(_mm256_and_si256(bits, lanes), lanes);
    let masked = _mm256_blendv_ps(_mm256_set1_ps(f32::INFINITY), t, _mm256_castsi256_ps(on));
    // The minimum over the eight lanes, in every lane.
    let m = _mm256_min_ps(masked, _mm256_permute_ps::<0b10_11_00_01>(masked));
    let m = _mm256_min_ps(m, _mm256_permute_ps::<0b01_00_11_10>(m));
    let m = _mm256_min_ps(m, _mm256_permute2f128_ps::<1>(m, m));
    let equal = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_EQ_OQ>(masked, m)) as u32 & hit;
    let lane = 31 - equal.leading_zeros() as usize;
    // Lane `lane` of each, moved to the bottom in registers (stored whole
    // and read back one lane, it waited on the store).
    let at = _mm256_set1_epi32(lane as i32);
    let pick = |v: __m256| _mm256_cvtss_f32(_mm256_permutevar8x32_ps(v, at));
    let hit = Hit {
        t: pick(t),
        u: pick(_mm256_mul_ps(f.e[1], inv_det)),
        v: pick(_mm256_mul_ps(f.e[2], inv_det)),
        triangle: 0,
    };
    (hit, lane)
}

/// Chapter 6's eight-wide tree with these kernels, for the queries
/// written once ([`wide_build::closest`], [`wide_build::occluded`]): the
/// ray kept in registers
/// ([`Splat`]), a leaf's nearest hit found by a vector minimum (the last
/// lane among equals, as `nearest_lane` picks) so that only its t, u and v
/// leave the registers, and the shadow test stopping at its first half
/// where no lane can hit. The same nodes and leaves in the same order as
/// the portable loops, so the same hits, bit for bit.
///
/// Its methods run AVX instructions: a `Kernels` is made only in the
/// `#[target_feature]` functions below (see the SAFETY note above).
struct Kernels<'a> {
    bvh: &'a Bvh8,
}

/// A ray for [`Kernels`]: splatted into registers, and as given, for the
/// rare lanes the one-triangle test decides.
struct AvxRay<'r> {
    sp: Splat,
    ray: &'r Ray,
}

impl WideTree<W> for Kernels<'_> {
    type Ray<'r> = AvxRay<'r>;

    #[inline(always)]
    fn root(&self) -> u32 {
        self.bvh.root
    }

    #[inline(always)]
    fn enter(&self, r: &AvxRay, node: usize, t_max: f32) -> (u32, [f32; W], &[u32; W]) {
        let node = &self.bvh.nodes[node];
        // SAFETY: a `Kernels` exists only where the CPU has AVX2.
        let (entered, t_near) = unsafe { enter_avx(&r.sp, node, t_max) };
        (entered, t_near, &node.child)
    }
}

impl ClosestHit<W> for Kernels<'_> {
    type Found = Nearest;

    #[inline(always)]
    fn leaf_closest(&self, r: &AvxRay, l: usize, found: &mut Nearest) {
        // SAFETY: as for `enter`.
        let leaf_hit = unsafe {
            let f = front!(&r.sp, &self.bvh.leaves[l], found.t);
            if f.candidates == 0 && f.zeros == 0 {
                return;
            }
            let (t, inv_det, hit, check) = trust!(&f);
            let best = (hit != 0).then(|| nearest(t, inv_det, &f, hit));
            match check {
                0 => best,
                // The rare lanes, by the one-triangle test.
                _ => self
                    .bvh
                    .leaf_checked(&RayData::new(r.ray), l, check, found.t, best),
            }
        };
        found.keep(leaf_hit, |lane| self.bvh.original[l * W + lane]);
    }
}

impl AnyHit<W> for Kernels<'_> {
    #[inline(always)]
    fn leaf_any(&self, r: &AvxRay, l: usize, t_max: f32) -> bool {
        // SAFETY: as for `enter`.
        unsafe {
            let f = front!(&r.sp, &self.bvh.leaves[l], t_max);
            if f.candidates == 0 && f.zeros == 0 {
                return false;
            }
            let (_, _, hit, check) = trust!(&f);
            hit != 0
                || (check != 0
                    && self
                        .bvh
                        .leaf_any_checked(&RayData::new(r.ray), l, check, t_max))
        }
    }
}

/// The two queries with [`Kernels`], compiled with the instructions
/// `$features` allows: once for AVX2 ([`v2`]) and once for AVX-512
/// ([`v512`]), where the compiler has 32 vector registers and mask
/// registers for the same intrinsics (measured faster; the book's
/// appendix has the number). Everything they call is inlined and compiled
/// with the same features.
macro_rules! traversals {
    ($features:literal) => {
        /// [`Bvh8::closest_with`] with these kernels, written to `out` (a
        /// returned hit would be stored piecewise and read back whole,
        /// stalling on store forwarding).
        #[target_feature(enable = $features)]
        #[inline]
        pub(in super::super) fn closest(
            bvh: &Bvh8,
            ray: &Ray,
            t_max: f32,
            stack: &mut [(u32, f32)],
            out: &mut Option<Hit>,
        ) {
            // The fallback builds its own RayData, so this one stays in registers.
            let r = AvxRay {
                sp: splat!(&RayData::new(ray)),
                ray,
            };
            let mut found = Nearest::new(t_max);
            wide_build::closest(&Kernels { bvh }, &r, &mut found, stack);
            *out = found.hit;
        }

        /// [`Bvh8::occluded_with`] with these kernels.
        #[target_feature(enable = $features)]
        #[inline]
        pub(in super::super) fn occluded(
            bvh: &Bvh8,
            ray: &Ray,
            t_max: f32,
            stack: &mut [(u32, f32)],
        ) -> bool {
            let r = AvxRay {
                sp: splat!(&RayData::new(ray)),
                ray,
            };
            wide_build::occluded(&Kernels { bvh }, &r, t_max, stack)
        }
    };
}

/// The traversals for CPUs with AVX2.
pub(super) mod v2 {
    use super::*;
    traversals!("avx2,fma");
}

/// The traversals for CPUs with AVX-512 (the same bits).
pub(super) mod v512 {
    use super::*;
    traversals!("avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt");
}
