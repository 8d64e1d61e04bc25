//! How the path capstone is graded, clause by clause of its contract
//! (the stub's doc), and the symptoms the check recognises.
//!
//! 1. The closed furnace ([`PathScene::furnace`], its albedo and emission
//!    drawn for each grading run, [`furnace_of_run`]): every ray
//!    sees Le / (1 − ρ), nothing escapes, and the only noise is the
//!    roulette's. 200,000 paths; the mean must be within 5 standard
//!    errors of the answer per channel (the standard error measured from
//!    the candidate's own samples). Measured: the book's loop has a
//!    standard deviation of about 0.8 × the mean per path, so the standard
//!    error is 0.17% of the mean, and a 2% bias has z ≈ 12 (the mutant
//!    tests check that ±2% fails with z > 7). A mean more than 10% off fails whatever its
//!    z (an estimator with infinite variance, whose measured variance
//!    means nothing). Besides the mean, the scene's [`Tally`] checks that
//!    every path ends (a path over [`BOUNCE_BUDGET`] bounces: no
//!    roulette), that bounces leave on the lit side, that each surface
//!    gets a light sample and each light sample its shadow ray, that
//!    whether a path goes on does not depend on the numbers its
//!    direction was drawn from (roulette needs a number of its own); the
//!    furnace's variants ([`open`]) show what its mean cannot.
//! 2. The Cornell box (`cornell-box.toml`, 32 × 32, 64 paths per pixel)
//!    against the reference with other random numbers, 8 × 8-pixel blocks
//!    within 5 standard errors (shadows and the light's cosines, which
//!    the furnace cannot see). Its images are the check's images.

use glam::{DVec3, Vec3};

use super::numbers::{bounce_numbers_not_uniform, light_numbers_not_uniform, went_on_by_numbers};
use super::open::{
    hidden_emission, BLACK_SURFACE, BOUNCE_EMISSION_ADDED, ENDS_OF_RANGE, HIDDEN_EMISSION_PATHS,
    LIGHT_FROM_BEHIND, LIGHT_THROUGH_OCCLUDER, PATHS_BEFORE, UNBOUNDED_THROUGHPUT,
};
use super::{reset_tally, tally, PathFn, PathScene, Tally, BOUNCE_BUDGET};
use crate::exercise::Symptom;

/// A path was still going after [`BOUNCE_BUDGET`] bounces in the closed
/// furnace.
pub const NO_ROULETTE: Symptom = Symptom {
    name: "a path never ends",
};

/// Many furnace paths end at exactly the same bounce, and the furnace is
/// too dark.
pub const DEPTH_CAP: Symptom = Symptom {
    name: "a fixed maximum depth (too dark in a closed room)",
};

/// The furnace lacks exactly the emission the camera sees.
pub const NO_FIRST_EMISSION: Symptom = Symptom {
    name: "the emission the camera sees is missing",
};

/// The furnace has the emission of every surface twice.
pub const DOUBLE_EMISSION: Symptom = Symptom {
    name: "emission counted twice",
};

/// The light samples alone bring twice what they should in the furnace.
pub const LIGHT_SAMPLE_WRONG: Symptom = Symptom {
    name: "the light sample's value is off",
};

/// The furnace is too dark by a factor.
pub const TOO_DARK: Symptom = Symptom {
    name: "too dark by a factor",
};

/// The furnace is too bright by a factor.
pub const TOO_BRIGHT: Symptom = Symptom {
    name: "too bright by a factor",
};

/// Bounces leave the surface on the wrong side.
pub const BELOW_SURFACE: Symptom = Symptom {
    name: "bounces below the surface",
};

/// Surfaces without a light sample.
pub const NO_NEE: Symptom = Symptom {
    name: "no light sample at each surface",
};

/// A light sample drawn from the numbers of the bounce that reached its
/// surface.
pub const LIGHT_FROM_BOUNCE_NUMBERS: Symptom = Symptom {
    name: "a light sample reuses the numbers of the bounce before it",
};

/// Light samples without a shadow ray.
pub const NO_SHADOW_RAY: Symptom = Symptom {
    name: "light samples without a shadow ray",
};

/// The furnace is right, the Cornell box is not.
pub const CORNELL_DIFFERS: Symptom = Symptom {
    name: "right in the furnace, wrong in the Cornell box",
};

