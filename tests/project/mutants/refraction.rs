//! Exercise 6.5's mutants: plausible wrong refractions written from the
//! stub's contract alone, each of which the check must fail under every
//! seed, naming its symptom; and correct alternatives, written
//! differently, that must pass under every seed.

use glam::{DVec3, Vec3};
use raystep::grading::exercises::refraction::{self as r, check_refraction};
use raystep::grading::{Check, Symptom};

use super::under_seeds;

const SEEDS: [u64; 5] = [0, 1, 0x5eed, 977, 31337];

/// What a mutant gets wrong.
#[derive(Clone, Copy, PartialEq)]
enum Bug {
    None,
    /// η = η_t / η_i.
    RatioInverted,
    /// d read as the book's ωo (pointing away from the surface).
    BookWo,
    /// Always the outside's normal and index first.
    NoFlip,
    /// Total internal reflection past the glass's critical angle on
    /// either side.
    TirEitherSide,
    /// Schlick's approximation (with the cosine on the thinner side).
    Schlick,
    /// cos θ_i on both sides of the Fresnel terms: the reflectance of
    /// normal incidence at every angle.
    CosIBothSides,
    /// The s-polarised reflectance alone.
    OnlyS,
    /// t built from sin θ_t along d's tangent part, which is not unit.
    NotNormalised,
    /// The reflected ray with f = 1 instead of None.
    ReflectInsteadOfNone,
    /// Near normal incidence (cos θ_i > 0.9999), d itself with the
    /// reflectance of normal incidence: a shortcut off by up to 0.014 rad
    /// (fourth fresh set).
    NearNormalShortcut,
}

fn refract(d: Vec3, n: Vec3, eo: f32, ei: f32, bug: Bug) -> Option<(Vec3, f32)> {
    let from_outside = d.dot(n) < 0.0 || bug == Bug::NoFlip;
    let (mut m, eta_i, eta_t) = if from_outside {
        (n, eo, ei)
    } else {
        (-n, ei, eo)
    };
    let mut dd = d;
    if bug == Bug::BookWo {
        // ωo = d: the normal on "its" side is the one d points along.
        dd = -d;
        m = -m;
    }
    let cos_i = -dd.dot(m);
    if bug == Bug::NearNormalShortcut && cos_i > 0.9999 {
        return Some((d, ((eta_i - eta_t) / (eta_i + eta_t)).powi(2)));
    }
    let eta = match bug {
        Bug::RatioInverted => eta_t / eta_i,
        _ => eta_i / eta_t,
    };
    let sin2_i = (1.0 - cos_i * cos_i).max(0.0);
    let sin2_t = eta * eta * sin2_i;
    if bug == Bug::TirEitherSide && sin2_i.sqrt() > eo.min(ei) / eo.max(ei) {
        return None;
    }
    if sin2_t >= 1.0 {
        return match bug {
            Bug::ReflectInsteadOfNone => Some((d - 2.0 * d.dot(n) * n, 1.0)),
            _ => None,
        };
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let t = if bug == Bug::NotNormalised {
        let tangent = dd + cos_i * m; // length sin θ_i, not 1
        tangent * sin2_t.sqrt() - cos_t * m
    } else {
        (eta * dd + (eta * cos_i - cos_t) * m).normalize()
    };
    let (ci, ct) = match bug {
        Bug::CosIBothSides => (cos_i, cos_i),
        _ => (cos_i, cos_t),
    };
    let f = if bug == Bug::Schlick {
        let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
        let c = if eta_i <= eta_t { cos_i } else { cos_t };
        r0 + (1.0 - r0) * (1.0 - c).powi(5)
    } else {
        let r_s = (eta_i * ci - eta_t * ct) / (eta_i * ci + eta_t * ct);
        let r_p = (eta_t * ci - eta_i * ct) / (eta_t * ci + eta_i * ct);
        match bug {
            Bug::OnlyS => r_s * r_s,
            _ => 0.5 * (r_s * r_s + r_p * r_p),
        }
    };
    Some((t, f))
}

macro_rules! with_bug {
    ($bug:expr) => {
        |d, n, eo, ei| refract(d, n, eo, ei, $bug)
    };
}

fn fails_naming(what: &str, check: impl Fn() -> Check, symptom: Symptom) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        assert!(!c.passed(), "{what} passed under seed {seed}: {}", c.detail);
        assert_eq!(
            c.symptom.map(|s| s.name),
            Some(symptom.name),
            "{what} under seed {seed}: {}",
            c.detail
        );
    }
}

fn passes(what: &str, check: impl Fn() -> Check) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        assert!(c.passed(), "{what} failed under seed {seed}: {}", c.detail);
    }
}

