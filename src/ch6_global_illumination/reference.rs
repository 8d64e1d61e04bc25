//! The stored Cornell-box reference and the statistical image test.
//!
//! A reference is a converged render kept under `scenes/references/`, named
//! by scene and size (`<stem>` = `<scene>-<width>x<height>`):
//! `<stem>-mean.exr` (the mean radiance), `<stem>-var.exr` (per pixel
//! and channel the estimated variance of that mean, s²/n) and
//! `<stem>.txt` (how it was made: resolution, samples, seed, estimator,
//! bounce limit, time, and the command that regenerates it; and the
//! scene's content hash, `content = …`).
//!
//! A reference is matched by name and size, then by content: the scene's
//! hash ([`crate::scene::content`]) must be the one stored beside it, or
//! there is none and the report says why ([`StoredReference::why_none`];
//! [`annotate_references`](super::annotate::annotate_references) records the hashes).
//!
//! The image test compares *regions*: the mean of a block of pixels in a
//! new render against the same block of the reference, as a z-score with
//! both variances, z = (m - m_ref) / √(σ²_m + σ²_ref). With R regions and 3
//! channels the threshold is Bonferroni-corrected: a correct renderer fails
//! with probability at most α over the whole image, not per region.

use std::path::{Path, PathBuf};

use glam::Vec3;

use crate::core::error::{Error, Result};
use crate::core::film::{write_atomically, Film};
use crate::scene::Scene;

use super::accumulate::{downsample, Accumulator};
use super::engine::EngineChoice;
use super::integrator::PathSettings;
use super::sampler::SamplerKind;
use crate::ch1_projection::camera::Camera;
use std::time::Instant;

/// Where references live.
pub fn reference_dir() -> PathBuf {
    crate::core::project_root().join("scenes/references")
}

/// A converged render with its per-pixel variance of the mean.
#[derive(Clone, Debug)]
pub struct StoredReference {
    /// The mean radiance.
    pub mean: Film,
    /// Per pixel and channel, the variance of `mean`.
    pub var_of_mean: Film,
    /// The settings it was made with, as `key = value` lines.
    pub meta: String,
}

/// The size of the reference the tests, the studies and the terminal UI
/// compare with (larger renders are box-downsampled to it).
pub const REFERENCE_SIZE: u32 = 64;

impl StoredReference {
    /// The stored [`REFERENCE_SIZE`]² reference of `scene`, if there is one
    /// for a scene of that name and the same content.
    pub fn for_scene(scene: &Scene) -> Option<StoredReference> {
        StoredReference::for_scene_at(scene, REFERENCE_SIZE, REFERENCE_SIZE)
    }

    /// The stored reference a render of `scene` at the scene's own size can
    /// be compared with, and the factor by which the render is larger
    /// ([`scale_factor`]). `None` when there is no reference, or when the
    /// render's size is not a whole multiple of it with the same aspect (a
    /// 256x128 Cornell box has no reference: the square one shows a
    /// different picture).
    /// A reference of the render's own size comes first (compared pixel
    /// by pixel), then one of [`REFERENCE_SIZE`] on the longer side (the
    /// render box-downsampled to it).
    pub fn for_render(scene: &Scene) -> Option<(StoredReference, u32)> {
        StoredReference::for_render_or_why(scene).ok()
    }

    /// Why a render of `scene` has no stored reference while one of its
    /// name is stored at a size [`StoredReference::for_render`] would use:
    /// one line for the report ("this scene's content differs from
    /// cornell-box's (hash …, stored …)"). `None` when it has one, or when none of
    /// its name is stored.
    pub fn why_none(scene: &Scene) -> Option<String> {
        StoredReference::for_render_or_why(scene).err().flatten()
    }

    /// [`StoredReference::for_render`], or why not ([`Self::why_none`]).
    fn for_render_or_why(
        scene: &Scene,
    ) -> std::result::Result<(StoredReference, u32), Option<String>> {
        let (w, h) = (scene.camera.width, scene.camera.height);
        let small = if w >= h {
            (REFERENCE_SIZE, REFERENCE_SIZE * h / w.max(1))
        } else {
            (REFERENCE_SIZE * w / h.max(1), REFERENCE_SIZE)
        };
        let mut why = None;
        for (rw, rh) in [(w, h), small] {
            let Some(factor) = scale_factor(w, h, rw, rh) else {
                continue;
            };
            match StoredReference::find(scene, rw, rh) {
                Ok(r) => return Ok((r, factor)),
                Err(reason) => why = why.or(reason),
            }
        }
        Err(why)
    }

