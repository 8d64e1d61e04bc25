//! Exercise 6.5: refraction in world space, from either side of a
//! boundary between two indices, checked against Snell's law and the
//! exact Fresnel reflectance worked out in f64.

use glam::{DVec3, Vec3};

use super::draws::{fold_drawn, worst_drawn, Draws};
use super::worst;
use crate::ch5_reflection::material::dielectric::{fresnel_dielectric, refract_local};
use crate::ch5_reflection::material::Frame;
use crate::exercise::{Check, Symptom};
use crate::exercises::stateless::{probes, vec3_at};
use crate::exercises::{stateless, AbsMax};

/// The candidate: (d, n, η outside, η inside) to (t, F), `None` under
/// total internal reflection.
pub type RefractFn = fn(Vec3, Vec3, f32, f32) -> Option<(Vec3, f32)>;

/// Total internal reflection where there is none, or none where there is.
pub const REFRACT_TIR: Symptom = Symptom {
    name: "total internal reflection at the wrong angles",
};
/// The refracted ray on the side the light came from (`d` read as the
/// book's ωo, which points away from the surface).
pub const REFRACT_SIDE: Symptom = Symptom {
    name: "the refracted ray on the wrong side",
};
/// The right side but the wrong angle (the ratio of indices upside down).
pub const REFRACT_SNELL: Symptom = Symptom {
    name: "the wrong angle of refraction",
};
/// Right from outside, wrong from inside (the normal or the indices not
/// turned round).
pub const REFRACT_INSIDE: Symptom = Symptom {
    name: "light from inside handled as from outside",
};
/// The direction right, the reflectance not.
pub const REFRACT_FRESNEL: Symptom = Symptom {
    name: "the Fresnel reflectance is off",
};
/// A direction whose length is not 1.
pub const REFRACT_NOT_UNIT: Symptom = Symptom {
    name: "not a unit direction",
};

/// The symptoms of [`check_refraction`].
pub const SYMPTOMS: [Symptom; 6] = [
    REFRACT_TIR,
    REFRACT_SIDE,
    REFRACT_SNELL,
    REFRACT_INSIDE,
    REFRACT_FRESNEL,
    REFRACT_NOT_UNIT,
];

/// How far from 1 the exact sin²θ_t may be for f32 rounding to decide
/// between refraction and total internal reflection (the contract's
/// band, about a degree round the critical angle of glass). Near it the
/// answer is ill-conditioned: the rounding of d and n alone (10⁻⁷) moves
/// the exact f by up to 2·10⁻⁵ at the band's edge, a fifth of [`TOL`].
const BAND: f64 = 3e-2;
/// The tolerance on every component of t and on F.
const TOL: f64 = 1e-4;

/// The exact answer in f64: sin²θ_t, the normal on the side the light
/// comes from, and (t, F) unless the light is totally reflected.
fn exact(d: Vec3, n: Vec3, eta_out: f32, eta_in: f32) -> (f64, DVec3, Option<(DVec3, f64)>) {
    let (d, n) = (d.as_dvec3().normalize(), n.as_dvec3().normalize());
    let (m, eta_i, eta_t) = if d.dot(n) < 0.0 {
        (n, eta_out as f64, eta_in as f64)
    } else {
        (-n, eta_in as f64, eta_out as f64)
    };
    let cos_i = -d.dot(m);
    let eta = eta_i / eta_t;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return (sin2_t, m, None);
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let t = (eta * d + (eta * cos_i - cos_t) * m).normalize();
    let r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    let r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    (sin2_t, m, Some((t, 0.5 * (r_s * r_s + r_p * r_p))))
}

/// raystep's answer: the lesson's `refract_local` and
/// `fresnel_dielectric` in the frame of the normal.
// ANCHOR: refraction
pub fn reference_refract(d: Vec3, n: Vec3, eta_out: f32, eta_in: f32) -> Option<(Vec3, f32)> {
    let frame = Frame::from_normal(n);
    let wo = frame.to_local(-d);
    let (eta_o, eta_far) = if wo.z > 0.0 {
        (eta_out, eta_in)
    } else {
        (eta_in, eta_out)
    };
    let t = refract_local(wo, eta_o / eta_far)?;
    let f = fresnel_dielectric(wo.z.abs(), t.z.abs(), eta_o, eta_far);
    Some((frame.to_world(t), f))
}
// ANCHOR_END: refraction

