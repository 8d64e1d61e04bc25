//! The report's studies: error against time for every estimator and both
//! samplers (Cornell box against the stored reference, closed furnace
//! against its analytic value), and the stiff cases.

use std::time::Instant;

use glam::Vec3;

use crate::ch5_reflection::world::World;
use crate::core::film::Film;
use crate::core::report::{
    format_number, format_seconds, ErrorTime, Measurement, Report, StabilityCase, Table,
};
use crate::core::stage::Settings;
use crate::scene::Scene;

use super::accumulate::Accumulator;
use super::integrator::{Estimator, PathSettings};
use super::reference::{film_mean, z_score, StoredReference};
use super::sampler::SamplerKind;
use super::scenes;

/// Renders `spp` samples per pixel of `scene` in one go: (sums, seconds).
pub fn render(
    scene: &Scene,
    path: &PathSettings,
    sampler: SamplerKind,
    spp: u32,
    seed: u64,
    layers: bool,
) -> (Accumulator, f64) {
    let world = World::new(scene);
    let mut acc = Accumulator::new(scene.camera.width, scene.camera.height, layers);
    let t = Instant::now();
    acc.add_samples(&world, &scene.camera, path, sampler, seed, spp);
    (acc, t.elapsed().as_secs_f64())
}

/// Every pixel's mean against one expected value: (z of the mean over
/// pixels, using the spread of the pixel means, and the mean itself).
/// Valid where every pixel has the same expectation (the furnaces).
pub fn flat_z(film: &Film, channel: usize, expected: f64) -> (f64, f64) {
    let vals: Vec<f64> = film.pixels.iter().map(|p| p[channel] as f64).collect();
    let n = vals.len() as f64;
    let sum: f64 = vals.iter().sum();
    let sum_sq: f64 = vals.iter().map(|v| v * v).sum();
    (z_score(sum, sum_sq, n, expected), sum / n)
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
    let world = World::new(scene);
    let mut acc = Accumulator::new(scene.camera.width, scene.camera.height, false);
    let mut seconds = 0.0;
    let mut spp = 1;
    while spp <= max_spp {
        let t = Instant::now();
        acc.add_samples(&world, &scene.camera, path, sampler, 7, spp - acc.samples);
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
pub fn all_variants() -> Vec<(Estimator, SamplerKind)> {
    Estimator::ALL
        .into_iter()
        .flat_map(|e| [(e, SamplerKind::Independent), (e, SamplerKind::Sobol)])
        .collect()
}

/// The error-against-time study. Cornell box (if the reference is
/// stored): rendered at the reference's resolution, `max_spp` doubling,
/// RMSE against the reference. Closed furnace (ρ = 0.8, Le = 0.5, 32x32,
/// unlimited bounces): RMSE against Le/(1 - ρ) = 2.5.
pub fn error_vs_time(max_spp: u32) -> ErrorTime {
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
                estimator: e,
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
            estimator: e,
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
/// against log time of one series: t = (e / a)^(1/slope). `None` when the
/// series has no negative slope.
pub fn time_to_error(et: &ErrorTime, series: &str, target: f64) -> Option<(f64, bool)> {
    let pts: Vec<(f64, f64)> = et
        .rows
        .iter()
        .filter(|r| r.series == series && r.error > 0.0 && r.seconds > 0.0)
        .map(|r| (r.seconds.ln(), r.error.ln()))
        .collect();
    let slope = crate::core::report::log_log_slope(&pts)?;
    if slope >= 0.0 {
        return None;
    }
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let t = ((target.ln() - my) / slope + mx).exp();
    let max_t = pts.iter().map(|p| p.0).fold(f64::MIN, f64::max).exp();
    Some((t, t > max_t))
}

/// The strategy table: per series the last row's RMSE and efficiency, the
/// slope, and the time to RMSE 0.02 and 0.01.
pub fn strategy_table(et: &ErrorTime) -> Table {
    let mut t = Table::new(
        "Strategies: efficiency and time to reach an RMSE (fitted on log-log axes; * = extrapolated)",
        &[
            "series",
            "spp",
            "time",
            "RMSE",
            "1/(MSE·time)",
            "slope",
            "t(RMSE 0.02)",
            "t(RMSE 0.01)",
        ],
    );
    for s in et.series() {
        let Some(last) = et.rows.iter().rev().find(|r| r.series == s) else {
            continue;
        };
        let fmt = |x: Option<(f64, bool)>| match x {
            Some((t, extra)) => format!("{}{}", format_seconds(t), if extra { "*" } else { "" }),
            None => "-".into(),
        };
        t.row(vec![
            s.clone(),
            last.variant.clone(),
            format_seconds(last.seconds),
            format_number(last.error),
            format_number(last.efficiency()),
            et.slope(&s).map_or("-".into(), |k| format!("{k:.2}")),
            fmt(time_to_error(et, &s, 0.02)),
            fmt(time_to_error(et, &s, 0.01)),
        ]);
    }
    t
}

/// The closed furnace with ρ = 0.999, Le = 1e-3, unlimited bounces: the
/// mean must be Le/(1 - ρ) = 1 (a thousand bounces matter). Returns the
/// case, the measured mean, its z-score and seconds.
pub fn furnace_0999(size: u32, spp: u32) -> (StabilityCase, f64, f64, f64) {
    let scene = scenes::closed_furnace(0.999, 1e-3, size);
    let path = PathSettings {
        max_bounces: None,
        ..PathSettings::default()
    };
    let (acc, secs) = render(&scene, &path, SamplerKind::Independent, spp, 3, false);
    let (z, mean) = flat_z(&acc.mean(), 0, 1.0);
    let ok = z.abs() < 4.0 && acc.stats.nonfinite == 0;
    (
        StabilityCase::new(
            "closed furnace ρ = 0.999, unlimited bounces",
            "mean = 1000·Le = 1 (|z| < 4): Russian roulette stays unbiased over ~1000 bounces",
            format!(
                "mean {} (z = {:.2}) in {} over {} paths, {} rays; {} cut",
                format_number(mean),
                z,
                format_seconds(secs),
                acc.stats.paths,
                acc.stats.rays,
                acc.stats.cut
            ),
            ok,
        ),
        mean,
        z,
        secs,
    )
}

/// A tiny (side 0.01), very bright (Le = 1e4) light over a floor: the
/// pixels under it against 0.5/π · Le · side² for MIS; BSDF sampling alone
/// for contrast (it finds the light with probability ~3e-5 per sample, so
/// its estimate is mostly 0 with rare huge values: unbiased, useless).
/// Reports each one's mean, sample variance and largest pixel. No
/// clamping. Returns the case and MIS's z.
pub fn tiny_light(size: u32, spp: u32) -> (StabilityCase, f64) {
    let scene = scenes::tiny_light(0.01, 1e4, size);
    let side: f64 = 0.01;
    let expected = 0.5 / std::f64::consts::PI * 1e4 * side * side * (1.0 - side * side / 3.0);
    let mut measured = Vec::new();
    let mut ok = true;
    let mut z_mis = f64::INFINITY;
    for e in [Estimator::Mis, Estimator::BsdfSampling] {
        let path = PathSettings {
            estimator: e,
            ..PathSettings::default()
        };
        let (acc, _) = render(&scene, &path, SamplerKind::Independent, spp, 5, false);
        let (s, q) = acc
            .sum
            .iter()
            .zip(&acc.sum_sq)
            .fold((0.0, 0.0), |(s, q), (a, b)| {
                (s + a.x as f64, q + b.x as f64)
            });
        let n = (spp as usize * acc.sum.len()) as f64;
        let z = z_score(s, q, n, expected);
        let var = ((q - s * s / n) / (n - 1.0)).max(0.0);
        let mean = acc.mean();
        let max = mean
            .pixels
            .iter()
            .map(|p| p.max_element())
            .fold(0.0f32, f32::max);
        ok &= acc.stats.nonfinite == 0 && mean.pixels.iter().all(|p| p.is_finite());
        if e == Estimator::Mis {
            ok &= z.abs() < 4.0;
            z_mis = z;
        }
        // With no sample reaching the light there is no variance to
        // scale by, so no z to print.
        let z_text = if var > 0.0 {
            format!("z = {z:.1}")
        } else {
            "no sample reached the light: no z".into()
        };
        measured.push(format!(
            "{}: mean {} ({z_text}), sample variance {}, largest pixel {}",
            e.name(),
            format_number(s / n),
            format_number(var),
            format_number(max as f64)
        ));
    }
    (
        StabilityCase::new(
            "tiny very bright light (side 0.01, Le = 1e4), no clamping",
            "MIS = 0.5/π·Le·side² = 0.159 (|z| < 4) and everything finite",
            measured.join("; "),
            ok,
        ),
        z_mis,
    )
}

/// Total internal reflection inside a glass cube: along the diagonal
/// everything is reflected forever (exactly 0); along an axis η² = 2.25.
pub fn total_internal_reflection(size: u32, spp: u32) -> (StabilityCase, f64, f64) {
    let path = PathSettings::default();
    let diag = scenes::glass_cube([1.0, 1.0, -1.0], size);
    let (acc, _) = render(&diag, &path, SamplerKind::Independent, spp, 9, false);
    let trapped = film_mean(&acc.mean()).max_element() as f64;
    let axis = scenes::glass_cube([0.0, 0.0, -1.0], size);
    let (acc2, _) = render(&axis, &path, SamplerKind::Independent, spp, 9, false);
    let (z, mean) = flat_z(&acc2.mean(), 0, 2.25 * (1.0 - 0.04f64.powi(17)));
    let ok = trapped == 0.0 && z.abs() < 4.0;
    (
        StabilityCase::new(
            "total internal reflection in a glass cube (η = 1.5)",
            "along the diagonal exactly 0 (trapped); along an axis η² = 2.25 (|z| < 4)",
            format!(
                "diagonal {trapped}; axis {} (z = {z:.2})",
                format_number(mean)
            ),
            ok,
        ),
        trapped,
        z,
    )
}

/// Glass of index 1 around the open furnace's sphere changes nothing: the
/// sphere's pixels stay ρ.
pub fn index_matched_glass(size: u32, spp: u32) -> (StabilityCase, f64) {
    let rho = 0.6;
    let scene = scenes::open_furnace(rho, size, Some(1.0));
    let (acc, _) = render(
        &scene,
        &PathSettings::default(),
        SamplerKind::Independent,
        spp,
        4,
        false,
    );
    let centre = centre_block(&acc.mean(), size / 4);
    flat_case(
        "glass of index 1.0 around the open furnace",
        "invisible: the sphere's pixels stay ρ = 0.6 (|z| < 4)",
        &acc,
        flat_z(&centre, 0, rho),
    )
}

/// A camera at the centre of a glass sphere under a sky of 1 sees η².
pub fn camera_inside_glass(size: u32, spp: u32) -> (StabilityCase, f64) {
    let scene = scenes::inside_glass(1.5, size);
    let (acc, _) = render(
        &scene,
        &PathSettings::default(),
        SamplerKind::Independent,
        spp,
        2,
        false,
    );
    let expected = 2.25 * (1.0 - 0.04f64.powi(17));
    flat_case(
        "camera inside glass (centre of a sphere, η = 1.5)",
        "every pixel η² = 2.25 (|z| < 4)",
        &acc,
        flat_z(&acc.mean(), 1, expected),
    )
}

/// A case whose pixels share one expected value, from [`flat_z`]'s
/// (z, mean): it holds when |z| < 4 and no NaN or Inf was caught.
/// Returns the case and z.
fn flat_case(
    name: &str,
    expected: &str,
    acc: &Accumulator,
    (z, mean): (f64, f64),
) -> (StabilityCase, f64) {
    let ok = z.abs() < 4.0 && acc.stats.nonfinite == 0;
    let measured = format!("{} (z = {z:.2})", format_number(mean));
    (StabilityCase::new(name, expected, measured, ok), z)
}

/// The middle `n` x `n` pixels of a film.
pub fn centre_block(film: &Film, n: u32) -> Film {
    let (x0, y0) = ((film.width - n) / 2, (film.height - n) / 2);
    let mut out = Film::new(n, n);
    for y in 0..n {
        for x in 0..n {
            *out.get_mut(x, y) = film.get(x0 + x, y0 + y);
        }
    }
    out
}

/// The stiff cases; `quick` runs them at the tests' small sizes.
pub fn stability_cases(quick: bool) -> Vec<StabilityCase> {
    if quick {
        return vec![
            furnace_0999(4, 8).0,
            tiny_light(4, 32).0,
            total_internal_reflection(4, 8).0,
            index_matched_glass(32, 8).0,
            camera_inside_glass(8, 8).0,
        ];
    }
    vec![
        furnace_0999(8, 16).0,
        tiny_light(16, 64).0,
        total_internal_reflection(8, 16).0,
        index_matched_glass(32, 16).0,
        camera_inside_glass(16, 16).0,
    ]
}

/// Adds the studies to a report: error against time, the strategy table
/// and the stiff cases. Below 16 spp (a quick run, such as the main
/// program's tour of every chapter) they run small: 2 spp per series and
/// the tests' sizes; otherwise up to `spp` (at most 64) per series.
pub fn add_studies(report: &mut Report, settings: &Settings) {
    let quick = settings.spp < 16;
    let max_spp = if quick {
        2
    } else {
        settings.spp.min(64).next_power_of_two()
    };
    let et = error_vs_time(max_spp);
    report.tables.push(strategy_table(&et));
    report.error_vs_time = Some(et);
    report.stability = stability_cases(quick);
}
