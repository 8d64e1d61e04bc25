//! The stiff and extreme cases of chapter 6 (requirement 2): a furnace of
//! albedo 0.999, a tiny very bright light, total internal reflection,
//! index-matched glass, a camera inside glass, and the Cornell box moved
//! far from the origin or scaled.

use crate::core::film::Film;
use crate::core::format::{format_number, format_seconds};
use crate::core::report::StabilityCase;
use crate::scene::place::{PLACEMENTS, PLACEMENTS_REQUIRED};
use crate::scene::Scene;
use glam::DVec3;

use super::accumulate::Accumulator;
use super::integrator::{PathSettings, Strategy};
use super::reference::{film_mean, region_z_test, z_score, StoredReference};
use super::sampler::SamplerKind;
use super::scenes;

use super::studies::render;

/// What a stiff case measured beside its report row: the numbers its
/// verdict was made from, so that a test can judge them by thresholds of
/// its own instead of trusting the row's `ok`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    /// The mean the case is about (over its pixels, or over its samples).
    pub mean: f64,
    /// The standard error of that mean, from the spread it was measured
    /// with (not floored).
    pub standard_error: f64,
    /// NaN or infinite values met: samples the renderer caught, and
    /// pixels of the result.
    pub nonfinite: u64,
}

impl Measured {
    /// From a sum, a sum of squares and a count of values, and the
    /// non-finite count.
    fn of(sum: f64, sum_sq: f64, n: f64, nonfinite: u64) -> Measured {
        let var = ((sum_sq - sum * sum / n) / (n - 1.0)).max(0.0);
        Measured {
            mean: sum / n,
            standard_error: (var / n).sqrt(),
            nonfinite,
        }
    }

    /// The pixel means of one channel of `film` (the furnaces, where every
    /// pixel has the same expectation), with `acc`'s non-finite count.
    fn flat(film: &Film, channel: usize, acc: &Accumulator) -> Measured {
        let vals = film.pixels.iter().map(|p| p[channel] as f64);
        let (sum, sum_sq) = vals.fold((0.0, 0.0), |(s, q), v| (s + v, q + v * v));
        let bad = film.pixels.iter().filter(|p| !p.is_finite()).count() as u64;
        Measured::of(
            sum,
            sum_sq,
            film.pixels.len() as f64,
            acc.stats.nonfinite + bad,
        )
    }
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

/// The closed furnace with ρ = 0.999, Le = 1e-3, unlimited bounces: the
/// mean must be Le/(1 - ρ) = 1 (a thousand bounces matter). Returns the
/// case, what it measured, its z-score and seconds.
pub fn furnace_0999(size: u32, spp: u32) -> (StabilityCase, Measured, f64, f64) {
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
        Measured::flat(&acc.mean(), 0, &acc),
        z,
        secs,
    )
}

