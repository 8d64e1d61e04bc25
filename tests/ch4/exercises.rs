//! Chapter 4's graders: the references pass, the shipped stubs fail
//! cleanly, and typical wrong answers fail with their worst case.

use crate::common;
use glam::Vec3;
use raystep::grading::exercises::ch4;

#[test]
fn chapter_4_references_pass() {
    common::references_pass(4, 3);
}

#[test]
fn a_sphere_sdf_without_the_radius_fails() {
    let check = ch4::check_sphere_sdf(|p, c, _| (p - c).length());
    assert!(!check.passed());
    assert!(check.detail.contains("expected"), "{}", check.detail);
    // The unsigned distance is wrong inside.
    let check = ch4::check_sphere_sdf(|p, c, r| ((p - c).length() - r).abs());
    assert!(!check.passed() && check.error >= 1.5, "{check:?}");
}

#[test]
fn a_tracer_that_overshoots_or_ignores_the_budget_fails() {
    // Steps twice the distance: lands inside, past the surface.
    let check = ch4::check_sphere_trace(|f, o, d, eps, steps, max| {
        let mut t = 0.0;
        for _ in 0..steps {
            let dist = f(o + t * d);
            if dist.abs() < eps {
                return Some(t);
            }
            t += 2.0 * dist;
            if t > max {
                return None;
            }
        }
        None
    });
    assert!(!check.passed(), "{check:?}");
    // Never gives up: keeps stepping past the budget.
    let check = ch4::check_sphere_trace(|f, o, d, eps, _, max| {
        let mut t = 0.0;
        while t <= max {
            let dist = f(o + t * d);
            if dist < eps {
                return Some(t);
            }
            t += dist;
        }
        None
    });
    assert!(!check.passed(), "{check:?}");
    assert!(check.detail.contains("3 steps"), "{}", check.detail);
}

#[test]
fn an_unnormalised_or_one_sided_gradient_fails() {
    let check = ch4::check_gradient_normal(|f, p, h| {
        Vec3::new(
            f(p + Vec3::X * h) - f(p - Vec3::X * h),
            f(p + Vec3::Y * h) - f(p - Vec3::Y * h),
            f(p + Vec3::Z * h) - f(p - Vec3::Z * h),
        )
    });
    assert!(!check.passed(), "{check:?}");
    // Swapped axes.
    let check = ch4::check_gradient_normal(|f, p, h| {
        Vec3::new(
            f(p + Vec3::Y * h) - f(p - Vec3::Y * h),
            f(p + Vec3::X * h) - f(p - Vec3::X * h),
            f(p + Vec3::Z * h) - f(p - Vec3::Z * h),
        )
        .normalize()
    });
    assert!(!check.passed(), "{check:?}");
}
