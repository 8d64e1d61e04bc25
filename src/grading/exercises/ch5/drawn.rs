//! Capstone 5's drawn cases: a shading point and a light point anywhere
//! (up to 10⁵ times their distance from the origin), at any scale (a
//! seventh from 10⁻¹⁵ to 10⁻⁴ and 10⁴ to 10¹⁵), each
//! facing any way (a fifth with the light near p's horizon), the light's
//! area, emission and the albedo drawn too (a tenth of the albedos dark,
//! down to 10⁻⁶), and a fifth of them blocked. The answer is the
//! estimator's closed form worked out in f64; cases where a cosine is so
//! small that rounding decides its sign are left out. Then samples that
//! skim a surface where the small cosine is exact ([`skimming_cases`]),
//! and bright lights in vast scenes ([`vast_cases`]).

use std::cell::Cell;
use std::f64::consts::PI;

use glam::{DVec3, Vec3};

use crate::exercises::draws::{worst_drawn, Draws};
use crate::exercises::AbsMax;

/// Capstone 5's signature (the checks' `DirectFn`).
type Direct = fn(Vec3, Vec3, Vec3, Vec3, Vec3, f32, Vec3, &dyn Fn(Vec3, Vec3) -> bool) -> Vec3;

/// The estimator's closed form for the sample y (normal `n_light`, area
/// `area`, emission `le`) seen from p (normal `n`, albedo `rho`), worked
/// out in f64: cos θ at p, cos θl at the light, and what the light would
/// bring with both cosines 1, ρ Le / π · A / d².
fn closed_form(
    (p, n, rho): (Vec3, Vec3, Vec3),
    (y, n_light, area, le): (Vec3, Vec3, f32, Vec3),
) -> (f64, f64, DVec3) {
    let to = (y - p).as_dvec3();
    let d2 = to.length_squared();
    let wi = to / d2.sqrt();
    let (cos, cos_l) = (n.as_dvec3().dot(wi), -n_light.as_dvec3().dot(wi));
    (cos, cos_l, (rho * le).as_dvec3() / PI * area as f64 / d2)
}

/// A drawn answer's error relative to the answer itself (worked out in
/// f64): per channel over its largest, infinite where a channel is NaN;
/// where the answer is 0, none if `got` is exactly 0 and infinite
/// otherwise.
pub(super) fn relative_or_zero(got: DVec3, want: DVec3) -> f64 {
    match want.max_element() > 0.0 {
        true => (got - want).abs_max() / want.max_element(),
        false if got == DVec3::ZERO => 0.0,
        false => f64::INFINITY,
    }
}

/// `visible` for the segment from `p` to `y`: answers `!blocked`, and
/// notes whether it was asked about any other segment.
struct Visibility {
    p: Vec3,
    y: Vec3,
    blocked: bool,
    other: Cell<bool>,
}

impl Visibility {
    fn new(p: Vec3, y: Vec3, blocked: bool) -> Visibility {
        Visibility {
            p,
            y,
            blocked,
            other: Cell::new(false),
        }
    }

    fn ask(&self, a: Vec3, b: Vec3) -> bool {
        self.other
            .set(self.other.get() || a != self.p || b != self.y);
        !self.blocked
    }

    /// Whether it was asked about another segment.
    fn asked_other(&self) -> bool {
        self.other.get()
    }

    /// What a message says of that.
    fn note(&self) -> &'static str {
        match self.asked_other() {
            true => " (visible was asked about another segment than p → y)",
            false => "",
        }
    }
}

