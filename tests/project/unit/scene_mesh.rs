//! Unit tests of `src/scene/mesh.rs`.

use glam::Vec3;
use raystep::scene::mesh::*;

#[test]
fn icosphere_counts_and_radius() {
    let m = Mesh::icosphere(2);
    assert_eq!(m.triangles.len(), 20 * 16);
    // Euler: V - E + F = 2 for a closed sphere.
    let (v, e, f) = (m.positions.len(), m.edges().len(), m.triangles.len());
    assert_eq!(v as i64 - e as i64 + f as i64, 2);
    assert!(m.positions.iter().all(|p| (p.length() - 1.0).abs() < 1e-6));
}

#[test]
fn cuboid_faces_point_outwards() {
    let m = Mesh::cuboid(Vec3::new(1.0, 2.0, 3.0));
    for [a, b, c] in &m.triangles {
        let (a, b, c) = (
            m.positions[*a as usize],
            m.positions[*b as usize],
            m.positions[*c as usize],
        );
        let n = (b - a).cross(c - a);
        let centre = (a + b + c) / 3.0;
        assert!(n.dot(centre) > 0.0, "inward face at {centre}");
    }
    assert_eq!(m.edges().len(), 18);
}
