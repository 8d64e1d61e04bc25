//! Capstone 1: project a mesh's edge, with near-plane clipping.
//!
//! An edge with one end in front of the camera and the other behind it has
//! no image as a whole, but its front part has. The idea: keep the part of
//! the edge in front of a near plane z = -`near` (camera space: pinhole at
//! the origin, looking down -z), then project what is left like a point
//! (exercise 1.1) and map it to pixels.
//!
//! The contract (what the grader checks):
//! * `a` and `b` are world points; `camera.to_camera` moves them to camera
//!   space, `camera.raster_from_image_plane` maps the image plane z = -1 to
//!   raster pixels. (`camera.project` is raystep's own exercise 1.1 and is
//!   refused inside this function.)
//! * Both ends in front of the near plane (z <= -near; an end exactly on
//!   it counts as in front): their two raster points.
//! * One end in front, the other behind (z > -near, including points
//!   between the pinhole and the near plane): the end behind is replaced
//!   by the point where the edge crosses z = -near, exactly on that plane.
//! * Nothing in front of the near plane: `None`. An edge that touches the
//!   plane with one end and lies behind it otherwise is that one point:
//!   `Some((p, p))`.
//! * The order of the ends: the first raster point is a's (or its cut), the
//!   second b's.
//! * Use `near` as given (the grader passes several values).
//!
//! Checked within 1e-5 relative on hand-made edges, then by drawing
//! chapter 1's railroad (`scenes/railroad.toml`) from between the rails.
//!
//! Grade it with: `cargo grade ch1`, and see it
//! render with `cargo run --release --bin ch1 -- --student`.

use glam::{Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;

/// The raster positions of the visible part of the world-space edge a→b.
pub fn draw_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    // TODO: clip, then project (the grader's second hint has the steps).
    todo!()
}
