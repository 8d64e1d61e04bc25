//! Capstone 2: rasterize a triangle.
//!
//! Which samples does a triangle cover, which of them does it win against
//! what is already drawn, and what colour does it leave there? The idea:
//! edge functions tell inside from outside, the depth buffer keeps the
//! nearest surface, and barycentric coordinates interpolate, corrected for
//! perspective because the triangle is seen slanted.
//!
//! The contract (the grader checks each clause on its own, then draws
//! chapter 2's `scenes/interpenetrating.toml`):
//! * Input: each vertex is (x, y, z): raster pixels (x right, y down) and
//!   the depth z > 0, the distance in front of the camera (smaller is
//!   nearer). Colours are per vertex. `depth` and `image` are `width` ×
//!   `height`, index y·width + x.
//! * Samples: pixel (x, y) has one sample, at its centre (x + 0.5, y + 0.5).
//! * Coverage is exact: a sample strictly inside is drawn; one exactly on
//!   an edge belongs to the triangle only for a top or a left edge (the
//!   top-left rule), so that a sample on an edge shared by two triangles is
//!   drawn exactly once. Either winding (clockwise or not) is drawn.
//! * The image border: vertices may lie far outside the image (10⁵ pixels);
//!   nothing outside it is written, and the work stays within the image.
//! * A triangle without area, or with a corner that is not finite, draws
//!   nothing.
//! * Depth: the depth at a sample is the true distance there, which is not
//!   the barycentric mix of the corners' depths on the screen (1/z is);
//!   it is drawn only if strictly smaller than `depth[i]` (a tie keeps what
//!   was drawn first), and then stored there.
//! * Colour: perspective-correct, the colour of the triangle's point seen
//!   at the sample (within 1e-4).
//!
//! Grade it with: `cargo grade ch2`, and see it
//! render with `cargo run --release --bin ch2 -- --student`.

use glam::{Vec2, Vec3};

/// Draws the triangle `v` with vertex colours `colors` into `image`,
/// with the depth test against `depth`.
pub fn rasterize_triangle(
    v: [Vec3; 3],
    colors: [Vec3; 3],
    width: u32,
    height: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    // TODO: coverage, depth, colour (the grader's second hint has the steps).
    todo!()
}