/// One case's error (on the scale of [`TOL`]) and what went wrong.
fn case(f: RefractFn, d: Vec3, n: Vec3, eo: f32, ei: f32) -> (f64, String, Option<Symptom>) {
    let (sin2_t, m, want) = exact(d, n, eo, ei);
    let got = f(d, n, eo, ei);
    let what = |e: &str| {
        let want = want.map(|(t, f)| (t.as_vec3(), f as f32));
        format!("d {d}, n {n}, η outside {eo}, inside {ei}: got {got:?}, expected {want:?}{e}")
    };
    let in_band = (1.0 - sin2_t).abs() < BAND;
    let Some((t, fr)) = got else {
        return match (want, in_band) {
            (Some(_), false) => (1.0, what(""), Some(REFRACT_TIR)),
            _ => (0.0, String::new(), None),
        };
    };
    if !(t.is_finite() && fr.is_finite()) {
        return (1.0, what(": not finite"), Some(REFRACT_NOT_UNIT));
    }
    if want.is_none() && !in_band {
        return (1.0, what(""), Some(REFRACT_TIR));
    }
    let t64 = t.as_dvec3();
    let length = (t64.length() - 1.0).abs();
    let side = t64.dot(m).max(0.0);
    let (dt, df) = match want {
        // Where rounding decides, f is not checked: computed from cosines
        // that rounding leaves with few correct digits, it can be anything.
        Some((tw, _)) if in_band => ((t64 - tw).abs_max(), 0.0),
        Some((tw, fw)) => ((t64 - tw).abs_max(), (f64::from(fr) - fw).abs()),
        None => (0.0, 0.0),
    };
    let symptom = if side > 1e-3 {
        REFRACT_SIDE
    } else if length > TOL {
        REFRACT_NOT_UNIT
    } else if dt > TOL {
        REFRACT_SNELL
    } else {
        REFRACT_FRESNEL
    };
    // Where rounding decides between refraction and total internal
    // reflection, t only has to be within 10⁻² of the exact one.
    let scale = if in_band { TOL / 1e-2 } else { 1.0 };
    let err = length.max(side).max(dt).max(df) * scale;
    (err, what(""), Some(symptom))
}

/// A direction that meets the normal `n` at cos θ = `c` (the sign says
/// which side it travels towards), in the drawn azimuth `a`. The normal is
/// made unit in f64 first: a drawn one is a few ulps off, and a tangent
/// square to it would then lean by as much, which at |c| = 10⁻⁶ can put d
/// on the other side, breaking the contract's |d·n| ≥ 10⁻⁶.
fn at_cos(n: Vec3, c: f64, a: Vec3) -> Vec3 {
    let (n, a) = (n.as_dvec3().normalize(), a.as_dvec3());
    let tangent = (a - n * a.dot(n)).normalize();
    (tangent * (1.0 - c * c).max(0.0).sqrt() + n * c).as_vec3()
}

/// Snell's law, the exact Fresnel reflectance and total internal
/// reflection, from either side, on hand cases and on drawn normals,
/// directions (grazing and near the critical angle among them) and
/// indices from 1 to 2.5 (equal among them); see the stub's contract.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_refraction(f: RefractFn) -> Check {
    stateless::unless_changed(refraction_values(f), || probe(f))
}

/// refract(d, n, η outside, η inside), the directions taken whole; half
/// the questions at grazing incidence (cos θ from 10⁻³ to 3·10⁻², where
/// the reflectance changes fastest). A twin turns d or n a little (its
/// numbers are moved, then it is made unit again); the indices stay (they
/// cannot move towards zero: 1 is their least). Questions outside the
/// contract's domain after a move (|d·n| below 10⁻⁵) and those where f32
/// rounding may decide between refraction and total reflection (the
/// exact sin²θ_t within 5·10⁻² of 1) are not asked.
fn probe(f: RefractFn) -> Option<String> {
    let mut k = 0;
    let q = probes::draw(108, &[0..3, 3..6], |d| {
        k += 1;
        let n = d.direction();
        let dir = match k % 2 {
            0 => d.direction(),
            _ => {
                let cos = d.sign() * d.decades(-3.0, -1.5);
                let a = d.direction();
                let side = (a - n * a.dot(n)).normalize_or(n.any_orthonormal_vector());
                (side * (1.0 - cos * cos).sqrt() + n * cos).normalize()
            }
        };
        let mut v = probes::cat(&[dir, n]);
        v.extend([d.range(1.0, 2.5) as f64, d.range(1.0, 2.5) as f64]);
        v
    });
    let args = |n: &[f64]| {
        let (d, normal) = (vec3_at(n, 0).normalize(), vec3_at(n, 3).normalize());
        let (eo, ei) = (n[6] as f32, n[7] as f32);
        let asked = d.dot(normal).abs() >= 1e-5 && (exact(d, normal, eo, ei).0 - 1.0).abs() > 5e-2;
        asked.then_some((d, normal, eo, ei))
    };
    let ask = |n: &[f64]| args(n).map(|(d, normal, eo, ei)| f(d, normal, eo, ei));
    let right = |n: &[f64]| args(n).map(|(d, normal, eo, ei)| reference_refract(d, normal, eo, ei));
    probes::both(&q, (&[0..3, 3..6], &[]), 208, ask, right)
}

