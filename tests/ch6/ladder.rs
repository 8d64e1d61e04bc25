//! The first rung of chapter 6's ladder, [`random_walk`] (the uniform
//! random walk, readable on its own), converges to the image of the full
//! MIS path loop: region z-tests with both sample variances.

use glam::{Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch5_reflection::world::World;
use raystep::ch6_global_illumination::integrator::{random_walk, PathSettings};
use raystep::ch6_global_illumination::reference::{region_z_test, RegionTest, StoredReference};
use raystep::ch6_global_illumination::sampler::SamplerKind;
use raystep::ch6_global_illumination::scenes;
use raystep::ch6_global_illumination::studies::render;
use raystep::core::film::Film;
use raystep::core::sampling::Sampler;
use raystep::scene::Scene;

/// Per-pixel mean and variance of the mean of `spp` random walks.
fn walk_image(scene: &Scene, spp: u32, max_depth: u32) -> (Film, Film) {
    let world = World::new(scene);
    let cam = Camera::of(scene);
    let (mut mean, mut var) = (
        Film::new(cam.width, cam.height),
        Film::new(cam.width, cam.height),
    );
    for y in 0..cam.height {
        for x in 0..cam.width {
            let pixel = (y * cam.width + x) as u64;
            let (mut sum, mut sum_sq) = (Vec3::ZERO, Vec3::ZERO);
            for sample in 0..spp {
                let mut s = Sampler::new(17, pixel, sample as u64);
                let raster = Vec2::new(x as f32, y as f32) + s.next2();
                let l = random_walk(&world, cam.ray(raster), max_depth, &mut s);
                assert!(l.is_finite(), "pixel ({x}, {y}): {l}");
                sum += l;
                sum_sq += l * l;
            }
            let n = spp as f32;
            let m = sum / n;
            mean.pixels[pixel as usize] = m;
            var.pixels[pixel as usize] = (sum_sq - n * m * m).max(Vec3::ZERO) / (n - 1.0) / n;
        }
    }
    (mean, var)
}

// ANCHOR: walk_against_mis
/// The random walk (`walk_spp` samples) against the full MIS loop
/// (`mis_spp`), both with at most 16 bounces, in `block`² regions.
/// `caught` is a brightness factor the test must catch (its power).
fn walk_against_mis(
    scene: &Scene,
    walk_spp: u32,
    mis_spp: u32,
    block: u32,
    caught: f32,
) -> (RegionTest, Film) {
    let path = PathSettings::default();
    assert_eq!(path.max_bounces, Some(16));
    let (walk, walk_var) = walk_image(scene, walk_spp, 16 + 1);
    let (acc, _) = render(scene, &path, SamplerKind::Independent, mis_spp, 11, false);
    let reference = StoredReference {
        mean: acc.mean(),
        var_of_mean: acc.variance_of_mean(),
        meta: String::new(),
    };
    let t = region_z_test(&walk, &walk_var, &reference, block, 1e-3);
    // The test has power: `caught` times the light fails it.
    let mut brighter = walk.clone();
    brighter.pixels.iter_mut().for_each(|p| *p *= caught);
    let power = region_z_test(&brighter, &walk_var, &reference, block, 1e-3);
    assert!(!power.passed(), "×{caught} passes: {power:?}");
    (t, walk)
}
// ANCHOR_END: walk_against_mis

#[test]
fn the_random_walk_converges_to_the_mis_image_of_the_cornell_box() {
    // The walk finds the small lamp only by hitting it: many samples per
    // region, or the sample variance of its rare hits is underestimated;
    // even so its regions stay noisy enough that 30% more light is what
    // the test is sure to catch.
    let scene = Scene::builtin().with_resolution(8, 8).unwrap();
    let (t, walk) = walk_against_mis(&scene, 8192, 256, 2, 1.3);
    assert!(t.passed(), "{t:?}");
    assert_eq!(t.regions, 16);
    assert!(walk.pixels.iter().all(|p| p.max_element() > 0.0));
}

#[test]
fn the_random_walk_converges_through_glass_under_a_sky() {
    // The open furnace in a glass shell: the sky found by escaping, and
    // the delta (glass) branch of the walk.
    let scene = scenes::open_furnace(0.6, 16, Some(1.5));
    let (t, _) = walk_against_mis(&scene, 1024, 64, 4, 1.1);
    assert!(t.passed(), "{t:?}");
    assert_eq!(t.regions, 16);
}
