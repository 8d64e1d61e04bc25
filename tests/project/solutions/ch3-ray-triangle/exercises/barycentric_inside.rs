//! Exercise 3.2, solved as a student would.

use glam::Vec3;

/// The barycentric (u, v) of `p` if it lies inside the triangle.
pub fn barycentric_inside(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    let e1 = tri[1] - tri[0];
    let e2 = tri[2] - tri[0];
    let q = p - tri[0];
    let n = e1.cross(e2);
    let nn = n.dot(n);
    if nn == 0.0 {
        return None;
    }
    let u = n.dot(q.cross(e2)) / nn;
    let v = n.dot(e1.cross(q)) / nn;
    if u >= 0.0 && v >= 0.0 && u + v <= 1.0 {
        Some((u, v))
    } else {
        None
    }
}
