//! Chapter 5's stage: what it builds and leaves out, its stiff cases, its
//! strategy study, determinism across thread counts, and snapshots of its
//! report and of quantized images.

use crate::common;
use std::sync::Arc;

use raystep::ch5_reflection::direct::Strategy;
use raystep::ch5_reflection::stability::{caught, stability_cases};
use raystep::ch5_reflection::stage::{Reflection, DEFAULT};
use raystep::ch5_reflection::studies::{error_against_time, Study};
use raystep::core::film::Film;
use raystep::core::report::{Report, Times};
use raystep::core::stage::{Chapter, Settings};
use raystep::scene::Scene;

use common::shipped_scene as scene;

fn render(stage: &Reflection, scene: Scene, spp: u32) -> (Film, Report) {
    let settings = Settings {
        spp,
        seed: 3,
        ..Settings::default()
    };
    let mut r = stage.start(Arc::new(scene), &settings).unwrap();
    while !r.pass().complete {}
    (r.snapshot().views[0].clone(), r.report())
}

/// Block means of the image, 2 significant decimals, as text.
fn summary(film: &Film, blocks: u32) -> String {
    let (bw, bh) = (film.width / blocks, film.height / blocks);
    let mut s = String::new();
    for by in 0..blocks {
        for bx in 0..blocks {
            let mut sum = glam::Vec3::ZERO;
            for y in by * bh..(by + 1) * bh {
                for x in bx * bw..(bx + 1) * bw {
                    sum += film.get(x, y);
                }
            }
            let m = sum / (bw * bh) as f32;
            s += &format!(" {:.2}", (m.x + m.y + m.z) / 3.0);
        }
        s += "\n";
    }
    s
}

#[test]
fn the_scene_decides_what_is_built() {
    // The Cornell box: an area light, occluders, no environment.
    let (_, r) = render(
        &DEFAULT,
        Scene::builtin().with_resolution(12, 12).unwrap(),
        1,
    );
    let built = r.built.join("\n");
    let left = r.left_out.join("\n");
    assert!(built.contains("light-sampling tables"), "{built}");
    assert!(built.contains("shadow rays"), "{built}");
    assert!(left.contains("environment"), "{left}");
    assert!(r
        .facts
        .iter()
        .any(|(k, v)| k == "rays" && !v.starts_with("0 shadow")));
    // The Lambert sphere: one convex mesh, one directional light.
    let (_, r) = render(&DEFAULT, scene("lambert-sphere", 16, 16), 1);
    let left = r.left_out.join("\n");
    assert!(left.contains("light-sampling tables"), "{left}");
    assert!(left.contains("shadow rays"), "{left}");
    assert!(r
        .facts
        .iter()
        .any(|(k, v)| k == "rays" && v.starts_with("0 shadow rays, 0 sampled")));
    // The SDF scene marches; the sphere scene does not.
    let (_, r) = render(&DEFAULT, scene("sdf-lit", 8, 6), 1);
    assert!(r.built.join("\n").contains("sphere tracer"));
}

/// The stiff cases, judged here on the numbers they measured (not on the
/// verdict each report row computes), against values and bounds stated
/// here; and no NaN or Inf caught anywhere.
#[test]
fn every_stiff_case_comes_out_as_expected_with_no_nan() {
    let cases = stability_cases();
    assert_eq!(cases.len(), 8);
    // The number `what` of the case whose name starts with `case`.
    let number = |case: &str, what: &str| {
        let c = cases
            .iter()
            .find(|c| c.case.name.starts_with(case))
            .unwrap_or_else(|| panic!("no stiff case \"{case}…\""));
        c.number(what)
            .unwrap_or_else(|| panic!("{case}: no number \"{what}\" in {:?}", c.numbers))
    };
    let pi = std::f64::consts::PI;
    // A point light of intensity 1 at height d over a floor of albedo 0.5,
    // seen straight down: 0.5/π · 1/d²; at d = 1e-30 that overflows, and
    // the light must be refused (0), not infinite.
    let near = number("point light", "at 1e-3");
    let want = 0.5 / pi / 1e-6;
    assert!((near - want).abs() < 1e-2 * want, "{near} against {want}");
    assert_eq!(number("point light", "at 1e-30"), 0.0);
    // Light and view 1e-7 from the horizon: almost nothing, and finite.
    let l = number("grazing", "L");
    assert!((0.0..1e-6).contains(&l), "{l}");
    assert_eq!(number("grazing", "bad f or pdf"), 0.0);
    // Lobes of exponent 1e4: energy-conserving (albedo at most 1, to the
    // noise of 4,096 samples), and the Lambertian's 1 among them.
    let albedo = number("glossy", "largest albedo");
    assert!((0.95..=1.001).contains(&albedo), "{albedo}");
    assert_eq!(number("glossy", "bad samples"), 0.0);
    // u at 0 and just below 1: samples kept, none of them broken.
    assert!(number("u = 0", "kept") > 0.0);
    assert_eq!(number("u = 0", "bad"), 0.0);
    // A 1e-4 m square light of radiance 1e8 one unit above the floor:
    // E = Le·A/d² = 1, so 0.5/π reflected, by light sampling and by MIS.
    for what in ["light", "MIS"] {
        let got = number("tiny area light", what);
        let want = 0.5 / pi * 1e8 * 1e-8;
        assert!(
            (got - want).abs() < 0.02 * want,
            "{what}: {got} against {want}"
        );
    }
    assert_eq!(number("tiny area light", "all finite"), 1.0);
    // Lights in the floor's plane and facing away give exactly nothing.
    assert_eq!(number("lights in the surface", "point light"), 0.0);
    assert_eq!(number("lights in the surface", "all finite"), 1.0);
    assert_eq!(number("back-facing", "largest"), 0.0);
    assert_eq!(number("back-facing", "all finite"), 1.0);
    // Moved or scaled scenes: the same random numbers, so only rounding
    // differs; every region within 2 % of the mean region.
    let dev = number("the Cornell box and", "largest region deviation");
    assert!(dev < 0.02, "{dev}");
    assert_eq!(caught(&cases), 0);
}

