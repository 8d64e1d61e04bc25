//! The capstone's Cornell box: the student's paths against the
//! reference's, block by block, and every light sample that could light
//! its surface with its shadow ray.

use crate::ch1_projection::camera::Camera;
use crate::exercise::Check;
use crate::exercises::images;

use super::{camera_sample, reference_path, PathFn, PathScene, NO_SHADOW_RAY};

/// The Cornell box with `f` and with the reference: the z-test's check.
pub(super) fn cornell(f: PathFn) -> Check {
    let scene = images::scene("cornell-box.toml");
    let camera = Camera::of(&scene)
        .with_resolution(32, 32)
        .expect("a valid camera");
    // One scene each: a candidate whose paths never end leaves its scene
    // finding nothing (see `PathScene::ran_away`).
    let (mine, theirs) = (PathScene::new(&scene), PathScene::new(&scene));
    let (w, h) = (camera.width, camera.height);
    let student = images::Estimate::gather(
        w,
        h,
        64,
        &camera_sample(f, &mine, &camera, 601, "the Cornell box"),
    );
    // The reference's paths call no student function: on the grader's
    // threads (see `bridge::on_grader_pool`).
    let reference = crate::bridge::on_grader_pool(|| {
        images::Estimate::gather(
            w,
            h,
            64,
            &camera_sample(reference_path, &theirs, &camera, 602, "the Cornell box"),
        )
    });
    if mine.unshadowed() > 0 {
        return Check {
            error: 1e9,
            tolerance: 5.0,
            detail: format!(
                "the Cornell box: {} light samples that could light their surface counted without \
                 a shadow ray (each needs its own before it counts, however small it is)",
                mine.unshadowed()
            ),
            images: None,
            symptom: Some(NO_SHADOW_RAY),
        };
    }
    images::z_test(student, reference, 8, 5.0, "radiance")
}
