//! Unit tests of `src/ch5_reflection/light/spot.rs`.

use glam::Vec3;
use raystep::ch5_reflection::light::spot::*;

#[test]
fn full_inside_zero_outside_smooth_between() {
    let s = Spot::new(Vec3::ZERO, -Vec3::Y, Vec3::ONE, 30.0, 10.0);
    let at = |deg: f32| {
        let r = deg.to_radians();
        s.falloff(Vec3::new(r.sin(), -r.cos(), 0.0))
    };
    assert_eq!(at(0.0), 1.0);
    assert_eq!(at(19.0), 1.0);
    assert_eq!(at(31.0), 0.0);
    let mid = at(25.0);
    assert!(mid > 0.2 && mid < 0.8, "{mid}");
    assert!(at(22.0) > at(25.0) && at(25.0) > at(28.0));
}
