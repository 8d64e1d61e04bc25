//! `ch6 --bench` on any scene: its table names the scene and size, the
//! per-pixel RMSE comes from that scene's stored reference, the fast
//! engine says which loop it ran, and a scene without a reference gets the
//! command that makes one instead of a number.

use raystep::ch6_global_illumination::integrator::PathSettings;
use raystep::ch6_global_illumination::reference::StoredReference;
use raystep::fast::bench;

use crate::common;

/// The cells of the table row that starts with `label`.
fn row<'a>(text: &'a str, label: &str) -> Vec<&'a str> {
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with(label))
        .unwrap_or_else(|| panic!("no row {label}:\n{text}"));
    line.split("  ")
        .map(str::trim)
        .filter(|c| !c.is_empty())
        .collect()
}

#[test]
fn the_cornell_box_is_measured_against_its_reference_on_the_wavefront() {
    let scene = common::shipped_scene("cornell-box", 64, 64);
    let text = bench::bench(1, &PathSettings::default(), &scene).unwrap();
    assert!(
        text.starts_with("ch6 benchmark: cornell-box 64x64, 1 spp"),
        "{text}"
    );
    for label in ["fast independent", "fast sobol", "readable independent"] {
        let cells = row(&text, label);
        let rmse: f64 = cells[4].parse().unwrap_or_else(|_| panic!("{text}"));
        // One sample per pixel of the Cornell box: noisy, but finite and
        // far from zero.
        assert!(rmse > 0.05 && rmse < 2.0, "{label}: {rmse}\n{text}");
    }
    assert!(
        text.contains("The fast engine on cornell-box uses"),
        "{text}"
    );
    assert!(!text.contains("No RMSE per pixel"), "{text}");
}

#[test]
fn a_scene_without_a_reference_at_its_size_gets_the_command_that_makes_one() {
    let scene = common::shipped_scene("cornell-glassball", 32, 32);
    assert!(StoredReference::for_scene_at(&scene, 32, 32).is_none());
    let text = bench::bench(1, &PathSettings::default(), &scene).unwrap();
    assert!(
        text.starts_with("ch6 benchmark: cornell-glassball 32x32"),
        "{text}"
    );
    assert_eq!(row(&text, "fast sobol")[4], "-", "{text}");
    assert!(text.contains("No RMSE per pixel"), "{text}");
    // Glass is on the wavefront, its vertices by the lesson's steps: the
    // note says so.
    assert!(
        text.contains("The fast engine on cornell-glassball uses the fast engine's wavefront loop"),
        "{text}"
    );
    assert!(text.contains("the others by the lesson's steps"), "{text}");
    let command = format!(
        "--make-reference --scene {} --width 32 --height 32 --spp 16384",
        scene.source
    );
    assert!(text.contains(&command), "{text}");
}

#[test]
fn the_glass_scene_has_its_reference_and_it_is_of_this_scene() {
    // The Mitsuba comparison's glass scene (`PEER_SCENE=glass`) is this
    // one: the per-pixel RMSE of `ch6 --bench --scene` needs its reference,
    // matched by content, not by name alone.
    let scene = common::shipped_scene("cornell-glassball", 256, 256);
    let r = StoredReference::for_scene_at(&scene, 256, 256).expect("a stored reference");
    assert_eq!(r.value("content"), Some(scene.content_hash().as_str()));
    assert_eq!(r.value("spp"), Some("16384"));
    assert!(r.mean.pixels.iter().all(|p| p.is_finite()));
}
