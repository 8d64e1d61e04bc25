//! Capstone 2: rasterize a triangle.
//!
//! The grader draws chapter 2's interpenetrating shapes
//! (`scenes/interpenetrating.toml`) and a fan and a grid of triangles
//! whose edges run exactly through sample points, one call per triangle.
//!
//! * Each vertex is (x, y, z): raster pixels (x right, y down) and depth
//!   (distance in front of the camera, smaller is nearer). Triangles come
//!   in either winding.
//! * Pixel (x, y) has one sample, at its centre (x + 0.5, y + 0.5), and
//!   index y·width + x in `depth` and `image`.
//! * Test only the samples in the triangle's bounding box, clipped to the
//!   image (vertices may lie far off screen).
//! * A sample is inside when all three edge functions say so. One that
//!   lies exactly on an edge (edge function 0) belongs to the triangle
//!   only for a top or a left edge (the top-left rule), so that a sample
//!   on an edge shared by two triangles is drawn exactly once.
//! * Interpolate z and the colour with the barycentric coordinates; draw
//!   only where z is nearer than the depth stored (then store it).
//!
//! Grade it with: `cargo run --release --bin grade -- ch2`, and see it
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
    // TODO: the doubled area from the edge function; nothing to draw when
    //       it is 0; swap two vertices (and colours) when it is negative so
    //       the edge functions are positive inside.
    // TODO: the bounding box of the three vertices, clipped to the image.
    // TODO: for every sample in it: the three edge functions; inside with
    //       the top-left rule for samples exactly on an edge.
    // TODO: barycentrics = edge functions / area; interpolate z; the
    //       depth test; interpolate the colour and write it.
    todo!()
}