    /// The stored reference of `scene` at `width` x `height`, if there is
    /// one (`<name>-<width>x<height>` in [`reference_dir`]).
    pub fn for_scene_at(scene: &Scene, width: u32, height: u32) -> Option<StoredReference> {
        StoredReference::find(scene, width, height).ok()
    }

    /// The stored reference of `scene` at `width` x `height`; without one,
    /// `Err(Some(why))` when one of the scene's name is stored there but
    /// for other content (or without a recorded hash), `Err(None)` when
    /// none is.
    fn find(
        scene: &Scene,
        width: u32,
        height: u32,
    ) -> std::result::Result<StoredReference, Option<String>> {
        let r = StoredReference::load(&reference_dir(), &stem(&scene.name, width, height))
            .map_err(|_| None)?;
        let sized = (r.mean.width, r.mean.height) == (width, height)
            && (r.var_of_mean.width, r.var_of_mean.height) == (width, height);
        if !sized {
            return Err(None);
        }
        let here = scene.content_hash();
        match r.value("content") {
            Some(stored) if stored == here => Ok(r),
            Some(stored) => Err(Some(format!(
                "this scene's content differs from {}'s (hash {here}, stored {stored})",
                scene.name
            ))),
            None => Err(Some(format!(
                "the one of {} records no content hash (ch6 --annotate-references)",
                scene.name
            ))),
        }
    }

    /// Reads `<name>-mean.exr`, `<name>-var.exr` and `<name>.txt` from `dir`.
    pub fn load(dir: &Path, name: &str) -> Result<StoredReference> {
        let meta_path = dir.join(format!("{name}.txt"));
        Ok(StoredReference {
            mean: Film::read_exr(&dir.join(format!("{name}-mean.exr")))?,
            var_of_mean: Film::read_exr(&dir.join(format!("{name}-var.exr")))?,
            meta: std::fs::read_to_string(&meta_path).map_err(|e| Error::io(&meta_path, e))?,
        })
    }

    /// A `key = value` entry of the metadata.
    pub fn value(&self, key: &str) -> Option<&str> {
        meta_value(&self.meta, key)
    }

    /// Writes the three files of a finished render into `dir`.
    pub fn save(acc: &Accumulator, dir: &Path, name: &str, meta: &str) -> Result<Vec<PathBuf>> {
        let files = vec![
            dir.join(format!("{name}-mean.exr")),
            dir.join(format!("{name}-var.exr")),
            dir.join(format!("{name}.txt")),
        ];
        acc.mean().write_exr(&files[0])?;
        acc.variance_of_mean().write_exr(&files[1])?;
        write_atomically(&files[2], |tmp| {
            std::fs::write(tmp, meta).map_err(|e| e.to_string())
        })?;
        Ok(files)
    }

    /// The reference at 1/`factor` of its resolution: means averaged over
    /// blocks, variances averaged and divided by factor².
    pub fn downsampled(&self, factor: u32) -> StoredReference {
        let mut var = downsample(&self.var_of_mean, factor);
        let k = 1.0 / (factor * factor) as f32;
        var.pixels.iter_mut().for_each(|p| *p *= k);
        StoredReference {
            mean: downsample(&self.mean, factor),
            var_of_mean: var,
            meta: self.meta.clone(),
        }
    }
}

/// A `key = value` entry of a reference's text.
pub(super) fn meta_value<'a>(meta: &'a str, key: &str) -> Option<&'a str> {
    meta.lines().find_map(|l| {
        let (k, v) = l.split_once('=')?;
        (k.trim() == key).then(|| v.trim())
    })
}

/// The file stem of the reference of scene `name` at `width` x `height`.
pub fn stem(name: &str, width: u32, height: u32) -> String {
    format!("{name}-{width}x{height}")
}

/// The integer factor by which a `width` x `height` render is larger than
/// a `ref_width` x `ref_height` reference, when it is the same picture at a
/// whole multiple of its size (same aspect, both sides divisible); `None`
/// otherwise, and then the render and the reference cannot be compared.
pub fn scale_factor(width: u32, height: u32, ref_width: u32, ref_height: u32) -> Option<u32> {
    if ref_width == 0
        || ref_height == 0
        || !width.is_multiple_of(ref_width)
        || !height.is_multiple_of(ref_height)
    {
        return None;
    }
    let factor = width / ref_width;
    (factor >= 1 && height / ref_height == factor).then_some(factor)
}

