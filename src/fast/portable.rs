//! The portable vectors: the `wide` crate's `f32x8` and `f32x4` as the
//! kernels' [`Vector`] (SSE2 registers on x86-64's baseline, NEON's on
//! aarch64, plain arrays elsewhere), and the two queries with them: eight
//! lanes, and four for a node or leaf that uses only its first four.

use wide::{f32x4, f32x8, CmpEq, CmpGt, CmpLe, CmpLt};

use super::bvh8::Bvh8;
use super::kernels::{self, Vector};
use super::lanes::W;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;

/// [`Vector`] for one of `wide`'s types, of `$lanes` lanes.
macro_rules! wide_vector {
    ($t:ty, $lanes:literal) => {
        impl Vector for $t {
            const LANES: usize = $lanes;
            #[inline(always)]
            fn splat(x: f32) -> Self {
                <$t>::splat(x)
            }
            #[inline(always)]
            fn load(a: &[f32; W]) -> Self {
                let mut v = [0.0; $lanes];
                v.copy_from_slice(&a[..$lanes]);
                <$t>::new(v)
            }
            #[inline(always)]
            fn max_over(self, old: Self) -> Self {
                self.fast_max(old)
            }
            #[inline(always)]
            fn min_over(self, old: Self) -> Self {
                self.fast_min(old)
            }
            #[inline(always)]
            fn eq(self, o: Self) -> Self {
                self.cmp_eq(o)
            }
            #[inline(always)]
            fn lt(self, o: Self) -> Self {
                self.cmp_lt(o)
            }
            #[inline(always)]
            fn gt(self, o: Self) -> Self {
                self.cmp_gt(o)
            }
            #[inline(always)]
            fn le(self, o: Self) -> Self {
                self.cmp_le(o)
            }
            #[inline(always)]
            fn and_not(self, m: Self) -> Self {
                self & !m
            }
            #[inline(always)]
            fn mask(self) -> u32 {
                self.move_mask() as u32
            }
            #[inline(always)]
            fn store(self) -> [f32; W] {
                let mut a = [0.0; W];
                a[..$lanes].copy_from_slice(&self.to_array());
                a
            }
            #[inline(always)]
            fn lane(self, j: usize) -> f32 {
                self.to_array()[j]
            }
            #[inline(always)]
            fn smallest(self, hits: u32) -> usize {
                let t = self.to_array();
                let mut bits = hits;
                let mut best = bits.trailing_zeros() as usize;
                bits &= bits - 1;
                while bits != 0 {
                    let j = bits.trailing_zeros() as usize;
                    if t[j] <= t[best] {
                        best = j;
                    }
                    bits &= bits - 1;
                }
                best
            }
        }
    };
}

wide_vector!(f32x8, 8);
wide_vector!(f32x4, 4);

/// [`kernels::closest`] with the portable vectors: `wide`'s eight lanes, and four
/// for narrow nodes and leaves.
#[inline(always)]
pub(super) fn closest(bvh: &Bvh8, ray: &Ray, t_max: f32, stack: &mut [(u32, f32)]) -> Option<Hit> {
    kernels::closest::<f32x8, f32x4>(bvh, ray, t_max, stack)
}

/// [`kernels::occluded`] with the portable vectors.
#[inline(always)]
pub(super) fn occluded(bvh: &Bvh8, ray: &Ray, t_max: f32, stack: &mut [(u32, f32)]) -> bool {
    kernels::occluded::<f32x8, f32x4>(bvh, ray, t_max, stack)
}
