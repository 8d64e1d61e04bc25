//! Exercise 1.2: build the look-at camera.
//!
//! A camera at `eye` looks at `target`, with `up` roughly up. Build the
//! matrix `camera_from_world` that moves the pinhole to the origin and turns
//! the world so that the camera looks down -z, with +y up on the picture
//! and +x to the right. The idea: find the camera's own three axes in world
//! coordinates; together with the eye they give the opposite map, from
//! camera space to the world.
//!
//! The contract (what the grader checks, every entry within 1e-4, on four
//! cameras, and by drawing the lecture's tetrahedron through it):
//! * the eye maps to the origin and the target onto the -z axis;
//! * the matrix is a rigid motion: unit, perpendicular, right-handed axes;
//! * `up` (of any length, not parallel to the view direction here)
//!   points up on the picture. The inputs always define a frame
//!   (eye != target).
//!
//! Grade it with: `cargo grade ch1`

use glam::{Mat4, Vec3};

/// The world-to-camera matrix of a look-at camera.
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    // TODO: the camera's axes, then the matrix (the grader's hints go further).
    todo!()
}
