//! Which vector instructions the fast engine's ray queries use, chosen
//! at run time, and the one place with `unsafe` code.
//!
//! The release build targets the x86-64 baseline (SSE2), so that the
//! binary runs on any x86-64 CPU. Each query is compiled three times: with
//! the portable lane loops of [`super::lanes`] for the baseline (the only
//! path on other architectures), and with the AVX2 kernel below for AVX2
//! and for AVX-512 CPUs (the same eight-lane code; with AVX-512 enabled the
//! compiler may use its mask registers). [`Level::detect`] picks the widest
//! the CPU has; `RAYSTEP_SIMD` (`portable`, `avx2`, `avx512`) asks for a
//! narrower one.
//!
//! Every path computes the same bits: each lane's arithmetic is the same
//! IEEE operations in the same order, and neither Rust nor the kernel
//! fuses a multiply and an add (tests render with each path and compare
//! the bytes).

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;

use crate::ch5_reflection::world::RayQueries;

use super::bvh8::Bvh8;
use super::lanes::{owen_finish_lanes, Kernel, Lanes, RayData};
use super::level::Level;
use super::shade8::{self, In8, Out8};

/// The closest hit of `ray` in (0, t_max) with `level`'s instructions.
#[inline]
pub fn closest(level: Level, bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    match level {
        // SAFETY: a `Bvh8` holds only levels `Level::available` said this
        // CPU has (`Bvh8::build` checks), and the function needs nothing
        // else than those instructions.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { closest_avx512(bvh, ray, t_max) },
        // SAFETY: as above.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { closest_avx2(bvh, ray, t_max) },
        _ => closest_lanes::<Lanes>(bvh, ray, t_max),
    }
}

/// Whether anything is hit in (0, t_max), with `level`'s instructions.
#[inline]
pub fn occluded(level: Level, bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    match level {
        // SAFETY: as in `closest`.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { occluded_avx512(bvh, ray, t_max) },
        // SAFETY: as in `closest`.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { occluded_avx2(bvh, ray, t_max) },
        _ => occluded_lanes::<Lanes>(bvh, ray, t_max),
    }
}

impl RayQueries for Bvh8 {
    fn closest(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        closest(self.level, self, ray, t_max)
    }
    fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        occluded(self.level, self, ray, t_max)
    }
    fn describe(&self) -> String {
        format!(
            "the fast engine's BVH, 8 wide ({} nodes, {} leaves; {} instructions)",
            self.nodes.len(),
            self.leaves.len(),
            self.level.name()
        )
    }
    fn as_any(&self) -> Option<&dyn std::any::Any> {
        Some(self)
    }
}

/// The widest level this CPU has (or `RAYSTEP_SIMD` asks for), found once.
pub fn best() -> Level {
    static BEST: std::sync::OnceLock<Level> = std::sync::OnceLock::new();
    *BEST.get_or_init(Level::detect)
}

/// [`owen_finish_lanes`] with the widest instructions this CPU has.
#[inline]
pub fn owen_finish(sobol: [u32; 4], seed: u32) -> [f32; 4] {
    owen_finish_at(best(), sobol, seed)
}

