//! The rays that leave a vertex, one lane at a time: chapter 3's
//! `offset_origin` and `stop_distance` and chapter 5's `World::spawn` and
//! `World::unoccluded`, written with selects in place of early returns so
//! that [`shade8`](super::shade8::shade8)'s lane loop stays branch-free.
//! Tests check every function's bits against the lesson's.

use crate::ch3_ray_triangle::spawn::{FLOAT_SCALE, INT_SCALE, ORIGIN, STOP_SCALE};

/// Chapter 3's [`offset_origin`](crate::ch3_ray_triangle::spawn::offset_origin)
/// for one coordinate, with a select in place of its early return (a test
/// checks that the bits agree).
#[inline(always)]
pub fn offset_coordinate(p: f32, n: f32) -> f32 {
    let near = p + FLOAT_SCALE * n;
    let ulps = truncate(INT_SCALE * n);
    let ulps = if p < 0.0 { ulps.wrapping_neg() } else { ulps };
    let far = f32::from_bits((p.to_bits() as i32).wrapping_add(ulps) as u32);
    if p.abs() < ORIGIN {
        near
    } else {
        far
    }
}

/// `x as i32`: x rounded towards zero, saturated to the `i32` range,
/// NaN giving 0. Written with float arithmetic that is exact for every
/// input, because the compiler turns Rust's saturating cast into one
/// scalar conversion per lane, and these steps into vector instructions
/// on every target (no per-lane shift, which the x86-64 baseline lacks).
/// A test checks it against `as i32`.
#[inline(always)]
pub fn truncate(x: f32) -> i32 {
    let a = x.abs();
    // Below 2^31 the integer part of |x| is hi 2^16 + lo with hi and lo
    // below 2^16, each found exactly: a scaling by a power of two, a
    // floor, and a difference whose exact value is a float.
    let hi = floor_small(a * (1.0 / 65536.0));
    let lo = floor_small(a - hi * 65536.0);
    let magnitude = (small_int(hi) << 16 | small_int(lo)) as i32;
    let negative = (x.to_bits() >> 31) != 0;
    let value = if negative {
        magnitude.wrapping_neg()
    } else {
        magnitude
    };
    let saturated = if negative { i32::MIN } else { i32::MAX };
    let out = if a >= 2_147_483_648.0 {
        saturated
    } else {
        value
    };
    if a.is_nan() {
        0
    } else {
        out
    }
}

/// 2^23: the smallest float whose ulp is 1.
const TWO_23: f32 = 8_388_608.0;

/// ⌊y⌋ for 0 ≤ y < 2^23: y + 2^23 rounds y to the nearest integer (ties
/// to even) exactly, and one less where that went up.
#[inline(always)]
fn floor_small(y: f32) -> f32 {
    let r = (y + TWO_23) - TWO_23;
    if r > y {
        r - 1.0
    } else {
        r
    }
}

/// An integer-valued float below 2^23 as an integer: its mantissa bits
/// once 2^23 is added (exact).
#[inline(always)]
fn small_int(v: f32) -> u32 {
    (v + TWO_23).to_bits().wrapping_sub(TWO_23.to_bits())
}

/// Chapter 3's [`stop_distance`](crate::ch3_ray_triangle::spawn::stop_distance),
/// with a select.
#[inline(always)]
pub fn stop_distance(y: [f32; 3]) -> f32 {
    let m = max_element([y[0].abs(), y[1].abs(), y[2].abs()]);
    let ulp = f32::from_bits(m.to_bits().wrapping_add(1)) - m;
    STOP_SCALE
        * if m < ORIGIN {
            FLOAT_SCALE
        } else {
            INT_SCALE * ulp
        }
}

/// A ray as `Ray::from_unit` makes it, for one lane; `ok` is false where
/// it gives `None`.
#[derive(Clone, Copy)]
pub struct LaneRay {
    /// Whether there is a ray.
    pub ok: bool,
    /// Its origin.
    pub origin: [f32; 3],
    /// Its unit direction.
    pub dir: [f32; 3],
}

/// `Ray::from_unit(origin, dir)`: `dir` as it is when its length is 1 to
/// within 10⁻⁵, else normalised (`Ray::new`); no ray for an origin that is
/// not finite or a direction that cannot be normalised.
#[inline(always)]
fn from_unit(origin: [f32; 3], dir: [f32; 3]) -> LaneRay {
    let len2 = dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2];
    let finite = (origin[0].abs() < f32::INFINITY)
        & (origin[1].abs() < f32::INFINITY)
        & (origin[2].abs() < f32::INFINITY);
    let unit = (len2 - 1.0).abs() <= 1e-5;
    let rcp = 1.0 / len2.sqrt();
    let normalisable = (rcp < f32::INFINITY) & (rcp > 0.0);
    LaneRay {
        ok: finite & (unit | normalisable),
        origin,
        dir: [
            if unit { dir[0] } else { dir[0] * rcp },
            if unit { dir[1] } else { dir[1] * rcp },
            if unit { dir[2] } else { dir[2] * rcp },
        ],
    }
}

/// `World::spawn(p, n, dir)` without SDFs: the origin moved off the
/// surface to the side `dir` leaves into.
#[inline(always)]
pub(super) fn spawn(p: [f32; 3], n: [f32; 3], dir: [f32; 3]) -> LaneRay {
    let back = n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2] < 0.0;
    let s = if back { -1.0 } else { 1.0 };
    let origin = [
        offset_coordinate(p[0], n[0] * s),
        offset_coordinate(p[1], n[1] * s),
        offset_coordinate(p[2], n[2] * s),
    ];
    from_unit(origin, dir)
}

/// The shadow ray of `World::unoccluded(p, n, wi, dist)` without SDFs:
/// `ray.ok` when it must be traced (to `t_max`), `free` when the two ends
/// meet and nothing can lie between; neither: blocked (no origin).
pub(super) struct ShadowRay {
    pub(super) ray: LaneRay,
    pub(super) t_max: f32,
    pub(super) free: bool,
}

#[inline(always)]
pub(super) fn shadow_ray(p: [f32; 3], n: [f32; 3], wi: [f32; 3], dist: f32) -> ShadowRay {
    let spawned = spawn(p, n, wi);
    let y = [
        p[0] + wi[0] * dist,
        p[1] + wi[1] * dist,
        p[2] + wi[2] * dist,
    ];
    let back = stop_distance(y);
    let to = [
        y[0] - wi[0] * back - spawned.origin[0],
        y[1] - wi[1] * back - spawned.origin[1],
        y[2] - wi[2] * back - spawned.origin[2],
    ];
    let t_max = (to[0] * to[0] + to[1] * to[1] + to[2] * to[2]).sqrt();
    let finite = t_max.abs() < f32::INFINITY;
    let infinite = !finite;
    let ahead = (t_max > 0.0) & (to[0] * wi[0] + to[1] * wi[1] + to[2] * wi[2] > 0.0);
    let aimed = from_unit(
        spawned.origin,
        [to[0] / t_max, to[1] / t_max, to[2] / t_max],
    );
    let ray = if infinite { spawned } else { aimed };
    ShadowRay {
        ray: LaneRay {
            ok: spawned.ok & (infinite | (ahead & aimed.ok)),
            ..ray
        },
        t_max: if infinite { f32::INFINITY } else { t_max },
        free: spawned.ok & !infinite & !(ahead & aimed.ok),
    }
}

/// glam's `Vec3::max_element`, in its order.
#[inline(always)]
pub(super) fn max_element(v: [f32; 3]) -> f32 {
    let max = |a: f32, b: f32| if a > b { a } else { b };
    max(v[0], max(v[1], v[2]))
}
