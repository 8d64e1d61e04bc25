//! The eight-lane [`Vector`] of AVX2: one `__m256` register, whose
//! operations are the intrinsics of the instructions the kernels of
//! [`kernels`](super::super::kernels) ask for. The kernels are written once;
//! this module compiles them with AVX2 and with AVX-512 enabled (the entry
//! points in [`super`]), where the portable path compiles them with the
//! `wide` crate's vectors. Same operations in the same order, so the same
//! bits.
//!
//! SAFETY (for every `unsafe` block below): an [`Eight`] is private to this
//! module, and its only users are the traversals below, which run only
//! inside the `#[target_feature(enable = "avx2,...")]` entry points of
//! [`super`], reached only on CPUs that have AVX2 (`Level::available`).
//! So every intrinsic here runs where the CPU has it. Every load reads a
//! whole `[f32; 8]` that the reference proves is there.

use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, BitXor, Div, Mul, Sub};

use super::super::bvh8::Bvh8;
use super::super::kernels::{self, Vector};
use super::super::lanes::W;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;

/// Eight lanes in one AVX register.
#[derive(Clone, Copy)]
struct Eight(__m256);

/// The binary operators of [`Eight`], one intrinsic each.
macro_rules! binary {
    ($($op:ident $f:ident $intrinsic:ident),*) => {$(
        impl $op for Eight {
            type Output = Eight;
            #[inline(always)]
            fn $f(self, o: Eight) -> Eight {
                // SAFETY: see the module.
                Eight(unsafe { $intrinsic(self.0, o.0) })
            }
        }
    )*};
}

binary!(
    Add add _mm256_add_ps,
    Sub sub _mm256_sub_ps,
    Mul mul _mm256_mul_ps,
    Div div _mm256_div_ps,
    BitAnd bitand _mm256_and_ps,
    BitOr bitor _mm256_or_ps,
    BitXor bitxor _mm256_xor_ps
);

impl Vector for Eight {
    const LANES: usize = W;
    #[inline(always)]
    fn splat(x: f32) -> Eight {
        // SAFETY: see the module.
        Eight(unsafe { _mm256_set1_ps(x) })
    }
    #[inline(always)]
    fn load(a: &[f32; W]) -> Eight {
        // SAFETY: see the module (eight floats behind the reference).
        Eight(unsafe { _mm256_loadu_ps(a.as_ptr()) })
    }
    #[inline(always)]
    fn max_over(self, old: Eight) -> Eight {
        // SAFETY: see the module. (The instruction gives its second
        // operand unless the first is larger.)
        Eight(unsafe { _mm256_max_ps(self.0, old.0) })
    }
    #[inline(always)]
    fn min_over(self, old: Eight) -> Eight {
        // SAFETY: see the module.
        Eight(unsafe { _mm256_min_ps(self.0, old.0) })
    }
    #[inline(always)]
    fn eq(self, o: Eight) -> Eight {
        // SAFETY: see the module.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_EQ_OQ>(self.0, o.0) })
    }
    #[inline(always)]
    fn lt(self, o: Eight) -> Eight {
        // SAFETY: see the module.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_LT_OQ>(self.0, o.0) })
    }
    #[inline(always)]
    fn gt(self, o: Eight) -> Eight {
        // SAFETY: see the module.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_GT_OQ>(self.0, o.0) })
    }
    #[inline(always)]
    fn le(self, o: Eight) -> Eight {
        // SAFETY: see the module.
        Eight(unsafe { _mm256_cmp_ps::<_CMP_LE_OQ>(self.0, o.0) })
    }
    #[inline(always)]
    fn and_not(self, m: Eight) -> Eight {
        // SAFETY: see the module.
        Eight(unsafe { _mm256_andnot_ps(m.0, self.0) })
    }
    #[inline(always)]
    fn mask(self) -> u32 {
        // SAFETY: see the module.
        unsafe { _mm256_movemask_ps(self.0) as u32 }
    }
    #[inline(always)]
    fn store(self) -> [f32; W] {
        let mut a = [0.0f32; W];
        // SAFETY: see the module (eight floats behind the pointer).
        unsafe { _mm256_storeu_ps(a.as_mut_ptr(), self.0) };
        a
    }
    #[inline(always)]
    fn lane(self, j: usize) -> f32 {
        // Moved to the bottom in registers: stored whole and read back one
        // lane, it waited on the store.
        // SAFETY: see the module.
        unsafe {
            _mm256_cvtss_f32(_mm256_permutevar8x32_ps(
                self.0,
                _mm256_set1_epi32(j as i32),
            ))
        }
    }
    #[inline(always)]
    fn smallest(self, hits: u32) -> usize {
        // SAFETY: see the module.
        let equal = unsafe {
            let lanes = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
            let bits = _mm256_set1_epi32(hits as i32);
            let on = _mm256_cmpeq_epi32(_mm256_and_si256(bits, lanes), lanes);
            let inf = _mm256_set1_ps(f32::INFINITY);
            let masked = _mm256_blendv_ps(inf, self.0, _mm256_castsi256_ps(on));
            // The minimum over the eight lanes, in every lane.
            let m = _mm256_min_ps(masked, _mm256_permute_ps::<0b10_11_00_01>(masked));
            let m = _mm256_min_ps(m, _mm256_permute_ps::<0b01_00_11_10>(m));
            let m = _mm256_min_ps(m, _mm256_permute2f128_ps::<1>(m, m));
            _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_EQ_OQ>(masked, m)) as u32 & hits
        };
        31 - equal.leading_zeros() as usize
    }
}

/// The two queries with the kernels in [`Eight`]s, compiled with the
/// instructions `$features` allows: once for AVX2 ([`v2`]) and once for
/// AVX-512 ([`v512`]), where the compiler has 32 vector registers and mask
/// registers for the same intrinsics (measured faster; the book's
/// appendix has the number). Everything they call is inlined and compiled
/// with the same features.
macro_rules! traversals {
    ($features:literal) => {
        /// [`kernels::closest`] with AVX, written to `out` (a returned hit
        /// would be stored piecewise and read back whole, stalling on
        /// store forwarding).
        #[target_feature(enable = $features)]
        #[inline]
        pub(in super::super) fn closest(
            bvh: &Bvh8,
            ray: &Ray,
            t_max: f32,
            stack: &mut [(u32, f32)],
            out: &mut Option<Hit>,
        ) {
            *out = kernels::closest::<Eight, Eight>(bvh, ray, t_max, stack);
        }

        /// [`kernels::occluded`] with AVX.
        #[target_feature(enable = $features)]
        #[inline]
        pub(in super::super) fn occluded(
            bvh: &Bvh8,
            ray: &Ray,
            t_max: f32,
            stack: &mut [(u32, f32)],
        ) -> bool {
            kernels::occluded::<Eight, Eight>(bvh, ray, t_max, stack)
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
