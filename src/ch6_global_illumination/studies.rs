//! Error against run time for chapter 6 (requirement 1): every estimator
//! with both samplers, on the Cornell box against the stored reference and
//! on a closed furnace against its analytic value; the strategy table.

use std::time::Instant;

use glam::Vec3;

use crate::ch1_projection::camera::Camera;
use crate::core::film::Film;
use crate::core::format::{format_number, format_seconds};
use crate::core::report::{ErrorTime, Measurement, Table};
use crate::scene::Scene;

use super::accumulate::Accumulator;
use super::engine::EngineChoice;
use super::integrator::{PathSettings, Strategy};
use super::reference::StoredReference;
use super::sampler::SamplerKind;
use super::scenes;

/// Renders `spp` samples per pixel of `scene` in one go with the lesson's
/// engine: (sums, seconds). The studies compare estimators and samplers
/// on this one engine, so that a difference in time is the estimator's.
pub fn render(
    scene: &Scene,
    path: &PathSettings,
    sampler: SamplerKind,
    spp: u32,
    seed: u64,
    layers: bool,
) -> (Accumulator, f64) {
    render_with(
        EngineChoice::READABLE,
        scene,
        path,
        sampler,
        (spp, seed),
        layers,
    )
}

/// [`render`] with `engine` (`spp_seed`: samples per pixel and seed); the
/// time includes building the engine's world.
pub fn render_with(
    engine: EngineChoice,
    scene: &Scene,
    path: &PathSettings,
    sampler: SamplerKind,
    (spp, seed): (u32, u64),
    layers: bool,
) -> (Accumulator, f64) {
    let t = Instant::now();
    let engine = engine.make(scene);
    let mut acc = Accumulator::new(scene.camera.width, scene.camera.height, layers);
    acc.add_samples(&*engine, &Camera::of(scene), path, sampler, seed, spp);
    (acc, t.elapsed().as_secs_f64())
}

/// One error-against-time series: `spp` doubling from 1 to `max_spp`,
/// time cumulative, error from `error_of`.
fn series(
    et: &mut ErrorTime,
    name: &str,
    scene: &Scene,
    path: &PathSettings,
    sampler: SamplerKind,
    max_spp: u32,
    error_of: &dyn Fn(&Accumulator) -> f64,
) {
    let engine = EngineChoice::READABLE.make(scene);
    let camera = Camera::of(scene);
    let mut acc = Accumulator::new(camera.width, camera.height, false);
    let mut seconds = 0.0;
    let mut spp = 1;
    while spp <= max_spp {
        let t = Instant::now();
        acc.add_samples(&*engine, &camera, path, sampler, 7, spp - acc.samples);
        seconds += t.elapsed().as_secs_f64();
        et.rows.push(Measurement {
            series: name.to_string(),
            variant: format!("{spp} spp"),
            seconds,
            samples: acc.stats.paths,
            error: error_of(&acc),
            notes: String::new(),
        });
        spp *= 2;
    }
}

/// Which estimators and samplers the study runs (all of them).
pub fn all_variants() -> Vec<(Strategy, SamplerKind)> {
    Strategy::ALL
        .into_iter()
        .flat_map(|e| [(e, SamplerKind::Independent), (e, SamplerKind::Sobol)])
        .collect()
}

/// The error-against-time study. Cornell box (if the reference is
/// stored): rendered at the reference's resolution, `max_spp` doubling,
/// RMSE against the reference. Closed furnace (ρ = 0.8, Le = 0.5, 32x32,
/// unlimited bounces): RMSE against Le/(1 - ρ) = 2.5.
pub fn error_against_time(max_spp: u32) -> ErrorTime {
    let mut et = ErrorTime {
        reference: "Cornell box: the stored 16k-spp render; furnace: Le/(1-ρ) = 2.5".into(),
        error_name: "RMSE".into(),
        rows: Vec::new(),
        show_slopes: true,
    };
    let cornell = Scene::builtin();
    if let Some(r) = StoredReference::for_scene(&cornell) {
        let scene = cornell
            .with_resolution(r.mean.width, r.mean.height)
            .expect("the reference's size is valid");
        let path = PathSettings::default();
        for (e, s) in all_variants() {
            let p = PathSettings {
                strategy: e,
                ..path
            };
            let name = format!("cornell {} {}", e.name(), s.name());
            series(&mut et, &name, &scene, &p, s, max_spp, &|acc| {
                acc.mean().rmse(&r.mean)
            });
        }
    }
    let furnace = scenes::closed_furnace(0.8, 0.5, 32);
    let expected = Film {
        pixels: vec![Vec3::splat(2.5); 32 * 32],
        ..Film::new(32, 32)
    };
    for (e, s) in all_variants() {
        let p = PathSettings {
            strategy: e,
            max_bounces: None,
            ..PathSettings::default()
        };
        let name = format!("furnace {} {}", e.name(), s.name());
        series(&mut et, &name, &furnace, &p, s, max_spp, &|acc| {
            acc.mean().rmse(&expected)
        });
    }
    et
}

/// Time to reach an RMSE, from the least-squares line of log error
/// against log time of one series ([`ErrorTime::fit`]), and whether that
/// is an extrapolation. `None` when the series has no trustworthy falling
/// fit, or the time lies over 10x outside the measured times.
pub fn time_to_error(et: &ErrorTime, series: &str, target: f64) -> Option<(f64, bool)> {
    et.fit(series)?.x_at(target)
}

/// The strategy table: per series the last row's RMSE and efficiency, the
/// slope, and the time to RMSE 0.02 and 0.01.
pub fn strategy_table(et: &ErrorTime) -> Table {
    let mut t = Table::new(
        "Strategies: efficiency, and t(x) = the time to reach RMSE x read off the log-log fit \
         (* = extrapolated, at most 10x beyond the measured times; — = no trustworthy fit, or further)",
        &[
            "series",
            "spp",
            "time",
            "RMSE",
            "1/(MSE·time)",
            "slope",
            "t(0.02)",
            "t(0.01)",
        ],
    );
    for s in et.series() {
        let Some(last) = et.rows.iter().rev().find(|r| r.series == s) else {
            continue;
        };
        let fmt = |x: Option<(f64, bool)>| match x {
            Some((t, extra)) => format!("{}{}", format_seconds(t), if extra { "*" } else { "" }),
            None => "—".into(),
        };
        t.row(vec![
            s.clone(),
            last.variant.clone(),
            format_seconds(last.seconds),
            format_number(last.error),
            format_number(last.efficiency()),
            et.slope(&s).map_or("—".into(), |k| format!("{k:.2}")),
            fmt(time_to_error(et, &s, 0.02)),
            fmt(time_to_error(et, &s, 0.01)),
        ]);
    }
    t
}
