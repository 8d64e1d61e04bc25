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
