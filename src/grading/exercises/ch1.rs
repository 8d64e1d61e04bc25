//! Chapter 1's exercises and how each is graded.

use glam::{Mat4, Vec2, Vec3};

use super::images;
use crate::ch1_projection::camera::{
    camera_from_world_look_at, project_pinhole, Camera, CameraDesc,
};
use crate::ch1_projection::wireframe::{clip_to_near, draw_scene, NEAR};
use crate::core::draw;
use crate::core::film::Film;
use crate::grading::exercise::{Check, Exercise};
use crate::scene::Material;

/// Chapter 1's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 1,
            name: "project_point",
            file: "chapters/ch1-projection/exercises/project_point.rs",
            hints: [
                "slide \"the pinhole camera\": draw the ray from the pinhole through p and the plane z = -1 (similar triangles).",
                "the ray is t·p; it meets z = -1 where t·z = -1. Points with z >= 0 are beside or behind the pinhole: no image.",
                "the ray from the origin through p meets z = -1 at p / (-z); return None when z >= 0",
            ],
            symptoms: &[],
            reference: || check_project_point(project_pinhole),
        },
        Exercise {
            chapter: 1,
            name: "look_at",
            file: "chapters/ch1-projection/exercises/look_at.rs",
            hints: [
                "slide \"placing the camera: look-at\": build the camera's own axes first, then the matrix that maps camera space to the world; you need its inverse.",
                "+z points from the target back to the eye; +x is perpendicular to up and +z (a cross product); +y = z × x. The columns of world_from_camera are x, y, z and the eye.",
                "back = normalize(eye - target), right = normalize(up x back), up' = back x right; \
                   world_from_camera has columns right, up', back, eye: invert it",
            ],
            symptoms: &[],
            reference: || check_look_at(|e, t, u| camera_from_world_look_at(e, t, u).unwrap_or(Mat4::NAN)),
        },
        Exercise {
            chapter: 1,
            name: "draw_edges",
            file: "chapters/ch1-projection/exercises/draw_edges.rs",
            hints: [
                "slide \"drawing edges; what lies behind the camera\": an edge with one end behind the pinhole has no image as a whole, but its front part does. Cut it at the near plane before projecting.",
                "the near plane is z = -near in camera space. Where an edge crosses it, the point a + s (b - a) with s = (a.z + near) / (a.z - b.z) lies on it. Project what is left with u = x / -z, then to raster coordinates.",
                "a, b = camera.to_camera(..); da = a.z + near, db = b.z + near; both > 0: None; one > 0: move it to a.lerp(b, da / (da - db)) with z = -near; raster = camera.raster_from_image_plane(Vec2::new(x / -z, y / -z)) for both ends",
            ],
            symptoms: &[],
            reference: || check_draw_edges(reference_edge),
        },
    ]
}

/// The capstone's candidate: a world-space edge to its two raster ends.
pub type EdgeFn = fn(&Camera, Vec3, Vec3, f32) -> Option<(Vec2, Vec2)>;

/// raystep's answer to the capstone: chapter 1's clip and projection.
pub fn reference_edge(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (ca, cb) = clip_to_near(camera.to_camera(a), camera.to_camera(b), near)?;
    let (ua, ub) = (project_pinhole(ca)?, project_pinhole(cb)?);
    Some((
        camera.raster_from_image_plane(ua),
        camera.raster_from_image_plane(ub),
    ))
}

/// The capstone: chapter 1's railroad (`railroad.toml`, 160 × 120), seen
/// from 3 m further down the track so that the rails run past the camera
/// and cross its near plane, drawn edge by
/// edge through the candidate and through the reference; the line images
/// must match (but for a few pixels where rounding decides), every whole
/// edge's ends must agree within 1e-4 (relative), and every clipped
/// edge's direction within 1e-3 rad, its uncut end within 0.01 pixel.
pub fn check_draw_edges(f: EdgeFn) -> Check {
    let scene = images::scene("railroad.toml");
    // The camera 3 m further down the track, standing between the rails:
    // their near ends are now behind it.
    let mut desc = scene.camera;
    desc.eye.z -= 3.0;
    desc.target.z -= 3.0;
    desc.width = 160;
    desc.height = 120;
    let camera = Camera::new(desc).expect("a valid camera");
    let edges: Vec<(Vec3, Vec3)> = scene
        .meshes
        .iter()
        .flat_map(|m| {
            m.edges()
                .into_iter()
                .map(|[i, j]| (m.positions[i as usize], m.positions[j as usize]))
        })
        .collect();
    let draw = |g: EdgeFn| {
        let mut film = Film::new(camera.width, camera.height);
        for (k, (a, b)) in edges.iter().enumerate() {
            crate::grading::progress(format_args!("calling draw_edges on edge {k}, {a} to {b}"));
            if let Some((ra, rb)) = g(&camera, *a, *b, NEAR) {
                draw::line(&mut film, ra, rb, Vec3::ONE, Vec3::ONE);
            }
        }
        film
    };
    // The worst edge, for the message and the numeric test.
    let mut worst = (0.0f64, String::new());
    for (a, b) in &edges {
        let got = f(&camera, *a, *b, NEAR);
        let want = reference_edge(&camera, *a, *b, NEAR);
        let (ca, cb) = (camera.to_camera(*a), camera.to_camera(*b));
        let clipped = ca.z > -NEAR || cb.z > -NEAR;
        // In units of the tolerance. A whole edge: its ends within 1e-4
        // (relative). A clipped one: its direction within 1e-3 rad (its
        // cut end lies far off the image, where f32 rounding of a point
        // 1 mm before the pinhole moves it by many pixels).
        let err = match (got, want) {
            (Some(g), Some(w)) if clipped => {
                let (dg, dw) = ((g.1 - g.0).normalize(), (w.1 - w.0).normalize());
                let angle = dg.dot(dw).clamp(-1.0, 1.0).acos() as f64;
                (angle / 1e-3).max((g.0 - w.0).length().min((g.1 - w.1).length()) as f64 / 1e-2)
            }
            (Some(g), Some(w)) => {
                let rel = |p: Vec2, q: Vec2| ((p - q).length() / q.length().max(1.0)) as f64;
                rel(g.0, w.0).max(rel(g.1, w.1)) / 1e-4
            }
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            worst = (
                err,
                format!(
                    "the edge from {a} to {b} (camera space z = {:.3} m and {:.3} m): \
                     yours ends at {got:?}, the reference at {want:?} (raster pixels)",
                    ca.z, cb.z
                ),
            );
        }
    }
    let explain = |_: u32, _: u32| worst.1.clone();
    let check = images::compare(
        draw(f),
        draw(reference_edge),
        0.05,
        2e-3,
        "wireframe",
        &explain,
    );
    if check.passed() && worst.0 > 1.0 {
        return Check {
            error: 1.0,
            detail: format!("the picture matches, but {}", worst.1),
            ..check
        };
    }
    check
}

