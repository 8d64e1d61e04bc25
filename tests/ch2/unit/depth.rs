//! Unit tests of `src/ch2_rasterization/depth.rs`.

use raystep::ch2_rasterization::depth::*;

#[test]
fn depth_test_keeps_the_nearest_and_the_first_of_equals() {
    let mut d = vec![f32::INFINITY; 2];
    assert!(depth_test(&mut d, 0, 5.0));
    assert!(!depth_test(&mut d, 0, 7.0));
    assert!(!depth_test(&mut d, 0, 5.0));
    assert!(!depth_test(&mut d, 0, f32::NAN));
    assert!(depth_test(&mut d, 0, 2.0));
    assert_eq!(d, vec![2.0, f32::INFINITY]);
}

#[test]
fn ties_go_to_the_lower_index_in_either_order() {
    let (a, b) = (Sample { inv_w: 0.5, tri: 3 }, Sample { inv_w: 0.5, tri: 9 });
    assert!(nearer(&a, &b) && !nearer(&b, &a));
    assert!(nearer(&a, &Sample::EMPTY));
}
