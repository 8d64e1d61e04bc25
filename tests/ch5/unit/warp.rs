//! Unit tests of `src/ch5_reflection/warp.rs`.

use glam::{Vec2, Vec3};
use raystep::ch5_reflection::warp::*;
use raystep::core::sampling::random;

fn u(i: u64) -> Vec2 {
    Vec2::new(random(1, i, 0, 0), random(1, i, 0, 1))
}

#[test]
fn directions_are_unit_and_on_the_right_side() {
    for i in 0..10_000 {
        let (a, b, c) = (
            uniform_hemisphere(u(i)),
            cosine_hemisphere(u(i)),
            uniform_sphere(u(i)),
        );
        for d in [a, b, c] {
            assert!((d.length() - 1.0).abs() < 1e-5, "{d}");
        }
        assert!(a.z >= 0.0 && b.z >= 0.0);
    }
}

#[test]
fn cosine_sampling_has_mean_cosine_two_thirds() {
    // E[cos θ] under pdf cos θ / π is ∫ cos² θ / π dω = 2/3.
    let n = 100_000;
    let mean: f64 = (0..n)
        .map(|i| cosine_hemisphere(u(i)).z as f64)
        .sum::<f64>()
        / n as f64;
    // σ of cos θ is sqrt(1/2 - 4/9) ≈ 0.236: 5σ/√n ≈ 0.0037.
    assert!((mean - 2.0 / 3.0).abs() < 0.004, "{mean}");
}

#[test]
fn triangle_points_are_uniform() {
    // The mean of uniform barycentrics is (1/3, 1/3, 1/3).
    let n = 100_000;
    let mean = (0..n).map(|i| uniform_triangle(u(i))).sum::<Vec3>() / n as f32;
    assert!(
        (mean - Vec3::splat(1.0 / 3.0)).abs().max_element() < 0.005,
        "{mean}"
    );
}
