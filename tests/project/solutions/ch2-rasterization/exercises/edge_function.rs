//! A student's solution of exercise 2.1 (the grader's tests run it).

use glam::Vec2;

/// The edge function of the edge a→b at the point p.
pub fn edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (b - a).perp_dot(p - a)
}
