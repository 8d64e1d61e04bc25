//! Checks that render: the chapter's scene drawn with the student's code
//! and with raystep's, compared pixel by pixel (exactly, up to a few
//! pixels at silhouettes where rounding decides), or, where the stage is
//! Monte Carlo, block by block with z-tests against the reference mean.

use glam::Vec3;

use crate::core::film::Film;
use crate::exercise::Check;
use crate::exercises::AbsMax;
use crate::scene::Scene;

/// The scenes of `scenes/` the checks draw.
pub const SCENES: [&str; 4] = [
    "cornell-box.toml",
    "interpenetrating.toml",
    "railroad.toml",
    "sdf-shapes.toml",
];

/// The scenes read so far, by name: the student's process reads them all
/// ([`preload`]) before its sandbox closes the file system.
static LOADED: std::sync::Mutex<Vec<(String, Scene)>> = std::sync::Mutex::new(Vec::new());

/// Reads every scene of [`SCENES`] now.
pub fn preload() {
    for name in SCENES {
        let _ = scene(name);
    }
}

/// A scene of `scenes/`, for a check (panics name the file: a broken
/// repository, not a student's error).
pub fn scene(name: &str) -> Scene {
    let mut loaded = LOADED.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, s)) = loaded.iter().find(|(n, _)| n == name) {
        return s.clone();
    }
    let path = crate::core::project_root().join("scenes").join(name);
    let s = Scene::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    loaded.push((name.to_string(), s.clone()));
    s
}

/// Compares two images of the same size: a pixel differs when a channel
/// differs by more than `threshold`. The error is the fraction of pixels
/// that differ; `tolerance` is the largest fraction that passes. The
/// detail names the worst pixel with `explain(x, y)` (the input there,
/// and what each side measured), with `what` the quantity and its unit.
pub fn compare(
    student: Film,
    reference: Film,
    threshold: f32,
    tolerance: f64,
    what: &str,
    explain: &dyn Fn(u32, u32) -> String,
) -> Check {
    let (w, h) = (reference.width, reference.height);
    let mut differ = 0usize;
    let mut worst = (0.0f32, 0u32, 0u32);
    for y in 0..h {
        for x in 0..w {
            let d = student.get(x, y) - reference.get(x, y);
            let d = if d.is_finite() {
                d.abs_max()
            } else {
                f32::INFINITY
            };
            if d > threshold {
                differ += 1;
            }
            if d > worst.0 {
                worst = (d, x, y);
            }
        }
    }
    let n = (w * h) as f64;
    let error = differ as f64 / n;
    let detail = if differ == 0 {
        format!("all {} pixels of the {what} image match", w * h)
    } else {
        format!(
            "{differ} of {} pixels of the {what} image differ by more than {threshold}; \
             the worst, pixel ({}, {}): {}",
            w * h,
            worst.1,
            worst.2,
            explain(worst.1, worst.2)
        )
    };
    Check {
        error,
        tolerance,
        detail,
        images: Some((student, reference)),
        symptom: None,
    }
}

/// Per-pixel running mean and variance of a Monte Carlo image.
pub struct Estimate {
    /// The mean of the samples, per pixel.
    pub mean: Film,
    /// The variance of one sample, per pixel and channel (luminance-free:
    /// the channel mean of the three).
    pub variance: Vec<f64>,
    /// Samples per pixel.
    pub spp: u32,
}

impl Estimate {
    /// Gathers `spp` samples of `sample(x, y, s)` per pixel.
    pub fn gather(
        w: u32,
        h: u32,
        spp: u32,
        sample: &(dyn Fn(u32, u32, u32) -> Vec3 + Sync),
    ) -> Estimate {
        use rayon::prelude::*;
        let per: Vec<(Vec3, f64)> = (0..w * h)
            .into_par_iter()
            .map(|i| {
                let (x, y) = (i % w, i / w);
                let (mut sum, mut sq) = (glam::DVec3::ZERO, 0.0f64);
                for s in 0..spp {
                    let v = sample(x, y, s);
                    let v = if v.is_finite() {
                        v.as_dvec3()
                    } else {
                        glam::DVec3::splat(f64::INFINITY)
                    };
                    sum += v;
                    sq += v.length_squared() / 3.0;
                }
                let mean = sum / spp as f64;
                let var = (sq / spp as f64 - mean.length_squared() / 3.0).max(0.0);
                (
                    mean.as_vec3(),
                    var * spp as f64 / (spp as f64 - 1.0).max(1.0),
                )
            })
            .collect();
        let mut mean = Film::new(w, h);
        for (i, p) in per.iter().enumerate() {
            mean.pixels[i] = p.0;
        }
        Estimate {
            mean,
            variance: per.iter().map(|p| p.1).collect(),
            spp,
        }
    }
}

/// A statistical image test: the images are cut into blocks of `block` ×
/// `block` pixels, and in each block the student's mean (per channel) is
/// compared with the reference's by a two-sample z-score from both
/// variances. The error is the largest |z|; `z_max` passes. The detail
/// names the worst block, its two means and the z-score.
///
/// The student's own variance is in the z-score, so a few huge samples
/// raise it with the mean and keep z small: a block whose mean is off by
/// more than 10 % of the reference's, plus 5 of the reference's standard
/// errors, fails whatever its z (as the furnaces' 10 % rule).
pub fn z_test(student: Estimate, reference: Estimate, block: u32, z_max: f64, what: &str) -> Check {
    let (w, h) = (reference.mean.width, reference.mean.height);
    let mut worst = (0.0f64, String::from("every block agrees"));
    // A floor under the allowed difference where a block is dark: 10⁻⁴ of
    // the image's mean.
    let level = reference
        .mean
        .pixels
        .iter()
        .map(|p| p.as_dvec3().abs_max())
        .sum::<f64>()
        / reference.mean.pixels.len().max(1) as f64
        * 1e-4;
    for by in (0..h).step_by(block as usize) {
        for bx in (0..w).step_by(block as usize) {
            let (mut a, mut b, mut va, mut vb, mut n) =
                (glam::DVec3::ZERO, glam::DVec3::ZERO, 0.0, 0.0, 0.0f64);
            for y in by..(by + block).min(h) {
                for x in bx..(bx + block).min(w) {
                    let i = (y * w + x) as usize;
                    a += student.mean.pixels[i].as_dvec3();
                    b += reference.mean.pixels[i].as_dvec3();
                    va += student.variance[i] / student.spp as f64;
                    vb += reference.variance[i] / reference.spp as f64;
                    n += 1.0;
                }
            }
            let (a, b) = (a / n, b / n);
            let sd = ((va + vb) / (n * n)).sqrt().max(1e-6);
            // Not clamped: an infinite mean gives z = inf, printed as `inf`
            // (a NaN counts as infinitely far off).
            let z = (a - b).abs_max() / sd;
            let allowed = 0.1 * b.abs_max() + 5.0 * (vb / (n * n)).sqrt() + level;
            let z = super::worse(z, z_max * (a - b).abs_max() / allowed.max(1e-12));
            if z > worst.0 {
                worst = (
                    z,
                    format!(
                        "the {what} in the block at pixels ({bx}, {by})–({}, {}): yours averages \
                         {:.4} W/(m²·sr), the reference {:.4} W/(m²·sr) (per channel, z = {z:.1})",
                        (bx + block).min(w) - 1,
                        (by + block).min(h) - 1,
                        a,
                        b
                    ),
                );
            }
        }
    }
    Check {
        error: worst.0,
        tolerance: z_max,
        detail: worst.1,
        images: Some((student.mean, reference.mean)),
        symptom: None,
    }
}
