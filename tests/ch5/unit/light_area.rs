//! Unit tests of `src/ch5_reflection/light/area.rs`.

use glam::{Vec2, Vec3};
use raystep::ch5_reflection::light::area::*;
use raystep::scene::mesh::Mesh;

#[test]
fn a_unit_square_light_seen_from_above_has_the_right_pdf() {
    let mesh = Mesh::rectangle(1.0, 1.0); // z = 0, facing +z
    let light = AreaLight::new(&mesh, 0, Vec3::ONE, false).unwrap();
    assert!((light.area - 1.0).abs() < 1e-6);
    let p = Vec3::new(0.0, 0.0, 2.0);
    let s = light.sample_li(p, Vec2::new(0.3, 0.7)).unwrap();
    let y = p + s.wi * s.dist;
    assert!(y.z.abs() < 1e-5);
    let cos = s.wi.z.abs();
    assert!((s.pdf - s.dist * s.dist / cos).abs() < 1e-4 * s.pdf);
    assert!((light.pdf_li(p, y, Vec3::Z) - s.pdf).abs() < 1e-4 * s.pdf);
    // One-sided: nothing reaches a point behind it.
    assert!(light.sample_li(-p, Vec2::new(0.3, 0.7)).is_none());
}
