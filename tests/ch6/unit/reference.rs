//! Unit tests of `src/ch6_global_illumination/reference.rs`.

use raystep::ch6_global_illumination::reference::*;

#[test]
fn normal_quantiles_match_tables() {
    assert!(normal_quantile(0.5).abs() < 1e-9);
    assert!((normal_quantile(0.975) - 1.959964).abs() < 1e-5);
    assert!((normal_quantile(0.999) - 3.090232).abs() < 1e-5);
    assert!((normal_quantile(0.001) + 3.090232).abs() < 1e-5);
}
