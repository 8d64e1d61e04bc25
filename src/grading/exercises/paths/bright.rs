//! The path capstone's brighter furnace (albedo 0.97, emission 10² to
//! 10⁵ times the run's furnace's): paths of 33
//! bounces on average and a few of several hundred, where what a path
//! loses or gains at each bounce adds up. A denominator nudged "to be
//! safe" (pdf + 10⁻⁴ loses 0.06 % a bounce, 2 % here) or a count that
//! stops a path at some depth (a byte's 255) shows here, while in the
//! run's own furnace (albedo 0.8 to 0.9, about 7 bounces) it hides in
//! the noise. Below 0.97, so that no right path runs past
//! [`BOUNCE_BUDGET`](super::BOUNCE_BUDGET) (0.97¹⁰⁰⁰ is 6·10⁻¹⁴).
//! Then a dim furnace ([`dim_furnace`]), where a path ended for being
//! dim loses the light of its later bounces, and one whose light is
//! faint and rarely sampled ([`faint_light_furnace`]), where a density
//! floored "to be safe" cuts the light samples' light.

use super::check::{cap_spike, furnace_of_run, judge_furnace_of, trace_furnace, DEPTH_CAP};
use super::{PathFn, PathScene};
use crate::exercise::Symptom;

/// The brighter furnace's albedo.
const ALBEDO: f32 = 0.97;
/// Paths traced in it: a 2 % bias is then about 7 standard errors.
const PATHS: u64 = 200_000;

/// `None` if the brighter furnace's mean is within 5 standard errors of
/// Le / (1 − ρ) and no depth ends many paths at once; else (error, what
/// was seen, the symptom).
pub fn bright_furnace(f: PathFn) -> Option<(f64, String, Option<Symptom>)> {
    // Its emission the run's times 10² to 10⁵ (radiance has no scale):
    // a light sample then brings hundreds to millions, and a clamp on what
    // one brings, at whatever level a student thinks bright, is a bias.
    let (_, le) = furnace_of_run();
    let le = le * crate::exercises::draws::Draws::new(616).decades(2.0, 5.0);
    let scene = PathScene::furnace(ALBEDO, le);
    let run = trace_furnace(f, &scene, PATHS, 613 ^ crate::run_seed());
    // A depth that ends paths piles them up at the longest length, here
    // however few of them reach it.
    if let Some((k, at)) = cap_spike(&run.lengths, 0) {
        let detail = format!(
            "a brighter closed furnace (albedo {ALBEDO}): {at} of {PATHS} paths end at exactly {k} \
             bounces (a depth that stops paths is a bias: only roulette may end them)"
        );
        return Some((1e3, detail, Some(DEPTH_CAP)));
    }
    let (error, detail, symptom) = judge_furnace_of(f, &run, PATHS, (ALBEDO, le));
    (error > 5.0).then(|| (error, format!("in a brighter {detail}"), symptom))
}

/// Paths traced in the dim furnace: short (1.2 bounces on average), and
/// a 0.1 % bias is about 6 standard errors there.
const DIM_PATHS: u64 = 400_000;

/// `None` if a dim closed furnace (albedo from 0.1 to 0.21, drawn for the
/// run) has the mean Le / (1 − ρ) within 5 standard errors; else (error,
/// what was seen, the symptom). There a path's throughput falls below
/// 0.05 by its second bounce, so a path ended for being dim (a cut-off
/// on β or on roulette's q) loses the light of every later bounce, ρ³ of
/// the answer (0.1 % to 0.9 %), which roulette divided by q would keep.
pub fn dim_furnace(f: PathFn) -> Option<(f64, String, Option<Symptom>)> {
    let (_, le) = furnace_of_run();
    let albedo = crate::exercises::draws::Draws::new(665).range(0.1, 0.21);
    let scene = PathScene::furnace(albedo, le);
    let run = trace_furnace(f, &scene, DIM_PATHS, 614 ^ crate::run_seed());
    let (error, detail, symptom) = judge_furnace_of(f, &run, DIM_PATHS, (albedo, le));
    (error > 5.0).then(|| (error, format!("in a dim {detail}"), symptom))
}

/// Paths traced in the faint light's furnace (a density floor cuts most
/// of the light there, far more than 5 standard errors).
const FAINT_PATHS: u64 = 20_000;

/// `None` if a closed furnace whose light samples come with radiance and
/// density both 10⁻¹⁰ to 10⁻⁶ times the run's furnace's (drawn for the
/// run) has the mean Le / (1 − ρ) within 5 standard errors; else (error,
/// what was seen, the symptom). Each light sample brings the same light
/// as in the run's furnace, but its density per steradian is far below
/// any an ordinary light gives nearby, as a large light's is close to it
/// (d² / (A cos θl)): a loop that floors the density, or skips a sample
/// whose density "looks wrong", loses that light.
pub fn faint_light_furnace(f: PathFn) -> Option<(f64, String, Option<Symptom>)> {
    let (albedo, le) = furnace_of_run();
    let scale = crate::exercises::draws::Draws::new(667).decades(-10.0, -6.0);
    let scene = PathScene::furnace_with_faint_light(albedo, le, scale);
    let run = trace_furnace(f, &scene, FAINT_PATHS, 618 ^ crate::run_seed());
    let (error, detail, symptom) = judge_furnace_of(f, &run, FAINT_PATHS, (albedo, le));
    (error > 5.0).then(|| {
        let detail = format!(
            "in a {detail}, its light samples' radiance and density both {scale:.1e} times its \
             own (the same light per sample)"
        );
        (error, detail, symptom)
    })
}
