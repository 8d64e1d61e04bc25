//! Chapter 5's graders: the references pass, the shipped stubs fail
//! cleanly, and typical wrong answers fail with their worst case.

use crate::common;
use glam::Vec3;
use raystep::grading::exercises::ch5;

#[test]
fn chapter_5_references_pass() {
    common::references_pass(5, 7);
}

#[test]
fn a_brdf_without_the_pi_or_one_sided_fails() {
    let check = ch5::check_lambert_brdf(|rho, _, _| rho);
    assert!(
        !check.passed() && check.detail.contains("expected"),
        "{}",
        check.detail
    );
    // Ignores which side ωi is on.
    let check = ch5::check_lambert_brdf(|rho, _, _| rho / std::f32::consts::PI);
    assert!(!check.passed(), "{}", check.detail);
}

#[test]
fn a_uniform_hemisphere_or_a_wrong_pdf_fails_the_statistics() {
    // Uniform directions with the cosine pdf claimed: z² is not uniform
    // (and the mean z is 1/2).
    let check = ch5::check_cosine_hemisphere(|u| {
        let w = raystep::ch5_reflection::warp::uniform_hemisphere(u);
        (w, w.z / std::f32::consts::PI)
    });
    assert!(
        !check.passed() && check.detail.contains("z² is up to 0.2"),
        "{}",
        check.detail
    );
    // The right directions, the uniform pdf.
    let check = ch5::check_cosine_hemisphere(|u| {
        (
            raystep::ch5_reflection::warp::cosine_hemisphere(u),
            raystep::ch5_reflection::warp::UNIFORM_HEMISPHERE_PDF,
        )
    });
    assert!(
        !check.passed() && check.detail.contains("pdf"),
        "{}",
        check.detail
    );
}

#[test]
fn forgetting_the_square_or_the_cosine_fails() {
    let check = ch5::check_point_light(|i, l, p, n| {
        let to = l - p;
        i * n.dot(to.normalize()).max(0.0) / to.length()
    });
    assert!(!check.passed(), "{}", check.detail);
    let check = ch5::check_point_light(|i, l, p, _| i / (l - p).length_squared());
    assert!(!check.passed(), "{}", check.detail);
}

#[test]
fn an_area_pdf_without_the_cosine_or_edge_on_guard_fails() {
    let check = ch5::check_area_pdf(|pdf, x, y, _| pdf * (y - x).length_squared());
    assert!(!check.passed(), "{}", check.detail);
    let check = ch5::check_area_pdf(|pdf, x, y, n: Vec3| {
        let to = y - x;
        pdf * to.length_squared() / n.dot(to.normalize()).abs()
    });
    assert!(
        !check.passed() && check.detail.contains("expected 0"),
        "{}",
        check.detail
    );
}

/// The capstone as a student writes it from the lecture; `mistake` leaves
/// one factor out.
#[allow(clippy::too_many_arguments)]
fn lecture_direct(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: &dyn Fn(Vec3, Vec3) -> bool,
    mistake: &str,
) -> Vec3 {
    let to = y - p;
    let d = to.length();
    let wi = to / d;
    let cos = n.dot(wi);
    let cos_l = n_light.dot(-wi);
    if cos <= 0.0 || cos_l <= 0.0 || !visible(p, y) {
        return Vec3::ZERO;
    }
    let f = rho / std::f32::consts::PI;
    let pdf_w = d * d / (cos_l * area);
    match mistake {
        "cos" => f * le / pdf_w,
        "pdf" => f * le * cos * area,
        _ => f * le * cos / pdf_w,
    }
}

#[test]
fn the_direct_light_capstone_passes_from_the_lecture_and_catches_mistakes() {
    let check = ch5::check_direct_light(|p, n, r, y, nl, a, le, v| {
        lecture_direct(p, n, r, y, nl, a, le, v, "")
    });
    assert!(check.passed(), "{}", check.detail);
    // A missing cos θ at the shading point.
    let check = ch5::check_direct_light(|p, n, r, y, nl, a, le, v| {
        lecture_direct(p, n, r, y, nl, a, le, v, "cos")
    });
    assert!(!check.passed(), "{}", check.detail);
    assert!(
        check.detail.contains("got") && check.detail.contains("expected"),
        "{}",
        check.detail
    );
    assert!(check.images.is_some());
    // The area density used as if it were per solid angle (no d², no cos θl).
    let check = ch5::check_direct_light(|p, n, r, y, nl, a, le, v| {
        lecture_direct(p, n, r, y, nl, a, le, v, "pdf")
    });
    assert!(!check.passed(), "{}", check.detail);
    // No shadow rays: light leaks behind the boxes.
    let check = ch5::check_direct_light(|p, n, r, y, nl, a, le, _| {
        lecture_direct(p, n, r, y, nl, a, le, &|_, _| true, "")
    });
    assert!(!check.passed(), "{}", check.detail);
}
