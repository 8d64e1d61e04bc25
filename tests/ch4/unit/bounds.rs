//! `bounds`: how far a scene reaches from its camera, and its length unit
//! against the shipped scenes.

use glam::DVec3;
use raystep::ch4_implicit_surfaces::bounds::{length_unit, reach};
use raystep::scene::Scene;

fn shipped(name: &str) -> Scene {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    Scene::load(&dir.join(format!("{name}.toml"))).unwrap()
}

/// Every shipped SDF scene is the unit (their pictures keep chapter 4's
/// ε of 1e-4 and march of 100), and scaling one up scales its unit by the
/// nearest power of four: ×1,000 is 4⁵.
#[test]
fn shipped_sdf_scenes_are_the_unit_and_scaled_ones_scale() {
    for name in ["sdf-lit", "sdf-shapes", "sdf-lipschitz"] {
        let scene = shipped(name);
        assert_eq!(length_unit(&scene), 1.0, "{name}: reach {}", reach(&scene));
        let big = scene.clone().placed(DVec3::splat(5e3), 1e3);
        assert_eq!(length_unit(&big), 1024.0, "{name}");
        // A tiny scene is scaled up at load by a power of two (its
        // `unit`), so its length unit stays near 1.
        let small = scene.placed(DVec3::ZERO, 1e-3);
        assert!(small.unit < 1.0 / 32.0, "{name}: {}", small.unit);
        assert!((1.0 / 16.0..=1.0).contains(&length_unit(&small)), "{name}");
    }
}
