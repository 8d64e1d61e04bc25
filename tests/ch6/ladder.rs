//! The first rung of chapter 6's ladder, [`random_walk`] (the uniform
//! random walk, readable on its own), converges to the image of the full
//! MIS path loop: region z-tests with both sample variances.

use raystep::ch6_global_illumination::integrator::PathSettings;
use raystep::ch6_global_illumination::random_walk::random_walk;
use raystep::ch6_global_illumination::reference::{region_z_test, RegionTest, StoredReference};
use raystep::ch6_global_illumination::sampler::SamplerKind;
use raystep::ch6_global_illumination::scenes;
use raystep::ch6_global_illumination::studies::render;
use raystep::core::film::Film;
use raystep::scene::Scene;

use crate::common::mean_and_variance;

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
    let (walk, walk_var) =
        mean_and_variance(scene, walk_spp, 17, &|w, r, s| random_walk(w, r, 16, s));
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
