//! A student's solution of capstone 1 (the grader's tests run it).

use glam::{Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;

/// The raster positions of the visible part of the world-space edge a→b.
pub fn draw_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (a, b) = (camera.to_camera(a), camera.to_camera(b));
    // How far each end is past the near plane: > 0 is behind it.
    let (da, db) = (a.z + near, b.z + near);
    let on_plane = |from: Vec3, to: Vec3, d_from: f32, d_to: f32| {
        let p = from + (to - from) * (d_from / (d_from - d_to));
        Vec3::new(p.x, p.y, -near)
    };
    let (a, b) = match (da > 0.0, db > 0.0) {
        (true, true) => return None,
        (true, false) => (on_plane(a, b, da, db), b),
        (false, true) => (a, on_plane(a, b, da, db)),
        (false, false) => (a, b),
    };
    let raster = |p: Vec3| camera.raster_from_image_plane(Vec2::new(p.x / -p.z, p.y / -p.z));
    Some((raster(a), raster(b)))
}