#[test]
fn the_study_errors_fall_as_one_over_root_n() {
    let et = error_against_time(&Study {
        counts: vec![16, 256],
        repeats: 24,
    });
    // Two problems by four strategies, and light sampling and MIS by solid
    // angle on the area problem, at two counts each.
    assert_eq!(et.rows.len(), (2 * 4 + 2) * 2);
    for pair in et.rows.chunks(2) {
        // 16× the samples: error / 4, within the noise of 24 repeats.
        let ratio = pair[0].error / pair[1].error;
        assert!(
            (2.5..6.5).contains(&ratio),
            "{}: {} → {} (ratio {ratio})",
            pair[0].series,
            pair[0].error,
            pair[1].error
        );
    }
    // Light sampling beats uniform sampling on the area light.
    let err = |s: &str| et.rows.iter().find(|r| r.series == s).unwrap().error;
    assert!(err("area: light") < 0.3 * err("area: uniform"));
    assert!(err("area: mis") < 0.3 * err("area: uniform"));
}

#[test]
fn the_same_bytes_on_one_and_two_threads() {
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| render(&DEFAULT, scene("brdf-row", 40, 16), 2).0)
    };
    let (a, b) = (run(1), run(2));
    assert_eq!(a.to_srgb8(), b.to_srgb8());
    assert_eq!(a.pixels, b.pixels);
}

#[test]
fn mirrors_recurse_a_bounded_number_of_times() {
    // Two mirrors facing each other, the camera between them.
    let text = r#"
[camera]
eye = [0, 0, 0]
target = [0, 0, -1]
width = 4
height = 4
fov = 10
[[materials]]
name = "m"
type = "mirror"
[[objects]]
shape = "rectangle"
size = [100, 100]
translate = [0, 0, -1]
material = "m"
[[objects]]
shape = "rectangle"
size = [100, 100]
rotate = { axis = [1, 0, 0], degrees = 180 }
translate = [0, 0, 1]
material = "m"
[[lights]]
type = "point"
position = [0, 0, 0]
intensity = [1, 1, 1]
"#;
    let s = Scene::from_text(text, "mirrors").unwrap();
    for bounces in [0u32, 3] {
        let stage = Reflection {
            strategy: Strategy::Mis,
            max_mirror_bounces: bounces,
        };
        let (film, r) = render(&stage, s.clone(), 1);
        let rays = r.facts.iter().find(|(k, _)| k == "rays").unwrap().1.clone();
        assert!(
            rays.ends_with(&format!("{} mirror bounces", 16 * bounces)),
            "{rays}"
        );
        assert!(film.pixels.iter().all(|p| p.is_finite()));
    }
}

/// The report without the lines that change from machine to machine.
fn stable_text(r: &Report) -> String {
    // The BVH's build time sits inside a "built" item: cut it out before
    // the report is laid out (a wrapped line would carry it on).
    let mut r = r.clone();
    for item in &mut r.built {
        if let Some(i) = item.find(", built with the lights in") {
            let end = item[i..].find(')').map_or(item.len(), |j| i + j);
            item.replace_range(i..end, "");
        }
    }
    r.to_text(Times::Hide)
        .lines()
        .filter(|l| !l.contains("render time") && !l.contains("  scene: "))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn snapshot_report_and_images() {
    let (film, report) = render(&DEFAULT, scene("lambert-sphere", 32, 32), 2);
    insta::assert_snapshot!("lambert_sphere_report", stable_text(&report));
    insta::assert_snapshot!("lambert_sphere_blocks", summary(&film, 8));
    let (film, report) = render(&DEFAULT, scene("brdf-row", 64, 24), 4);
    insta::assert_snapshot!("brdf_row_report", stable_text(&report));
    insta::assert_snapshot!("brdf_row_blocks", summary(&film, 8));
}

#[test]
fn the_lambert_sphere_is_brightest_facing_the_light_and_dark_beyond_the_terminator() {
    // Light from (1, 1, 1)/√3: the upper-right of the sphere faces it.
    let (film, _) = render(&DEFAULT, scene("lambert-sphere", 32, 32), 1);
    let lit = film.get(20, 11).x;
    let dark = film.get(8, 24).x;
    let want = 0.8 / std::f32::consts::PI * 3.0;
    assert!(
        lit > 0.7 * want && lit <= want * 1.001,
        "{lit} vs at most {want}"
    );
    assert!(dark < 0.1 * lit, "{dark}");
}