/// Every symptom [`check_path_radiance`](super::check_path_radiance) can name.
pub const SYMPTOMS: [Symptom; 19] = [
    NO_ROULETTE,
    UNBOUNDED_THROUGHPUT,
    LIGHT_FROM_BEHIND,
    LIGHT_THROUGH_OCCLUDER,
    BOUNCE_EMISSION_ADDED,
    BLACK_SURFACE,
    ENDS_OF_RANGE,
    PATHS_BEFORE,
    DEPTH_CAP,
    NO_FIRST_EMISSION,
    DOUBLE_EMISSION,
    TOO_DARK,
    TOO_BRIGHT,
    BELOW_SURFACE,
    NO_NEE,
    NO_SHADOW_RAY,
    LIGHT_FROM_BOUNCE_NUMBERS,
    CORNELL_DIFFERS,
    LIGHT_SAMPLE_WRONG,
];

/// The furnace's albedo (grey).
pub const FURNACE_ALBEDO: f32 = 0.85;
/// The furnace's emitted radiance.
pub const FURNACE_LE: Vec3 = Vec3::new(1.0, 0.75, 0.5);
/// Paths traced in the furnace.
pub const FURNACE_PATHS: u64 = 200_000;

/// What the candidate did in the furnace.
#[derive(Clone, Debug, Default)]
pub struct FurnaceRun {
    /// Sum and sum of squares of the returned radiance.
    pub sum: DVec3,
    /// Sum of squares, per channel.
    pub sum_sq: DVec3,
    /// Paths whose radiance was not finite.
    pub non_finite: u64,
    /// The sum of every path's tally (`over_budget`: any path's).
    pub tally: Tally,
    /// Light samples that could light their surface beyond the shadow
    /// rays cast, path by path, summed.
    pub unshadowed: u64,
    /// How many paths made each number of bounces (the last entry: more).
    pub lengths: Vec<u64>,
    /// Per channel, the largest (radiance − 1) per light sample found of
    /// one path: in a furnace of Le = 1, each sample brings β ρ, so this
    /// is ρ times the path's mean throughput at its samples.
    pub most_per_sample: DVec3,
}

impl FurnaceRun {
    /// The mean radiance of its `n` paths and its standard error, per
    /// channel (the error at least 10⁻⁶, so a z-score is always finite).
    pub fn mean_and_error(&self, n: u64) -> (DVec3, DVec3) {
        let m = n as f64;
        let mean = self.sum / m;
        let var = ((self.sum_sq / m - mean * mean) * (m / (m - 1.0))).max(DVec3::ZERO);
        (mean, (var / m).max(DVec3::splat(1e-12)).powf(0.5))
    }

    fn merge(mut self, o: FurnaceRun) -> FurnaceRun {
        self.sum += o.sum;
        self.sum_sq += o.sum_sq;
        self.non_finite += o.non_finite;
        self.unshadowed += o.unshadowed;
        let (a, b) = (&mut self.tally, o.tally);
        a.bounces += b.bounces;
        a.vertices += b.vertices;
        a.light_samples += b.light_samples;
        a.lights_found += b.lights_found;
        a.lights_useful += b.lights_useful;
        a.shadow_rays += b.shadow_rays;
        a.below += b.below;
        a.over_budget |= b.over_budget;
        a.light_from_bounce_numbers += b.light_from_bounce_numbers;
        for (x, y) in a.light_cells.iter_mut().zip(b.light_cells) {
            *x += y;
        }
        for (x, y) in a
            .cosine_quarters
            .iter_mut()
            .chain(&mut a.cosine_went_on)
            .zip(b.cosine_quarters.into_iter().chain(b.cosine_went_on))
        {
            for (x, y) in x.iter_mut().zip(y) {
                *x += y;
            }
        }
        self.most_per_sample = self.most_per_sample.max(o.most_per_sample);
        if self.lengths.is_empty() {
            self.lengths = o.lengths;
        } else {
            for (x, y) in self.lengths.iter_mut().zip(o.lengths) {
                *x += y;
            }
        }
        self
    }
}

