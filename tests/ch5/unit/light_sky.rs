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
