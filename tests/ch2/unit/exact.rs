//! Unit tests of `src/ch2_rasterization/exact.rs`.

use glam::DVec2;
use raystep::ch2_rasterization::exact::*;

#[test]
fn half_pixel_and_whole_pixel() {
    let t = [
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(0.0, 1.0),
    ];
    assert_eq!(pixel_coverage(&t, 0, 0), 0.5);
    let big = [
        DVec2::new(-10.0, -10.0),
        DVec2::new(30.0, -10.0),
        DVec2::new(-10.0, 30.0),
    ];
    assert!((pixel_coverage(&big, 3, 4) - 1.0).abs() < 1e-12);
    assert_eq!(pixel_coverage(&t, 5, 5), 0.0);
    // A triangle of area 8 spread over many pixels sums to 8.
    let t = [
        DVec2::new(0.5, 0.25),
        DVec2::new(4.5, 0.25),
        DVec2::new(0.5, 4.25),
    ];
    let sum: f64 = coverage_image(&[t], 8, 8).iter().sum();
    assert!((sum - 8.0).abs() < 1e-12);
}