/// [`check_refraction`]'s checks of the values.
fn refraction_values(f: RefractFn) -> Check {
    let n = Vec3::new(0.3, -0.5, 0.8).normalize();
    let tilt = Vec3::new(0.7, 0.2, -0.1);
    let hand = [
        (-n, n, 1.0, 1.5, "straight in, air to glass: F = 0.04"),
        (n, n, 1.0, 1.5, "straight out of glass: F = 0.04"),
        (at_cos(n, -0.7, tilt), n, 1.33, 1.5, "water to glass"),
        (
            at_cos(n, 0.4, tilt),
            n,
            1.0,
            1.5,
            "from inside the glass beyond the critical angle",
        ),
        (
            at_cos(n, 0.9, tilt),
            n,
            1.0,
            1.5,
            "from inside the glass below the critical angle",
        ),
        (
            at_cos(n, -0.3, tilt),
            n,
            1.33,
            1.33,
            "equal indices: no bending, F = 0",
        ),
        (at_cos(n, -1e-4, tilt), n, 1.0, 1.5, "grazing: F near 1"),
        (
            at_cos(n, 0.99, tilt),
            n,
            1.0,
            2.5,
            "from inside a dense glass 8° off the normal: F is not yet the normal incidence's",
        ),
    ];
    let cases = hand.into_iter().map(|(d, n, eo, ei, name)| {
        let (e, what, s) = case(f, d, n, eo, ei);
        (e, (format!("{name}: {what}"), s))
    });
    let (mut error, (mut detail, mut symptom)) =
        worst(cases).unwrap_or_else(|| (0.0, ("all cases match".into(), None)));
    let mut drawn_symptom = None;
    let drawn = worst_drawn(drawn_questions().into_iter().map(|(d, n, eo, ei, kind)| {
        let (e, what, s) = case(f, d, n, eo, ei);
        if e > TOL {
            drawn_symptom = drawn_symptom.or(s);
        }
        (e, format!("{what}{kind}"))
    }));
    if drawn.0 > error {
        symptom = drawn_symptom;
    }
    fold_drawn(&mut error, &mut detail, drawn);
    Check {
        error,
        tolerance: TOL,
        detail,
        images: None,
        symptom: (error > TOL)
            .then(|| probe_symptom(f).or(symptom))
            .flatten(),
    }
}

/// A drawn question: d, n, η outside, η inside, and what kind of
/// question it is (for the message).
type Question = (Vec3, Vec3, f32, f32, String);

