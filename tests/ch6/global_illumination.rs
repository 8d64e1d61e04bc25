//! Chapter 6 against known answers: closed and open furnaces (bounce layers
//! by z-tests with the estimated variance), every estimator and sampler
//! agreeing, the Cornell box against its stored reference (region z-test),
//! glass, the stiff cases, NaN/Inf, determinism across threads, the
//! report's built/left-out lists and the stage boundary the TUI uses.

use std::sync::Arc;

use glam::Vec3;
use raystep::ch6_global_illumination::accumulate::{downsample, Accumulator};
use raystep::ch6_global_illumination::integrator::{PathSettings, Strategy};
use raystep::ch6_global_illumination::layers::{LAYER_SLOTS, RENDER_LAYERS, SLOT_BEYOND};
use raystep::ch6_global_illumination::reference::{region_z_test, StoredReference};
use raystep::ch6_global_illumination::sampler::SamplerKind;
use raystep::ch6_global_illumination::scenes;
use raystep::ch6_global_illumination::stability::{self, centre_block, flat_z};
use raystep::ch6_global_illumination::stage::DEFAULT;
use raystep::ch6_global_illumination::studies::{self, render};
use raystep::core::stage::{Chapter, Settings};
use raystep::scene::{LightSampling, Scene};

const Z: f64 = 4.0;

fn unlimited(strategy: Strategy) -> PathSettings {
    PathSettings {
        strategy,
        max_bounces: None,
        ..PathSettings::default()
    }
}

fn closed_furnace_layers(rho: f64) {
    let le = 0.5;
    let scene = scenes::closed_furnace(rho, le, 8);
    let (acc, _) = render(
        &scene,
        &unlimited(Strategy::Mis),
        SamplerKind::Independent,
        32,
        1,
        true,
    );
    assert_eq!(acc.stats.nonfinite, 0);
    // Layer E: the emitters seen directly, exactly Le in every pixel.
    let e = acc.layer(0).unwrap();
    assert!(e
        .pixels
        .iter()
        .all(|p| (*p - Vec3::splat(le as f32)).abs().max_element() < 1e-6));
    // Layer k: Le·ρ^(k+1).
    for k in 0..6 {
        let layer = acc.layer(k + 1).unwrap();
        let want = le * rho.powi(k as i32 + 1);
        let (z, mean) = flat_z(&layer, 0, want);
        assert!(
            z.abs() < Z,
            "ρ {rho}, layer {k}: {mean} vs {want} (z = {z:.2})"
        );
    }
    // The unlimited image: Le / (1 - ρ).
    let (z, mean) = flat_z(&acc.mean(), 1, le / (1.0 - rho));
    assert!(z.abs() < Z, "ρ {rho}: {mean} (z = {z:.2})");
    // The layers add up to the image.
    let sum: Vec3 = (0..LAYER_SLOTS)
        .map(|s| acc.layer(s).unwrap().pixels[5])
        .sum();
    assert!((sum - acc.mean().pixels[5]).abs().max_element() < 1e-4 * sum.max_element());
}

#[test]
fn closed_furnace_rho_half_layers_are_le_rho_to_the_k_plus_one() {
    closed_furnace_layers(0.5);
}

#[test]
fn closed_furnace_rho_0_8_layers_are_le_rho_to_the_k_plus_one() {
    closed_furnace_layers(0.8);
}

#[test]
fn a_bounce_limit_leaves_the_beyond_layer_empty_and_cuts_exactly_there() {
    let scene = scenes::closed_furnace(0.8, 0.5, 4);
    let path = PathSettings {
        max_bounces: Some(3),
        ..PathSettings::default()
    };
    let (acc, _) = render(&scene, &path, SamplerKind::Independent, 16, 1, true);
    for slot in 5..LAYER_SLOTS {
        assert_eq!(
            raystep::ch6_global_illumination::reference::film_mean(&acc.layer(slot).unwrap()),
            Vec3::ZERO,
            "slot {slot}"
        );
    }
    let (z, _) = flat_z(&acc.layer(4).unwrap(), 0, 0.5 * 0.8f64.powi(4));
    assert!(z.abs() < Z, "{z}");
    // Unlimited: light beyond 16 bounces lands in the last layer.
    let (acc, _) = render(
        &scene,
        &unlimited(Strategy::Mis),
        SamplerKind::Independent,
        16,
        1,
        true,
    );
    let beyond = 0.5 * 0.8f64.powi(18) / (1.0 - 0.8);
    let (z, _) = flat_z(&acc.layer(SLOT_BEYOND).unwrap(), 0, beyond);
    assert!(z.abs() < Z, "{z}");
}

