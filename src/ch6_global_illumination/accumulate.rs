//! The accumulation film of a progressive render: per pixel the sum and
//! the sum of squares of the sample values (for the mean and its standard
//! error), and, when asked for, the sum per bounce layer. Each pass adds a
//! few samples per pixel; the image can be read after any pass.

use glam::Vec3;
use rayon::prelude::*;

use crate::ch1_projection::camera::Camera;
use crate::core::film::Film;

use super::engine::{PassSpec, PathEngine, RowSums};
use super::integrator::{PathSettings, PathStats};
use super::layers::{LAYER_SLOTS, RENDER_LAYERS};
use super::sampler::SamplerKind;

/// Sums over the samples taken so far.
#[derive(Clone, Debug)]
pub struct Accumulator {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels: the rows it holds.
    pub height: u32,
    /// The image row its first row is (0 unless the run renders in bands):
    /// it holds rows `first_row .. first_row + height`.
    pub first_row: u32,
    /// Samples per pixel so far.
    pub samples: u32,
    /// Σ L per pixel.
    pub sum: Vec<Vec3>,
    /// Σ L² per pixel and channel.
    pub sum_sq: Vec<Vec3>,
    /// Σ L per pixel and layer slot; `None` when only the final image is
    /// wanted (nothing allocated for layers then).
    pub layers: Option<Vec<[Vec3; LAYER_SLOTS]>>,
    /// Per pixel, the contributions that were NaN or infinite, counted and
    /// left out of the sums (so a viewer can show where they were).
    pub caught: Vec<u32>,
    /// Counts over every pass.
    pub stats: PathStats,
}

impl Accumulator {
    /// An empty accumulator, with layer sums if `layers`.
    pub fn new(width: u32, height: u32, layers: bool) -> Accumulator {
        Accumulator::of_rows(width, 0..height, layers)
    }

    /// An empty accumulator for rows `rows` of an image `width` pixels wide.
    pub fn of_rows(width: u32, rows: std::ops::Range<u32>, layers: bool) -> Accumulator {
        let n = width as usize * rows.len();
        Accumulator {
            width,
            height: rows.len() as u32,
            first_row: rows.start,
            samples: 0,
            sum: vec![Vec3::ZERO; n],
            sum_sq: vec![Vec3::ZERO; n],
            layers: layers.then(|| vec![[Vec3::ZERO; LAYER_SLOTS]; n]),
            caught: vec![0; n],
            stats: PathStats::default(),
        }
    }

    /// Traces samples `first .. first + count` of every pixel with
    /// `engine`, rows in parallel. The result does not depend on the
    /// number of threads: each pixel's samples are added in order by one
    /// thread.
    // ANCHOR: render_pass
    // ANCHOR: render_pass_setup
    pub fn add_samples(
        &mut self,
        engine: &dyn PathEngine,
        camera: &Camera,
        settings: &PathSettings,
        sampler: SamplerKind,
        seed: u64,
        count: u32,
    ) {
        let (w, first_row) = (self.width as usize, self.first_row as usize);
        let pass = PassSpec {
            camera,
            settings,
            sampler: (sampler, seed),
            first: self.samples,
            count,
        };
        let mut layer_rows: Vec<Option<&mut [[Vec3; LAYER_SLOTS]]>> = match &mut self.layers {
            Some(l) => l.chunks_mut(w).map(Some).collect(),
            None => (0..self.height).map(|_| None).collect(),
        };
        // ANCHOR_END: render_pass_setup
        // ANCHOR: render_pass_rows
        let stats = self
            .sum
            .par_chunks_mut(w)
            .zip(self.sum_sq.par_chunks_mut(w))
            .zip(layer_rows.par_iter_mut())
            .zip(self.caught.par_chunks_mut(w))
            .enumerate()
            .map(|(i, (((sum, sum_sq), layers), caught))| {
                let mut stats = PathStats::default();
                let layers = layers.take();
                engine.trace_row(
                    &pass,
                    RowSums {
                        y: first_row + i,
                        sum,
                        sum_sq,
                        layers,
                        caught,
                    },
                    &mut stats,
                );
                stats
            })
            .reduce(PathStats::default, |mut a, b| {
                a.add(&b);
                a
            });
        self.stats.add(&stats);
        self.samples += count;
    }
    // ANCHOR_END: render_pass_rows
    // ANCHOR_END: render_pass

