//! Exercise 5.2: cosine-weighted hemisphere sampling and its pdf.
//!
//! Turn two uniform numbers u = (u.x, u.y) in [0, 1)² into a direction on
//! the hemisphere z ≥ 0 whose density in solid angle is cos θ / π, and
//! return that density with it. Malley's method: pick a uniform point on
//! the unit disk (r = √u.x, φ = 2π u.y), then lift it onto the hemisphere
//! (z = √(1 − x² − y²)).
//!
//! Grade it with: `cargo run --release --bin grade -- ch5`
//! (the grader checks the pdf and the statistics of many samples).

use glam::{Vec2, Vec3};

/// A cosine-distributed direction about +z and its solid-angle pdf.
pub fn cosine_hemisphere(u: Vec2) -> (Vec3, f32) {
    // TODO: a uniform point (x, y) on the unit disk from u.
    // TODO: lift it: z = sqrt(1 - x² - y²).
    // TODO: the pdf is cos θ / π = z / π.
    todo!()
}
