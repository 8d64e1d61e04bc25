//! Capstone 1: project and draw a mesh's edges, with near-plane clipping.
//!
//! The grader draws every edge of chapter 1's railroad
//! (`scenes/railroad.toml`) with the two raster points this function
//! returns. The rails start beside the camera: some edges have one end
//! in front of the camera and the other behind it, and such an edge has no
//! image as a whole, only its front part does.
//!
//! * Move both ends into camera space (`camera.to_camera`): the pinhole at
//!   the origin, looking down -z.
//! * Keep the part of the edge in front of the near plane z = -`near`
//!   (z <= -near); return `None` when nothing is.
//! * Project each kept end onto the image plane z = -1 (the lecture's
//!   u = x / -z, v = y / -z), then to raster pixels with
//!   `camera.raster_from_image_plane`.
//!
//! Grade it with: `cargo run --release --bin grade -- ch1`, and see it
//! render with `cargo run --release --bin ch1 -- --student`.

use glam::{Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;

/// The raster positions of the visible part of the world-space edge a→b.
pub fn draw_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    // TODO: both ends to camera space.
    // TODO: clip at z = -near: both in front, keep the edge; both behind,
    //       None; one of each, replace the one behind by the point where
    //       the edge crosses the plane.
    // TODO: project both ends (x / -z, y / -z) and map them to raster
    //       pixels.
    todo!()
}