/// Traces `n` paths of `scene` (a furnace) with `f`, in parallel, each with its own
/// random numbers from (seed, path).
pub fn trace_furnace(f: PathFn, scene: &PathScene, n: u64, seed: u64) -> FurnaceRun {
    use rayon::prelude::*;
    let chunk = 2_000u64;
    (0..n.div_ceil(chunk))
        .into_par_iter()
        .map(|c| {
            let mut acc = FurnaceRun {
                lengths: vec![0; BOUNCE_BUDGET as usize + 2],
                ..FurnaceRun::default()
            };
            for i in c * chunk..((c + 1) * chunk).min(n) {
                let (dir, mut rng) = super::furnace_path(seed, i);
                if i % 50_000 == 0 {
                    crate::progress(format_args!(
                        "calling path_radiance in the closed furnace, path {i} of {n}"
                    ));
                }
                reset_tally();
                let l = f(scene, super::FURNACE_ORIGIN, dir, &mut rng);
                let t = tally();
                let per_sample = (l.as_dvec3() - 1.0) / f64::from(t.lights_found);
                let one = FurnaceRun {
                    tally: t,
                    unshadowed: u64::from(t.lights_useful.saturating_sub(t.shadow_rays)),
                    most_per_sample: if t.lights_found > 0 && per_sample.is_finite() {
                        per_sample
                    } else {
                        DVec3::ZERO
                    },
                    ..FurnaceRun::default()
                };
                acc = acc.merge(one);
                let k = (t.bounces as usize).min(acc.lengths.len() - 1);
                acc.lengths[k] += 1;
                if l.is_finite() {
                    let l = l.as_dvec3();
                    acc.sum += l;
                    acc.sum_sq += l * l;
                } else {
                    acc.non_finite += 1;
                }
            }
            acc
        })
        .reduce(FurnaceRun::default, FurnaceRun::merge)
}

/// The furnace run `r` of `f`: (error against a tolerance of 5, what was seen,
/// the symptom).
pub fn judge_furnace(f: PathFn, r: &FurnaceRun, n: u64) -> (f64, String, Option<Symptom>) {
    judge_furnace_of(f, r, n, (FURNACE_ALBEDO, FURNACE_LE))
}

/// The furnace of this grading run: its albedo from 0.8 to 0.9 and its
/// emission from 0.2 to 20 per channel (one of them from 10), drawn from the run's seed (a
/// solution cannot recognise the furnace by fixed numbers and answer it in
/// closed form). Below 0.8 the means that the symptoms' hypotheses predict
/// (the first emission missing, roulette's survivors not divided by q)
/// come too close to tell apart.
pub fn furnace_of_run() -> (f32, Vec3) {
    let mut draws = crate::exercises::draws::Draws::new(64);
    let albedo = draws.range(0.8, 0.9);
    let mut le = Vec3::new(
        draws.decades(-0.7, 1.3),
        draws.decades(-0.7, 1.3),
        draws.decades(-0.7, 1.3),
    );
    // One channel from 10 to 20: a light sample then brings more than
    // ρ·10 (a clamp on what one sample brings is a bias).
    le[draws.count(0, 2)] = draws.range(10.0, 20.0);
    (albedo, le)
}

