//! Chapter 5's mutants: plausible wrong `direct_light`s that the
//! capstone's check must fail, each naming its symptom, correct
//! alternatives that must pass, and the common mistakes of the smaller
//! exercises.

use std::f32::consts::PI;

use glam::{Vec2, Vec3};
use raystep::grading::exercise::{Check, Symptom};
use raystep::grading::exercises::ch5::{self, check_direct_light};

type Visible<'a> = &'a dyn Fn(Vec3, Vec3) -> bool;

/// What a mutant of `direct_light` gets wrong.
#[derive(Clone, Copy, PartialEq)]
enum Bug {
    /// f = ρ (the 1/π forgotten).
    NoPi,
    /// pdf_A used as if it were per steradian: f · Le · cos θ · A.
    NoJacobian,
    /// d instead of d².
    DistanceNotSquared,
    /// Divides by cos θl instead of multiplying (the Jacobian upside down).
    JacobianInverted,
    /// cos θ at p left out.
    NoCosSurface,
    /// |cos θl|: the light shines from its back face too.
    TwoSided,
    /// cos θ at p not clamped: light from below the surface subtracts.
    NoClampSurface,
    /// The shadow test ignored.
    NoShadow,
    /// visible(p, p + wi): a unit-length shadow ray, not to the light.
    UnitShadowRay,
    /// visible(y, p): the segment from the light back.
    ShadowReversed,
    /// Divides by the area instead of multiplying (pdf_A = A).
    AreaInverted,
}

/// The book's estimate with one bug switched in.
#[allow(clippy::too_many_arguments)]
fn direct(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: Visible,
    bug: Bug,
) -> Vec3 {
    let to = y - p;
    let d = to.length();
    let wi = to / d;
    let cos = n.dot(wi);
    let cos_l = match bug {
        Bug::TwoSided => n_light.dot(-wi).abs(),
        _ => n_light.dot(-wi),
    };
    if (bug != Bug::NoClampSurface && cos <= 0.0) || cos_l <= 0.0 {
        return Vec3::ZERO;
    }
    let seen = match bug {
        Bug::NoShadow => true,
        Bug::UnitShadowRay => visible(p, p + wi),
        Bug::ShadowReversed => visible(y, p),
        _ => visible(p, y),
    };
    if !seen {
        return Vec3::ZERO;
    }
    let f = if bug == Bug::NoPi { rho } else { rho / PI };
    let c = if bug == Bug::NoCosSurface { 1.0 } else { cos };
    let geometry = match bug {
        Bug::NoJacobian => 1.0,
        Bug::DistanceNotSquared => cos_l / d,
        Bug::JacobianInverted => 1.0 / (cos_l * d * d),
        _ => cos_l / (d * d),
    };
    let a = if bug == Bug::AreaInverted {
        1.0 / area
    } else {
        area
    };
    f * le * c * geometry * a
}

macro_rules! mutant {
    ($bug:expr) => {
        check_direct_light(|p, n, r, y, nl, a, le, v| direct(p, n, r, y, nl, a, le, v, $bug))
    };
}

fn fails_with(check: Check, symptom: Symptom) {
    super::fails_naming(check, symptom, &ch5::exercises(), "");
}

#[test]
fn the_brdf_and_the_jacobian_are_named() {
    fails_with(mutant!(Bug::NoPi), ch5::BRDF_PI);
    fails_with(mutant!(Bug::NoJacobian), ch5::JACOBIAN);
    fails_with(mutant!(Bug::DistanceNotSquared), ch5::JACOBIAN);
    fails_with(mutant!(Bug::JacobianInverted), ch5::JACOBIAN);
    fails_with(mutant!(Bug::AreaInverted), ch5::AREA);
}

#[test]
fn the_cosines_and_their_clamps_are_named() {
    fails_with(mutant!(Bug::NoCosSurface), ch5::COS_SURFACE);
    fails_with(mutant!(Bug::TwoSided), ch5::TWO_SIDED);
    fails_with(mutant!(Bug::NoClampSurface), ch5::BEHIND);
}

#[test]
fn the_shadow_test_is_checked_with_its_endpoints() {
    fails_with(mutant!(Bug::NoShadow), ch5::NO_SHADOW);
    fails_with(mutant!(Bug::UnitShadowRay), ch5::WRONG_SEGMENT);
    fails_with(mutant!(Bug::ShadowReversed), ch5::WRONG_SEGMENT);
}

