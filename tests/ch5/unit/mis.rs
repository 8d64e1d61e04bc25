//! Unit tests of `src/ch5_reflection/mis.rs`.

use raystep::ch5_reflection::mis::*;

#[test]
fn weights_sum_to_one_and_survive_extremes() {
    for (f, g) in [
        (1.0, 1.0),
        (0.3, 7.0),
        (1e30, 1e-30),
        (1e-30, 1e30),
        (2.0, 0.0),
    ] {
        let s = power_heuristic(f, g) + power_heuristic(g, f);
        assert!((s - 1.0).abs() < 1e-6, "{f} {g}: {s}");
        let b = balance_heuristic(f, g) + balance_heuristic(g, f);
        assert!((b - 1.0).abs() < 1e-6, "{f} {g}: {b}");
    }
    assert_eq!(power_heuristic(0.0, 0.0), 0.0);
    assert_eq!(power_heuristic(f32::INFINITY, 1.0), 1.0);
    assert_eq!(power_heuristic(f32::NAN, 1.0), 0.0);
}