/// Compares a pinhole projection with values worked out by hand.
pub fn check_project_point(f: fn(Vec3) -> Option<Vec2>) -> Check {
    // (point, expected image): in front of the camera, worked out by hand...
    let mut cases: Vec<(Vec3, Option<Vec2>)> = vec![
        (Vec3::new(1.0, 2.0, -2.0), Some(Vec2::new(0.5, 1.0))),
        (Vec3::new(-3.0, 0.0, -1.0), Some(Vec2::new(-3.0, 0.0))),
        (Vec3::new(0.2, -0.4, -4.0), Some(Vec2::new(0.05, -0.1))),
        (Vec3::new(0.0, 0.0, -1e6), Some(Vec2::ZERO)),
        // ... and points with no image.
        (Vec3::new(0.0, 0.0, 1.0), None),
        (Vec3::new(1.0, 1.0, 0.0), None),
    ];
    // A grid of points at several depths: x/(-z), y/(-z).
    for k in 1..=4 {
        let z = -(k as f32) * 1.5;
        for x in [-2.0f32, 0.5, 3.0] {
            cases.push((
                Vec3::new(x, 1.0 - x, z),
                Some(Vec2::new(x / -z, (1.0 - x) / -z)),
            ));
        }
    }
    let mut worst = (0.0f64, String::from("all cases match"));
    for (p, want) in cases {
        let got = f(p);
        let err = match (got, want) {
            (Some(g), Some(w)) => ((g - w).length() / w.length().max(1.0)) as f64,
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        // A NaN (from a NaN answer) counts as infinitely wrong.
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            worst = (err, format!("p = {p}: got {got:?}, expected {want:?}"));
        }
    }
    Check {
        error: worst.0,
        tolerance: 1e-5,
        detail: worst.1,
        images: None,
        symptom: None,
    }
}

/// Compares a look-at matrix with the reference on several cameras, then
/// renders the lecture's tetrahedron through it.
pub fn check_look_at(f: fn(Vec3, Vec3, Vec3) -> Mat4) -> Check {
    let cameras = [
        (Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y),
        (Vec3::new(3.0, 2.0, 4.0), Vec3::new(0.0, 0.5, 0.0), Vec3::Y),
        (
            Vec3::new(-2.0, 5.0, 1.0),
            Vec3::new(1.0, 0.0, -1.0),
            Vec3::new(0.0, 0.0, -1.0),
        ),
        (
            Vec3::new(10.0, -3.0, 0.5),
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(0.3, 1.0, 0.1),
        ),
    ];
    let mut worst = (0.0f64, String::from("all matrices match"));
    for (eye, target, up) in cameras {
        let want = camera_from_world_look_at(eye, target, up).expect("proper frames");
        let got = f(eye, target, up);
        // The camera must send the eye to the origin and the target onto -z.
        let err = (got - want)
            .to_cols_array()
            .iter()
            .map(|d| d.abs() as f64)
            .fold(0.0, f64::max);
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            worst = (
                err,
                format!(
                    "eye {eye}, target {target}, up {up}: eye maps to {}, target to {}",
                    got.transform_point3(eye),
                    got.transform_point3(target)
                ),
            );
        }
    }
    // The picture: the tetrahedron through the candidate and the reference.
    let desc = CameraDesc {
        eye: glam::DVec3::new(3.0, 2.0, 4.0),
        target: glam::DVec3::ZERO,
        up: glam::DVec3::Y,
        fov_degrees: 45.0,
        width: 160,
        height: 120,
    };
    let reference = Camera::new(desc).expect("valid camera");
    let mut candidate = reference.clone();
    candidate.camera_from_world = f(desc.eye.as_vec3(), desc.target.as_vec3(), desc.up.as_vec3());
    let mesh = [crate::scene::mesh::Mesh::tetrahedron()];
    let materials = [Material::default_grey()];
    let (ref_films, _) = draw_scene(&reference, &mesh, &materials);
    let (cand_films, _) = draw_scene(&candidate, &mesh, &materials);
    Check {
        error: worst.0,
        tolerance: 1e-4,
        detail: worst.1,
        images: Some((cand_films[0].clone(), ref_films[0].clone())),
        symptom: None,
    }
}
