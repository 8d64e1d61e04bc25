//! Unit tests of `src/ch5_reflection/light/sky.rs`.

use glam::{Vec2, Vec3};
use raystep::ch5_reflection::light::sky::*;
use raystep::core::sampling::random;

#[test]
fn the_sky_pdf_integrates_to_one_and_matches_its_samples() {
    let sky = Sky {
        zenith: Vec3::new(0.2, 0.4, 1.0),
        horizon: Vec3::splat(1.0),
        ground: Vec3::splat(0.1),
    };
    // ∫ pdf dω by a midpoint rule in (y, φ): dω = dy dφ.
    let n = 400;
    let mut total = 0.0f64;
    for i in 0..n {
        let y = -1.0 + 2.0 * (i as f32 + 0.5) / n as f32;
        let w = Vec3::new((1.0 - y * y).sqrt(), y, 0.0);
        total += sky.pdf(w) as f64 * (2.0 / n as f64) * std::f64::consts::TAU;
    }
    assert!((total - 1.0).abs() < 1e-3, "{total}");
    // E[1/pdf] over samples is the measure of the support: 4π.
    let m = 50_000;
    let mean: f64 = (0..m)
        .map(|i| {
            let w = sky.sample(Vec2::new(random(3, i, 0, 0), random(3, i, 0, 1)));
            assert!((w.length() - 1.0).abs() < 1e-4);
            1.0 / sky.pdf(w) as f64
        })
        .sum::<f64>()
        / m as f64;
    let four_pi = 4.0 * std::f64::consts::PI;
    assert!((mean - four_pi).abs() < 0.05 * four_pi, "{mean}");
}

/// A sky at the largest radiance a scene may give (1e20) samples the same
/// directions as the same sky at 1: the inverse CDF squares the radiances,
/// and 1e20² overflowed f32 (the sky rendered 3.5 % off on average).
#[test]
fn a_sky_at_the_radiance_limit_samples_like_the_same_sky_at_one() {
    use glam::{Vec2, Vec3};
    let unit = Sky {
        zenith: Vec3::new(1.0, 0.9, 0.8),
        horizon: Vec3::splat(0.3),
        ground: Vec3::splat(0.1),
    };
    let big = Sky {
        zenith: unit.zenith * 1e20,
        horizon: unit.horizon * 1e20,
        ground: unit.ground * 1e20,
    };
    for i in 0..1000u64 {
        let r = |d| raystep::core::sampling::random(41, i, 0, d);
        let u = Vec2::new(r(0), r(1));
        let (a, b) = (unit.sample(u), big.sample(u));
        assert!((a - b).abs().max_element() < 1e-5, "{u}: {a} vs {b}");
        assert!(((unit.pdf(a) - big.pdf(b)) / unit.pdf(a)).abs() < 1e-4);
        assert!(b.is_finite());
    }
}