/// A correct alternative: through the solid-angle pdf, as the lecture
/// writes the estimator, with the shadow test asked first.
#[allow(clippy::too_many_arguments)]
fn through_the_pdf(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: Visible,
) -> Vec3 {
    if !visible(p, y) {
        return Vec3::ZERO;
    }
    let wi = (y - p).normalize();
    let cos_theta = n.dot(wi).max(0.0);
    let cos_light = (-wi).dot(n_light);
    if cos_light <= 0.0 {
        return Vec3::ZERO;
    }
    let pdf_area = 1.0 / area;
    let pdf_w = pdf_area * y.distance_squared(p) / cos_light;
    rho / PI * le * cos_theta / pdf_w
}

/// A correct alternative: in f64, the geometry term first.
#[allow(clippy::too_many_arguments)]
fn in_f64(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: Visible,
) -> Vec3 {
    let to = (y - p).as_dvec3();
    let d2 = to.length_squared();
    let g = n.as_dvec3().dot(to).max(0.0) * (-n_light.as_dvec3()).dot(to).max(0.0) / (d2 * d2);
    if g == 0.0 || !visible(p, y) {
        return Vec3::ZERO;
    }
    (rho.as_dvec3() * le.as_dvec3() * (g * area as f64 / std::f64::consts::PI)).as_vec3()
}

#[test]
fn correct_alternatives_pass() {
    let check = check_direct_light(through_the_pdf);
    assert!(check.passed(), "through the pdf: {}", check.detail);
    let check = check_direct_light(in_f64);
    assert!(check.passed(), "in f64: {}", check.detail);
    assert!(check.images.is_some());
}

// The smaller exercises' common mistakes.

#[test]
fn lambert_mistakes_are_named() {
    fails_with(ch5::check_lambert_brdf(|rho, _, _| rho), ch5::LAMBERT_PI);
    fails_with(
        ch5::check_lambert_brdf(|rho, wo, wi| {
            if wo.z > 0.0 && wi.z > 0.0 {
                rho / PI
            } else {
                Vec3::ZERO
            }
        }),
        ch5::LAMBERT_ONE_SIDED,
    );
}

#[test]
fn cosine_hemisphere_mistakes_are_named() {
    // r = u instead of √u: too many directions near the pole.
    let linear = |u: Vec2| {
        let (r, phi) = (u.x, 2.0 * PI * u.y);
        let z = (1.0 - r * r).max(0.0).sqrt();
        (Vec3::new(r * phi.cos(), r * phi.sin(), z), z / PI)
    };
    fails_with(ch5::check_cosine_hemisphere(linear), ch5::NOT_COSINE);
    // The pdf without its 1/π.
    let no_pi = |u: Vec2| {
        let (r, phi) = (u.x.sqrt(), 2.0 * PI * u.y);
        let z = (1.0 - r * r).max(0.0).sqrt();
        (Vec3::new(r * phi.cos(), r * phi.sin(), z), z)
    };
    fails_with(ch5::check_cosine_hemisphere(no_pi), ch5::COSINE_PDF);
    // z = 1 − r²: not a unit vector.
    let flat = |u: Vec2| {
        let (r, phi) = (u.x.sqrt(), 2.0 * PI * u.y);
        let z = 1.0 - r * r;
        (Vec3::new(r * phi.cos(), r * phi.sin(), z), z / PI)
    };
    fails_with(ch5::check_cosine_hemisphere(flat), ch5::NOT_ON_HEMISPHERE);
}

#[test]
fn point_light_mistakes_are_named() {
    fails_with(
        ch5::check_point_light(|i, l, p, n| {
            let to = l - p;
            i * n.dot(to.normalize()).max(0.0) / to.length()
        }),
        ch5::INVERSE_SQUARE,
    );
    fails_with(
        ch5::check_point_light(|i, l, p, n| {
            let to = l - p;
            i * n.dot(to.normalize()) / to.length_squared()
        }),
        ch5::POINT_BEHIND,
    );
}

#[test]
fn area_pdf_mistakes_are_named() {
    // The signed cosine: negative for a light seen from behind.
    fails_with(
        ch5::check_area_pdf(|pdf, x, y, n: Vec3| {
            let to = y - x;
            let c = n.dot(-to.normalize());
            if c == 0.0 {
                0.0
            } else {
                pdf * to.length_squared() / c
            }
        }),
        ch5::PDF_SIGN,
    );
    // The Jacobian upside down.
    fails_with(
        ch5::check_area_pdf(|pdf, x, y, n: Vec3| {
            let to = y - x;
            pdf * n.dot(to.normalize()).abs() / to.length_squared()
        }),
        ch5::PDF_JACOBIAN,
    );
}

