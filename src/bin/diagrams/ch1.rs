//! Chapter 1's diagrams: the pinhole's similar triangles, drawn with
//! [`project_pinhole`], and parallel lines meeting at their vanishing
//! point, drawn with [`Camera::project`].

use glam::{DVec3, Vec2, Vec3};
use raystep::ch1_projection::camera::{project_pinhole, Camera, CameraDesc};
use raystep::core::error::{Error, Result};

use crate::svg::{Anchor, Stroke, Svg, BLUE, FILL_BLUE, FILL_ORANGE, GREY, INK, ORANGE, RED};
use crate::Diagram;

/// Chapter 1's diagrams, in the order the chapter shows them.
pub fn diagrams() -> Result<Vec<Diagram>> {
    Ok(vec![
        Diagram {
            name: "ch1-pinhole-diagram",
            what: "similar triangles of the pinhole, side view: two equal sticks and where project_pinhole puts their tops",
            svg: pinhole()?,
        },
        Diagram {
            name: "ch1-vanishing-point-diagram",
            what: "two families of parallel lines on the ground, projected by Camera::project, meeting where project_pinhole sends their direction",
            svg: vanishing_points()?,
        },
    ])
}

/// The image height v of a point at height `y`, depth `depth` (z = -depth).
fn image_height(y: f32, depth: f32) -> Result<f32> {
    project_pinhole(Vec3::new(0.0, y, -depth))
        .map(|uv| uv.y)
        .ok_or_else(|| Error::Usage("pinhole diagram: point behind the camera".into()))
}

/// Side view (depth −z to the right, y up): the pinhole c, the image plane
/// z = −1, and two sticks of the same height at depths 2.5 and 5. The ray
/// from each top through c crosses the image plane at y/(−z).
fn pinhole() -> Result<Svg> {
    let (y, near, far) = (1.5f32, 2.5f32, 5.0f32);
    let (v_near, v_far) = (image_height(y, near)?, image_height(y, far)?);
    let (y, near, far) = (y as f64, near as f64, far as f64);
    let (v_near, v_far) = (v_near as f64, v_far as f64);
    let mut s = Svg::new(640.0, [-0.9, 6.1, -0.75, 2.15]);
    // The two similar triangles of the near point.
    s.area(&[(0.0, 0.0), (near, 0.0), (near, y)], FILL_BLUE);
    s.area(&[(0.0, 0.0), (1.0, 0.0), (1.0, v_near)], FILL_ORANGE);
    // The optical axis (depth grows to the right) and the image plane.
    s.arrow((-0.6, 0.0), (5.85, 0.0), Stroke::solid(GREY, 1.2));
    s.text(
        (5.85, 0.0),
        (0.0, 18.0),
        "−z",
        15.0,
        Anchor::End,
        GREY,
        true,
    );
    s.line((1.0, -0.45), (1.0, 1.95), Stroke::solid(INK, 2.0));
    s.text(
        (1.0, 1.95),
        (6.0, 4.0),
        "image plane z = −1",
        14.0,
        Anchor::Start,
        INK,
        false,
    );
    // The sticks and the rays from their tops through the pinhole.
    for (depth, v, dashed) in [(near, v_near, false), (far, v_far, true)] {
        s.line((depth, 0.0), (depth, y), Stroke::solid(ORANGE, 3.0));
        let ray = if dashed {
            Stroke::dashed(BLUE, 1.6)
        } else {
            Stroke::solid(BLUE, 1.6)
        };
        s.line((0.0, 0.0), (depth, y), ray);
        s.dot((depth, y), 4.5, INK);
        s.dot((1.0, v), 4.5, RED);
    }
    s.dot((0.0, 0.0), 5.0, INK);
    s.text((0.0, 0.0), (-6.0, 20.0), "c", 15.0, Anchor::End, INK, true);
    s.text(
        (near, y),
        (0.0, -10.0),
        "p",
        15.0,
        Anchor::Middle,
        INK,
        true,
    );
    s.text(
        (far, y),
        (0.0, -10.0),
        "p′",
        15.0,
        Anchor::Middle,
        INK,
        true,
    );
    // Lengths: 1 to the plane, −z to the point, y and v up.
    s.text(
        (0.5, 0.0),
        (0.0, 18.0),
        "1",
        14.0,
        Anchor::Middle,
        INK,
        false,
    );
    let depth_label = format!("−z = {near:.1}");
    s.text(
        (near, 0.0),
        (0.0, 18.0),
        &depth_label,
        14.0,
        Anchor::Middle,
        INK,
        false,
    );
    let far_label = format!("−z = {far:.1}");
    s.text(
        (far, 0.0),
        (0.0, 18.0),
        &far_label,
        14.0,
        Anchor::Middle,
        INK,
        false,
    );
    let y_label = format!("y = {y:.1}");
    s.text(
        (near, y / 2.0),
        (8.0, 5.0),
        &y_label,
        14.0,
        Anchor::Start,
        ORANGE,
        false,
    );
    s.text(
        (far, y / 2.0),
        (8.0, 5.0),
        &y_label,
        14.0,
        Anchor::Start,
        ORANGE,
        false,
    );
    let v_label = format!("v = {v_near:.2}");
    s.text(
        (1.0, v_near),
        (-8.0, 0.0),
        &v_label,
        14.0,
        Anchor::End,
        RED,
        false,
    );
    let v_label = format!("v = {v_far:.2}");
    s.text(
        (1.0, v_far),
        (8.0, 14.0),
        &v_label,
        14.0,
        Anchor::Start,
        RED,
        false,
    );
    s.caption(&format!(
        "v = y / (−z): twice as far, half as tall on the image plane ({v_near:.2} → {v_far:.2})"
    ));
    Ok(s)
}

