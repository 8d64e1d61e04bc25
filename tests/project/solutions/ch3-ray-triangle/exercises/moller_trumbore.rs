//! Exercise 3.3, solved as a student would.

use glam::Vec3;

/// (t, u, v) of the ray o + t d hitting the triangle, if it does.
pub fn moller_trumbore(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let det3 = |a: Vec3, b: Vec3, c: Vec3| a.dot(b.cross(c));
    let e1 = tri[1] - tri[0];
    let e2 = tri[2] - tri[0];
    let s = o - tri[0];
    let det = det3(e1, e2, -d);
    if det == 0.0 {
        return None;
    }
    let u = det3(s, e2, -d) / det;
    let v = det3(e1, s, -d) / det;
    let t = det3(e1, e2, s) / det;
    if u < 0.0 || v < 0.0 || u + v > 1.0 || t <= 0.0 {
        return None;
    }
    Some((t, u, v))
}
