//! Russian roulette does not end a path for being inside glass.
//! Refraction scales radiance by η², so a camera path that enters a ball of
//! index 1.5 carries β = (1/1.5)² although its light comes back, times
//! 1.5², on the way out. Roulette that read that β would end such paths
//! more often than any other and make glass the noisiest thing in the
//! picture; the path loop reads β with the scaling undone (`eta_scale`).

use glam::Vec3;

use raystep::ch1_projection::camera::Camera;
use raystep::ch5_reflection::material::Bsdf;
use raystep::ch6_global_illumination::engine::{PathEngine, PathLoop};
use raystep::ch6_global_illumination::integrator::PathSettings;
use raystep::ch6_global_illumination::path_record::record_path;
use raystep::ch6_global_illumination::sampler::SamplerKind;

use crate::common;

#[test]
fn a_path_refracted_into_glass_survives_roulette_for_sure() {
    let (w, h) = (48, 48);
    let scene = common::shipped_scene("cornell-glass", w, h);
    let engine = PathLoop::new(&scene);
    let world = engine.world();
    let camera = Camera::of(&scene);
    // Roulette from the first scattering on (the default).
    let path = PathSettings::default();
    assert_eq!(path.rr_min_bounce, 1);
    // The ball of scenes/cornell-glass.toml.
    let centre = Vec3::new(0.33, -0.65, 0.38);
    let mut entered = 0;
    for (x, y) in (0..h).flat_map(|y| (0..w).map(move |x| (x, y))) {
        let r = record_path(
            world,
            &camera,
            &path,
            SamplerKind::Independent,
            3,
            (x, y),
            0,
        );
        let Some(v) = r.vertices.first() else {
            continue;
        };
        let (Bsdf::Dielectric(_), Some(s)) = (&world.bsdfs[v.material], v.scatter) else {
            continue;
        };
        if s.wi.dot(v.p - centre) >= 0.0 {
            continue; // reflected off the ball
        }
        // Into the ball: β is (1/1.5)², and yet the path survives.
        let shrunk = Vec3::splat(1.0 / 2.25);
        assert!((s.beta - shrunk).abs().max_element() < 1e-6, "{:?}", s.beta);
        let (q, survived) = v.roulette.expect("roulette at the first scattering");
        assert!(q > 0.9999 && survived, "pixel ({x}, {y}): q = {q}");
        entered += 1;
    }
    assert!(
        entered >= 20,
        "only {entered} camera paths entered the ball"
    );
}
