//! Chapter 1's exercises and how each is graded.

use glam::{Mat4, Vec2, Vec3};

use crate::ch1_projection::camera::{
    camera_from_world_look_at, project_pinhole, Camera, CameraDesc,
};
use crate::ch1_projection::wireframe::draw_scene;
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
            reference: || check_look_at(|e, t, u| camera_from_world_look_at(e, t, u).unwrap_or(Mat4::NAN)),
        },
    ]
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
    }
}