// Exercises 5.6 and 5.7: wrong solutions written from the contracts, each
// failing under every seed tried (naming its symptom where the check
// names one), and correct alternatives passing under every seed.

const SEEDS: [u64; 5] = [0, 1, 0x5eed, 977, 31337];

fn fails_under_seeds(what: &str, symptom: Option<Symptom>, check: impl Fn() -> Check) {
    for (seed, c) in super::under_seeds(&SEEDS, check) {
        assert!(!c.passed(), "{what} passed under seed {seed}: {}", c.detail);
        if let Some(s) = symptom {
            let d = super::fails_naming(c, s, &ch5::exercises(), what);
            assert!(!d.is_empty(), "{what}: no detail");
        }
    }
}

fn passes_under_seeds(what: &str, check: impl Fn() -> Check) {
    for (seed, c) in super::under_seeds(&SEEDS, check) {
        assert!(c.passed(), "{what} failed under seed {seed}: {}", c.detail);
    }
}

/// Van Oosterom and Strackee's tan(Ω/2) = num / den, from the corners
/// seen from p, with the triple product as written (b × c).
fn vos_parts(p: Vec3, t: [Vec3; 3]) -> (f32, f32) {
    let (a, b, c) = (t[0] - p, t[1] - p, t[2] - p);
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    (a.dot(b.cross(c)), den)
}

/// The triangle's area and the way from p to its centroid.
fn area_and_centroid(p: Vec3, t: [Vec3; 3]) -> (f32, Vec3, Vec3) {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    (
        0.5 * n.length(),
        n.normalize(),
        (t[0] + t[1] + t[2]) / 3.0 - p,
    )
}

/// A mistake in a solid angle.
#[derive(Clone, Copy, Debug)]
enum SolidBug {
    /// A / r², no cosine.
    NoCosine,
    /// A cos θ / r² with r the distance to the first corner.
    VertexDistance,
    /// 2 atan(num / den): loses π when den < 0.
    Atan,
    /// The triple product's sign kept: negative for one winding.
    Signed,
    /// The triple product from the corners themselves,
    /// a·(b×c) − p·(a×b + b×c + c×a): p subtracted too late.
    SubtractLate,
    /// Van Oosterom–Strackee in f32 with b × c of the vectors from p:
    /// a small triangle far away cancels.
    NaiveTripleProduct,
    /// Girard's excess with the angles from acos of unnormalised normals.
    GirardUnnormalised,
    /// Girard's excess in f64, angles by acos: half the digits lost where
    /// the spherical triangle is thin.
    GirardAcos,
    /// 2 atan(num / den), a negative angle wrapped by 4π.
    WrapFourPi,
    /// tan(Ω/2) taken for tan Ω: the 2 forgotten.
    Half,
    /// An absolute ε: 0 when the triple product is below 10⁻⁶.
    AbsoluteEpsilon,
}

fn girard(p: Vec3, t: [Vec3; 3], normalise: bool) -> f32 {
    let v = t.map(|x| x.as_dvec3() - p.as_dvec3());
    let v = if normalise {
        v.map(|x| x.normalize())
    } else {
        v
    };
    let mut sum = 0.0;
    for i in 0..3 {
        let (a, b, c) = (v[i], v[(i + 1) % 3], v[(i + 2) % 3]);
        let (n1, n2) = (a.cross(b), a.cross(c));
        let cos = if normalise {
            n1.normalize().dot(n2.normalize())
        } else {
            n1.dot(n2)
        };
        sum += cos.clamp(-1.0, 1.0).acos();
    }
    (sum - std::f64::consts::PI).abs() as f32
}

fn solid_mutant(p: Vec3, t: [Vec3; 3], bug: SolidBug) -> f32 {
    let (num, den) = vos_parts(p, t);
    let (area, n, to) = area_and_centroid(p, t);
    match bug {
        SolidBug::NoCosine => area / to.length_squared(),
        SolidBug::VertexDistance => {
            let r = (t[0] - p).length();
            area * n.dot(to.normalize()).abs() / (r * r)
        }
        SolidBug::Atan => (2.0 * (num / den).atan()).abs(),
        SolidBug::Signed => 2.0 * num.atan2(den.abs()) * if den < 0.0 { -1.0 } else { 1.0 },
        SolidBug::SubtractLate => {
            let [a, b, c] = t;
            let late = a.dot(b.cross(c)) - p.dot(a.cross(b) + b.cross(c) + c.cross(a));
            2.0 * late.abs().atan2(den)
        }
        SolidBug::NaiveTripleProduct => 2.0 * num.abs().atan2(den),
        SolidBug::GirardUnnormalised => girard(p, t, false),
        SolidBug::GirardAcos => girard(p, t, true),
        SolidBug::WrapFourPi => {
            let o = 2.0 * (num.abs() / den).atan();
            if o < 0.0 {
                o + 4.0 * PI
            } else {
                o
            }
        }
        SolidBug::Half => num.abs().atan2(den),
        SolidBug::AbsoluteEpsilon => {
            let careful = (t[0] - p).dot((t[1] - t[0]).cross(t[2] - t[0])).abs();
            if careful < 1e-6 {
                0.0
            } else {
                2.0 * careful.atan2(den)
            }
        }
    }
}

