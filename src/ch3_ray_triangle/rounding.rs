//! pbrt-v4's bound on the rounding error of the watertight test's t
//! (`IntersectTriangle`, from the γ bounds of every operation that led to
//! it), written once over a lane type: one f32 for the readable test and
//! the fast engine's lane loops, four for the four-wide test, four or
//! eight in the fast engine's kernels. A t at or below the bound cannot be told from 0.
//!
//! Every caller takes the largest magnitudes (of the sheared corners'
//! x, y and z, and of the three edge functions) its own way, and this
//! function does the rest in one order of operations, so every instruction
//! set gets the same bits.

use std::ops::{Add, Mul};

use glam::Vec4;

/// γ(n) = n ε / (1 - n ε), the bound on the relative error of n f32
/// operations (ε = 2⁻²⁴, half the machine epsilon).
pub(crate) const fn gamma(n: i32) -> f32 {
    let eps = f32::EPSILON * 0.5;
    (n as f32 * eps) / (1.0 - n as f32 * eps)
}

/// A number, or several side by side, with what the bound needs.
pub trait Lanes: Copy + Add<Output = Self> + Mul<Output = Self> {
    /// `x` in every lane.
    fn splat(x: f32) -> Self;
    /// |x| lane by lane.
    fn abs(self) -> Self;
}

impl Lanes for f32 {
    #[inline(always)]
    fn splat(x: f32) -> f32 {
        x
    }
    #[inline(always)]
    fn abs(self) -> f32 {
        f32::abs(self)
    }
}

impl Lanes for Vec4 {
    #[inline(always)]
    fn splat(x: f32) -> Vec4 {
        Vec4::splat(x)
    }
    #[inline(always)]
    fn abs(self) -> Vec4 {
        Vec4::abs(self)
    }
}

/// The bound on the error of t, from the largest |x|, |y| and |z| of the
/// sheared corners, the largest |edge function| and 1/det.
#[inline(always)]
pub fn t_error_bound<L: Lanes>(max_xt: L, max_yt: L, max_zt: L, max_e: L, inv_det: L) -> L {
    let g = |n| L::splat(gamma(n));
    let delta_z = g(3) * max_zt;
    let delta_x = g(5) * (max_xt + max_zt);
    let delta_y = g(5) * (max_yt + max_zt);
    let delta_e = L::splat(2.0) * (g(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
    L::splat(3.0) * (g(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * inv_det.abs()
}