/// The worst drawn case of `f`: (error relative to what the light would
/// bring facing p, what it was).
pub(super) fn drawn_cases(f: Direct) -> (f64, String) {
    let mut draws = Draws::new(54);
    let (mut black, mut black_asked) = (Draws::new(154), false);
    // A tenth of the albedos 10⁻⁶ to 10⁻³ times as bright (dark is not
    // black), from a stream of their own.
    let mut dark = Draws::new(254);
    // A light or a surface with a channel off (a pure green light, a
    // surface black in red): each channel of each off a fifth of the time.
    let mut channels = Draws::new(454);
    // A seventh at scales from 10⁻¹⁵ to 10⁻⁴ or 10⁴ to 10¹⁵ (the answer
    // does not depend on the scene's scale; d⁴ or d³ leaves f32's range
    // there), from a stream of their own.
    let mut wide = Draws::new(354);
    // A fifth with a light far larger than its distance from p (d from
    // 10⁻⁴ to 10⁻¹·⁵ of the light's size, as for a wall beside a ceiling
    // light), facing p from above its horizon: the density per steradian
    // is then far below 1, and nothing floors it. From a stream of its
    // own.
    let mut near = Draws::new(754);
    let mut last: Option<(Vec3, Vec3, bool)> = None;
    worst_drawn((0..draws.count(100, 400)).filter_map(|_| {
        draws.next_case();
        dark.next_case();
        wide.next_case();
        near.next_case();
        let s = draws.decades(-2.0, 4.0);
        let wide_scale = wide.far_scale(1.0 / 7.0, (-15.0, -4.0), (4.0, 15.0));
        let (is_wide, s) = (wide_scale.is_some(), wide_scale.unwrap_or(s));
        // A third up to 10⁵ times their size from the origin (where the
        // plane's equation in absolute coordinates rounds).
        let far = draws.unit() < 1.0 / 3.0;
        let mut p = draws.place_for(s, if far { 5.0 } else { 2.0 });
        let mut n = draws.direction();
        // A fifth with y just above or below p's horizon (|cos θ| from
        // 10⁻³ to 10⁻²), 10⁵ to 10⁶ times their distance from the origin.
        let horizon = draws.unit() < 0.2;
        if horizon {
            p = draws.direction() * s * draws.decades(5.0, 6.0);
        }
        let mut y = p + draws.direction() * s * draws.range(0.5, 5.0);
        if horizon {
            let wi = (y - p).normalize();
            let tilt = draws.sign() * draws.decades(-3.0, -2.0);
            n = (wi.any_orthonormal_vector() + wi * tilt).normalize();
        }
        let mut n_light = draws.direction();
        let mut area = s * s * draws.decades(-2.0, 1.0);
        // Emission from 10⁻¹ to 10², a tenth from 10⁻¹² (dim is not dark),
        // a fifth from 10³ to 10⁸ (bright is not a firefly).
        let (dim, bright) = match draws.count(0, 9) {
            0 => (-12.0, 2.0),
            1 | 2 => (3.0, 8.0),
            _ => (-1.0, 2.0),
        };
        let le = Vec3::new(draws.unit(), draws.unit(), draws.unit()) * draws.decades(dim, bright);
        let mut rho = Vec3::new(draws.unit(), draws.unit(), draws.unit());
        if dark.unit() < 0.1 {
            rho *= dark.decades(-6.0, -3.0);
        }
        let le = le * channels.channels_off(0.2);
        rho *= channels.channels_off(0.2);
        let mut blocked = draws.unit() < 0.2;
        // A quarter keep the last light point, seen from another p, and
        // blocked or not afresh: visibility is a question about p too.
        // (Not at a scale of their own: their light belongs to it.)
        let again = last.is_some() && draws.unit() < 0.25 && !is_wide;
        if let Some((last_y, last_n, last_blocked)) = last.filter(|_| again) {
            let moved = last_y + draws.direction() * s * draws.range(0.5, 5.0);
            // Not where rounding puts p on the light point.
            if (moved - last_y).length() > 0.25 * s {
                (y, n_light, blocked, p) = (last_y, last_n, !last_blocked, moved);
            }
        }
        // A tenth with the light's normal along an axis, its plane through
        // the origin, and p just in front of it (cos θl from 10⁻⁵ to
        // 10⁻²): every right cosine there is exact to a few ulps, so these
        // are judged relative to the answer itself (an ε added to cos θl
        // "against division by 0" is off by ε / cos θl).
        let exact_light = !horizon && draws.unit() < 0.1;
        if exact_light {
            let axis = draws.count(0, 2);
            n_light = Vec3::AXES[axis] * draws.sign();
            y[axis] = 0.0;
            let mut off = draws.direction();
            off[axis] = 0.0;
            let dist = s * draws.range(0.5, 5.0);
            p = y + off.normalize_or(n_light.any_orthonormal_vector()) * dist;
            p[axis] = n_light[axis] * dist * draws.decades(-5.0, -2.0);
        }
        if !is_wide && near.unit() < 0.2 {
            let to = y - p;
            area = to.length_squared() * near.decades(3.0, 8.0);
            n *= n.dot(to).signum();
            n_light *= -n_light.dot(to).signum();
        }
        last = (!is_wide).then_some((y, n_light, blocked)).or(last);
        let (cos, cos_l, facing) = closed_form((p, n, rho), (y, n_light, area, le));
        if cos.abs() < 1e-3 || (cos_l.abs() < 1e-3 && !exact_light) {
            return None;
        }
        let want = if cos > 0.0 && cos_l > 0.0 && !blocked {
            facing * cos * cos_l
        } else {
            DVec3::ZERO
        };
        let seen = Visibility::new(p, y, blocked);
        let visible = |a: Vec3, b: Vec3| seen.ask(a, b);
        let got = f(p, n, rho, y, n_light, area, le, &visible).as_dvec3();
        let scale = match exact_light && want.max_element() > 0.0 {
            true => want.max_element(),
            false => facing.max_element(),
        }
        .max(f64::MIN_POSITIVE);
        // Where the answer is 0 (a back face, below p's horizon, blocked:
        // each well decided here), exactly 0.
        let err = if seen.asked_other() || (want == DVec3::ZERO && got != DVec3::ZERO) {
            f64::INFINITY
        } else {
            (got - want).abs_max() / scale
        };
        // The first that brings light, and a fifth of the others, asked
        // again with the light off and with the surface black: exactly 0,
        // not 0/0 (drawn apart, so that the other draws stay as they were).
        let again = want != glam::DVec3::ZERO && (!black_asked || black.unit() < 0.2);
        black_asked |= again;
        let black_case = |le: Vec3, rho: Vec3| {
            let got = f(p, n, rho, y, n_light, area, le, &visible).as_dvec3();
            (got != glam::DVec3::ZERO).then_some((le, rho, got))
        };
        let failed = match again {
            true => black_case(Vec3::ZERO, rho).or_else(|| black_case(le, Vec3::ZERO)),
            false => None,
        };
        let (le, rho, got, want, err) = match failed {
            Some((le, rho, got)) => (le, rho, got, glam::DVec3::ZERO, f64::INFINITY),
            None => (le, rho, got, want, err),
        };
        Some((
            err,
            format!(
                "p {p}, n {n}, ρ {rho}, y {y}, n_light {n_light}, A {area}, Le {le}{}: got {got}, \
                 expected {want}{}",
                if blocked { ", blocked" } else { "" },
                seen.note()
            ),
        ))
    }))
}

