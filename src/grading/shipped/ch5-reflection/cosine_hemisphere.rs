//! Exercise 5.2: cosine-weighted hemisphere sampling and its pdf.
//!
//! The reflection equation weighs incoming light by cos θ; drawing
//! directions with a density proportional to cos θ cancels that factor
//! and lowers the noise. The idea (Malley's method): points spread
//! uniformly over the unit disk, lifted straight up onto the hemisphere,
//! are distributed as cos θ.
//!
//! Contract (what the grader checks):
//! * from two uniform numbers u = (u.x, u.y) in [0, 1)², return a unit
//!   direction (length 1 to 10⁻⁴) on the hemisphere z ≥ 0 about +z;
//! * with it, its density per steradian, which must be cos θ / π (z / π,
//!   to 10⁻⁴ relative) for every sample;
//! * the directions must really have that density: over 40,000 samples,
//!   E[x] = E[y] = 0, E[z] = 2/3 and P(z < 1/2) = 1/4, each within 5
//!   standard errors; over 640,000 more, P(z < 0.03) = 0.03² and, about
//!   the pole, P(x² + y² < s) = s for s = 2.5·10⁻⁴, each within 5
//!   standard errors, and no band of directions left out, however thin:
//!   the sorted values of z² (from 0 to 1) and of the azimuth over 2π
//!   (round the circle) leave no gap wider than (ln(N + 1) + 16.1) / N
//!   = 4.6·10⁻⁵ for N = 640,000, which a right map exceeds with
//!   probability 10⁻⁷; and from a 256 × 256 grid of u (the cells'
//!   centres, u = ((i + ½)/256, (j + ½)/256)), z² and the azimuth
//!   over 2π spread evenly over [0, 1] (both are uniform under cos θ / π;
//!   the share below any t within 0.02 of t, and the grid's averages of
//!   cos kφ and sin kφ for k = 1 to 8, of z² and of z⁴ within 10⁻³ of
//!   0, 1/2 and 1/3).
//!
//! Hints: `cargo grade --hint ch5/cosine_hemisphere`.
//! Grade it with: `cargo grade ch5`

use glam::{Vec2, Vec3};

/// A cosine-distributed direction about +z and its solid-angle pdf.
pub fn cosine_hemisphere(u: Vec2) -> (Vec3, f32) {
    // TODO: a uniform point of the unit disk, lifted onto the hemisphere.
    todo!()
}
