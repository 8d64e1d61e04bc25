//! Unit tests of `src/core/sampling.rs`.

use raystep::core::sampling::*;

#[test]
fn uniform_in_unit_interval_with_the_right_mean() {
    let n = 100_000;
    let mut sum = 0.0f64;
    for i in 0..n {
        let r = random(7, i, 3, 1);
        assert!((0.0..1.0).contains(&r));
        sum += r as f64;
    }
    // Mean 1/2, standard error 1/sqrt(12 n) ≈ 9e-4: allow 5 of those.
    assert!((sum / n as f64 - 0.5).abs() < 5.0 * (1.0 / (12.0 * n as f64)).sqrt());
}

#[test]
fn every_coordinate_changes_the_number() {
    let base = random(1, 2, 3, 4);
    assert_ne!(base, random(0, 2, 3, 4));
    assert_ne!(base, random(1, 0, 3, 4));
    assert_ne!(base, random(1, 2, 0, 4));
    assert_ne!(base, random(1, 2, 3, 0));
    assert_eq!(base, random(1, 2, 3, 4));
}
