//! Unit tests of `src/ch4_implicit_surfaces/operators.rs`.

use raystep::ch4_implicit_surfaces::operators::*;

#[test]
fn smooth_union_blends_only_within_k() {
    assert_eq!(op_smooth_union(1.0, 3.0, 0.5), 1.0);
    assert_eq!(op_smooth_union(1.0, 1.0, 0.5), 1.0 - 0.125);
    assert_eq!(op_smooth_union(1.0, 2.0, 0.0), 1.0);
    assert_eq!(op_difference(-1.0, -0.5), 0.5);
    assert_eq!(op_intersection(-1.0, 0.5), 0.5);
    assert_eq!(op_union(-1.0, 0.5), -1.0);
}