/// Each mutant fails under every seed, naming its symptom where given.
macro_rules! solid_mutants_fail {
    ($($bug:ident: $symptom:expr,)*) => {
        $(fails_under_seeds(stringify!($bug), $symptom, || {
            ch5::check_solid_angle(|p, t| solid_mutant(p, t, SolidBug::$bug))
        });)*
    };
}

#[test]
fn solid_angle_mistakes_fail_under_every_seed() {
    solid_mutants_fail! {
        Signed: Some(ch5::SOLID_SIGNED),
        NoCosine: Some(ch5::SOLID_FAR_LIMIT),
        VertexDistance: Some(ch5::SOLID_FAR_LIMIT),
        Atan: Some(ch5::SOLID_ABOVE_PI),
        WrapFourPi: Some(ch5::SOLID_ABOVE_PI),
        SubtractLate: Some(ch5::SOLID_PRECISION),
        NaiveTripleProduct: Some(ch5::SOLID_PRECISION),
        GirardUnnormalised: None,
        GirardAcos: None,
        Half: None,
        AbsoluteEpsilon: None,
    }
}

/// Correct: Girard's excess in f64, each corner's angle by atan2 (no
/// digits lost to acos near 0 or π).
fn girard_atan2(p: Vec3, t: [Vec3; 3]) -> f32 {
    let v = t.map(|x| (x.as_dvec3() - p.as_dvec3()).normalize());
    let angle = |a: glam::DVec3, b: glam::DVec3, c: glam::DVec3| {
        let (n1, n2) = (a.cross(b), a.cross(c));
        n1.cross(n2).length().atan2(n1.dot(n2))
    };
    let sum = angle(v[0], v[1], v[2]) + angle(v[1], v[2], v[0]) + angle(v[2], v[0], v[1]);
    (sum - std::f64::consts::PI).max(0.0) as f32
}

/// Correct: l'Huilier's theorem in f64, from the arcs between the
/// corners on the unit sphere.
fn lhuilier(p: Vec3, t: [Vec3; 3]) -> f32 {
    let v = t.map(|x| (x.as_dvec3() - p.as_dvec3()).normalize());
    let arc = |x: glam::DVec3, y: glam::DVec3| 2.0 * ((x - y).length() / 2.0).min(1.0).asin();
    let (a, b, c) = (arc(v[1], v[2]), arc(v[2], v[0]), arc(v[0], v[1]));
    let s = (a + b + c) / 2.0;
    let h = |x: f64| (x / 2.0).max(0.0).tan();
    4.0 * (h(s) * h(s - a) * h(s - b) * h(s - c)).sqrt().atan() as f32
}

/// Correct: Van Oosterom–Strackee in f32, the triple product from the
/// edges, the corners in another order.
fn vos_edges(p: Vec3, t: [Vec3; 3]) -> f32 {
    let [c, a, b] = t.map(|x| x - p);
    let num = c.dot((t[0] - t[1]).cross(t[0] - t[2]));
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    2.0 * num.abs().atan2(den)
}

#[test]
fn solid_angle_alternatives_pass_under_every_seed() {
    passes_under_seeds("Girard by atan2 in f64", || {
        ch5::check_solid_angle(girard_atan2)
    });
    passes_under_seeds("l'Huilier in f64", || ch5::check_solid_angle(lhuilier));
    passes_under_seeds("Van Oosterom–Strackee in f32", || {
        ch5::check_solid_angle(vos_edges)
    });
}

