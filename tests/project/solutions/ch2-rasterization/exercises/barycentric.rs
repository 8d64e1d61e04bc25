//! A student's solution of exercise 2.2 (the grader's tests run it).

use glam::{Vec2, Vec3};

fn area2(a: Vec2, b: Vec2, c: Vec2) -> f32 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

/// (φi, φj, φk) of `p` in the triangle (pi, pj, pk).
pub fn barycentric(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    let whole = area2(pi, pj, pk);
    if whole == 0.0 {
        return None;
    }
    Some(Vec3::new(area2(pj, pk, p), area2(pk, pi, p), area2(pi, pj, p)) / whole)
}