/// Samples that skim a surface, from a stream of their own: half with p's
/// normal along an axis, p in the plane through the origin across it and
/// y 10⁻¹² to 10⁻⁶ of their distance above that plane (cos θ that small),
/// half the same at the light (cos θl that small). The small cosine is one
/// exact coordinate over the distance, the other well above 0, so the
/// answer is as exact as anywhere and judged relative to itself: a sample
/// taken for "in the plane" below some small cosine (`f32::EPSILON`, say)
/// brings nothing where it brings light. A fifth lie exactly in the plane
/// (the light seen edge-on, or y on p's horizon): exactly 0, where a
/// density per steradian taken as 0 and divided by gives infinity.
pub(super) fn skimming_cases(f: Direct) -> (f64, String) {
    let mut draws = Draws::new(554);
    worst_drawn((0..draws.count(24, 48)).map(|_| {
        draws.next_case();
        let dist = draws.decades(-2.0, 3.0);
        let (flat, on, mut over) = draws.skimming(dist);
        // A fifth exactly in the plane (cos θ or cos θl exactly 0): no
        // light, and exactly 0, not 0/0 or x/0.
        let edge_on = draws.unit() < 0.2;
        if edge_on {
            over -= flat * flat.dot(over);
        }
        // The other normal: towards the other point, tilted by up to 0.3.
        let tilt = draws.direction() * draws.range(0.0, 0.3);
        let facing = |from: Vec3, to: Vec3| ((to - from).normalize() + tilt).normalize();
        // Skimming p's plane (p on it, y over it), or the light's.
        let at_light = draws.unit() < 0.5;
        let (p, n, y, n_light) = match at_light {
            false => (on, flat, over, facing(over, on)),
            true => (over, facing(over, on), on, flat),
        };
        let area = dist * dist * draws.decades(-2.0, 1.0);
        let (rho, le) = (draws.colour(), draws.colour() * draws.decades(-1.0, 2.0));
        let (cos, cos_l, full) = closed_form((p, n, rho), (y, n_light, area, le));
        let want = full * cos * cos_l;
        let seen = Visibility::new(p, y, false);
        let got = f(p, n, rho, y, n_light, area, le, &|a, b| seen.ask(a, b)).as_dvec3();
        let err = match seen.asked_other() {
            true => f64::INFINITY,
            false => relative_or_zero(got, want),
        };
        (
            err,
            format!(
                "p {p}, n {n}, ρ {rho}, y {y}, n_light {n_light}, A {area}, Le {le} (y skims {}: \
                 cos θ = {cos:.2e}, cos θl = {cos_l:.2e}): got {got}, expected {want}{}",
                if at_light {
                    "the light's plane"
                } else {
                    "p's plane"
                },
                seen.note()
            ),
        )
    }))
}

