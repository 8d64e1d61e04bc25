//! Exercise 2.1: the edge function.
//!
//! For an edge from a to b, E_ab(p) = (b - a) × (p - a): the 2D cross
//! product of the edge and the vector from a to p. It is twice the signed
//! area of the triangle (a, b, p): zero when p is on the line through a and
//! b, positive on one side, negative on the other.
//!
//! Grade it with: `cargo run --release --bin grade -- ch2`

use glam::Vec2;

/// The edge function of the edge a→b at the point p.
pub fn edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    // TODO: the 2D cross product (b - a) × (p - a) = dx·ey - dy·ex.
    todo!()
}