#[test]
fn open_furnace_sphere_pixels_are_rho_for_any_bounce_limit() {
    let rho = 0.7;
    let scene = scenes::open_furnace(rho, 32, None);
    for (max, estimator) in [
        (Some(0), Strategy::Mis),
        (Some(1), Strategy::Light),
        (Some(16), Strategy::Bsdf),
        (None, Strategy::Mis),
    ] {
        let path = PathSettings {
            strategy: estimator,
            max_bounces: max,
            ..PathSettings::default()
        };
        let (acc, _) = render(&scene, &path, SamplerKind::Sobol, 4, 2, false);
        let (z, mean) = flat_z(&centre_block(&acc.mean(), 8), 0, rho);
        assert!(z.abs() < Z, "{max:?} {estimator:?}: {mean} (z = {z:.2})");
        // The sky around it is 1, seen directly.
        assert_eq!(acc.mean().get(0, 0), Vec3::ONE);
    }
}

#[test]
fn every_estimator_and_sampler_converges_to_the_furnace_value() {
    let scene = scenes::closed_furnace(0.8, 0.5, 8);
    for (e, s) in studies::all_variants() {
        let (acc, _) = render(&scene, &unlimited(e), s, 16, 3, false);
        let (z, mean) = flat_z(&acc.mean(), 2, 2.5);
        assert!(z.abs() < Z, "{e:?} {s:?}: {mean} (z = {z:.2})");
        assert_eq!(acc.stats.nonfinite, 0);
    }
}

#[test]
fn roulette_at_any_scale_converges_to_the_furnace_value() {
    // s only trades noise for time: with either sampler, at s = 1, 2 and
    // 8, the closed furnace's mean stays Le / (1 - ρ).
    let scene = scenes::closed_furnace(0.8, 0.5, 8);
    for sampler in [SamplerKind::Independent, SamplerKind::Sobol] {
        let mut rays = Vec::new();
        for s in [1, 2, 8] {
            let settings = PathSettings {
                rr_scale: Some(s),
                ..unlimited(Strategy::Mis)
            };
            let (acc, _) = render(&scene, &settings, sampler, 16, 3, false);
            let (z, mean) = flat_z(&acc.mean(), 2, 2.5);
            assert!(z.abs() < Z, "{sampler:?} s = {s}: {mean} (z = {z:.2})");
            assert_eq!(acc.stats.nonfinite, 0);
            rays.push(acc.stats.rays);
        }
        // A larger scale ends fewer paths early: more rays.
        assert!(
            rays[0] < rays[1] && rays[1] < rays[2],
            "{sampler:?}: {rays:?}"
        );
    }
}

fn cornell_reference() -> StoredReference {
    StoredReference::for_scene(&Scene::builtin())
        .expect("scenes/references holds the Cornell-box reference (see its README)")
}

#[test]
fn the_cornell_box_matches_its_reference_region_by_region_for_every_estimator() {
    let r = cornell_reference();
    // Small renders against the reference box-downsampled to their size,
    // in regions (16 regions x 3 channels, Bonferroni α = 1e-3). The
    // estimators that find the small lamp only by hitting it need many
    // samples per region, or the sample variance (a heavy tail of rare
    // hits) is underestimated.
    for (e, size, block, spp) in [
        (Strategy::Mis, 16, 4, 64),
        (Strategy::Light, 16, 4, 64),
        (Strategy::Bsdf, 8, 2, 2048),
        (Strategy::Uniform, 8, 2, 2048),
    ] {
        let reference = r.downsampled(r.mean.width / size);
        let scene = Scene::builtin().with_resolution(size, size).unwrap();
        let path = PathSettings {
            strategy: e,
            ..PathSettings::default()
        };
        let (acc, _) = render(&scene, &path, SamplerKind::Independent, spp, 11, false);
        let t = region_z_test(
            &acc.mean(),
            &acc.variance_of_mean(),
            &reference,
            block,
            1e-3,
        );
        assert!(t.passed(), "{e:?}: {t:?}");
        assert_eq!(t.regions, 16);
    }
}

