//! "Noise or wrong?": a render against its reference in units of their
//! combined standard error. Per pixel, z = (render − reference) /
//! √(σ²_render + σ²_reference), what the terminal UI's z view colours; per
//! block of 8 x 8 pixels, the grader's statistic for chapter 6 (a block
//! passes within 5 standard errors), what its verdict says in words, at
//! the stored reference's own resolution ([`verdict_at`]).
//!
//! A block's z is only as good as its standard error, which the render
//! estimates from its own samples. When a few rare, large samples carry a
//! block's light (uniform sampling finding a small lamp), the ones not yet
//! drawn make the mean low and the estimate of the noise lower still, and
//! z says "biased" of a correct render. So the verdict also counts a
//! block's *effective* samples, (Σx)² / Σx² (n for equal samples, about
//! the number of rare hits when those dominate), and below
//! [`MIN_EFFECTIVE`] it says "too few samples" instead.

use glam::{DVec3, Vec3};

use crate::core::film::Film;
use crate::core::preview::downsample;

/// The side of a verdict's blocks, in pixels: the grader's.
pub const BLOCK: u32 = 8;

/// The |z| a block may reach and still be noise: the grader's.
pub const Z_MAX: f64 = 5.0;

/// The fewest effective samples a block needs before its z is believed:
/// below it, the block's light comes from too few samples for their
/// spread to estimate the noise.
pub const MIN_EFFECTIVE: f64 = 100.0;

/// The z a pixel gets where neither image has noise but they differ: a
/// difference no noise explains, finite so that it is coloured, not
/// mistaken for a NaN.
pub const NOISELESS: f32 = 1e30;

/// z per pixel and channel. A pixel's own standard error, from the few
/// samples of a progressive render, is a poor guess (at 2 samples its
/// variance has one degree of freedom, and two alike samples claim almost
/// none), so the render's variance is averaged over the pixel's block of
/// [`BLOCK`] x [`BLOCK`] pixels, as the verdict pools it. Where both
/// standard errors are 0, z is 0 for equal values and ±[`NOISELESS`]
/// otherwise; a non-finite render stays non-finite. All four films have
/// the render's size.
pub fn z_film(
    render: &Film,
    render_stderr: &Film,
    reference: &Film,
    reference_stderr: &Film,
) -> Film {
    let (w, h) = (render.width, render.height);
    let block_var = |bx: u32, by: u32| {
        let (mut v, mut n) = (Vec3::ZERO, 0.0);
        for y in by..(by + BLOCK).min(h) {
            for x in bx..(bx + BLOCK).min(w) {
                let s = render_stderr.get(x, y);
                v += s * s;
                n += 1.0;
            }
        }
        v / n
    };
    let mut out = Film::new(w, h);
    for by in (0..h).step_by(BLOCK as usize) {
        for bx in (0..w).step_by(BLOCK as usize) {
            let var = block_var(bx, by);
            for y in by..(by + BLOCK).min(h) {
                for x in bx..(bx + BLOCK).min(w) {
                    let d = render.get(x, y) - reference.get(x, y);
                    let sb = reference_stderr.get(x, y);
                    let s = (var + sb * sb).powf(0.5);
                    *out.get_mut(x, y) = Vec3::from_array(std::array::from_fn(|c| {
                        if s[c] > 0.0 || !d[c].is_finite() {
                            d[c] / s[c]
                        } else if d[c] == 0.0 {
                            0.0
                        } else {
                            NOISELESS.copysign(d[c])
                        }
                    }));
                }
            }
        }
    }
    out
}

