//! The first rung of chapter 5's ladder, [`direct_lighting`] (light
//! sampling alone, readable on its own), against the chapter's full
//! estimator: the same numbers as its light-sampling strategy, and the same
//! image in expectation as its MIS strategy.

use glam::{Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch5_reflection::direct::{direct_lighting, Counters, Estimator, Strategy};
use raystep::ch5_reflection::world::World;
use raystep::ch6_global_illumination::reference::{region_z_test, StoredReference};
use raystep::core::film::Film;
use raystep::core::sampling::Sampler;
use raystep::scene::Scene;

const SEED: u64 = 5;

fn estimator(strategy: Strategy) -> Estimator {
    Estimator {
        strategy,
        max_mirror_bounces: 4,
        shadow_rays: true,
    }
}

/// Per-pixel mean and variance of the mean of `spp` samples of `radiance`,
/// each sample's camera ray jittered as chapter 5's `render_pass` does.
fn render(
    scene: &Scene,
    spp: u32,
    radiance: &dyn Fn(&World, &raystep::ch3_ray_triangle::ray::Ray, &mut Sampler) -> Vec3,
) -> (Film, Film) {
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
                let mut s = Sampler::new(SEED, pixel, sample as u64);
                let raster = Vec2::new(x as f32, y as f32) + s.next2();
                let l = radiance(&world, &cam.ray(raster), &mut s);
                assert!(l.is_finite(), "pixel ({x}, {y}): {l}");
                sum += l;
                sum_sq += l * l;
            }
            let n = spp as f32;
            let m = sum / n;
            mean.pixels[pixel as usize] = m;
            // The sample variance, divided by n: the variance of the mean.
            var.pixels[pixel as usize] = (sum_sq - n * m * m).max(Vec3::ZERO) / (n - 1.0) / n;
        }
    }
    (mean, var)
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
    let (lesson, lesson_var) = render(&scene, 64, &|w, r, s| direct_lighting(w, r, s));
    let mis = estimator(Strategy::Mis);
    let (full, full_var) = render(&scene, 64, &|w, r, s| {
        mis.radiance(w, r, s, &mut Counters::default())
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
