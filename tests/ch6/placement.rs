//! Where the scene sits and how big it is must not change the picture (and
//! a scene that reflects everything is said to defeat roulette): the
//! Cornell box moved far from the origin or scaled down renders like the
//! box at the origin. Chapter 6 against the stored reference of the box
//! (region z-test, as the box at the origin is tested), chapter 5 against
//! its own render of the box at the origin with the same random numbers.
//!
//! Before shadow rays were aimed at the light's point, the box 100 units
//! up was about 10 % too dark in chapter 6 and the box scaled by 0.01
//! about 8 %: a shadow ray started at the moved-off origin kept the old
//! direction and length, and met the light's own surface.

use glam::{DVec3, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch5_reflection::direct::{Estimator, Strategy};
use raystep::ch5_reflection::render::render_pass;
use raystep::ch5_reflection::world::World;
use raystep::ch6_global_illumination::integrator::PathSettings;
use raystep::ch6_global_illumination::reference::{region_z_test, StoredReference};
use raystep::ch6_global_illumination::sampler::SamplerKind;
use raystep::ch6_global_illumination::stability;
use raystep::ch6_global_illumination::studies::render;
use raystep::scene::place::{PLACEMENTS, PLACEMENTS_REQUIRED};
use raystep::scene::Scene;

/// Placements of the box: (offset, scale), the stiff ones of the issue
/// and one on each axis.
fn placements() -> Vec<(DVec3, f64)> {
    vec![
        (DVec3::new(0.0, 100.0, 0.0), 1.0),
        (DVec3::new(1000.0, 0.0, 0.0), 1.0),
        (DVec3::new(0.0, 0.0, -1.0e4), 1.0),
        (DVec3::ZERO, 1.0e-2),
        (DVec3::ZERO, 1.0e-3),
        (DVec3::new(-30.0, 20.0, 10.0), 1.0e3),
    ]
}

#[test]
fn the_moved_or_scaled_cornell_box_matches_the_reference_in_chapter_6() {
    let stored = StoredReference::for_scene(&Scene::builtin()).expect("the Cornell reference");
    let reference = stored.downsampled(stored.mean.width / 16);
    let path = PathSettings {
        strategy: Strategy::Mis,
        ..PathSettings::default()
    };
    for (offset, scale) in placements() {
        let scene = Scene::builtin()
            .with_resolution(16, 16)
            .unwrap()
            .placed(offset, scale);
        let (acc, _) = render(&scene, &path, SamplerKind::Independent, 64, 11, false);
        let t = region_z_test(&acc.mean(), &acc.variance_of_mean(), &reference, 4, 1e-3);
        let mean = |f: &[Vec3]| f.iter().copied().sum::<Vec3>() / f.len() as f32;
        assert!(
            t.passed(),
            "offset {offset}, scale {scale}: {t:?}; mean {} against {}",
            mean(&acc.mean().pixels),
            mean(&reference.mean.pixels)
        );
    }
}

#[test]
fn the_moved_or_scaled_cornell_box_renders_the_same_in_chapter_5() {
    let render5 = |scene: &Scene| {
        let world = World::new(scene);
        let camera = Camera::of(scene);
        let est = Estimator {
            strategy: Strategy::Mis,
            max_mirror_bounces: 4,
            trace_light_rays: true,
        };
        let n = (camera.width * camera.height) as usize;
        let (mut sums, mut caught) = (vec![Vec3::ZERO; n], vec![0; n]);
        for sample in 0..16 {
            render_pass(
                &world,
                &camera,
                &est,
                5,
                sample,
                0..camera.height,
                &mut sums,
                &mut caught,
            );
        }
        assert!(
            caught.iter().all(|&c| c == 0),
            "a sample was NaN or infinite"
        );
        sums
    };
    let at_origin = render5(&Scene::builtin().with_resolution(24, 24).unwrap());
    let total = |s: &[Vec3]| s.iter().map(|p| p.element_sum() as f64).sum::<f64>();
    for (offset, scale) in placements() {
        let scene = Scene::builtin()
            .with_resolution(24, 24)
            .unwrap()
            .placed(offset, scale);
        let moved = render5(&scene);
        // The same random numbers draw the same camera rays and light
        // points: what differs is rounding, and the rare sample whose
        // shadow ray grazes an edge. Measured at the fix: under 0.1 %
        // overall; the bug made it 2.6 % (100 units) and 1.2 % (0.01).
        let rel = (total(&moved) / total(&at_origin) - 1.0).abs();
        assert!(rel < 0.005, "offset {offset}, scale {scale}: {rel:.4}");
        // The floor, in the bottom third of the picture, was the worst.
        let floor = |s: &[Vec3]| total(&s[s.len() * 2 / 3..]);
        let rel = (floor(&moved) / floor(&at_origin) - 1.0).abs();
        assert!(rel < 0.01, "offset {offset}, scale {scale}: floor {rel:.4}");
    }
}

/// A placement row says its worst deviation (`what`) and names any
/// placement not required (none since tiny scenes are scaled up, issue
/// 48). (Whether it passed is judged by each caller on the number itself,
/// not on the row's `ok`.)
fn says_its_worst_and_where_f32_runs_out(case: &raystep::core::report::StabilityCase, what: &str) {
    assert!(case.measured.contains(what), "{}", case.measured);
    for (label, _, _) in &PLACEMENTS[PLACEMENTS_REQUIRED..] {
        assert!(
            case.measured.contains(&format!("{label}: ")),
            "{}",
            case.measured
        );
    }
}

#[test]
fn the_report_says_where_f32_runs_out() {
    let (case, worst_z) = stability::placement(16, 16);
    assert!(worst_z > 0.0 && worst_z < 5.0, "{worst_z}");
    says_its_worst_and_where_f32_runs_out(&case, "largest deviation of the mean");
}

/// A scene that reflects everything is named as such before chapter 6
/// spends the safety limit on every path (it used to run at about 20
/// paths/s without a word).
#[test]
fn a_scene_that_reflects_everything_is_said_to_defeat_roulette() {
    use raystep::ch6_global_illumination::integrator::roulette_cannot_end;
    use raystep::ch6_global_illumination::scenes;
    assert!(roulette_cannot_end(&scenes::closed_furnace(1.0, 0.5, 4)));
    assert!(!roulette_cannot_end(&scenes::closed_furnace(0.99, 0.5, 4)));
    assert!(!roulette_cannot_end(&Scene::builtin()));
    let dir = crate::common::temp_dir("lossless");
    let file = dir.join("white.toml");
    std::fs::write(
        &file,
        "[[materials]]\nname = \"white\"\nreflectance = [1, 1, 1]\n\n[[objects]]\nshape = \"box\"\nmaterial = \"white\"\n",
    )
    .unwrap();
    // Warned before anything renders (this scene has no light, so the
    // run then stops): with --unlimited, and with a bounce limit at or
    // past the safety limit, which is the same as none.
    let warning = |limit: &[&str], out: &str| {
        let run = std::process::Command::new(env!("CARGO_BIN_EXE_ch6"))
            .args(limit)
            .args([
                "--spp",
                "1",
                "--width",
                "4",
                "--height",
                "4",
                "--final-only",
                "--scene",
            ])
            .arg(&file)
            .arg("--out")
            .arg(dir.join(out))
            .output()
            .unwrap();
        String::from_utf8_lossy(&run.stderr).into_owned()
    };
    for (limit, out) in [
        (&["--unlimited"][..], "out"),
        (&["--max-bounces", "4294967295"][..], "out2"),
    ] {
        let err = warning(limit, out);
        assert!(
            err.contains("roulette cannot end these paths"),
            "{limit:?}: {err}"
        );
    }
}

#[test]
fn chapter_5s_report_prints_the_worst_placement() {
    let row = raystep::ch5_reflection::stability::placement();
    // Every region within 2 % of the mean region of the render at the origin.
    let dev = row.number("largest region deviation").expect("the number");
    assert!(dev < 0.02, "{dev}");
    says_its_worst_and_where_f32_runs_out(&row.case, "largest region deviation");
}
