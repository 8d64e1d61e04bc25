//! Unit tests of `src/ch3_ray_triangle/spawn.rs`.

use glam::Vec3;
use raystep::ch3_ray_triangle::spawn::*;

#[test]
fn offset_grows_with_magnitude_and_follows_the_normal() {
    let near = offset_origin(Vec3::new(1.0, 0.0, 0.0), Vec3::X);
    let far = offset_origin(Vec3::new(1e5, 0.0, 0.0), Vec3::X);
    let (dn, df) = (near.x - 1.0, far.x - 1e5);
    assert!(dn > 0.0 && df > 0.0);
    assert!(df / dn > 1e4, "offset at 1e5 {df} vs at 1 {dn}");
    // Negative coordinates move the right way too.
    assert!(offset_origin(Vec3::splat(-3.0), Vec3::X).x > -3.0);
    assert!(offset_origin(Vec3::splat(-3.0), -Vec3::X).x < -3.0);
    // Near zero: a small fixed step.
    assert_eq!(offset_origin(Vec3::ZERO, Vec3::Y).y, FLOAT_SCALE);
    assert!(spawn_ray(Vec3::ZERO, Vec3::Y, Vec3::ZERO).is_none());
}
