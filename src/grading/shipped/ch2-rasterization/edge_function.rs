//! Exercise 2.1: the edge function.
//!
//! For an edge from a to b, E_ab(p) is the 2D cross product of the edge
//! vector b - a with the vector p - a from a to the point. It is twice the
//! signed area of the triangle (a, b, p): zero when p is on the line
//! through a and b, positive on one side, negative on the other.
//!
//! The contract (checked on values worked out by hand, then on drawn edges
//! from 10⁻⁹ to 10⁶ long):
//! * the order matters: the edge first, then the point, so that for
//!   a = (0, 0), b = (1, 0) the point (0, 1) gives +1 and (0, -1) gives -1;
//! * a point on the line gives exactly 0;
//! * within 1e-5 of |b - a|·|p - a|, what the rounding of this very
//!   formula allows: a point near a, nearly on the line, has a tiny E
//!   that a form built from p - b would lose.
//!
//! Grade it with: `cargo grade ch2`

use glam::Vec2;

/// The edge function of the edge a→b at the point p.
pub fn edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    // TODO: a 2D cross product.
    todo!()
}
