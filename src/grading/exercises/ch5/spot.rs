//! Exercise 5.7, a spot light's power: hand-made cones whose answer is the
//! lesson's falloff ([`Spot::falloff`]) integrated over the sphere
//! numerically, then drawn cones against the closed form in f64.

use std::f64::consts::PI;

use glam::{DVec3, Vec3};

use super::{SPOT_BAND, SPOT_FACTOR, SPOT_NARROW};
use crate::cases;
use crate::ch5_reflection::light::spot::Spot;
use crate::ch5_reflection::radiometry::spot_flux;
use crate::exercise::{Check, Symptom};
use crate::exercises::draws::{fold_drawn, worst_drawn, Draws};
use crate::exercises::{stateless, AbsMax};

type SpotFn = fn(Vec3, f32, f32) -> Vec3;

/// ∫ falloff dω over the sphere for the spot of half-angles `inner`,
/// `outer` (radians), by two-point Gauss–Legendre in cos θ on each piece
/// where the lesson's falloff is a polynomial (1, the smoothstep, 0): exact
/// for cubics, and it never evaluates the falloff where a piece ends.
pub fn falloff_integral(inner: f32, outer: f32) -> f64 {
    let spot = Spot {
        position: Vec3::ZERO,
        axis: Vec3::Z,
        intensity: Vec3::ONE,
        cos_outer: outer.cos(),
        cos_inner: inner.cos(),
    };
    let s = |c: f64| {
        let c = c as f32;
        f64::from(spot.falloff(Vec3::new((1.0 - c * c).max(0.0).sqrt(), 0.0, c)))
    };
    let gauss = |a: f64, b: f64| {
        let (n, half) = (16, 0.5 / 3f64.sqrt());
        let h = (b - a) / n as f64;
        (0..n)
            .map(|k| {
                let mid = a + (k as f64 + 0.5) * h;
                (s(mid - half * h) + s(mid + half * h)) * h / 2.0
            })
            .sum::<f64>()
    };
    let (co, ci) = (f64::from(spot.cos_outer), f64::from(spot.cos_inner));
    2.0 * PI * (gauss(-1.0, co) + gauss(co, ci) + gauss(ci, 1.0))
}

fn rel(got: Vec3, want: DVec3) -> f64 {
    let e = (got.as_dvec3() - want).abs_max() / want.abs_max().max(1e-300);
    if e.is_nan() {
        f64::INFINITY
    } else {
        e
    }
}

/// A hand-made cone (`src/grading/cases.toml`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct SpotCase {
    inner: f32,
    outer: f32,
}

/// Φ = ∫ I · falloff dω for hand-made cones (the falloff integrated
/// numerically), then drawn ones, each channel to 10⁻⁵ of the brightest
/// channel's power (as `point_light` does).
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_spot(f: SpotFn) -> Check {
    stateless::unless_changed(spot_values(f), || {
        stateless::probes::spot(f, super::reference_spot)
    })
}

/// [`check_spot`]'s checks of the values.
fn spot_values(f: SpotFn) -> Check {
    let i = Vec3::new(4.0, 2.0, 0.5);
    let hand = cases::worst("ch5/spot", |c: &SpotCase| {
        let (inner, outer) = (c.inner, c.outer);
        let want = i.as_dvec3() * falloff_integral(inner, outer);
        let got = f(i, inner, outer);
        let shown = want.as_vec3();
        (
            rel(got, want),
            format!("I {i}, inner {inner}, outer {outer}: got {got}, expected {shown}"),
        )
    });
    let (mut worst, mut detail) = match hand {
        Ok(w) => w,
        Err(check) => return check,
    };
    // Drawn cones from 10⁻⁵ rad to π, hard-edged, all soft or in between,
    // and intensities over six decades with a channel sometimes 0 (or
    // all three).
    let mut d = Draws::new(57);
    let drawn = worst_drawn((0..d.count(200, 600)).map(|_| {
        d.next_case();
        let outer = if d.unit() < 0.1 {
            std::f32::consts::PI
        } else {
            d.decades(-5.0, std::f32::consts::PI.log10())
        };
        let inner = match d.count(0, 3) {
            0 => outer,
            1 => 0.0,
            _ => outer * d.unit(),
        };
        let mut i = Vec3::new(d.unit(), d.unit(), d.unit()) * d.decades(-3.0, 3.0);
        if d.unit() < 0.2 {
            i[d.count(0, 2)] = 0.0;
        }
        // Now and then a spot that is off: no power, and no NaN.
        if d.unit() < 0.05 {
            i = Vec3::ZERO;
        }
        let want = i.as_dvec3() * spot_flux(1.0, f64::from(inner), f64::from(outer));
        let got = f(i, inner, outer);
        (
            rel(got, want),
            format!(
                "I {i}, inner {inner}, outer {outer}: got {got}, expected {}",
                want.as_vec3()
            ),
        )
    }));
    fold_drawn(&mut worst, &mut detail, drawn);
    let check = Check {
        error: worst,
        tolerance: 1e-5,
        detail,
        images: None,
        symptom: None,
    };
    match check.passed() {
        true => check,
        false => match spot_symptom(f) {
            Some(symptom) => check.with_symptom(symptom),
            None => check,
        },
    }
}

/// What a failing spot power got wrong: a hard-edged and a soft cone, a
/// second soft cone, a narrow one.
fn spot_symptom(f: SpotFn) -> Option<Symptom> {
    let ratio = |inner: f32, outer: f32| {
        f64::from(f(Vec3::ONE, inner, outer).x) / spot_flux(1.0, inner.into(), outer.into())
    };
    let (hard, soft, other) = (ratio(0.5, 0.5), ratio(0.3, 0.6), ratio(0.2, 1.4));
    let narrow = ratio(1e-3, 2e-3);
    let off = |r: f64| r.is_nan() || (r - 1.0).abs() > 1e-5;
    if off(hard)
        && off(soft)
        && ((soft - hard) / hard).abs() < 1e-4
        && ((other - hard) / hard).abs() < 1e-4
    {
        Some(SPOT_FACTOR)
    } else if !off(hard) && off(soft) {
        Some(SPOT_BAND)
    } else if !off(hard) && !off(soft) && !off(other) && off(narrow) {
        Some(SPOT_NARROW)
    } else {
        None
    }
}