#[test]
fn the_cornell_box_with_its_light_sampled_by_solid_angle_matches_its_reference() {
    // The same test with the lamp sampled by the solid angle it covers: a
    // different estimator of the same image.
    let r = cornell_reference();
    let size = 16;
    let reference = r.downsampled(r.mean.width / size);
    for e in [Strategy::Mis, Strategy::Light] {
        let scene = Scene {
            light_sampling: LightSampling::SolidAngle,
            ..Scene::builtin().with_resolution(size, size).unwrap()
        };
        let path = PathSettings {
            strategy: e,
            ..PathSettings::default()
        };
        let (acc, _) = render(&scene, &path, SamplerKind::Independent, 64, 11, false);
        let t = region_z_test(&acc.mean(), &acc.variance_of_mean(), &reference, 4, 1e-3);
        assert!(t.passed(), "{e:?}: {t:?}");
        assert_eq!(acc.stats.nonfinite, 0);
    }
}

#[test]
fn the_two_stored_references_agree() {
    // The 256x256 reference (the benchmark's per-pixel RMSE), box-filtered
    // to 64x64, against the 64x64 one, region by region with both
    // variances: two independent 16k-spp renders of the same image.
    let small = cornell_reference();
    let large = StoredReference::for_scene_at(&Scene::builtin(), 256, 256)
        .expect("scenes/references holds the 256x256 Cornell-box reference");
    let t = region_z_test(
        &small.mean,
        &small.var_of_mean,
        &large.downsampled(4),
        4,
        1e-3,
    );
    assert!(t.passed(), "{t:?}");
    assert_eq!(t.regions, 256);
    // No reference of a size that was never made.
    assert!(StoredReference::for_scene_at(&Scene::builtin(), 128, 128).is_none());
}

#[test]
fn a_wrong_renderer_fails_the_region_test() {
    // The test has power: 10% too much light is caught.
    let r = cornell_reference();
    let size = 16;
    let r16 = r.downsampled(r.mean.width / size);
    let scene = Scene::builtin().with_resolution(size, size).unwrap();
    let (acc, _) = render(
        &scene,
        &PathSettings::default(),
        SamplerKind::Independent,
        64,
        11,
        false,
    );
    let mut brighter = acc.mean();
    brighter.pixels.iter_mut().for_each(|p| *p *= 1.1);
    let t = region_z_test(&brighter, &acc.variance_of_mean(), &r16, 4, 1e-3);
    assert!(!t.passed(), "{t:?}");
}

/// The stiff cases, judged here on the numbers they measured (not on the
/// verdict the report row computes): each mean within 4 standard errors
/// of a value worked out in this test, plus 1e-4 relative for f32
/// rounding (an estimator with no variance has a standard error of 0),
/// and no NaN or Inf anywhere.
#[test]
fn the_stiff_cases_come_out_as_expected() {
    let near = |m: stability::Measured, want: f64, what: &str| {
        let allowed = Z * m.standard_error + 1e-4 * want.abs();
        assert!(
            (m.mean - want).abs() <= allowed && m.nonfinite == 0,
            "{what}: measured {m:?}, expected {want} ± {allowed}"
        );
    };
    // A closed furnace of albedo ρ lit by Le everywhere: Le / (1 - ρ).
    let (_, m, _, _) = stability::furnace_0999(4, 8);
    near(m, 1e-3 / (1.0 - 0.999), "closed furnace ρ = 0.999");
    assert!((m.mean - 1.0).abs() < 0.2, "{m:?}");
    // Under a square light of side s and radiance Le one unit above a
    // floor of albedo 0.5: 0.5/π · Le ∫∫ dx dy / (1 + x² + y²)² over the
    // square, summed here on a 64 x 64 midpoint grid.
    let (side, le, k) = (0.01f64, 1e4, 64);
    let cell = side / k as f64;
    let irradiance: f64 = (0..k * k)
        .map(|i| {
            let x = -side / 2.0 + cell * ((i % k) as f64 + 0.5);
            let y = -side / 2.0 + cell * ((i / k) as f64 + 0.5);
            le * cell * cell / (1.0 + x * x + y * y).powi(2)
        })
        .sum();
    let (_, m) = stability::tiny_light(4, 32);
    near(
        m,
        0.5 / std::f64::consts::PI * irradiance,
        "tiny bright light, MIS",
    );
    // Glass of η = 1.5: along the cube's diagonal every internal ray is
    // totally reflected, nothing gets out; along an axis the radiance
    // inside is η² times the sky's 1.
    let (_, trapped, m) = stability::total_internal_reflection(4, 8);
    assert_eq!(trapped, 0.0);
    near(m, 1.5 * 1.5, "glass cube along an axis");
    // Glass of index 1 is not there: the open furnace's sphere shows ρ.
    let (_, m) = stability::index_matched_glass(32, 8);
    near(m, 0.6, "index-matched glass");
    // Inside a glass sphere under a sky of 1: η².
    let (_, m) = stability::camera_inside_glass(8, 8);
    near(m, 1.5 * 1.5, "camera inside glass");
}