/// Picture coordinates (y up) of a raster position (y down) in an image
/// `height` pixels tall.
fn up(p: Vec2, height: f64) -> (f64, f64) {
    (p.x as f64, height - p.y as f64)
}

/// A camera 1.5 units above the ground looking slightly down; two families
/// of parallel lines on the ground (straight ahead, and turned to the
/// right), each projected with [`Camera::project`]. Each family heads for
/// the image of its direction, [`project_pinhole`] of the direction in
/// camera space; dots mark p + t d for t = 1, 2, 4, ... on one line.
fn vanishing_points() -> Result<Svg> {
    let (width, height) = (640u32, 280u32);
    let cam = Camera::new(CameraDesc {
        eye: DVec3::new(0.0, 1.5, 0.0),
        target: DVec3::new(0.0, 1.0, -10.0),
        up: DVec3::Y,
        fov_degrees: 55.0,
        width,
        height,
    })?;
    let h = height as f64;
    let no_image = || Error::Usage("vanishing diagram: a point has no image".into());
    let project = |p: Vec3| cam.project(p).map(|q| up(q, h)).ok_or_else(no_image);
    let vanishing = |d: Vec3| -> Result<(f64, f64)> {
        let uv =
            project_pinhole(cam.camera_from_world.transform_vector3(d)).ok_or_else(no_image)?;
        Ok(up(cam.raster_from_image_plane(uv), h))
    };
    let frame = [0.0, width as f64, 0.0, h];
    let mut s = Svg::new(640.0, frame);
    let ahead = Vec3::new(0.0, 0.0, -1.0);
    let turned = Vec3::new(0.55, 0.0, -1.0).normalize();
    let (vp_ahead, vp_turned) = (vanishing(ahead)?, vanishing(turned)?);
    // The horizon: the images of every direction parallel to the ground.
    s.line(
        (0.0, vp_ahead.1),
        (width as f64, vp_ahead.1),
        Stroke::dashed(GREY, 1.2),
    );
    s.text(
        (6.0, vp_ahead.1),
        (0.0, -6.0),
        "horizon",
        13.0,
        Anchor::Start,
        GREY,
        false,
    );
    // Rails straight ahead, from z = −1.2 on.
    for x in [-2.4f32, -0.8, 0.8, 2.4] {
        let start = Vec3::new(x, 0.0, -1.2);
        if let Some((a, b)) = clip(project(start)?, vp_ahead, frame) {
            s.line(a, b, Stroke::solid(BLUE, 1.8));
        }
    }
    // Lines turned to the right, starting on the left.
    for x in [-4.0f32, -2.5, -1.0] {
        let start = Vec3::new(x, 0.0, -2.0);
        if let Some((a, b)) = clip(project(start)?, vp_turned, frame) {
            s.line(a, b, Stroke::solid(ORANGE, 1.8));
        }
    }
    // p + t d for doubling t on one rail: the dots crowd to the point.
    let p = Vec3::new(2.4, 0.0, -3.2);
    for k in -1..7 {
        let t = if k < 0 { 0.0 } else { 2f32.powi(k) };
        s.dot(project(p + t * ahead)?, 4.0, INK);
    }
    s.text(
        project(p)?,
        (10.0, 4.0),
        "p + t d",
        14.0,
        Anchor::Start,
        INK,
        true,
    );
    s.circle(vp_ahead, 7.0, Stroke::solid(RED, 2.2), None);
    s.circle(vp_turned, 7.0, Stroke::solid(RED, 2.2), None);
    s.text(
        vp_ahead,
        (0.0, -14.0),
        "image of d",
        14.0,
        Anchor::Middle,
        RED,
        false,
    );
    s.text(
        vp_turned,
        (0.0, -14.0),
        "image of d′",
        14.0,
        Anchor::Middle,
        RED,
        false,
    );
    s.polyline(
        &[(0.0, 0.0), (width as f64, 0.0), (width as f64, h), (0.0, h)],
        Stroke::solid(GREY, 1.0),
        Some("none"),
    );
    s.caption("blue lines run along d, orange ones along d′: each family meets at the image of");
    s.caption("its direction; the dots are p + t d for t = 0, 1, 2, 4, …, 64");
    Ok(s)
}

/// The part of segment a-b inside `rect` = [x0, x1, y0, y1] (Liang–Barsky).
pub fn clip(a: (f64, f64), b: (f64, f64), rect: [f64; 4]) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - rect[0]),
        (dx, rect[1] - a.0),
        (-dy, a.1 - rect[2]),
        (dy, rect[3] - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    let at = |t: f64| (a.0 + t * dx, a.1 + t * dy);
    (t0 <= t1).then(|| (at(t0), at(t1)))
}
