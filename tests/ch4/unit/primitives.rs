//! Unit tests of `src/ch4_implicit_surfaces/primitives.rs`.

use glam::Vec3;
use raystep::ch4_implicit_surfaces::primitives::*;

#[test]
fn hand_values() {
    assert_eq!(sd_sphere(Vec3::new(3.0, 4.0, 0.0), 1.0), 4.0);
    assert_eq!(sd_box(Vec3::new(2.0, 0.0, 0.0), Vec3::ONE), 1.0);
    // Corner region: distance to the corner (1, 1, 1).
    let d = sd_box(Vec3::new(2.0, 2.0, 1.0), Vec3::ONE);
    assert!((d - 2f32.sqrt()).abs() < 1e-6);
    assert_eq!(sd_box(Vec3::new(0.5, 0.0, 0.0), Vec3::ONE), -0.5);
    assert!((sd_torus(Vec3::new(2.0, 0.0, 0.0), 2.0, 0.5) + 0.5).abs() < 1e-6);
    assert_eq!(sd_plane(Vec3::new(0.0, 3.0, 0.0), Vec3::Y, 1.0), 2.0);
    let c = sd_capsule(Vec3::new(0.0, 5.0, 0.0), Vec3::ZERO, Vec3::Y, 0.5);
    assert!((c - 3.5).abs() < 1e-6);
    assert_eq!(sd_cylinder(Vec3::new(0.0, 3.0, 0.0), 1.0, 1.0), 2.0);
    assert_eq!(sd_cylinder(Vec3::new(3.0, 0.0, 0.0), 1.0, 1.0), 2.0);
    let r = sd_rounded_box(Vec3::new(2.0, 0.0, 0.0), Vec3::ONE, 0.2);
    assert!((r - 1.0).abs() < 1e-6);
}