#[test]
fn index_one_glass_leaves_the_image_unchanged_statistically() {
    let (a, _) = render(
        &scenes::open_furnace(0.6, 16, None),
        &PathSettings::default(),
        SamplerKind::Independent,
        16,
        1,
        false,
    );
    let (b, _) = render(
        &scenes::open_furnace(0.6, 16, Some(1.0)),
        &PathSettings::default(),
        SamplerKind::Independent,
        16,
        1,
        false,
    );
    let r = StoredReference {
        mean: a.mean(),
        var_of_mean: a.variance_of_mean(),
        meta: String::new(),
    };
    let t = region_z_test(&b.mean(), &b.variance_of_mean(), &r, 4, 1e-3);
    assert!(t.passed(), "{t:?}");
    // And a real glass shell is not invisible.
    let (c, _) = render(
        &scenes::open_furnace(0.6, 16, Some(1.5)),
        &PathSettings::default(),
        SamplerKind::Independent,
        16,
        1,
        false,
    );
    let t = region_z_test(&c.mean(), &c.variance_of_mean(), &r, 4, 1e-3);
    assert!(!t.passed(), "{t:?}");
}

#[test]
fn same_bytes_on_one_and_two_threads() {
    let scene = Scene::builtin().with_resolution(12, 12).unwrap();
    let run = |threads: usize, sampler, layers| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| render(&scene, &PathSettings::default(), sampler, 4, 5, layers).0)
    };
    let samplers = [SamplerKind::Independent, SamplerKind::Sobol];
    for (sampler, layers) in samplers.into_iter().flat_map(|s| [(s, true), (s, false)]) {
        let (a, b): (Accumulator, Accumulator) = (run(1, sampler, layers), run(2, sampler, layers));
        assert_eq!(a.sum, b.sum);
        assert_eq!(a.sum_sq, b.sum_sq);
        assert_eq!(a.layers, b.layers);
        assert_eq!(a.stats, b.stats);
    }
}