/// Bright lights in vast scenes, from a stream of their own: Le 10^8.5 to
/// 10⁹ (the drawn cases' brightest is 10⁸, the sun's 2·10⁷), the scene
/// 10^14.8 to 10¹⁵ across (the drawn cases' largest) and the light's area
/// 5 to 10 times its square. The answer depends on the area only over the
/// squared distance, and is 10⁸ to 10¹¹ here, while f · Le times the area
/// is past f32's largest number: a product formed before its division
/// overflows. Both points face each other (tilted by up to 0.3), and the
/// answer is judged relative to itself.
pub(super) fn vast_cases(f: Direct) -> (f64, String) {
    let mut draws = Draws::new(654);
    worst_drawn((0..draws.count(8, 16)).map(|_| {
        draws.next_case();
        let s = draws.decades(14.8, 15.0);
        let p = draws.place_for(s, 1.0);
        let y = p + draws.direction() * s * draws.range(0.5, 5.0);
        let mut facing = |from: Vec3, to: Vec3| {
            ((to - from).normalize() + draws.direction() * draws.range(0.0, 0.3)).normalize()
        };
        let (n, n_light) = (facing(p, y), facing(y, p));
        let area = s * s * draws.range(5.0, 10.0);
        let (rho, le) = (draws.colour(), draws.colour() * draws.decades(8.5, 9.0));
        let (cos, cos_l, full) = closed_form((p, n, rho), (y, n_light, area, le));
        let want = full * cos * cos_l;
        let got = f(p, n, rho, y, n_light, area, le, &|_, _| true).as_dvec3();
        (
            relative_or_zero(got, want),
            format!(
                "p {p}, n {n}, ρ {rho}, y {y}, n_light {n_light}, A {area}, Le {le} (a bright \
                 light in a vast scene: Le · A is past f32's largest number, the answer is \
                 not): got {got}, expected {want}"
            ),
        )
    }))
}
