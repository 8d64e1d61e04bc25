//! A path written down by [`record_path`] is the path the render traced:
//! its table's contributions add up to what the render's own pass added
//! to the pixel for that sample, layer by layer, and each row's numbers
//! are consistent with one another (β f Li cos w / pdf, β · f cos / pdf).

use glam::Vec3;

use raystep::ch1_projection::camera::Camera;
use raystep::ch5_reflection::world::World;
use raystep::ch6_global_illumination::accumulate::Accumulator;
use raystep::ch6_global_illumination::engine::{PathEngine, PathLoop};
use raystep::ch6_global_illumination::integrator::{PathSettings, Strategy};
use raystep::ch6_global_illumination::path_record::{record_path, PathEnd, PathRecord};
use raystep::ch6_global_illumination::sampler::SamplerKind;
use raystep::scene::Scene;

const SEED: u64 = 5;

fn close(a: Vec3, b: Vec3, rel: f32) -> bool {
    (a - b).abs().max_element() <= rel * a.abs().max(b.abs()).max_element().max(1e-6)
}

/// What the render's pass adds to every pixel for sample `sample` alone,
/// with layers.
fn render_sample(
    engine: &PathLoop,
    camera: &Camera,
    path: &PathSettings,
    kind: SamplerKind,
    sample: u32,
) -> Accumulator {
    let mut acc = Accumulator::new(camera.width, camera.height, true);
    acc.samples = sample;
    acc.add_samples(engine, camera, path, kind, SEED, 1);
    acc
}

/// Checks every pixel of a `step`-spaced grid for samples `samples`;
/// returns the records for the caller's own checks.
fn check_scene(scene: &Scene, path: PathSettings, kind: SamplerKind) -> Vec<PathRecord> {
    let engine = PathLoop::new(scene);
    let world = engine.world();
    let camera = Camera::of(scene);
    let mut records = Vec::new();
    for sample in [0u32, 1, 7] {
        let acc = render_sample(&engine, &camera, &path, kind, sample);
        let layers = acc.layers.as_ref().unwrap();
        for y in (1..camera.height).step_by(5) {
            for x in (2..camera.width).step_by(5) {
                let i = (y * camera.width + x) as usize;
                let r = record_path(world, &camera, &path, kind, SEED, (x, y), sample);
                let rendered = acc.sum[i];
                let sum = r.contributions_sum();
                assert!(
                    close(sum, rendered, 1e-5),
                    "{} {:?} {kind:?} pixel ({x}, {y}) sample {sample}: table {sum} vs render {rendered}\n{r:#?}",
                    scene.name,
                    path.strategy
                );
                assert_eq!(r.layers, layers[i], "layers of ({x}, {y}) sample {sample}");
                check_rows(&r);
                records.push(r);
            }
        }
    }
    records
}

/// Each row's columns agree with its contribution.
fn check_rows(r: &PathRecord) {
    for (k, v) in r.vertices.iter().enumerate() {
        if let Some(e) = v.emission {
            assert!(
                close(e.contribution, v.beta * e.le * e.weight, 1e-5),
                "{k}: {e:?}"
            );
        }
        if let Some(l) = v.light {
            let expected = if l.visible {
                v.beta * l.f * l.li * l.cos * l.weight / l.pdf
            } else {
                Vec3::ZERO
            };
            assert!(close(l.contribution, expected, 1e-4), "{k}: {l:?}");
        }
        if let Some(s) = v.scatter {
            if !s.delta {
                let expected = v.beta * s.f * s.cos / s.pdf;
                assert!(close(s.beta, expected, 1e-4), "{k}: {s:?} from {}", v.beta);
            }
            // The next vertex arrives with β, divided by q if roulette was played.
            if let Some(next) = r.vertices.get(k + 1) {
                let q = v.roulette.map_or(1.0, |(q, _)| q);
                assert!(close(next.beta, s.beta / q, 1e-5), "{k}");
            }
        }
    }
}

fn cornell() -> Scene {
    Scene::builtin().with_resolution(24, 24).unwrap()
}

fn glass() -> Scene {
    crate::common::shipped_scene("cornell-glass", 24, 24)
}

#[test]
fn the_table_adds_up_to_the_renders_sample_with_mis_and_sobol() {
    let records = check_scene(&cornell(), PathSettings::default(), SamplerKind::Sobol);
    // Not a trivial agreement: paths bounce, light sampling adds light
    // (some of it MIS-weighted below 1), and some paths end by roulette.
    assert!(records.iter().any(|r| r.vertices.len() >= 3));
    let lights: Vec<_> = records
        .iter()
        .flat_map(|r| r.vertices.iter().filter_map(|v| v.light))
        .collect();
    assert!(lights
        .iter()
        .any(|l| l.visible && l.contribution.max_element() > 0.0));
    assert!(lights.iter().any(|l| !l.visible));
    assert!(lights.iter().any(|l| l.weight > 0.0 && l.weight < 1.0));
    assert!(records.iter().any(|r| r.end == PathEnd::Roulette));
    // Emission found by BSDF sampling counts with a weight below 1.
    assert!(records
        .iter()
        .flat_map(|r| r.vertices.iter().skip(1).filter_map(|v| v.emission))
        .any(|e| e.weight < 1.0));
}

#[test]
fn the_table_adds_up_on_the_glass_scene() {
    let records = check_scene(&glass(), PathSettings::default(), SamplerKind::Sobol);
    assert!(
        records.iter().any(|r| r
            .vertices
            .iter()
            .any(|v| v.scatter.is_some_and(|s| s.delta))),
        "some path goes through the glass"
    );
}

#[test]
fn the_table_adds_up_for_the_uniform_walk_with_independent_numbers() {
    let path = PathSettings {
        strategy: Strategy::Uniform,
        ..PathSettings::default()
    };
    let records = check_scene(&cornell(), path, SamplerKind::Independent);
    // The walk samples no lights: all its light is emission it hits.
    assert!(records
        .iter()
        .all(|r| r.vertices.iter().all(|v| v.light.is_none())));
    // It finds the light only by hitting it, now and then.
    let scene = cornell();
    let (world, camera) = (World::new(&scene), Camera::of(&scene));
    let found = (0..4000)
        .map(|s| {
            record_path(
                &world,
                &camera,
                &path,
                SamplerKind::Independent,
                SEED,
                (12, 12),
                s,
            )
        })
        .filter(|r| r.vertices.iter().skip(1).any(|v| v.emission.is_some()))
        .count();
    assert!(found > 0);
}