/// The drawn questions, from a stream of their own: anywhere in the
/// domain; then grazing sweeps; then near the normal.
fn drawn_questions() -> Vec<Question> {
    let mut draws = Draws::new(65);
    let mut asked = Vec::new();
    for _ in 0..draws.count(600, 1500) {
        draws.next_case();
        // A tenth along an axis, either way: a frame built by crossing n
        // with a fixed axis has none there.
        let n = match draws.unit() < 0.1 {
            true => Vec3::AXES[draws.count(0, 2)] * draws.sign(),
            false => draws.direction(),
        };
        let eo = if draws.unit() < 0.4 {
            1.0
        } else {
            draws.range(1.0, 2.5)
        };
        let ei = match draws.count(0, 9) {
            0 => eo,
            1 => eo * (1.0 + draws.decades(-5.0, -2.0)),
            _ => draws.range(1.0, 2.5),
        };
        // From outside (-1) or inside (+1), and the ratio of the indices.
        let side = draws.sign() as f64;
        let ratio = if side < 0.0 { eo / ei } else { ei / eo } as f64;
        let cos = match draws.count(0, 9) {
            // Straight through, or within 10⁻⁴ to 0.02 rad of it.
            0 if draws.unit() < 0.5 => 1.0,
            0 => (draws.decades(-4.0, -1.7) as f64).cos(),
            // Grazing.
            1 | 2 => draws.decades(-6.0, -1.0) as f64,
            // About the critical angle (grazing where there is none).
            3 | 4 => {
                let sin2_t = 1.0 + draws.sign() as f64 * draws.decades(-5.0, -0.5) as f64;
                (1.0 - sin2_t / (ratio * ratio)).max(0.0).sqrt()
            }
            _ => draws.unit() as f64,
        };
        let d = at_cos(n, side * cos.max(1e-6), draws.direction());
        asked.push((d, n, eo, ei, String::new()));
    }
    // Sweeps at grazing incidence from outside, where F changes fastest
    // (by about 10⁻³ when cos θ moves by 2.5·10⁻⁴): 48 directions one
    // after another, cos θ from a drawn c₀ (10⁻³ to 0.05) up in steps of
    // 0.2 % of it, the plane of incidence kept. Each answer is its own:
    // one kept from a near question (a table keyed on a rounded cosine)
    // is off by more than the tolerance.
    for _ in 0..draws.count(3, 5) {
        draws.next_case();
        let n = draws.direction();
        let (eo, ei) = (draws.range(1.0, 1.6), draws.range(1.3, 2.5));
        let (c0, a) = (draws.decades(-3.0, -1.3) as f64, draws.direction());
        for k in 0..48 {
            let d = at_cos(n, -c0 * (1.0 + 2e-3 * k as f64), a);
            let kind = format!(" (a grazing sweep, direction {k} of 48)");
            asked.push((d, n, eo, ei, kind));
        }
    }
    // Near the normal, most from inside a dense medium: F is close to its
    // value at normal incidence there, but not equal (from inside glass of
    // 2.5 into air, off by 3·10⁻⁴ at 8°). cos θ from 0.97 to 1; half at
    // the domain's extreme indices, 1 outside and 2.5 inside.
    for k in 0..128 {
        draws.next_case();
        let n = draws.direction();
        let (eo, ei) = match k % 2 {
            0 => (1.0, 2.5),
            _ => (draws.range(1.0, 1.5), draws.range(1.8, 2.5)),
        };
        let side = if draws.unit() < 0.75 { 1.0 } else { -1.0 };
        let cos = draws.range(0.97, 1.0) as f64;
        asked.push((
            at_cos(n, side * cos, draws.direction()),
            n,
            eo,
            ei,
            " (near the normal)".into(),
        ));
    }
    // Indices 10⁻⁵ to 10^-3.5 apart, from either side at 60° to 80° from
    // the normal: t bends by up to 10⁻³ there, so equal indices are no
    // shortcut for nearly equal ones.
    for _ in 0..32 {
        draws.next_case();
        let (n, eo) = (draws.direction(), draws.range(1.0, 2.4));
        let ei = eo + draws.sign() * draws.decades(-5.0, -3.5);
        let cos = draws.sign() as f64 * draws.range(0.17, 0.5) as f64;
        let d = at_cos(n, cos, draws.direction());
        asked.push((d, n, eo, ei, " (nearly equal indices)".into()));
    }
    asked
}

/// What a failing refraction got wrong, from probes about a tilted
/// normal: into glass at 30° and at 60°, out of glass at 20° (also told
/// with the normal turned round) and at 60°; else what the worst case of
/// the check showed.
fn probe_symptom(f: RefractFn) -> Option<Symptom> {
    let n = Vec3::new(-0.2, 0.9, 0.3).normalize();
    let a = Vec3::new(0.5, 0.1, 0.8);
    let right = |c: f64, eo: f32, ei: f32| case(f, at_cos(n, c, a), n, eo, ei);
    let into = right(-0.866, 1.0, 1.5);
    let out = right(0.94, 1.0, 1.5);
    // The same crossing as `out`, told with the normal turned round: the
    // light now comes from "outside", whose index is the glass's.
    let mirrored = case(f, at_cos(-n, -0.94, a), -n, 1.5, 1.0);
    if into.0 > TOL {
        return into.2;
    }
    if out.0 > TOL && mirrored.0 <= TOL {
        return Some(REFRACT_INSIDE);
    }
    [right(-0.5, 1.0, 1.5), right(0.5, 1.0, 1.5), out]
        .into_iter()
        .find(|c| c.0 > TOL)
        .and_then(|c| c.2)
}