/// A mutant: its name, its check, and the symptom it must be named by.
type Case = (&'static str, fn() -> Check, Symptom);

#[test]
fn wrong_refractions_fail_and_are_named() {
    let cases: [Case; 10] = [
        (
            "ratio inverted",
            || check_refraction(with_bug!(Bug::RatioInverted)),
            r::REFRACT_SNELL,
        ),
        (
            "the book's ωo",
            || check_refraction(with_bug!(Bug::BookWo)),
            r::REFRACT_SIDE,
        ),
        (
            "no flip from inside",
            || check_refraction(with_bug!(Bug::NoFlip)),
            r::REFRACT_INSIDE,
        ),
        (
            "TIR on either side",
            || check_refraction(with_bug!(Bug::TirEitherSide)),
            r::REFRACT_TIR,
        ),
        (
            "Schlick",
            || check_refraction(with_bug!(Bug::Schlick)),
            r::REFRACT_FRESNEL,
        ),
        (
            "cos θ_i twice",
            || check_refraction(with_bug!(Bug::CosIBothSides)),
            r::REFRACT_FRESNEL,
        ),
        (
            "s only",
            || check_refraction(with_bug!(Bug::OnlyS)),
            r::REFRACT_FRESNEL,
        ),
        (
            "not normalised",
            || check_refraction(with_bug!(Bug::NotNormalised)),
            r::REFRACT_NOT_UNIT,
        ),
        (
            "reflects under TIR",
            || check_refraction(with_bug!(Bug::ReflectInsteadOfNone)),
            r::REFRACT_TIR,
        ),
        (
            "d kept near normal incidence",
            || check_refraction(with_bug!(Bug::NearNormalShortcut)),
            r::REFRACT_SNELL,
        ),
    ];
    for (what, check, symptom) in cases {
        fails_naming(what, check, symptom);
    }
}

/// Correct, glam's own `refract` (GLSL's: the zero vector under total
/// internal reflection) and cos θ_t read back from t.
fn with_glam(d: Vec3, n: Vec3, eo: f32, ei: f32) -> Option<(Vec3, f32)> {
    let (m, a, b) = if d.dot(n) < 0.0 {
        (n, eo, ei)
    } else {
        (-n, ei, eo)
    };
    let t = d.refract(m, a / b);
    if t == Vec3::ZERO {
        return None;
    }
    let t = t.normalize();
    let (ci, ct) = (-d.dot(m), -t.dot(m));
    let r_s = (a * ci - b * ct) / (a * ci + b * ct);
    let r_p = (b * ci - a * ct) / (b * ci + a * ct);
    Some((t, (r_s * r_s + r_p * r_p) / 2.0))
}

/// Correct, in f64 by the tangent: sin θ_t = η sin θ_i along d's part in
/// the surface, cos θ_t along the normal, and F as tan and sin ratios.
fn by_tangent(d: Vec3, n: Vec3, eo: f32, ei: f32) -> Option<(Vec3, f32)> {
    let (d, n) = (d.as_dvec3(), n.as_dvec3());
    let inside = d.dot(n) > 0.0;
    let (a, b) = if inside { (ei, eo) } else { (eo, ei) };
    let eta = a as f64 / b as f64;
    let along = d.dot(n) * n;
    let tangent = d - along;
    let sin_t = eta * tangent.length();
    if sin_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let dir = tangent.try_normalize().unwrap_or(DVec3::ZERO);
    let t = dir * sin_t + along.normalize() * cos_t;
    let cos_i = d.dot(n).abs();
    let f = if eta == 1.0 {
        0.0
    } else {
        let (a, b) = (a as f64, b as f64);
        let r_s = (a * cos_i - b * cos_t) / (a * cos_i + b * cos_t);
        let r_p = (b * cos_i - a * cos_t) / (b * cos_i + a * cos_t);
        (r_s * r_s + r_p * r_p) / 2.0
    };
    Some((t.as_vec3(), f as f32))
}

#[test]
fn right_refractions_pass() {
    passes("the book's loop turned to the light's side", || {
        check_refraction(with_bug!(Bug::None))
    });
    passes("glam's refract", || check_refraction(with_glam));
    passes("by the tangent, in f64", || check_refraction(by_tangent));
    passes("by sines", || check_refraction(by_cross));
    passes("raystep's", || check_refraction(r::reference_refract));
}

/// Correct, by sines: sin θ_i = |d × m|, the tangent direction from d,
/// and t from sin θ_t and cos θ_t (unit without normalising).
fn by_cross(d: Vec3, n: Vec3, eo: f32, ei: f32) -> Option<(Vec3, f32)> {
    let c = d.dot(n);
    let (m, a, b) = if c < 0.0 { (n, eo, ei) } else { (-n, ei, eo) };
    let sin_i = d.cross(m).length();
    let sin_t = a / b * sin_i;
    if sin_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let cos_i = c.abs();
    let tan = (d + cos_i * m).normalize_or_zero();
    let t = tan * sin_t - m * cos_t;
    let r_s = (a * cos_i - b * cos_t) / (a * cos_i + b * cos_t);
    let r_p = (b * cos_i - a * cos_t) / (b * cos_i + a * cos_t);
    Some((t, 0.5 * (r_s * r_s + r_p * r_p)))
}

#[test]
fn a_right_refraction_passes_under_many_seeds() {
    // The drawn cases keep the contract's |d·n| ≥ 10⁻⁶ under any seed. A
    // drawn normal a few ulps off unit length gave a d with d·n near
    // 10⁻⁸, whose side f32 rounding decides, and a right solution failed
    // a CI run.
    // 19,892,539 drew that case before the fix; 20,000 seeds of this
    // series passed after it (the test keeps 400 and that one).
    let mut seeds: Vec<u64> = (0..400).map(|s| s * 7919 + 11).collect();
    seeds.push(19_892_539);
    let right: [(&str, r::RefractFn); 4] = [
        ("vector Snell", with_bug!(Bug::None)),
        ("with glam", with_glam),
        ("by tangent", by_tangent),
        ("by cross", by_cross),
    ];
    for (name, f) in right {
        for (seed, check) in under_seeds(&seeds, || check_refraction(f)) {
            assert!(check.passed(), "{name}, seed {seed}: {}", check.detail);
        }
    }
}
