//! Chapter 1's capstone: drawing edges with near-plane clipping. A
//! solution written from the lecture passes; typical mistakes fail with a
//! message naming the edge.

use glam::{Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::grading::exercises::ch1;

/// The capstone as a student writes it from the lecture.
fn lecture_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (mut a, mut b) = (camera.to_camera(a), camera.to_camera(b));
    // How far behind the near plane each end is (> 0: behind).
    let (da, db) = (a.z + near, b.z + near);
    if da > 0.0 && db > 0.0 {
        return None;
    }
    // The cut, placed on the plane (its z from the ends' would round).
    if da > 0.0 {
        a = a.lerp(b, da / (da - db)).with_z(-near);
    } else if db > 0.0 {
        b = b.lerp(a, db / (db - da)).with_z(-near);
    }
    let project = |p: Vec3| camera.raster_from_image_plane(Vec2::new(p.x / -p.z, p.y / -p.z));
    Some((project(a), project(b)))
}

#[test]
fn the_edge_capstone_passes_from_the_lecture_and_catches_mistakes() {
    let check = ch1::check_draw_edges(lecture_edges);
    assert!(check.passed(), "{}", check.detail);
    // No clipping: an end behind the camera projects through the pinhole
    // to the wrong side of the image.
    let check = ch1::check_draw_edges(|camera, a, b, _| {
        let (a, b) = (camera.to_camera(a), camera.to_camera(b));
        let project = |p: Vec3| camera.raster_from_image_plane(Vec2::new(p.x / -p.z, p.y / -p.z));
        Some((project(a), project(b)))
    });
    assert!(!check.passed(), "{}", check.detail);
    assert!(check.detail.contains("the edge from"), "{}", check.detail);
    assert!(check.images.is_some());
    // Dropping every edge that crosses the near plane loses the rails.
    let check = ch1::check_draw_edges(|camera, a, b, near| {
        let (ca, cb) = (camera.to_camera(a), camera.to_camera(b));
        if ca.z > -near || cb.z > -near {
            return None;
        }
        lecture_edges(camera, a, b, near)
    });
    assert!(!check.passed(), "{}", check.detail);
    assert!(check.detail.contains("None"), "{}", check.detail);
}
