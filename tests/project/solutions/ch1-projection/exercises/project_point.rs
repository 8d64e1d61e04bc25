//! A student's solution of exercise 1.1 (the grader's tests run it).

use glam::{Vec2, Vec3};

/// Projects the camera-space point `p` onto the image plane z = -1.
pub fn project_point(p: Vec3) -> Option<Vec2> {
    // The plane z = -1 lies in front of the pinhole: only z < 0 gets there
    // (this also turns a NaN z away).
    if !(p.z < 0.0) {
        return None;
    }
    // The ray t·p meets z = -1 at t = 1 / (-z).
    let t = 1.0 / -p.z;
    Some(Vec2::new(p.x * t, p.y * t))
}
