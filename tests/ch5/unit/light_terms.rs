//! Unit tests of `src/ch5_reflection/light_terms.rs`.

use glam::Vec3;
use raystep::ch1_projection::camera::Camera;
use raystep::ch5_reflection::direct::{Estimator, Strategy};
use raystep::ch5_reflection::light_terms::*;
use raystep::ch5_reflection::render::render_pass;
use raystep::ch5_reflection::world::World;
use raystep::scene::Scene;

fn check(scene: &Scene, strategy: Strategy) -> usize {
    let world = World::new(scene);
    let camera = Camera::of(scene);
    let est = Estimator {
        strategy,
        max_mirror_bounces: 4,
        trace_light_rays: true,
    };
    let mut split = 0;
    for sample in [0, 3] {
        let n = (camera.width * camera.height) as usize;
        let (mut sums, mut caught) = (vec![Vec3::ZERO; n], vec![0; n]);
        render_pass(
            &world,
            &camera,
            &est,
            9,
            sample,
            0..camera.height,
            &mut sums,
            &mut caught,
        );
        for y in 0..camera.height {
            for x in 0..camera.width {
                let p = pixel_light(&world, &camera, &est, 9, (x, y), sample);
                let r = sums[(y * camera.width + x) as usize];
                assert_eq!(p.total, r, "({x}, {y})");
                if !p.delta {
                    let d = (p.sum() - r).abs().max_element();
                    assert!(
                        d <= 1e-5 * r.max_element().max(1e-3),
                        "({x}, {y}): {} vs {r}",
                        p.sum()
                    );
                    split += usize::from(
                        p.lights.iter().filter(|t| t.sampled != Vec3::ZERO).count() >= 2,
                    );
                }
            }
        }
    }
    split
}

#[test]
fn the_lights_terms_add_up_to_the_renders_sample() {
    let gallery = crate::common::shipped_scene("lights-gallery", 20, 15);
    for s in Strategy::ALL {
        let split = check(&gallery, s);
        if s != Strategy::Uniform && s != Strategy::Bsdf {
            assert!(
                split > 10,
                "{s:?}: pixels lit by two lights or more: {split}"
            );
        }
    }
    let cornell = Scene::builtin().with_resolution(16, 16).unwrap();
    check(&cornell, Strategy::Mis);
}
