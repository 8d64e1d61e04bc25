//! A student's solution of exercise 1.2 (the grader's tests run it).

use glam::{Mat4, Vec3};

/// The world-to-camera matrix of a look-at camera.
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    // The camera looks down -z: +z points back from the target to the eye.
    let z = (eye - target).normalize();
    let x = up.cross(z).normalize();
    let y = z.cross(x);
    // The inverse of a rotation is its transpose: the axes as rows, then
    // the eye moved to the origin.
    let rotation = Mat4::from_cols(
        x.extend(0.0),
        y.extend(0.0),
        z.extend(0.0),
        Vec3::ZERO.extend(1.0),
    )
    .transpose();
    rotation * Mat4::from_translation(-eye)
}