/// [`judge_furnace`] for the furnace of albedo and emission `(albedo, le)`.
pub fn judge_furnace_of(
    f: PathFn,
    r: &FurnaceRun,
    n: u64,
    (albedo, furnace_le): (f32, Vec3),
) -> (f64, String, Option<Symptom>) {
    let t = r.tally;
    let bad = 1e9;
    if t.over_budget {
        let detail = format!(
            "closed furnace: a path was still going after {BOUNCE_BUDGET} bounces (nothing \
             escapes a closed room, so only Russian roulette can end it)"
        );
        return (bad, detail, Some(NO_ROULETTE));
    }
    if t.below as u64 * 1000 > t.bounces as u64 {
        let detail = format!(
            "closed furnace: {} of {} bounces left their surface on the wrong side (wi · n ≤ 0)",
            t.below, t.bounces
        );
        return (bad, detail, Some(BELOW_SURFACE));
    }
    if t.light_samples * 2 < t.vertices {
        let detail = format!(
            "closed furnace: {} light samples for {} surfaces reached (one per surface expected)",
            t.light_samples, t.vertices
        );
        return (bad, detail, Some(NO_NEE));
    }
    if r.unshadowed > 0 {
        let detail = format!(
            "closed furnace: {} light samples that could light their surface counted without a \
             shadow ray (each needs its own before it counts, however small it is)",
            r.unshadowed
        );
        return (bad, detail, Some(NO_SHADOW_RAY));
    }
    if t.light_from_bounce_numbers > 0 {
        let detail = format!(
            "closed furnace: {} light samples were drawn from the same two numbers as the bounce \
             that reached their surface (the light point then depends on where the surface is)",
            t.light_from_bounce_numbers
        );
        return (bad, detail, Some(LIGHT_FROM_BOUNCE_NUMBERS));
    }
    if t.shadow_rays * 2 < t.lights_found {
        let detail = format!(
            "closed furnace: {} shadow rays for {} light samples (one per sample expected)",
            t.shadow_rays, t.lights_found
        );
        return (bad, detail, Some(NO_SHADOW_RAY));
    }
    if let Some(detail) = bounce_numbers_not_uniform(&t.cosine_quarters) {
        return (bad, detail, None);
    }
    if let Some(detail) = light_numbers_not_uniform(&t.light_cells) {
        return (bad, detail, None);
    }
    if r.non_finite > 0 {
        let detail = format!(
            "closed furnace: {} of {n} paths returned a radiance that is not finite (inf or NaN)",
            r.non_finite
        );
        return (f64::INFINITY, detail, Some(TOO_BRIGHT));
    }
    let (mean, se) = r.mean_and_error(n);
    let rho = albedo as f64;
    let le = furnace_le.as_dvec3();
    let want = le / (1.0 - rho);
    let z = ((mean - want).abs() / se).max_element();
    let rel = ((mean - want) / want).abs().max_element();
    let ratio = (mean / want).element_sum() / 3.0;
    let mut detail = format!(
        "closed furnace (albedo {rho:.2}, Le {le:.2}: every ray sees Le/(1 − ρ) = {want:.3}): \
         the mean of your {n} paths is {mean:.3} ({:+.1}%, z = {z:.1})",
        100.0 * (ratio - 1.0)
    );
    // A mean more than 10% off fails whatever its z: an estimator with
    // infinite variance has a measured variance that means nothing.
    let error = if rel > 0.1 { z.max(1e3) } else { z };
    if error <= 5.0 {
        // Right on average in the furnace, whose symmetry hides which
        // directions went on: were they all equally likely to?
        return match went_on_by_numbers(&t) {
            Some(detail) => (bad, detail, None),
            None => (error, detail, None),
        };
    }
    // Which hypothesis fits the mean (within 5 standard errors or 1%).
    // (Within 5 standard errors counts only within 10%: an estimator with
    // an enormous spread is within 5 of anything.)
    let fits = |h: DVec3| {
        let rel = ((mean - h) / h).abs().max_element();
        (((mean - h).abs() / se).max_element() <= 5.0 && rel < 0.1) || rel < 0.01
    };
    let symptom = if fits(want - le) {
        Some(NO_FIRST_EMISSION)
    } else if fits(le + 2.0 * rho * want) {
        // Emission counted twice, or each light sample doubled: the
        // furnace without emission at bounced hits tells them apart.
        let (mean, _) =
            hidden_emission(f, albedo, furnace_le).mean_and_error(HIDDEN_EMISSION_PATHS);
        if ((mean - want) / want).abs().max_element() < 0.05 {
            Some(DOUBLE_EMISSION)
        } else {
            Some(LIGHT_SAMPLE_WRONG)
        }
    } else if ratio < 1.0 && cap_spike(&r.lengths, 1).is_some() {
        let (k, count) = cap_spike(&r.lengths, 1).unwrap_or_default();
        detail += &format!("; {count} paths end at exactly {k} bounces");
        Some(DEPTH_CAP)
    } else if ratio < 1.0 {
        Some(TOO_DARK)
    } else {
        Some(TOO_BRIGHT)
    };
    (error, detail, symptom)
}

/// A fixed maximum depth shows as a spike in the path lengths: many
/// paths (≥ 20, and at least `per_mille` ‰ of them all) at the longest
/// length, more than twice as many as one bounce shorter (under roulette
/// the longest lengths are a thin geometric tail: one or two paths).
pub(super) fn cap_spike(lengths: &[u64], per_mille: u64) -> Option<(usize, u64)> {
    let k = lengths.iter().rposition(|c| *c > 0)?;
    let total: u64 = lengths.iter().sum();
    let at = lengths[k];
    let before = if k > 0 { lengths[k - 1] } else { 0 };
    (at >= 20 && at * 1000 >= total * per_mille && at > 2 * before).then_some((k, at))
}