/// A mistake in a spot's power.
#[derive(Clone, Copy, Debug)]
enum SpotBug {
    /// The band forgotten: the whole outer cone at full intensity.
    OuterOnly,
    /// The band forgotten: only the inner cone.
    InnerOnly,
    /// The smoothstep taken in angle: the cone of the mean half-angle.
    MeanAngle,
    /// Without the 2π of the integral over φ.
    No2Pi,
    /// 4π, the whole sphere's solid angle, for 2π.
    FourPi,
    /// The angles read as degrees.
    Degrees,
    /// 1 − cos θ in f32: a narrow cone cancels.
    OneMinusCos,
    /// The intensity's brightest channel for every channel.
    OneChannel,
    /// The band at its full width, as if the falloff were 1 across it
    /// up to the middle... weighted 2/3 (the smoothstep's t² part).
    TwoThirds,
}

fn spot_mutant(i: Vec3, inner: f32, outer: f32, bug: SpotBug) -> Vec3 {
    let (ci, co) = (inner.cos(), outer.cos());
    let careful = |t: f32| 2.0 * (t / 2.0).sin().powi(2);
    let share = match bug {
        SpotBug::OuterOnly => 2.0 * careful(outer),
        SpotBug::InnerOnly => 2.0 * careful(inner),
        SpotBug::MeanAngle => 2.0 * careful((inner + outer) / 2.0),
        SpotBug::Degrees => careful(inner.to_radians()) + careful(outer.to_radians()),
        SpotBug::OneMinusCos => 2.0 - ci - co,
        SpotBug::TwoThirds => 2.0 * careful(inner) + (ci - co) * 2.0 * 2.0 / 3.0,
        _ => careful(inner) + careful(outer),
    };
    let factor = match bug {
        SpotBug::No2Pi => 0.5,
        SpotBug::FourPi => 2.0 * PI,
        _ => PI,
    } * share;
    match bug {
        SpotBug::OneChannel => Vec3::splat(i.max_element() * factor),
        _ => i * factor,
    }
}

/// Each mutant fails under every seed, naming its symptom where given.
macro_rules! spot_mutants_fail {
    ($($bug:ident: $symptom:expr,)*) => {
        $(fails_under_seeds(stringify!($bug), $symptom, || {
            ch5::check_spot(|i, a, b| spot_mutant(i, a, b, SpotBug::$bug))
        });)*
    };
}

#[test]
fn spot_mistakes_fail_under_every_seed() {
    spot_mutants_fail! {
        OuterOnly: Some(ch5::SPOT_BAND),
        InnerOnly: Some(ch5::SPOT_BAND),
        MeanAngle: Some(ch5::SPOT_BAND),
        TwoThirds: Some(ch5::SPOT_BAND),
        No2Pi: Some(ch5::SPOT_FACTOR),
        FourPi: Some(ch5::SPOT_FACTOR),
        OneMinusCos: Some(ch5::SPOT_NARROW),
        Degrees: None,
        OneChannel: None,
    }
}

/// Correct: the closed form in f64, 1 − (cos θi + cos θo)/2.
fn spot_f64(i: Vec3, inner: f32, outer: f32) -> Vec3 {
    let (ci, co) = (f64::from(inner).cos(), f64::from(outer).cos());
    (i.as_dvec3() * (2.0 * std::f64::consts::PI * (1.0 - (ci + co) / 2.0))).as_vec3()
}

/// Correct: the falloff integrated numerically over θ in f64 (Simpson's
/// rule with sin θ dθ on each piece), written again from the book.
fn spot_quadrature(i: Vec3, inner: f32, outer: f32) -> Vec3 {
    let (ti, to) = (f64::from(inner), f64::from(outer));
    let (ci, co) = (ti.cos(), to.cos());
    let falloff = |theta: f64| {
        let c = theta.cos();
        if c >= ci {
            1.0
        } else if c <= co {
            0.0
        } else {
            let t = (c - co) / (ci - co);
            t * t * (3.0 - 2.0 * t)
        }
    };
    let simpson = |a: f64, b: f64| {
        let n = 200;
        let h = (b - a) / n as f64;
        let g = |x: f64| falloff(x) * x.sin();
        let mid: f64 = (1..n)
            .map(|k| g(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
            .sum();
        (g(a) + g(b) + mid) * h / 3.0
    };
    let total = simpson(0.0, ti) + simpson(ti, to);
    (i.as_dvec3() * (2.0 * std::f64::consts::PI * total)).as_vec3()
}

#[test]
fn spot_alternatives_pass_under_every_seed() {
    passes_under_seeds("the closed form in f64", || ch5::check_spot(spot_f64));
    passes_under_seeds("Simpson's rule in θ, f64", || {
        ch5::check_spot(spot_quadrature)
    });
}