#[test]
fn the_stage_reports_what_it_built_and_left_out() {
    let settings = Settings {
        spp: 2,
        ..Settings::default()
    };
    let cornell = Arc::new(Scene::builtin().with_resolution(16, 16).unwrap());
    // Chapter 6 as the front ends list it: with the fast engine.
    let ch6 = raystep::chapters::all()[5];
    let mut r = ch6.start(cornell, &settings).unwrap();
    while !r.pass().complete {}
    let rep = r.report();
    let built = rep.built.join("\n");
    let left = rep.left_out.join("\n");
    assert!(built.contains("8 wide ("), "{built}");
    assert!(built.contains("wavefront loop"), "{built}");
    assert!(built.contains("over 36 triangles"), "{built}");
    assert!(built.contains("light sampling over 1 light"), "{built}");
    assert!(!built.contains("1 lights"), "{built}");
    assert!(built.contains("per-bounce layers"), "{built}");
    assert!(left.contains("no glass"), "{left}");
    assert!(left.contains("no SDFs"), "{left}");
    assert_eq!(rep.nonfinite_caught, 0);

    // The lamp sampled by solid angle: the report says so, and that the
    // wavefront's lanes, which sample by area, leave every hit to the
    // lesson's steps.
    let by_solid_angle = Scene {
        light_sampling: LightSampling::SolidAngle,
        ..Scene::builtin().with_resolution(16, 16).unwrap()
    };
    let mut r = ch6.start(Arc::new(by_solid_angle), &settings).unwrap();
    while !r.pass().complete {}
    let text = r.report().to_text(raystep::core::report::Times::Hide);
    assert!(text.contains("area lights by solid angle"), "{text}");
    let words = text.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        words.contains("every hit shaded by the lesson's steps"),
        "{text}"
    );

    // Only the final image, a scene lit by the sky alone, with glass.
    let mut stage = DEFAULT;
    stage.layers = false;
    let mut r = stage
        .start(Arc::new(scenes::open_furnace(0.5, 8, Some(1.5))), &settings)
        .unwrap();
    while !r.pass().complete {}
    assert!(r.snapshot().layers.is_none());
    let rep = r.report();
    assert!(rep.left_out.join("\n").contains("only the final image"));
    assert!(rep
        .built
        .join("\n")
        .contains("environment sampled by cosine"));
    assert!(rep.built.join("\n").contains("dielectric"));

    // The random walk samples no lights.
    let mut r = stage
        .with_variant(0)
        .start(Arc::new(scenes::open_furnace(0.5, 8, None)), &settings)
        .unwrap();
    while !r.pass().complete {}
    assert!(r
        .report()
        .left_out
        .join("\n")
        .contains("does not sample lights"));
}

#[test]
fn the_stage_boundary_gives_layers_that_sum_to_the_image_and_an_error_series() {
    let ch = raystep::chapters::all()
        .into_iter()
        .find(|c| c.info().number == 6)
        .expect("chapter 6 is registered");
    assert!(ch.info().bounces && ch.info().radiance);
    assert_eq!(ch.info().variants.len(), 8);
    let r = cornell_reference();
    let scene = Arc::new(
        Scene::builtin()
            .with_resolution(r.mean.width, r.mean.height)
            .unwrap(),
    );
    let settings = Settings {
        spp: 2,
        variant: Some(7),
        ..Settings::default()
    };
    let mut render = ch.start(scene, &settings).unwrap();
    let mut passes = 0;
    while !render.pass().complete {
        passes += 1;
    }
    assert_eq!(passes, 1, "2 spp: the first passes take 1 and 1 spp");
    let snap = render.snapshot();
    assert_eq!(snap.pass.samples, 2);
    assert_eq!((snap.pass.done, snap.pass.planned), (2, 2));
    let layers = snap.layers.clone().unwrap();
    assert_eq!(layers.len(), RENDER_LAYERS);
    let image = snap.views[0].clone();
    let i = image.pixels.len() / 2 + 7;
    let sum: Vec3 = layers.iter().map(|l| l.pixels[i]).sum();
    assert!((sum - image.pixels[i]).abs().max_element() < 1e-4);
    let series = snap.error_series.clone();
    assert_eq!(series.len(), 2, "one point per pass");
    assert!(series[0].1 > 0.0 && series[0].1 < 1.0, "{series:?}");
    assert_eq!(snap.reference.unwrap().width, image.width);
    // Downsampling keeps the mean.
    let d = downsample(&image, 2);
    let m = |f: &raystep::core::film::Film| f.pixels.iter().sum::<Vec3>() / f.pixels.len() as f32;
    assert!((m(&d) - m(&image)).abs().max_element() < 1e-4);
}

#[test]
fn the_image_does_not_depend_on_how_samples_are_split_into_passes() {
    let scene = Arc::new(Scene::builtin().with_resolution(16, 16).unwrap());
    let settings = Settings {
        spp: 8,
        ..Settings::default()
    };
    let image = |per_pass: u32| {
        let mut stage = DEFAULT;
        stage.spp_per_pass = per_pass;
        let mut r = stage.start(scene.clone(), &settings).unwrap();
        while !r.pass().complete {}
        assert_eq!(r.snapshot().pass.samples, 8);
        r.snapshot().views[0].clone()
    };
    let (a, b) = (image(4), image(1));
    assert_eq!(
        a.pixels, b.pixels,
        "same bytes for passes of 1, 1, 2, 4 and of 1 each"
    );
}
