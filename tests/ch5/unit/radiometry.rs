//! Unit tests of `src/ch5_reflection/radiometry.rs`.

use glam::DVec3;
use raystep::ch5_reflection::radiometry::*;
use std::f64::consts::PI;

#[test]
fn an_octant_is_an_eighth_of_the_sphere() {
    let o = triangle_solid_angle(DVec3::X, DVec3::Y, DVec3::Z);
    assert!((o - 4.0 * PI / 8.0).abs() < 1e-12, "{o}");
    assert!((cap_solid_angle(PI) - 4.0 * PI).abs() < 1e-12);
    assert!((cap_solid_angle(PI / 2.0) - 2.0 * PI).abs() < 1e-12);
}
