//! The capstone's Cornell box: the student's paths against the
//! reference's, block by block, and every light sample that could light
//! its surface with its shadow ray. And how the capstone's scenes seen by
//! a camera call the student's paths ([`camera_sample`]).

use glam::{Vec2, Vec3};

use super::{reference_path, reset_tally, tally, PathFn, PathScene, NO_SHADOW_RAY};
use crate::ch1_projection::camera::Camera;
use crate::core::sampling::random;
use crate::exercise::Check;
use crate::exercises::images;

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

/// One sample of pixel (x, y) of the scene `paths` seen by `camera`
/// (called `what` in the progress lines) with `g`.
pub(crate) fn camera_sample<'a>(
    g: PathFn,
    paths: &'a PathScene,
    camera: &'a Camera,
    seed: u64,
    what: &'a str,
) -> impl Fn(u32, u32, u32) -> Vec3 + Sync + 'a {
    move |x: u32, y: u32, s: u32| -> Vec3 {
        let ray = camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
        let pixel = (y * camera.width + x) as u64;
        let mut dim = 0u64;
        let mut rng = || {
            dim += 1;
            random(seed, pixel, s as u64, dim).min(1.0 - f32::EPSILON)
        };
        if x == 0 && s == 0 {
            crate::progress(format_args!(
                "calling path_radiance for {what}'s camera rays, row {y} of {}",
                camera.height
            ));
        }
        reset_tally();
        let radiance = g(paths, ray.origin, ray.dir, &mut rng);
        paths.note_shadow_rays(&tally());
        radiance
    }
}
