//! Chapter 5's graders: the references pass, the shipped stubs fail
//! cleanly, and typical wrong answers fail with their worst case.

use crate::common;
use glam::Vec3;
use raystep::grading::exercises::ch5;

#[test]
fn chapter_5_references_pass() {
    common::references_pass(5, 4);
}

#[test]
fn a_brdf_without_the_pi_or_one_sided_fails() {
    let check = ch5::check_lambert_brdf(|rho, _, _| rho);
    assert!(
        !check.passed() && check.detail.contains("expected"),
        "{check:?}"
    );
    // Ignores which side ωi is on.
    let check = ch5::check_lambert_brdf(|rho, _, _| rho / std::f32::consts::PI);
    assert!(!check.passed(), "{check:?}");
}

#[test]
fn a_uniform_hemisphere_or_a_wrong_pdf_fails_the_statistics() {
    // Uniform directions with the cosine pdf claimed: the mean z is 1/2.
    let check = ch5::check_cosine_hemisphere(|u| {
        let w = raystep::ch5_reflection::warp::uniform_hemisphere(u);
        (w, w.z / std::f32::consts::PI)
    });
    assert!(
        !check.passed() && check.detail.contains("mean z"),
        "{check:?}"
    );
    // The right directions, the uniform pdf.
    let check = ch5::check_cosine_hemisphere(|u| {
        (
            raystep::ch5_reflection::warp::cosine_hemisphere(u),
            raystep::ch5_reflection::warp::UNIFORM_HEMISPHERE_PDF,
        )
    });
    assert!(!check.passed() && check.detail.contains("pdf"), "{check:?}");
}

#[test]
fn forgetting_the_square_or_the_cosine_fails() {
    let check = ch5::check_point_light(|i, l, p, n| {
        let to = l - p;
        i * n.dot(to.normalize()).max(0.0) / to.length()
    });
    assert!(!check.passed(), "{check:?}");
    let check = ch5::check_point_light(|i, l, p, _| i / (l - p).length_squared());
    assert!(!check.passed(), "{check:?}");
}

#[test]
fn an_area_pdf_without_the_cosine_or_edge_on_guard_fails() {
    let check = ch5::check_area_pdf(|pdf, x, y, _| pdf * (y - x).length_squared());
    assert!(!check.passed(), "{check:?}");
    let check = ch5::check_area_pdf(|pdf, x, y, n: Vec3| {
        let to = y - x;
        pdf * to.length_squared() / n.dot(to.normalize()).abs()
    });
    assert!(
        !check.passed() && check.detail.contains("expected 0"),
        "{check:?}"
    );
}
