//! Exercise 5.4, a light's area density as a solid-angle one: hand-worked
//! cases from `src/grading/cases.toml`, then drawn points and lights over
//! every scale, edge-on and grazing.

use glam::Vec3;

use super::{AreaPdfFn, PDF_JACOBIAN, PDF_SIGN};
use crate::cases::{self, unit, v3, V3};
use crate::exercise::{Check, Symptom};
use crate::exercises::draws::{fold_drawn, worst_drawn, Draws};
use crate::exercises::stateless;

/// A hand-worked case of the area-to-solid-angle density
/// (`src/grading/cases.toml`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct AreaPdfCase {
    pdf_area: f32,
    x: V3,
    y: V3,
    n_light: V3,
    expect: f32,
}

/// pdf_A d²/|cos θl| for hand-worked cases, and 0 edge-on.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_area_pdf(f: AreaPdfFn) -> Check {
    stateless::unless_changed(area_pdf_values(f), || {
        stateless::probes::area_pdf(f, super::reference_area_pdf)
    })
}

/// [`check_area_pdf`]'s checks of the values.
fn area_pdf_values(f: AreaPdfFn) -> Check {
    let worst = cases::worst("ch5/area_pdf", |c: &AreaPdfCase| {
        let (pdf, x, y, n, want) = (c.pdf_area, v3(c.x), v3(c.y), unit(c.n_light), c.expect);
        let got = f(pdf, x, y, n);
        let err = if want == 0.0 {
            got.abs() as f64
        } else {
            ((got - want) / want).abs() as f64
        };
        (
            err,
            format!("pdf_A {pdf}, x {x}, y {y}, n_light {n}: got {got}, expected {want}"),
        )
    });
    let (mut error, mut detail) = match worst {
        Ok(w) => w,
        Err(check) => return check,
    };
    // Drawn points and lights: distances from 10⁻⁵ to 10³ (a tenth from
    // 10⁻¹¹ to 10⁻⁵ and a tenth from 10³ to 10¹¹), up to 10³ times that
    // from the origin (grazing ones up to 10^3.5), either face, pdfs over
    // six decades, lights seen exactly edge-on, at grazing angles, and
    // nearly face-on.
    // Then, from a stream of their own, a seventh of the scenes scaled
    // to 10⁻¹⁵ to 10⁻¹¹ or 10¹¹ to 10¹⁵ with the density scaled as a
    // light's area would (pdf · d² from 0.1 to 10): the answer does not
    // change with the scene's scale, but d³ leaves f32's range.
    // And from a third stream, a seventh of the others 10^13.5 to 10¹⁵
    // away or 10⁻¹⁵ to 10^-13.5, the density as drawn (10⁻² to 10²): a
    // light small for its distance (or large), whose density per
    // steradian f32 holds although d³ does not.
    let mut draws = Draws::new(53);
    let mut scaled = Draws::new(353);
    let mut lone = Draws::new(453);
    let mut last: Option<(Vec3, Vec3, f32)> = None;
    let drawn = worst_drawn((0..draws.count(200, 1000)).map(|_| {
        draws.next_case();
        scaled.next_case();
        lone.next_case();
        let scale = match draws.unit() {
            u if u < 0.1 => draws.decades(-11.0, -5.0),
            u if u < 0.2 => draws.decades(3.0, 11.0),
            _ => draws.decades(-5.0, 3.0),
        };
        let stiff = scaled.far_scale(1.0 / 7.0, (-15.0, -11.0), (11.0, 15.0));
        let alone = lone
            .far_scale(1.0 / 7.0, (-15.0, -13.5), (13.5, 15.0))
            .filter(|_| stiff.is_none());
        let scale = stiff.or(alone).unwrap_or(scale);
        let mut x = draws.place_for(scale, 3.0);
        let axis = draws.count(0, 2);
        let mut offset = draws.direction();
        let mut n = draws.direction();
        let kind = draws.unit();
        if kind < 0.15 {
            // Edge-on: the light's normal and the way to it on two
            // different axes.
            offset = Vec3::ZERO;
            offset[axis] = draws.sign();
            // -axis has zeros of sign -: the cosine may be -0.
            n = Vec3::AXES[(axis + 1) % 3] * draws.sign();
        } else if kind < 0.3 {
            // Grazing, not edge-on: |cos θl| from 10⁻⁵ to 10⁻³.
            let tilt = draws.sign() * draws.decades(-5.0, -3.0);
            n = (offset.any_orthonormal_vector() + offset * tilt).normalize();
            // Half of them 10^2.5 to 10^3.5 times the distance from the
            // origin, where n · x and n · y round alike.
            if draws.unit() < 0.5 {
                x = draws.direction() * scale * draws.decades(2.5, 3.5);
            }
        } else if kind < 0.4 {
            // Nearly face-on: θl from 1° to 2.5°, where a cosine taken as
            // 1 is 1.5·10⁻⁴ to 10⁻³ off.
            let tilt = draws.range(1.0, 2.5).to_radians();
            let side = offset.any_orthonormal_vector() * tilt.sin();
            n = (offset * tilt.cos() + side) * draws.sign();
        }
        let mut y = x + offset * scale;
        // A tenth keep the last light point and its normal, seen from
        // another x: the density depends on x too.
        // (Not a scaled scene's: its density belongs to its own scale.)
        let usual = stiff.is_none() && alone.is_none();
        let again = draws.unit() < 0.1 && usual;
        if let Some((last_y, last_n, last_scale)) = last.filter(|_| again) {
            let moved = last_y + draws.direction() * last_scale * draws.range(0.5, 2.0);
            // Not where rounding puts x on the light point.
            if (moved - last_y).length() > 0.25 * last_scale {
                (y, n, x) = (last_y, last_n, moved);
            }
        }
        last = usual.then_some((y, n, scale)).or(last);
        let pdf = draws.decades(-3.0, 3.0);
        let to = (y - x).as_dvec3();
        let pdf = match stiff {
            Some(_) => (scaled.decades(-1.0, 1.0) as f64 / to.length_squared()) as f32,
            None if alone.is_some() => lone.decades(-2.0, 2.0),
            None => pdf,
        };
        let cos = (n.as_dvec3().dot(to) / to.length()).abs();
        let want = if cos == 0.0 {
            0.0
        } else {
            pdf as f64 * to.length_squared() / cos
        };
        let got = f(pdf, x, y, n);
        // The error relative to what rounding allows: 10⁻⁴, plus what an
        // f32 cosine's own rounding (a few 10⁻⁸, here 10⁻⁶ to be generous)
        // does to 1/cos at grazing angles: up to 10% at |cos| = 10⁻⁵, so a
        // density of 0 short of edge-on fails.
        let err = if want == 0.0 {
            f64::from(got.abs())
        } else {
            (f64::from(got) - want).abs() / want * 1e-4 / (1e-4 + 1e-6 / cos)
        };
        (
            err,
            format!("pdf_A {pdf}, x {x}, y {y}, n_light {n}: got {got}, expected {want}"),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    Check {
        error,
        tolerance: 1e-4,
        detail,
        images: None,
        symptom: (error > 1e-4).then(|| area_pdf_symptom(f)).flatten(),
    }
}

/// What a failing area-to-solid-angle conversion got wrong: a light seen
/// from behind (the same density expected), or straight above.
fn area_pdf_symptom(f: AreaPdfFn) -> Option<Symptom> {
    let y = Vec3::new(0.0, 0.0, 2.0);
    let front = f(0.5, Vec3::ZERO, y, -Vec3::Z);
    let back = f(0.5, Vec3::ZERO, y, Vec3::Z);
    if back.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) && front > 0.0 {
        Some(PDF_SIGN)
    } else if ((front - 2.0) / 2.0).abs() > 1e-4 || ((back - 2.0) / 2.0).abs() > 1e-4 {
        Some(PDF_JACOBIAN)
    } else {
        None
    }
}
