//! Chapter 4's graders: the references pass, the shipped stubs fail
//! cleanly, and typical wrong answers fail with their worst case.

use crate::common;
use glam::Vec3;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::grading::exercises::ch4;

#[test]
fn chapter_4_references_pass() {
    common::references_pass(4, 4);
}

#[test]
fn a_sphere_sdf_without_the_radius_fails() {
    let check = ch4::check_sphere_sdf(|p, c, _| (p - c).length());
    assert!(!check.passed());
    assert!(check.detail.contains("expected"), "{}", check.detail);
    // The unsigned distance is wrong inside.
    let check = ch4::check_sphere_sdf(|p, c, r| ((p - c).length() - r).abs());
    assert!(!check.passed() && check.error >= 1.5, "{}", check.detail);
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
    assert!(!check.passed(), "{}", check.detail);
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
    assert!(!check.passed(), "{}", check.detail);
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
    assert!(!check.passed(), "{}", check.detail);
    // Swapped axes.
    let check = ch4::check_gradient_normal(|f, p, h| {
        Vec3::new(
            f(p + Vec3::Y * h) - f(p - Vec3::Y * h),
            f(p + Vec3::X * h) - f(p - Vec3::X * h),
            f(p + Vec3::Z * h) - f(p - Vec3::Z * h),
        )
        .normalize()
    });
    assert!(!check.passed(), "{}", check.detail);
}

/// The capstone as a student writes it from the lecture.
fn lecture_trace(sdf: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    let mut t = 0.0;
    let mut f = sdf(o);
    let mut steps = 1;
    loop {
        let p = o + t * d;
        if f.abs() < m.epsilon_at(p) {
            break;
        }
        if t > m.max_distance || steps >= m.max_steps {
            return None;
        }
        t += f;
        f = sdf(o + t * d);
        steps += 1;
    }
    let p = o + t * d;
    let h = m.epsilon_at(p).max(1e-4);
    let g = Vec3::new(
        sdf(p + Vec3::X * h) - sdf(p - Vec3::X * h),
        sdf(p + Vec3::Y * h) - sdf(p - Vec3::Y * h),
        sdf(p + Vec3::Z * h) - sdf(p - Vec3::Z * h),
    ) / (2.0 * h);
    let n = g.try_normalize().unwrap_or(-d);
    Some((t, if n.dot(d) > 0.0 { -n } else { n }))
}

#[test]
fn the_sphere_tracing_capstone_passes_from_the_lecture_and_catches_mistakes() {
    let check = ch4::check_trace_scene(lecture_trace);
    assert!(check.passed(), "{}", check.detail);
    // A normal that is not normalised: the normal image is wrong, and the
    // message names a pixel, its ray and both answers.
    let check = ch4::check_trace_scene(|f, o, d, m| {
        let (t, n) = lecture_trace(f, o, d, m)?;
        Some((t, n * 0.5))
    });
    assert!(!check.passed(), "{}", check.detail);
    assert!(
        check.detail.contains("pixel (") && check.detail.contains("the reference"),
        "{}",
        check.detail
    );
    assert!(check.images.is_some());
    // A normal that does not face the viewer where the gradient points away.
    let check = ch4::check_trace_scene(|f, o, d, m| {
        let (t, n) = lecture_trace(f, o, d, m)?;
        Some((t, -n))
    });
    assert!(!check.passed(), "{}", check.detail);
    // A tiny budget of 8 steps: rays run out before they reach the far
    // shapes.
    let check =
        ch4::check_trace_scene(|f, o, d, m| lecture_trace(f, o, d, &March { max_steps: 8, ..*m }));
    assert!(!check.passed(), "{}", check.detail);
    assert!(check.detail.contains("a miss"), "{}", check.detail);
}
