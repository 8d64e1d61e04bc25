//! Exercise 3.2's hand cases: a triangle in the plane z = 0 asked inside,
//! at a corner, on an edge and outside; triangles standing in the other
//! axis planes and in the diagonal ones; and one without area.

use glam::Vec3;

/// Barycentric (u, v).
pub type Uv = (f32, f32);

/// (p, triangle, the expected (u, v) or None).
pub(super) fn hand_cases() -> Vec<(Vec3, [Vec3; 3], Option<Uv>)> {
    let tri = [
        Vec3::ZERO,
        Vec3::new(2.0, 0.0, 0.0),
        Vec3::new(0.0, 2.0, 0.0),
    ];
    vec![
        (Vec3::new(1.0, 0.5, 0.0), tri, Some((0.5, 0.25))),
        (Vec3::ZERO, tri, Some((0.0, 0.0))),
        (Vec3::new(1.0, 1.0, 0.0), tri, Some((0.5, 0.5))),
        (Vec3::new(1.5, 1.5, 0.0), tri, None),
        (Vec3::new(-0.1, 0.5, 0.0), tri, None),
        // On the line of an edge (v or u exactly 0), beyond its ends.
        (Vec3::new(3.0, 0.0, 0.0), tri, None),
        (Vec3::new(-1.0, 0.0, 0.0), tri, None),
        (Vec3::new(0.0, 3.0, 0.0), tri, None),
        // A triangle standing in the plane x = 0 (seen edge-on from +z).
        (
            Vec3::new(0.0, 0.5, 0.5),
            [
                Vec3::ZERO,
                Vec3::new(0.0, 2.0, 0.0),
                Vec3::new(0.0, 0.0, 2.0),
            ],
            Some((0.25, 0.25)),
        ),
        (
            Vec3::new(0.5, 0.5, 0.0),
            [Vec3::ZERO, Vec3::X, Vec3::X * 2.0],
            None,
        ),
        // Triangles in the diagonal planes x = y, y = z, z = x and
        // x + y + z = 2: two or three of the normal's components equal
        // (a test that picks an axis to drop must not drop the one that
        // is 0).
        (
            Vec3::splat(0.25),
            [Vec3::ZERO, Vec3::new(1.0, 1.0, 0.0), Vec3::Z],
            Some((0.25, 0.25)),
        ),
        (
            Vec3::splat(0.25),
            [Vec3::ZERO, Vec3::new(0.0, 1.0, 1.0), Vec3::X],
            Some((0.25, 0.25)),
        ),
        (
            Vec3::splat(0.25),
            [Vec3::ZERO, Vec3::new(1.0, 0.0, 1.0), Vec3::Y],
            Some((0.25, 0.25)),
        ),
        (
            Vec3::new(1.0, 0.5, 0.5),
            [Vec3::X * 2.0, Vec3::Y * 2.0, Vec3::Z * 2.0],
            Some((0.25, 0.25)),
        ),
        // Thin, but with an area (its unit edges' cosine rounds to 1).
        (
            Vec3::new(0.5, 2f32.powi(-14), 0.0),
            [Vec3::ZERO, Vec3::X, Vec3::new(0.5, 2f32.powi(-13), 0.0)],
            Some((0.25, 0.5)),
        ),
    ]
}