    /// The mean image.
    pub fn mean(&self) -> Film {
        let inv = 1.0 / self.samples.max(1) as f32;
        Film {
            width: self.width,
            height: self.height,
            pixels: self.sum.iter().map(|s| *s * inv).collect(),
        }
    }

    /// Per pixel and channel, the estimated variance of the mean:
    /// s² / n with the unbiased sample variance s².
    pub fn variance_of_mean(&self) -> Film {
        let n = self.samples as f64;
        let pixels = self
            .sum
            .iter()
            .zip(&self.sum_sq)
            .map(|(s, q)| {
                if n < 2.0 {
                    return Vec3::ZERO;
                }
                let (s, q) = (s.as_dvec3(), q.as_dvec3());
                let var = ((q - s * s / n) / (n - 1.0)).max(glam::DVec3::ZERO);
                (var / n).as_vec3()
            })
            .collect();
        Film {
            width: self.width,
            height: self.height,
            pixels,
        }
    }

    /// The mean of layer slot `slot` (see [`super::integrator`]), if layers
    /// are kept.
    pub fn layer(&self, slot: usize) -> Option<Film> {
        let layers = self.layers.as_ref()?;
        let inv = 1.0 / self.samples.max(1) as f32;
        Some(Film {
            width: self.width,
            height: self.height,
            pixels: layers.iter().map(|l| l[slot] * inv).collect(),
        })
    }

    /// The mean of slots `0 ..= last` summed: the image "up to" a bounce.
    pub fn prefix(&self, last: usize) -> Option<Film> {
        let layers = self.layers.as_ref()?;
        let inv = 1.0 / self.samples.max(1) as f32;
        Some(Film {
            width: self.width,
            height: self.height,
            pixels: layers
                .iter()
                .map(|l| l[..=last].iter().sum::<Vec3>() * inv)
                .collect(),
        })
    }

    /// Per-bounce layers as [`Snapshot::layers`](crate::core::stage::Snapshot::layers)
    /// defines them, if layers are kept.
    pub fn render_layers(&self) -> Option<Vec<Film>> {
        // layers[0] is direct illumination with the emitters seen directly
        // included, layers[k] bounce k; the last holds everything beyond:
        // RENDER_LAYERS, one fewer than the slots.
        // One sweep over the sums (they are stored per pixel, all slots
        // together), as `layer(slot)` for every slot would read them
        // all once per slot.
        let sums = self.layers.as_ref()?;
        let inv = 1.0 / self.samples.max(1) as f32;
        let (w, h) = (self.width, self.height);
        let mut out: Vec<Film> = (0..RENDER_LAYERS).map(|_| Film::new(w, h)).collect();
        for (i, l) in sums.iter().enumerate() {
            for slot in 1..LAYER_SLOTS {
                let mut v = l[slot] * inv;
                if slot == 1 {
                    v += l[0] * inv;
                }
                out[slot - 1].pixels[i] = v;
            }
        }
        for f in &mut out {
            f.scrub_nonfinite();
        }
        Some(out)
    }
}

/// The box-filtered image at 1/`factor` the resolution (each output pixel
/// the mean of a factor x factor block). With box-filtered pixels this has
/// exactly the expectation of a render at the lower resolution.
pub fn downsample(film: &Film, factor: u32) -> Film {
    let (w, h) = (film.width / factor, film.height / factor);
    let mut out = Film::new(w, h);
    let inv = 1.0 / (factor * factor) as f32;
    for y in 0..h {
        for x in 0..w {
            let mut s = Vec3::ZERO;
            for dy in 0..factor {
                for dx in 0..factor {
                    s += film.get(x * factor + dx, y * factor + dy);
                }
            }
            *out.get_mut(x, y) = s * inv;
        }
    }
    out
}
