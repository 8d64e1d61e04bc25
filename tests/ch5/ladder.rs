//! The first rung of chapter 5's ladder, [`direct_lighting`] (light
//! sampling alone, readable on its own), against the chapter's full
//! estimator: the same numbers as its light-sampling strategy, and the same
//! image in expectation as its MIS strategy.

use glam::Vec2;
use raystep::ch1_projection::camera::Camera;
use raystep::ch5_reflection::direct::{direct_lighting, Estimator, Strategy};
use raystep::ch5_reflection::shading_events::Counters;
use raystep::ch5_reflection::world::World;
use raystep::ch6_global_illumination::reference::{region_z_test, StoredReference};
use raystep::core::sampling::Sampler;
use raystep::scene::Scene;

use crate::common::mean_and_variance;

const SEED: u64 = 5;

fn estimator(strategy: Strategy) -> Estimator {
    Estimator {
        strategy,
        max_mirror_bounces: 4,
        trace_light_rays: true,
    }
}

#[test]
fn direct_lighting_is_the_light_strategy_up_to_rounding() {
    let scene = Scene::builtin().with_resolution(16, 16).unwrap();
    let world = World::new(&scene);
    let cam = Camera::of(&scene);
    let full = estimator(Strategy::Light);
    let mut lit = 0;
    for pixel in 0..256u64 {
        for sample in 0..4 {
            let mut s = Sampler::new(SEED, pixel, sample);
            let raster = Vec2::new((pixel % 16) as f32, (pixel / 16) as f32) + s.next2();
            let ray = cam.ray(raster);
            let a = direct_lighting(&world, &ray, &mut s.clone());
            let b = full.radiance(&world, &ray, &mut s, &mut Counters::default());
            let tolerance = 1e-5 * b.max_element().max(1e-3);
            assert!(
                (a - b).abs().max_element() <= tolerance,
                "pixel {pixel}: {a} vs {b}"
            );
            lit += usize::from(a.max_element() > 0.0);
        }
    }
    assert!(lit > 500, "only {lit} lit samples");
}

// ANCHOR: converge
#[test]
fn direct_lighting_and_mis_converge_to_the_same_image() {
    let scene = Scene::builtin().with_resolution(16, 16).unwrap();
    let (lesson, lesson_var) =
        mean_and_variance(&scene, 64, SEED, &|w, r, s| direct_lighting(w, &r, s));
    let mis = estimator(Strategy::Mis);
    let (full, full_var) = mean_and_variance(&scene, 64, SEED, &|w, r, s| {
        mis.radiance(w, &r, s, &mut Counters::default())
    });
    let reference = StoredReference {
        mean: full,
        var_of_mean: full_var,
        meta: String::new(),
    };
    // 16 regions of 4x4 pixels, 3 channels, Bonferroni α = 1e-3.
    let t = region_z_test(&lesson, &lesson_var, &reference, 4, 1e-3);
    assert!(t.passed(), "{t:?}");
    assert_eq!(t.regions, 16);
    // The test has power: 10% less light is caught.
    let mut dimmer = lesson.clone();
    dimmer.pixels.iter_mut().for_each(|p| *p *= 0.9);
    assert!(!region_z_test(&dimmer, &lesson_var, &reference, 4, 1e-3).passed());
}
// ANCHOR_END: converge
