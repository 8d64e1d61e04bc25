//! Exercise 5.3, the point light: hand-worked cases from the case file,
//! then drawn lights and surfaces (grazing ones among them, some with a
//! normal along an axis, where the cosine is exact, down to 10⁻¹²).

use glam::Vec3;

use super::super::draws::{fold_drawn, worst_drawn, Draws};
use super::drawn::relative_or_zero;
use super::{off, rel, INVERSE_SQUARE, POINT_BEHIND};
use crate::cases::{self, unit, v3, V3};
use crate::exercise::{Check, Symptom};
use crate::exercises::{stateless, AbsMax};

type PointFn = fn(Vec3, Vec3, Vec3, Vec3) -> Vec3;

/// A hand-worked case of the point light (`src/grading/cases.toml`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct PointCase {
    intensity: V3,
    light: V3,
    p: V3,
    n: V3,
    expect: V3,
}

/// E = I cos θ / r² for hand-worked cases.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_point_light(f: PointFn) -> Check {
    stateless::unless_changed(point_light_values(f), || {
        stateless::probes::point_light(f, super::reference_point)
    })
}

/// [`check_point_light`]'s checks of the values.
fn point_light_values(f: PointFn) -> Check {
    let worst = cases::worst("ch5/point_light", |c: &PointCase| {
        let (i, light, p, n, want) = (
            v3(c.intensity),
            v3(c.light),
            v3(c.p),
            unit(c.n),
            v3(c.expect),
        );
        let got = f(i, light, p, n);
        (
            off(got, want),
            format!("I {i}, light at {light}, p {p}, n {n}: got {got}, expected {want}"),
        )
    });
    let (mut error, mut detail) = match worst {
        Ok(w) => w,
        Err(check) => return check,
    };
    // Drawn lights and surfaces: distances from 10⁻³ to 10⁶ (the
    // inverse-square law has no range), up to 10³ times that from the
    // origin, intensities over six decades, a tenth nearly facing the
    // light, a fifth of them at grazing angles (half of those 10^2.5 to 10^3.5 times the distance from the
    // origin, where n · light and n · p round alike); E worked out in f64.
    let mut draws = Draws::new(52);
    let mut off = Draws::new(152);
    // Lights with a channel off (pure green, no red), a fifth of the
    // channels.
    let mut channels = Draws::new(352);
    // From streams of their own: a tenth of the lights 10⁹ to 10¹⁵ away
    // (r³ past f32's range there, r² not) and a tenth 10⁻⁶ to 10⁻³ away,
    // and a tenth of the others faint, 10⁻¹² to 10⁻⁶ of the drawn
    // intensity (faint is not off).
    let (mut reach, mut faint) = (Draws::new(252), Draws::new(253));
    let mut last_light: Option<(Vec3, f32)> = None;
    let drawn = worst_drawn((0..draws.count(200, 1000)).map(|_| {
        draws.next_case();
        reach.next_case();
        faint.next_case();
        let scale = draws.decades(-3.0, 6.0);
        let (far, near) = match reach.unit() {
            u if u < 0.1 => (true, false),
            u => (false, u < 0.2),
        };
        let scale = match (far, near) {
            (true, _) => reach.decades(9.0, 15.0),
            (_, true) => reach.decades(-6.0, -3.0),
            _ => scale,
        };
        let mut p = draws.place_for(scale, 3.0);
        let mut way = draws.direction();
        let mut light = p + way * scale;
        // A tenth keep the last light and move p (a light lights many
        // points): E depends on p too.
        if let Some((last, last_scale)) = last_light.filter(|_| draws.unit() < 0.1) {
            let moved = last + draws.direction() * last_scale * draws.range(0.5, 2.0);
            // Not where rounding puts p on the light.
            if (moved - last).length() > 0.25 * last_scale {
                (light, p) = (last, moved);
                way = (light - p).normalize();
            }
        }
        let mut n = draws.direction();
        // With a normal along an axis and p in the plane through the
        // origin across it, the light's height above the surface is one
        // exact coordinate, and so is the cosine's numerator: no slack.
        let mut exact = false;
        match draws.count(0, 9) {
            // Grazing: |cos θ| from 10⁻⁵ to 10⁻³, in front or behind.
            0 | 1 => {
                let tilt = draws.sign() * draws.decades(-5.0, -3.0);
                n = (way.any_orthonormal_vector() + way * tilt).normalize();
                if draws.unit() < 0.5 {
                    p = draws.direction() * scale * draws.decades(2.5, 3.5);
                    light = p + way * scale;
                }
            }
            // Nearly facing the light: 1 - cos θ from 1.3·10⁻⁴ to 10⁻³
            // (the cosine still counts there).
            3 => {
                let tilt = draws.decades(-1.8, -1.35);
                n = (way + way.any_orthonormal_vector() * tilt).normalize();
            }
            // The same along an axis.
            2 => {
                let axis = draws.count(0, 2);
                n = Vec3::AXES[axis] * draws.sign();
                p[axis] = 0.0;
                light = p + way * scale;
                light[axis] = draws.sign() * draws.decades(-5.0, -3.0) * scale;
                exact = true;
            }
            _ => {}
        }
        let intensity =
            Vec3::new(draws.unit(), draws.unit(), draws.unit()) * draws.decades(-3.0, 3.0);
        // Now and then a light that is off: nothing arrives, not 0/0
        // (drawn apart, so that the other draws stay as they were).
        let intensity = if off.unit() < 0.05 {
            Vec3::ZERO
        } else {
            intensity * channels.channels_off(0.2)
        };
        let intensity = match !far && faint.unit() < 0.1 {
            true => intensity * faint.decades(-12.0, -6.0),
            false => intensity,
        };
        last_light = Some((light, scale));
        let to = (light - p).as_dvec3();
        let cos = n.as_dvec3().dot(to) / to.length();
        let want = (intensity.as_dvec3() * cos.max(0.0) / to.length_squared()).as_vec3();
        let got = f(intensity, light, p, n);
        let err = if cos < -1e-4 && got.abs_max() > 0.0 {
            // Well behind (no rounding of a cosine brings it in front):
            // exactly nothing.
            1.0
        } else if cos <= 0.0 {
            // Behind, near the horizon: nothing, but for what the rounding
            // of an f32 cosine lets through (a few 10⁻⁸ of E at normal
            // incidence; 10⁻⁶ of it allowed, as in front). A cut-off at
            // cos θ = -10⁻⁴ lets up to 10⁻⁴ through, and fails.
            let leak = got.abs_max() as f64 * to.length_squared()
                / f64::from(intensity.max_element()).max(f64::MIN_POSITIVE);
            leak * 1e-4 / 1e-6
        } else {
            // Relative to what rounding allows: 10⁻⁴, plus what an f32
            // cosine's own rounding (a few 10⁻⁸; 10⁻⁶ to be generous)
            // does at grazing angles. A light cut off short of 90° fails.
            // (Relative to E itself, however small: a faint or far light's
            // E is as exact in f32 as any other.)
            let relative = |got: Vec3, want: Vec3| {
                let e = match (want == Vec3::ZERO, got == Vec3::ZERO) {
                    (true, true) => 0.0,
                    (true, false) => f64::INFINITY,
                    _ => ((got - want).abs_max() / want.abs_max()) as f64,
                };
                if e.is_nan() {
                    f64::INFINITY
                } else {
                    e
                }
            };
            match exact {
                true => relative(got, want),
                false => relative(got, want) * 1e-4 / (1e-4 + 1e-6 / cos),
            }
        };
        (
            err,
            format!("I {intensity}, light at {light}, p {p}, n {n}: got {got}, expected {want}"),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    fold_drawn(&mut error, &mut detail, skimming(f));
    Check {
        error,
        tolerance: 1e-4,
        detail,
        images: None,
        symptom: (error > 1e-4).then(|| point_symptom(f)).flatten(),
    }
}

/// Lights that skim the surface, from a stream of their own: a normal
/// along an axis, p in the plane through the origin across it, and the
/// light 10⁻¹² to 10⁻⁶ of its distance above that plane. cos θ (10⁻¹² to
/// 10⁻⁶) is then one exact coordinate over the distance, so E is as exact
/// there as anywhere, and judged relative to itself: a light counted as
/// behind below some small cosine (`f32::EPSILON`, say) delivers nothing
/// where the law says E. A fifth lie exactly in the plane (exactly 0),
/// and a fifth of the intensities are near f32's largest number, where E
/// is still far below it but I / r² may not be.
fn skimming(f: PointFn) -> (f64, String) {
    let mut draws = Draws::new(452);
    worst_drawn((0..draws.count(24, 48)).map(|_| {
        draws.next_case();
        let scale = draws.decades(-2.0, 3.0);
        let (n, p, mut light) = draws.skimming(scale);
        // A fifth exactly in the surface's plane: exactly 0.
        if draws.unit() < 0.2 {
            light -= n * n.dot(light);
        }
        let grey = draws.colour();
        // A fifth of the lights 10³⁷ to 10^38.5 (f32's largest is 3.4·10³⁸):
        // E stays far below it at these cosines, I / r² may not.
        let intensity = match draws.unit() < 0.2 {
            true => grey * draws.decades(37.0, 38.5),
            false => grey * draws.decades(-2.0, 2.0),
        };
        let to = (light - p).as_dvec3();
        let cos = n.as_dvec3().dot(to) / to.length();
        let want = intensity.as_dvec3() * cos / to.length_squared();
        let got = f(intensity, light, p, n);
        (
            relative_or_zero(got.as_dvec3(), want),
            format!(
                "I {intensity}, light at {light}, p {p}, n {n} (the light skims the surface: cos θ \
                 = {cos:.2e}): got {got}, expected {}",
                want.as_vec3()
            ),
        )
    }))
}

/// What a failing point light got wrong: the light straight above at
/// 2 m (I/4 expected), or one behind the surface (0 expected).
fn point_symptom(f: PointFn) -> Option<Symptom> {
    let i = Vec3::ONE;
    let above = f(i, Vec3::new(0.0, 0.0, 2.0), Vec3::ZERO, Vec3::Z);
    let behind = f(i, Vec3::new(0.0, 0.0, -2.0), Vec3::ZERO, Vec3::Z);
    if behind.abs_max() > 1e-6 {
        Some(POINT_BEHIND)
    } else if rel(above, i / 4.0) > 1e-4 {
        Some(INVERSE_SQUARE)
    } else {
        None
    }
}
