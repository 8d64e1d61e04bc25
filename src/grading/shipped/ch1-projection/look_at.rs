//! Exercise 1.2: build the look-at camera.
//!
//! A camera at `eye` looks at `target`, with `up` roughly up. Build the
//! matrix `camera_from_world` that moves the pinhole to the origin and turns
//! the world so that the camera looks down -z with +y up and +x to the
//! right. The inputs here always define a proper frame (eye != target, up
//! not parallel to the view direction).
//!
//! Grade it with: `cargo run --release --bin grade -- ch1`

use glam::{Mat4, Vec3};

/// The world-to-camera matrix of a look-at camera.
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    // TODO: find the camera's three axes in world coordinates: +z points
    //       from the target back towards the eye; +x is perpendicular to
    //       `up` and +z; +y completes a right-handed frame.
    // TODO: build world_from_camera from the axes and the eye, and return
    //       its inverse.
    todo!()
}