/// A tiny (side 0.01), very bright (Le = 1e4) light over a floor: the
/// pixels under it against 0.5/π · Le · side² for MIS; BSDF sampling alone
/// for contrast (it finds the light with probability ~3e-5 per sample, so
/// its estimate is mostly 0 with rare huge values: unbiased, useless).
/// Reports each one's mean, sample variance and largest pixel. No
/// clamping. Returns the case and what MIS measured (its mean over every
/// sample; its non-finite count covers both estimators).
pub fn tiny_light(size: u32, spp: u32) -> (StabilityCase, Measured) {
    let scene = scenes::tiny_light(0.01, 1e4, size);
    let side: f64 = 0.01;
    let expected = 0.5 / std::f64::consts::PI * 1e4 * side * side * (1.0 - side * side / 3.0);
    let mut measured = Vec::new();
    let mut ok = true;
    let mut mis = Measured {
        mean: f64::NAN,
        standard_error: f64::NAN,
        nonfinite: 0,
    };
    let mut nonfinite = 0;
    for e in [Strategy::Mis, Strategy::Bsdf] {
        let path = PathSettings {
            strategy: e,
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
        nonfinite +=
            acc.stats.nonfinite + mean.pixels.iter().filter(|p| !p.is_finite()).count() as u64;
        if e == Strategy::Mis {
            ok &= z.abs() < 4.0;
            mis = Measured::of(s, q, n, 0);
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
        Measured { nonfinite, ..mis },
    )
}

/// Total internal reflection inside a glass cube: along the diagonal
/// everything is reflected forever (exactly 0); along an axis η² = 2.25.
/// Returns the case, the diagonal's largest mean channel (trapped) and
/// what the axis measured.
pub fn total_internal_reflection(size: u32, spp: u32) -> (StabilityCase, f64, Measured) {
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
        Measured::flat(&acc2.mean(), 0, &acc2),
    )
}

/// Glass of index 1 around the open furnace's sphere changes nothing: the
/// sphere's pixels stay ρ. Returns the case and what the centre block of
/// pixels measured.
pub fn index_matched_glass(size: u32, spp: u32) -> (StabilityCase, Measured) {
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
    let case = flat_case(
        "glass of index 1.0 around the open furnace",
        "invisible: the sphere's pixels stay ρ = 0.6 (|z| < 4)",
        &acc,
        flat_z(&centre, 0, rho),
    );
    (case, Measured::flat(&centre, 0, &acc))
}

/// A camera at the centre of a glass sphere under a sky of 1 sees η².
/// Returns the case and what the pixels measured (green).
pub fn camera_inside_glass(size: u32, spp: u32) -> (StabilityCase, Measured) {
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
    let case = flat_case(
        "camera inside glass (centre of a sphere, η = 1.5)",
        "every pixel η² = 2.25 (|z| < 4)",
        &acc,
        flat_z(&acc.mean(), 1, expected),
    );
    (case, Measured::flat(&acc.mean(), 1, &acc))
}

/// A case whose pixels share one expected value, from [`flat_z`]'s
/// (z, mean): it holds when |z| < 4 and no NaN or Inf was caught.
fn flat_case(
    name: &str,
    expected: &str,
    acc: &Accumulator,
    (z, mean): (f64, f64),
) -> StabilityCase {
    let ok = z.abs() < 4.0 && acc.stats.nonfinite == 0;
    let measured = format!("{} (z = {z:.2})", format_number(mean));
    StabilityCase::new(name, expected, measured, ok)
}

/// The Cornell box moved and scaled ([`PLACEMENTS`]), each against the
/// stored reference of the box at the origin by the region z-test; the
/// worst z and the largest deviation of the mean of the required ones, and
/// what happens to any placement not required. Returns the case and the worst z.
pub fn placement(size: u32, spp: u32) -> (StabilityCase, f64) {
    let name = "the Cornell box moved 1e1 to 1e6 along an axis and scaled 1e-5 to 1e3";
    let expected = "every placement matches the box at the origin's reference region by \
                    region (|z| below the Bonferroni threshold)";
    let Some(stored) = StoredReference::for_scene(&Scene::builtin()) else {
        let measured = "no stored reference of the Cornell box: not run".to_string();
        return (StabilityCase::new(name, expected, measured, true), 0.0);
    };
    let reference = stored.downsampled(stored.mean.width / size);
    let path = PathSettings {
        strategy: Strategy::Mis,
        ..PathSettings::default()
    };
    // The mean over pixels and channels.
    let level = |f: &Film| film_mean(f).element_sum() as f64 / 3.0;
    let ref_mean = level(&reference.mean);
    let (mut ok, mut worst_z, mut worst_dev) = (true, 0.0f64, (0.0f64, "", 0.0f64));
    let mut beyond = Vec::new();
    for (i, (label, offset, scale)) in PLACEMENTS.iter().enumerate() {
        let scene = Scene::builtin()
            .with_resolution(size, size)
            .expect("a valid size")
            .placed(DVec3::from_array(*offset), *scale);
        let (acc, _) = render(&scene, &path, SamplerKind::Independent, spp, 11, false);
        let t = region_z_test(&acc.mean(), &acc.variance_of_mean(), &reference, 4, 1e-3);
        let dev = level(&acc.mean()) / ref_mean - 1.0;
        // The noise of that mean: its standard error, relative.
        let var = acc.variance_of_mean();
        let n = var.pixels.len() as f64;
        let se = (level(&var) * n).sqrt() / n / ref_mean;
        if i < PLACEMENTS_REQUIRED {
            ok &= t.passed() && acc.stats.nonfinite == 0;
            worst_z = worst_z.max(t.worst_z);
            if dev.abs() > worst_dev.0.abs() {
                worst_dev = (dev, label, se);
            }
        } else {
            beyond.push(format!(
                "{label}: {:+.1} % (z = {:.0})",
                100.0 * dev,
                t.worst_z
            ));
        }
    }
    let mut measured = format!(
        "worst |z| {worst_z:.1}; largest deviation of the mean {:+.2} % ({}, where its noise \
         is ±{:.2} %)",
        100.0 * worst_dev.0,
        worst_dev.1,
        100.0 * worst_dev.2,
    );
    if !beyond.is_empty() {
        measured += &format!("; not required: {}", beyond.join(", "));
    }
    (StabilityCase::new(name, expected, measured, ok), worst_z)
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
            placement(16, 16).0,
        ];
    }
    vec![
        furnace_0999(8, 16).0,
        tiny_light(16, 64).0,
        total_internal_reflection(8, 16).0,
        index_matched_glass(32, 16).0,
        camera_inside_glass(16, 16).0,
        placement(16, 64).0,
    ]
}