/// [`owen_finish_lanes`] with `level`'s instructions (the portable path if
/// this CPU lacks them).
#[inline]
pub fn owen_finish_at(level: Level, sobol: [u32; 4], seed: u32) -> [f32; 4] {
    match level {
        // SAFETY: only where `Level::available` says the CPU has AVX2.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 | Level::Avx512 if level.available() => unsafe {
            owen_finish_avx2(sobol, seed)
        },
        _ => owen_finish_lanes(sobol, seed),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn owen_finish_avx2(sobol: [u32; 4], seed: u32) -> [f32; 4] {
    owen_finish_lanes(sobol, seed)
}

/// One vertex of eight paths ([`shade8::shade8`]) with `level`'s
/// instructions: the same lane loops, compiled for AVX2's eight-lane
/// registers where the CPU has them (the same operations, so the same bits).
#[inline]
pub(super) fn shade8_at(level: Level, x: &In8, o: &mut Out8) {
    match level {
        // SAFETY: `level.available()` checked that this CPU has AVX2, all
        // the function needs.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 | Level::Avx512 if level.available() => unsafe { shade8_avx2(x, o) },
        _ => shade8::shade8(x, o),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn shade8_avx2(x: &In8, o: &mut Out8) {
    shade8::shade8(x, o)
}

/// [`sobol_group8`](super::sobol8::sobol_group8) with `level`'s
/// instructions (the same bits on every path).
#[inline]
pub fn sobol_group8_at(
    level: Level,
    sample: &[u32; 8],
    pixel_scramble: &[u64; 8],
    group: u64,
) -> [[f32; 8]; 4] {
    match level {
        // SAFETY: `level.available()` checked that this CPU has AVX2, all
        // the function needs.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 | Level::Avx512 if level.available() => unsafe {
            sobol_group8_avx2(sample, pixel_scramble, group)
        },
        _ => super::sobol8::sobol_group8(sample, pixel_scramble, group),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn sobol_group8_avx2(
    sample: &[u32; 8],
    pixel_scramble: &[u64; 8],
    group: u64,
) -> [[f32; 8]; 4] {
    super::sobol8::sobol_group8(sample, pixel_scramble, group)
}

/// [`independent8`](super::sobol8::independent8) with `level`'s
/// instructions (the same bits on every path).
#[inline]
pub fn independent8_at(level: Level, prefix: &[u64; 8], first: u64) -> [[f32; 8]; 8] {
    match level {
        // SAFETY: `level.available()` checked that this CPU has AVX2, all
        // the function needs.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 | Level::Avx512 if level.available() => unsafe {
            independent8_avx2(prefix, first)
        },
        _ => super::sobol8::independent8(prefix, first),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn independent8_avx2(prefix: &[u64; 8], first: u64) -> [[f32; 8]; 8] {
    super::sobol8::independent8(prefix, first)
}

/// Entries of a traversal stack kept on the call stack: a small one for
/// small trees (up to 2 levels; clearing it is part of every query), a
/// larger one up to 9 levels (over 8^9 leaves), else one on the heap.
const SMALL_STACK: usize = 16;
const ON_STACK: usize = 64;

// (No helper taking a closure: a closure is compiled without the AVX
// features of its caller, and the kernels inside it would become calls.)
#[inline(always)]
fn closest_lanes<K: Kernel>(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    let (r, n) = (RayData::new(ray), bvh.stack_size());
    if n <= SMALL_STACK {
        bvh.closest_with::<K>(&r, t_max, &mut [(0u32, 0f32); SMALL_STACK])
    } else if n <= ON_STACK {
        bvh.closest_with::<K>(&r, t_max, &mut [(0u32, 0f32); ON_STACK])
    } else {
        bvh.closest_with::<K>(&r, t_max, &mut vec![(0, 0.0); n])
    }
}

#[inline(always)]
fn occluded_lanes<K: Kernel>(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    let (r, n) = (RayData::new(ray), bvh.stack_size());
    if n <= SMALL_STACK {
        bvh.occluded_with::<K>(&r, t_max, &mut [(0u32, 0f32); SMALL_STACK])
    } else if n <= ON_STACK {
        bvh.occluded_with::<K>(&r, t_max, &mut [(0u32, 0f32); ON_STACK])
    } else {
        bvh.occluded_with::<K>(&r, t_max, &mut vec![(0, 0.0); n])
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn closest_avx512(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    closest_lanes::<avx::Avx>(bvh, ray, t_max)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn closest_avx2(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    closest_lanes::<avx::Avx>(bvh, ray, t_max)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn occluded_avx512(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    occluded_lanes::<avx::Avx>(bvh, ray, t_max)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn occluded_avx2(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    occluded_lanes::<avx::Avx>(bvh, ray, t_max)
}

/// The two lane tests written with AVX intrinsics, eight lanes in one
/// register, in exactly the operations and order of the portable loops in
/// [`super::bvh8`] (so the same bits; `max`/`min` take the new value first,
/// so a NaN keeps the old one, as `f32::max` does).
///
/// SAFETY (for every `unsafe` block below): these functions are only
/// reached from the `#[target_feature(enable = "avx2,...")]` entry points
/// above, which run only on CPUs that have AVX2 (`Level::available`); every
/// load reads a whole `[f32; 8]` that the reference proves is there.
#[cfg(target_arch = "x86_64")]
mod avx {
    use std::arch::x86_64::*;

    use super::super::lanes::{Hits8, Kernel, Leaf8, Node8, RayData, FAR_STRETCH, W};
    use crate::ch3_ray_triangle::triangle::gamma;

    pub(super) struct Avx;

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

    impl Kernel for Avx {
        #[inline(always)]
        fn enter(r: &RayData, node: &Node8, t_max: f32) -> (u32, [f32; W]) {
            // SAFETY: see the module.
            unsafe { enter_avx(r, node, t_max) }
        }

        #[inline(always)]
        fn leaf(r: &RayData, leaf: &Leaf8, t_max: f32) -> Hits8 {
            // SAFETY: see the module.
            unsafe { leaf_avx(r, leaf, t_max) }
        }
    }

    #[target_feature(enable = "avx2,fma")]
    #[inline]
    fn enter_avx(r: &RayData, node: &Node8, t_max: f32) -> (u32, [f32; W]) {
        {
            let mut t_near = _mm256_setzero_ps();
            let mut t_far = _mm256_set1_ps(t_max);
            for axis in 0..3 {
                let (near, far) = match r.negative[axis] {
                    true => (&node.max[axis], &node.min[axis]),
                    false => (&node.min[axis], &node.max[axis]),
                };
                let (o, inv) = (_mm256_set1_ps(r.o[axis]), _mm256_set1_ps(r.inv[axis]));
                t_near = _mm256_max_ps(_mm256_mul_ps(_mm256_sub_ps(load(near), o), inv), t_near);
                t_far = _mm256_min_ps(_mm256_mul_ps(_mm256_sub_ps(load(far), o), inv), t_far);
            }
            let stretched = _mm256_mul_ps(t_far, _mm256_set1_ps(FAR_STRETCH));
            let entered = _mm256_cmp_ps::<_CMP_LE_OQ>(t_near, stretched);
            (_mm256_movemask_ps(entered) as u32, store(t_near))
        }
    }

    #[target_feature(enable = "avx2,fma")]
    #[inline]
    fn leaf_avx(r: &RayData, leaf: &Leaf8, t_max: f32) -> Hits8 {
        let (px, py, pz) = (&leaf.p[r.k[0]], &leaf.p[r.k[1]], &leaf.p[r.k[2]]);
        let [ox, oy, oz] = r.ko.map(|x| _mm256_set1_ps(x));
        let [sx, sy, sz] = r.s.map(|x| _mm256_set1_ps(x));
        let (add, sub, mul) = (_mm256_add_ps, _mm256_sub_ps, _mm256_mul_ps);
        let zero = _mm256_setzero_ps();
        let z = [0, 1, 2].map(|j| sub(load(&pz[j]), oz));
        let x = [0, 1, 2].map(|j| add(sub(load(&px[j]), ox), mul(sx, z[j])));
        let y = [0, 1, 2].map(|j| add(sub(load(&py[j]), oy), mul(sy, z[j])));
        let e0 = sub(mul(x[1], y[2]), mul(y[1], x[2]));
        let e1 = sub(mul(x[2], y[0]), mul(y[2], x[0]));
        let e2 = sub(mul(x[0], y[1]), mul(y[0], x[1]));
        let or3 = |a, b, c| _mm256_or_ps(_mm256_or_ps(a, b), c);
        let any_zero = or3(
            _mm256_cmp_ps::<_CMP_EQ_OQ>(e0, zero),
            _mm256_cmp_ps::<_CMP_EQ_OQ>(e1, zero),
            _mm256_cmp_ps::<_CMP_EQ_OQ>(e2, zero),
        );
        let neg = or3(
            _mm256_cmp_ps::<_CMP_LT_OQ>(e0, zero),
            _mm256_cmp_ps::<_CMP_LT_OQ>(e1, zero),
            _mm256_cmp_ps::<_CMP_LT_OQ>(e2, zero),
        );
        let pos = or3(
            _mm256_cmp_ps::<_CMP_GT_OQ>(e0, zero),
            _mm256_cmp_ps::<_CMP_GT_OQ>(e1, zero),
            _mm256_cmp_ps::<_CMP_GT_OQ>(e2, zero),
        );
        let det = add(add(e0, e1), e2);
        let zs = z.map(|zj| mul(zj, sz));
        let ts = add(add(mul(e0, zs[0]), mul(e1, zs[1])), mul(e2, zs[2]));
        let (lo, hi) = (mul(zero, det), mul(_mm256_set1_ps(t_max), det));
        let and = _mm256_and_ps;
        let in_neg = and(
            and(
                _mm256_cmp_ps::<_CMP_LT_OQ>(det, zero),
                _mm256_cmp_ps::<_CMP_LT_OQ>(ts, lo),
            ),
            _mm256_cmp_ps::<_CMP_GE_OQ>(ts, hi),
        );
        let in_pos = and(
            and(
                _mm256_cmp_ps::<_CMP_GT_OQ>(det, zero),
                _mm256_cmp_ps::<_CMP_GT_OQ>(ts, lo),
            ),
            _mm256_cmp_ps::<_CMP_LE_OQ>(ts, hi),
        );
        let sign = _mm256_set1_ps(-0.0);
        let abs = |v| _mm256_andnot_ps(sign, v);
        let finite = _mm256_cmp_ps::<_CMP_LT_OQ>(abs(det), _mm256_set1_ps(f32::INFINITY));
        let candidate = _mm256_andnot_ps(and(neg, pos), and(finite, _mm256_or_ps(in_neg, in_pos)));
        let candidates = _mm256_movemask_ps(candidate) as u32;
        let zeros = _mm256_movemask_ps(any_zero) as u32;
        let mut h = Hits8 {
            hit: 0,
            check: zeros,
            t: [0.0; W],
            u: [0.0; W],
            v: [0.0; W],
        };
        if candidates == 0 {
            return h;
        }
        let max = |a, b| _mm256_max_ps(b, a);
        let max3 = |v: [__m256; 3]| max(max(abs(v[0]), abs(v[1])), abs(v[2]));
        let g = |n| _mm256_set1_ps(gamma(n));
        let inv_det = _mm256_div_ps(_mm256_set1_ps(1.0), det);
        let t = mul(ts, inv_det);
        let (max_zt, max_xt, max_yt) = (max3(zs), max3(x), max3(y));
        let delta_z = mul(g(3), max_zt);
        let delta_x = mul(g(5), add(max_xt, max_zt));
        let delta_y = mul(g(5), add(max_yt, max_zt));
        let delta_e = mul(
            _mm256_set1_ps(2.0),
            add(
                add(mul(mul(g(2), max_xt), max_yt), mul(delta_y, max_xt)),
                mul(delta_x, max_yt),
            ),
        );
        let max_e = max3([e0, e1, e2]);
        let inner = add(
            add(mul(mul(g(3), max_e), max_zt), mul(delta_e, max_zt)),
            mul(delta_z, max_e),
        );
        let delta_t = mul(mul(_mm256_set1_ps(3.0), inner), abs(inv_det));
        let trusted = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_GT_OQ>(t, delta_t)) as u32;
        h.hit = candidates & trusted & !zeros;
        h.check = zeros | (candidates & !trusted);
        h.t = store(t);
        h.u = store(mul(e1, inv_det));
        h.v = store(mul(e2, inv_det));
        h
    }
}
