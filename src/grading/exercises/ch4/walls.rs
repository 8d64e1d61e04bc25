//! The walls and balls of chapter 4's contract cases
//! ([`cases`](super::contract::cases)): distance functions whose values
//! along the cases' rays are exact in f32 (or as good as a right tracer's
//! own arithmetic), each with what it catches.

use glam::Vec3;

/// A wall at z = 0 whose function is its distance capped at 1 (a bound
/// like any other: it never overstates): from z = 1.5 the first step is 1,
/// to t = 1, where f = 1/2; the second lands on the wall at t = 3/2.
pub(super) fn capped_wall(p: Vec3) -> f32 {
    p.z.min(1.0)
}

/// A wall at z = 0 whose function is half its distance: from z = 1 each
/// step goes half the remaining way, f = 2^-(k+1) after k steps, exact in
/// f32. Below ε = 1e-4 first at k = 13: the 14th evaluation hits.
pub(super) fn half_wall(p: Vec3) -> f32 {
    0.5 * p.z
}

/// The same wall 6,000 m up, where ε is scaled to 8 f32 spacings of the
/// coordinates (5.7e-3): the 8th evaluation (f = 2^-8) hits; with a fixed
/// ε = 1e-4 the march goes on.
pub(super) fn far_half_wall(p: Vec3) -> f32 {
    0.5 * (p.z - 6000.0)
}

/// A wall 6,000 m up seen from near the world's origin: ε must be taken
/// where the march is (5.7e-3 there), not at the ray's origin (1e-4),
/// which a march so far away never reaches before it lands on the wall.
pub(super) fn far_ahead_wall(p: Vec3) -> f32 {
    0.5 * (6000.0 - p.z)
}

/// A wall at z = 0 whose function overstates the distance by a hair: the
/// first step from z = 1 lands 2^-16 behind it, within ε, where the
/// gradient points away from a viewer above.
pub(super) fn eager_wall(p: Vec3) -> f32 {
    p.z.abs() * (1.0 + 2f32.powi(-16))
}

/// A wall at z = 0 whose function overstates the distance by half: from
/// z = 1 the first step lands at z = -1/2, inside (f = -3/4), and every
/// step after it halves the distance and changes side, exact in f32.
/// |f| is below 1e-4 first at z = 2^-14, the 15th evaluation; a march
/// that takes f < ε for a hit stops inside, at the second.
pub(super) fn overshooting_wall(p: Vec3) -> f32 {
    1.5 * p.z
}

/// A wall through (2^20, 0, 0) tilted 45° between x and y: along the x
/// axis its function is half the distance to x = 2^20, exact in f32, so
/// from x = 2^20 − 64 the steps are 32, 16, …, 1, and ε there is 8 f32
/// spacings of x (1 − 10⁻⁶): the 7th evaluation (f = 1/2) hits at
/// x = 2^20 − 1. Its normal (−1, 1, 0)/√2 needs the contract's difference
/// step, ε at p: there x moves in steps of 1/16, so a step of 10⁻² rounds
/// away in x and leaves only the y part of the gradient.
pub(super) fn far_tilted_wall(p: Vec3) -> f32 {
    0.5 * (1_048_576.0 - p.x) + 0.5 * p.y
}

/// A ball of radius 1 6,000 m along x: ε at its surface is 5.7e-3, and
/// a difference step of 10⁻⁴ vanishes in the rounding of x there.
pub(super) fn far_ball(p: Vec3) -> f32 {
    (p - Vec3::new(6000.0, 0.0, 0.0)).length() - 1.0
}

/// A ball of radius 4 whose top touches the origin, for a march with ε
/// far below 10⁻⁴: near the top ε at p is below 10⁻⁶, while f, computed
/// from a distance near 4, moves in steps of 2.4e-7, so a difference step
/// of ε alone gives a gradient in steps of a quarter; 10⁻⁴ gives it to
/// 10⁻³.
pub(super) fn low_ball(p: Vec3) -> f32 {
    (p - Vec3::new(0.0, 0.0, -4.0)).length() - 4.0
}

/// A wall at x = 1000 whose function understates by a hair: from the
/// origin the first step lands 5·10⁻⁴ short of it, where ε at p (9.5e-4)
/// calls it a hit; ε at the ray's origin or at the previous point (10⁻⁴)
/// would not, and the march would take one more step.
pub(super) fn understating_far_wall(p: Vec3) -> f32 {
    (1.0 - 5e-7) * (1000.0 - p.x)
}

/// A box of half size 0.5 at the origin: seen from 1,000 m away near an
/// edge, a difference step of ε at the ray's origin (9.5e-4) reaches
/// across the edge, one of ε at the hit (floored at 10⁻⁴) does not.
pub(super) fn box_at_origin(p: Vec3) -> f32 {
    crate::ch4_implicit_surfaces::primitives::sd_box(p, Vec3::splat(0.5))
}

/// Flat (zero) below z = 0.5, twice the distance above: the first step
/// from z = 1 lands at z = 0, where the gradient is zero.
pub(super) fn flat_floor(p: Vec3) -> f32 {
    2.0 * (p.z - 0.5).max(0.0)
}