impl StoredReference {
    /// The mean and its standard error (√ of the variance of the mean),
    /// each pixel repeated `factor` x `factor` times for a larger render.
    pub fn upsampled(&self, factor: u32) -> (Film, Film) {
        let stderr = self.var_of_mean.clone().sqrt_clamped();
        (upsample(&self.mean, factor), upsample(&stderr, factor))
    }
}

/// Nearest-neighbour enlargement by an integer factor (for showing a
/// smaller reference beside a larger render).
pub fn upsample(film: &Film, factor: u32) -> Film {
    let mut out = Film::new(film.width * factor, film.height * factor);
    for y in 0..out.height {
        for x in 0..out.width {
            *out.get_mut(x, y) = film.get(x / factor, y / factor);
        }
    }
    out
}

/// The outcome of a region z-test.
#[derive(Clone, Debug, PartialEq)]
pub struct RegionTest {
    /// Regions compared (each in 3 channels).
    pub regions: usize,
    /// The largest |z| over regions and channels.
    pub worst_z: f64,
    /// Where: (region column, region row, channel).
    pub worst_at: (u32, u32, usize),
    /// The Bonferroni-corrected threshold for the requested α.
    pub threshold: f64,
}

impl RegionTest {
    /// Whether every region is within the threshold.
    pub fn passed(&self) -> bool {
        self.worst_z <= self.threshold
    }
}

/// Compares a render (`mean`, `var_of_mean`) against `reference` of the
/// same size in blocks of `block` x `block` pixels; α is the chance that a
/// correct render fails anywhere.
// ANCHOR: region_z_test
// ANCHOR: region_z_test_sum
pub fn region_z_test(
    mean: &Film,
    var_of_mean: &Film,
    reference: &StoredReference,
    block: u32,
    alpha: f64,
) -> RegionTest {
    assert_eq!(
        (mean.width, mean.height),
        (reference.mean.width, reference.mean.height)
    );
    let (rw, rh) = (mean.width / block, mean.height / block);
    let sum_block = |f: &Film, bx: u32, by: u32| -> glam::DVec3 {
        let mut s = glam::DVec3::ZERO;
        for y in by * block..(by + 1) * block {
            for x in bx * block..(bx + 1) * block {
                s += f.get(x, y).as_dvec3();
            }
        }
        s
    };
    let p = (block * block) as f64;
    let mut worst = (0.0f64, (0, 0, 0));
    // ANCHOR_END: region_z_test_sum
    // ANCHOR: region_z_test_worst
    for by in 0..rh {
        for bx in 0..rw {
            let m = sum_block(mean, bx, by) / p;
            let r = sum_block(&reference.mean, bx, by) / p;
            // The variance of a block mean: Σ σ²_i / P².
            let v = (sum_block(var_of_mean, bx, by) + sum_block(&reference.var_of_mean, bx, by))
                / (p * p);
            for c in 0..3 {
                let z = (m[c] - r[c]).abs() / v[c].max(1e-30).sqrt();
                let z = if z.is_nan() { f64::INFINITY } else { z };
                if z > worst.0 {
                    worst = (z, (bx, by, c));
                }
            }
        }
    }
    let regions = (rw * rh) as usize;
    RegionTest {
        regions,
        worst_z: worst.0,
        worst_at: worst.1,
        threshold: normal_quantile(1.0 - alpha / (2.0 * 3.0 * regions as f64)),
    }
}
// ANCHOR_END: region_z_test_worst
// ANCHOR_END: region_z_test

/// The z-score of a mean against an expected value, from the sample
/// values' sum, sum of squares and count. The standard error is floored
/// at 1e-6 of the expected value: f32 rendering cannot be closer than
/// that, and an estimator with (almost) no variance would otherwise turn
/// rounding into huge z.
pub fn z_score(sum: f64, sum_sq: f64, n: f64, expected: f64) -> f64 {
    let mean = sum / n;
    let var = ((sum_sq - sum * sum / n) / (n - 1.0)).max(0.0);
    let se = (var / n).sqrt().max(1e-6 * expected.abs().max(1e-3));
    (mean - expected) / se
}

