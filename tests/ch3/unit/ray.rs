//! Unit tests of `src/ch3_ray_triangle/ray.rs`.

use glam::Vec3;
use raystep::ch3_ray_triangle::ray::*;

#[test]
fn from_unit_keeps_unit_directions_and_refuses_bad_ones() {
    let d = Vec3::new(0.6, 0.0, 0.8);
    assert_eq!(Ray::from_unit(Vec3::ONE, d).unwrap().dir, d);
    assert_eq!(Ray::from_unit(Vec3::ONE, 2.0 * d).unwrap().dir, d);
    assert!(Ray::from_unit(Vec3::ONE, Vec3::ZERO).is_none());
    assert!(Ray::from_unit(Vec3::ONE, Vec3::splat(f32::NAN)).is_none());
    assert!(Ray::from_unit(Vec3::splat(f32::INFINITY), d).is_none());
}

#[test]
fn bad_directions_are_refused() {
    assert!(Ray::new(Vec3::ZERO, Vec3::ZERO).is_err());
    assert!(Ray::new(Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 1.0)).is_err());
    assert!(Ray::new(Vec3::splat(f32::INFINITY), Vec3::X).is_err());
    assert_eq!(
        Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -2.0)).unwrap().dir,
        -Vec3::Z
    );
}
