//! Exercise 1.1: project a point with the lecture's pinhole model.
//!
//! The pinhole is at the origin and the camera looks down -z; the image
//! plane is z = -1, in front of the pinhole. Return where the straight line
//! from p through the pinhole meets the image plane, as (u, v).
//!
//! The contract (what the grader checks, within 1e-5 relative):
//! * a point in front of the camera (z < 0) has an image, the right way up:
//!   a point up and to the right of the view axis (x > 0, y > 0) lands at
//!   u > 0, v > 0. Mind the sign: the lecture's slide draws the image plane
//!   behind the pinhole, where the picture is upside down.
//! * a point on the camera's own plane (z = 0) or behind it (z > 0) has no
//!   image: `None`.
//!
//! Grade it with: `cargo grade ch1`

use glam::{Vec2, Vec3};

/// Projects the camera-space point `p` onto the image plane z = -1.
pub fn project_point(p: Vec3) -> Option<Vec2> {
    // TODO: similar triangles (the grader's hints go further).
    todo!()
}