/// The verdict on a whole image: its worst block.
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    /// Blocks compared.
    pub blocks: usize,
    /// The largest |z| over blocks and channels (infinite for a NaN).
    pub worst_z: f64,
    /// The worst block's top-left pixel.
    pub at: (u32, u32),
    /// The worst block's mean, over its pixels and the three channels: the
    /// render's and the reference's.
    pub means: (f64, f64),
    /// Whether the render's samples in the worst block all agreed
    /// (variance 0): then its noise is not yet seen, and a difference
    /// says too few samples, not a bias (a rare light no sample found).
    pub unseen: bool,
    /// The worst block's effective number of samples, (Σx)² / Σx² over
    /// its samples, the fewer of the render's and the reference's
    /// (infinite where neither is counted).
    pub effective: f64,
}

/// [`verdict`] at the stored reference's own resolution: a render
/// `factor` times larger per side than the reference (which was enlarged
/// to its size, pixel by pixel) is box-averaged down first, its variance
/// with it, so that each block compares what the reference really knows
/// (an enlarged reference's copies of one pixel are one measurement, not
/// `factor`² independent ones). `samples` are the render's and the
/// reference's samples per pixel, as for [`verdict`]; the block's `at` is
/// given in the render's pixels.
pub fn verdict_at(
    factor: u32,
    render: &Film,
    render_stderr: &Film,
    reference: &Film,
    reference_stderr: &Film,
    samples: (u32, u32),
) -> Verdict {
    let k = factor.max(1);
    if k == 1 || !render.width.is_multiple_of(k) || !render.height.is_multiple_of(k) {
        return verdict(render, render_stderr, reference, reference_stderr, samples);
    }
    // Box-averaged k x k: a mean's standard error is √(mean of σ²) / k.
    let (w, h) = (render.width / k, render.height / k);
    let shrink = |film: &Film| downsample(film, w, h);
    let mut variance = render_stderr.clone();
    variance.pixels.iter_mut().for_each(|s| *s *= *s);
    let mut stderr = shrink(&variance);
    let inv_k = 1.0 / k as f32;
    stderr
        .pixels
        .iter_mut()
        .for_each(|v| *v = v.powf(0.5) * inv_k);
    // The reference's k x k copies of a pixel are one value: their mean,
    // and its standard error, are that pixel's.
    let mut v = verdict(
        &shrink(render),
        &stderr,
        &shrink(reference),
        &shrink(reference_stderr),
        (samples.0.saturating_mul(k * k), samples.1),
    );
    v.at = (v.at.0 * k, v.at.1 * k);
    v
}

/// Compares `render` with `reference` (each with its standard error per
/// pixel and channel) in blocks of [`BLOCK`] pixels: in each block the two
/// means per channel, and their difference over the standard error of the
/// difference of the means, √(Σ σ²_render + Σ σ²_reference) / n.
/// `samples` are the samples per pixel of the render and of the reference
/// (0: unknown, or so many that it does not matter: that side's effective
/// samples are not counted).
pub fn verdict(
    render: &Film,
    render_stderr: &Film,
    reference: &Film,
    reference_stderr: &Film,
    samples: (u32, u32),
) -> Verdict {
    let (w, h) = (render.width, render.height);
    let mut v = Verdict {
        blocks: 0,
        worst_z: 0.0,
        at: (0, 0),
        means: (0.0, 0.0),
        unseen: false,
        effective: f64::INFINITY,
    };
    for by in (0..h).step_by(BLOCK as usize) {
        for bx in (0..w).step_by(BLOCK as usize) {
            let (mut a, mut b, mut var, mut n) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO, 0.0);
            let mut own = DVec3::ZERO;
            for y in by..(by + BLOCK).min(h) {
                for x in bx..(bx + BLOCK).min(w) {
                    a += render.get(x, y).as_dvec3();
                    b += reference.get(x, y).as_dvec3();
                    let (sa, sb) = (
                        render_stderr.get(x, y).as_dvec3(),
                        reference_stderr.get(x, y).as_dvec3(),
                    );
                    var += sa * sa + sb * sb;
                    own += sa * sa;
                    n += 1.0;
                }
            }
            let (a, b) = (a / n, b / n);
            let sd = var.powf(0.5) / n;
            let z = DVec3::from_array(std::array::from_fn(|c| {
                let d = (a[c] - b[c]).abs();
                if d.is_nan() {
                    f64::INFINITY
                } else if sd[c] > 0.0 {
                    d / sd[c]
                } else if d == 0.0 {
                    0.0
                } else {
                    f64::from(NOISELESS)
                }
            }))
            .max_element();
            v.blocks += 1;
            if z > v.worst_z || v.blocks == 1 {
                v.worst_z = z;
                v.at = (bx, by);
                v.means = (a.element_sum() / 3.0, b.element_sum() / 3.0);
                v.unseen = own.max_element() == 0.0;
                let lit = |c: usize| a[c] > 0.0 || b[c] > 0.0;
                let block = (bx, by);
                v.effective = effective(render, render_stderr, samples.0, block, lit).min(
                    effective(reference, reference_stderr, samples.1, block, lit),
                );
            }
        }
    }
    v
}