/// [`flat_floor`] with a rise along x that starts 1.5·10⁻⁴ from the hit
/// at the origin: the six differences of step h = 10⁻⁴ there are all
/// zero (the gradient is zero: the normal is -dir), those of 2h are not.
pub(super) fn flat_then_rising(p: Vec3) -> f32 {
    flat_floor(p) + (p.x - 1.5e-4).max(0.0)
}

/// A floor at z = 0 that bends down along x from x = 5·10⁻⁵ on, at 45°:
/// a ray straight down hits it at the origin, within h = 10⁻⁴ of the bend
/// on one side only, so the difference across p sees half the slope, and
/// one taken from p forwards sees all of it (backwards, none).
pub(super) fn bend_ahead(p: Vec3) -> f32 {
    p.z - (p.x - 5e-5).max(0.0)
}

/// [`far_half_wall`] mirrored: the wall 6,000 m below the world's origin,
/// where every coordinate of p is 0 or negative, and ε still 5.7e-3 (it
/// scales with the largest |coordinate|).
pub(super) fn far_half_floor(p: Vec3) -> f32 {
    0.5 * (p.z + 6000.0)
}

/// A slab 0.05 m thick 1,200 m along x whose function is half the
/// distance: the steps shrink to nothing at its face, with no floor under
/// them (a step of 0.12 from 0.07 short would land past the slab).
pub(super) fn far_thin_slab(p: Vec3) -> f32 {
    0.5 * (1200.0 - p.x).max(p.x - 1200.05)
}

/// A floor at z = 0 and a wall at x = 2^-9: a ray along x at height 2^-13
/// (1.2e-4, just above ε = 1e-4) steps 2^-13 sixteen times, f never below
/// 2ε, then lands on the wall. Exact in f32.
pub(super) fn skimmed_floor(p: Vec3) -> f32 {
    p.z.min(2f32.powi(-9) - p.x)
}

/// A floor 2^-6 below the line y = z = 0 from x = 2^20 on, its distance
/// bounded from below by the larger of the two gaps: a ray along x from
/// the origin lands at t = 2^20 in one step, then f = 2^-6 for ever, above
/// ε = 1e-4, while t + 2^-6 rounds to t (f32's spacing there is 2^-3):
/// the march stands still, and only the budget ends it. Exact in f32.
pub(super) fn stalling_floor(p: Vec3) -> f32 {
    (1_048_576.0 - p.x).max(p.z + 0.015_625)
}

/// A slab between z = 4.5 and z = 5 (exact distance): from z = 10 the
/// first step lands on its top.
pub(super) fn slab_below(p: Vec3) -> f32 {
    (p.z - 5.0).max(4.5 - p.z)
}

/// A wall 2·10²⁰ m below the origin whose function is half the distance:
/// from the origin the steps halve the way there, past a max_distance of
/// 1.2·10²⁰ (whose square is past f32's range) at the second.
pub(super) fn very_far_half_wall(p: Vec3) -> f32 {
    0.5 * (p.z + 2e20)
}

/// A wall at z = 0 whose function is 2 % of the distance: from z = 1 each
/// step leaves 98 % of the way, and f first falls below ε = 10⁻⁴ after
/// about 260 evaluations.
pub(super) fn slow_wall(p: Vec3) -> f32 {
    0.02 * p.z
}

/// A floor 2^-8 below the x axis and a wall across it at x = 3/4: along
/// the axis from the origin f is 2^-8 (the floor) until the wall is
/// nearer, so the march takes 192 steps of 2^-8, each exact in f32, and
/// hits the wall at the 193rd evaluation.
pub(super) fn corridor(p: Vec3) -> f32 {
    (p.y + 0.003_906_25).min(0.75 - p.x)
}

/// [`corridor`] with its wall at x = 8: 2,048 steps of 2^-8 (every t and
/// point exact in f32, ε never above 2^-8 on the way), the hit at the
/// 2,049th evaluation. (Not much longer: a right tracer may recurse once
/// per step.)
pub(super) fn long_corridor(p: Vec3) -> f32 {
    (p.y + 0.003_906_25).min(8.0 - p.x)
}

/// A wall at z = 0 whose function is the exact distance (signed).
pub(super) fn wall(p: Vec3) -> f32 {
    p.z
}

/// A wall at z = 0 whose function is a quarter of the distance: its
/// gradient is a quarter long, and still not zero.
pub(super) fn quarter_wall(p: Vec3) -> f32 {
    0.25 * p.z
}

/// A wall at z = 0 whose function is 2^-50 of the distance (a bound, if
/// a loose one): within ε of 0 everywhere near it, and its gradient,
/// 2^-50 long, is still not zero. (Scaling by a power of two is exact, so
/// the central differences are 2^-50 times the exact wall's.)
pub(super) fn faint_wall(p: Vec3) -> f32 {
    p.z * 2f32.powi(-50)
}

/// A wall at x = 1 facing −x, whose function is half the distance: its
/// gradient (−1/2, 0, 0) has no component above 0, and still is not zero.
pub(super) fn west_wall(p: Vec3) -> f32 {
    0.5 * (1.0 - p.x)
}