/// Φ⁻¹(p), the standard normal quantile (Acklam's rational approximation,
/// relative error below 1.2e-9).
pub fn normal_quantile(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969683028665376e1,
        2.209460984245205e2,
        -2.759285104469687e2,
        1.383_577_518_672_69e2,
        -3.066479806614716e1,
        2.506628277459239,
    ];
    const B: [f64; 5] = [
        -5.447609879822406e1,
        1.615858368580409e2,
        -1.556989798598866e2,
        6.680131188771972e1,
        -1.328068155288572e1,
    ];
    const C: [f64; 6] = [
        -7.784894002430293e-3,
        -3.223964580411365e-1,
        -2.400758277161838,
        -2.549732539343734,
        4.374664141464968,
        2.938163982698783,
    ];
    const D: [f64; 4] = [
        7.784695709041462e-3,
        3.224671290700398e-1,
        2.445134137142996,
        3.754408661907416,
    ];
    let p = p.clamp(1e-300, 1.0 - 1e-16);
    let lo = 0.02425;
    if p < lo {
        let q = (-2.0 * p.ln()).sqrt();
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    } else if p <= 1.0 - lo {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    } else {
        -normal_quantile(1.0 - p)
    }
}

/// The mean of a film's pixels.
pub fn film_mean(f: &Film) -> Vec3 {
    f.pixels.iter().sum::<Vec3>() / f.pixels.len().max(1) as f32
}

/// ` --scene <file>` for a scene loaded from a file, nothing for the
/// built-in one: the flag a command that remakes `scene` needs.
pub fn scene_flag(scene: &Scene) -> String {
    match scene.source.starts_with('<') {
        true => String::new(),
        false => format!(" --scene {}", scene.source),
    }
}

/// Renders the stored reference of `scene` (`spp` samples per pixel with
/// `path` and `sampler`, seeded by `seed`) into [`reference_dir`], with a
/// text file of every setting and the command that remakes it; returns that
/// text and the files written.
pub fn make_reference(
    engine: EngineChoice,
    path: &PathSettings,
    sampler: SamplerKind,
    scene: &Scene,
    spp: u32,
    seed: u64,
) -> Result<(String, Vec<PathBuf>)> {
    let camera = Camera::new(scene.camera)?;
    let spp = spp.max(1);
    let t = Instant::now();
    let mut acc = Accumulator::new(scene.camera.width, scene.camera.height, false);
    let engine = engine.make(scene);
    let chunk = 256;
    while acc.samples < spp {
        let count = chunk.min(spp - acc.samples);
        acc.add_samples(&*engine, &camera, path, sampler, seed, count);
        eprint!("\rreference: {}/{spp} spp", acc.samples);
    }
    eprintln!();
    let secs = t.elapsed().as_secs_f64();
    let meta = format!(
        "scene = {}\ncontent = {}\ntriangles = {}\nwidth = {}\nheight = {}\nspp = {spp}\nseed = {}\n\
         estimator = {}\nsampler = {}\nmax_bounces = {}\nrr_after = {}\nrr_scale = {}\npaths = {}\nseconds = {secs:.1}\n\
         threads = {}\ncommand = cargo run --release --bin ch6 -- --make-reference{} --width {} --height {} --spp {spp} \
         --seed {} --estimator {} --sampler {} {} --rr-after {} --rr-scale {}\n",
        scene.name,
        scene.content_hash(),
        scene.triangle_count(),
        acc.width,
        acc.height,
        seed,
        path.strategy.name(),
        sampler.name(),
        path.max_bounces.map_or("unlimited".into(), |k| k.to_string()),
        path.rr_min_bounce,
        path.rr_scale_for(sampler),
        acc.stats.paths,
        rayon::current_num_threads(),
        scene_flag(scene),
        acc.width,
        acc.height,
        seed,
        path.strategy.name(),
        sampler.name(),
        path.max_bounces
            .map_or("--unlimited".into(), |k| format!("--max-bounces {k}")),
        path.rr_min_bounce,
        path.rr_scale_for(sampler),
    );
    let name = stem(&scene.name, acc.width, acc.height);
    let files = StoredReference::save(&acc, &reference_dir(), &name, &meta)?;
    Ok((meta, files))
}
