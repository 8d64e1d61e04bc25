//! Where samples were NaN or infinite: each engine counts, per pixel, the
//! contributions it caught and left out, the counts add up to the
//! render's total, every SIMD path of the fast engine gives the same
//! counts, and the lesson's engine nearly the same (the wavefront's paths
//! equal the lesson's only up to the last bits of a sine, and a path that
//! grazes the lamp may find it in one and miss it in the other). The light is made infinite in code, past what a scene file
//! accepts, so that the real renderer meets non-finite values.

use glam::Vec3;

use raystep::ch1_projection::camera::Camera;
use raystep::ch6_global_illumination::accumulate::Accumulator;
use raystep::ch6_global_illumination::engine::{PathEngine, PathLoop};
use raystep::ch6_global_illumination::integrator::{PathSettings, Strategy};
use raystep::ch6_global_illumination::layers::SLOT_EMITTED;
use raystep::ch6_global_illumination::sampler::SamplerKind;
use raystep::core::stage::Settings;
use raystep::fast::level::Level;
use raystep::fast::FastEngine;
use raystep::scene::Scene;

/// The Cornell box at `size`², its lamp emitting `le`.
fn cornell(size: u32, le: f32) -> Scene {
    let mut scene = Scene::builtin().with_resolution(size, size).unwrap();
    for m in &mut scene.materials {
        if m.emission.max_element() > 0.0 {
            m.emission = Vec3::splat(le);
        }
    }
    scene
}

fn render(engine: &dyn PathEngine, scene: &Scene, strategy: Strategy, layers: bool) -> Accumulator {
    let camera = Camera::of(scene);
    let path = PathSettings {
        strategy,
        ..PathSettings::default()
    };
    let mut acc = Accumulator::new(camera.width, camera.height, layers);
    acc.add_samples(engine, &camera, &path, SamplerKind::Sobol, 7, 2);
    acc.add_samples(engine, &camera, &path, SamplerKind::Sobol, 7, 2);
    acc
}

#[test]
fn both_engines_count_each_pixels_caught_samples_alike() {
    let scene = cornell(24, f32::INFINITY);
    let readable = PathLoop::new(&scene);
    for layers in [false, true] {
        let lesson = render(&readable, &scene, Strategy::Mis, layers);
        let total: u64 = lesson.caught.iter().map(|&c| u64::from(c)).sum();
        assert!(total > 0, "an infinite lamp gives infinite samples");
        assert_eq!(total, lesson.stats.nonfinite, "the pixels' counts add up");
        assert!(lesson.mean().pixels.iter().all(|p| p.is_finite()));
        let portable = render(
            &FastEngine::at(&scene, Level::Portable),
            &scene,
            Strategy::Mis,
            layers,
        );
        let fast_total: u64 = portable.caught.iter().map(|&c| u64::from(c)).sum();
        assert_eq!(fast_total, portable.stats.nonfinite);
        let differ = (lesson.caught.iter().zip(&portable.caught))
            .filter(|(a, b)| a != b)
            .count();
        assert!(
            differ * 50 <= lesson.caught.len() && fast_total.abs_diff(total) * 100 <= total,
            "{differ} pixels differ; {fast_total} caught against {total}"
        );
        for level in Level::ALL.into_iter().filter(|l| l.available()) {
            let fast = render(
                &FastEngine::at(&scene, level),
                &scene,
                Strategy::Mis,
                layers,
            );
            assert_eq!(fast.caught, portable.caught, "{level:?}, layers {layers}");
        }
    }
}

#[test]
fn the_counts_are_where_the_light_is_found_and_nowhere_for_a_finite_lamp() {
    // BSDF sampling finds the lamp only by hitting it: the pixels that see
    // it directly catch a sample every time, most others never.
    let infinite_scene = cornell(24, f32::INFINITY);
    let infinite = render(
        &PathLoop::new(&infinite_scene),
        &infinite_scene,
        Strategy::Bsdf,
        false,
    );
    let finite_scene = cornell(24, 10.0);
    let finite = render(
        &PathLoop::new(&finite_scene),
        &finite_scene,
        Strategy::Bsdf,
        true,
    );
    assert!(finite.caught.iter().all(|&c| c == 0), "a finite lamp: none");
    let layers = finite.layers.as_ref().unwrap();
    let mut seen = 0;
    for (i, slots) in layers.iter().enumerate() {
        if slots[SLOT_EMITTED].max_element() > 0.0 {
            seen += 1;
            assert!(infinite.caught[i] >= 1, "pixel {i} sees the lamp");
        }
    }
    assert!(seen > 0, "the camera sees the lamp");
    let none = infinite.caught.iter().filter(|&&c| c == 0).count();
    assert!(
        none > infinite.caught.len() / 4,
        "{none} of {} pixels caught nothing",
        infinite.caught.len()
    );
}

#[test]
fn chapters_5_and_6_show_the_counts_as_their_non_finite_view() {
    let scene = std::sync::Arc::new(cornell(16, f32::INFINITY));
    let settings = Settings {
        spp: 2,
        ..Settings::default()
    };
    for n in [5, 6] {
        let chapter = raystep::chapters::all()[n - 1];
        let k = chapter
            .info()
            .views
            .iter()
            .position(|v| v.name == "non-finite");
        let k = k.unwrap_or_else(|| panic!("chapter {n} has the view"));
        let mut render = chapter.start(scene.clone(), &settings).unwrap();
        while !render.pass().complete {}
        let snap = render.snapshot();
        let total: f64 = snap.views[k].pixels.iter().map(|p| f64::from(p.x)).sum();
        assert!(total > 0.0, "chapter {n}");
        assert_eq!(
            total as u64,
            render.report().nonfinite_caught,
            "chapter {n}: the view's counts are the report's"
        );
        assert!(snap.views[0].pixels.iter().all(|p| p.is_finite()));
    }
}