/// The effective number of samples, (Σx)² / Σx², of the block at `block`
/// of an image with `n` samples per pixel (infinite for `n` = 0: not
/// counted), in its fewest channel among those `lit` (light on either
/// side). Σx and Σx² come from each pixel's mean m and standard error s:
/// N m, and N (N − 1) s² + N m².
fn effective(
    mean: &Film,
    stderr: &Film,
    n: u32,
    block: (u32, u32),
    lit: impl Fn(usize) -> bool,
) -> f64 {
    if n == 0 {
        return f64::INFINITY;
    }
    let big_n = f64::from(n);
    let (bx, by) = block;
    let (mut sum, mut sum_sq) = (DVec3::ZERO, DVec3::ZERO);
    for y in by..(by + BLOCK).min(mean.height) {
        for x in bx..(bx + BLOCK).min(mean.width) {
            let (m, s) = (mean.get(x, y).as_dvec3(), stderr.get(x, y).as_dvec3());
            sum += big_n * m;
            sum_sq += big_n * (big_n - 1.0) * s * s + big_n * m * m;
        }
    }
    (0..3)
        .filter(|&c| lit(c))
        .map(|c| match sum_sq[c] > 0.0 {
            true => sum[c] * sum[c] / sum_sq[c],
            false => 0.0,
        })
        .fold(f64::INFINITY, f64::min)
}

impl Verdict {
    /// Whether every block is within [`Z_MAX`].
    pub fn within_noise(&self) -> bool {
        self.worst_z <= Z_MAX
    }

    /// The verdict in two short lines, for a narrow panel: "within noise"
    /// or "biased: 12.3% brighter", then where and by how many standard
    /// errors.
    pub fn lines(&self) -> [String; 2] {
        let (x, y) = self.at;
        let (a, b) = self.means;
        let z = if self.worst_z >= f64::from(NOISELESS) {
            "no noise".to_string()
        } else {
            format!("{:.1}", self.worst_z)
        };
        if self.within_noise() {
            return [
                "verdict: within noise".into(),
                format!("max |z| {z} (limit {Z_MAX})"),
            ];
        }
        if self.unseen && a.is_finite() {
            return [
                "verdict: too few samples".into(),
                format!("at ({x}, {y}) they all agree: render longer"),
            ];
        }
        if self.effective < MIN_EFFECTIVE && a.is_finite() {
            return [
                "verdict: too few samples".into(),
                format!("at ({x}, {y}): ~{:.0} samples carry it", self.effective),
            ];
        }
        if !self.worst_z.is_finite() || !a.is_finite() {
            return [
                "verdict: wrong, not a number".into(),
                format!("in the block at ({x}, {y})"),
            ];
        }
        let side = if a >= b { "brighter" } else { "darker" };
        let by = if b != 0.0 {
            format!("{:.1}% {side}", 100.0 * (a - b).abs() / b.abs())
        } else {
            side.to_string()
        };
        [
            format!("verdict: biased, {by}"),
            format!("at ({x}, {y}): |z| {z} (limit {Z_MAX})"),
        ]
    }
}
