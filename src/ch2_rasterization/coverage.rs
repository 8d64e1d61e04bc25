//! Coverage: which samples of which pixels a triangle covers.
//!
//! A sample is covered when all three edge functions are non-negative, a
//! zero counting only on a top-left edge (see [`super::edge`]). Two loops
//! do this: the readable one tests every sample of the screen against every
//! triangle; the one the renderer uses only visits the triangle's bounding
//! box, splits the screen into bands of rows that rayon renders in
//! parallel, and keeps the nearest triangle per sample in a depth buffer.
//! Both give the same covered samples (a test checks it).

use glam::I64Vec2;
use rayon::prelude::*;

use super::depth::{nearer, Sample};
use super::edge::{edge_fixed, fill_bias, SUBPIXEL};
use super::setup::ScreenTriangle;
use crate::core::sampling::random;

/// Rows per band of parallel work.
pub const BAND_ROWS: u32 = 8;

/// Position of sample `s` inside pixel (x, y) in fixed point, in [0, 256)²:
/// the pixel centre for 1 sample; for a square number of samples n = k², one
/// jittered sample in each cell of a k x k grid (stratified); otherwise
/// uniformly jittered samples. Jitter comes from (seed, pixel, sample).
// ANCHOR: sample_offset
pub fn sample_offset(spp: u32, seed: u64, pixel: u64, s: u32) -> I64Vec2 {
    if spp == 1 {
        return I64Vec2::splat(SUBPIXEL / 2);
    }
    let (r0, r1) = (
        random(seed, pixel, s as u64, 0) as f64,
        random(seed, pixel, s as u64, 1) as f64,
    );
    let k = (spp as f64).sqrt().round() as u32;
    let (x, y) = if k * k == spp {
        // Stratified: sample s takes cell (s mod k, s div k).
        (
            ((s % k) as f64 + r0) / k as f64,
            ((s / k) as f64 + r1) / k as f64,
        )
    } else {
        (r0, r1)
    };
    let q = |t: f64| ((t * SUBPIXEL as f64) as i64).min(SUBPIXEL - 1);
    I64Vec2::new(q(x), q(y))
}
// ANCHOR_END: sample_offset

/// The fixed-point position of sample `s` of pixel (x, y).
pub fn sample_position(spp: u32, seed: u64, width: u32, x: u32, y: u32, s: u32) -> I64Vec2 {
    let pixel = y as u64 * width as u64 + x as u64;
    I64Vec2::new(x as i64 * SUBPIXEL, y as i64 * SUBPIXEL) + sample_offset(spp, seed, pixel, s)
}

/// Whether the sample at fixed-point `p` is inside `tri`, with the top-left
/// rule on its edges.
// ANCHOR: covers
pub fn covers(tri: &ScreenTriangle, p: I64Vec2) -> bool {
    let [v0, v1, v2] = tri.v;
    edge_fixed(v1, v2, p) + fill_bias(v1, v2) >= 0
        && edge_fixed(v2, v0, p) + fill_bias(v2, v0) >= 0
        && edge_fixed(v0, v1, p) + fill_bias(v0, v1) >= 0
}
// ANCHOR_END: covers

/// The readable loop: for every triangle, test every sample of the screen;
/// returns how many triangles cover each sample (index (y·w + x)·spp + s).
// ANCHOR: coverage_counts
pub fn coverage_counts(
    tris: &[ScreenTriangle],
    width: u32,
    height: u32,
    spp: u32,
    seed: u64,
) -> Vec<u32> {
    let mut counts = vec![0; (width * height * spp) as usize];
    for tri in tris {
        for y in 0..height {
            for x in 0..width {
                for s in 0..spp {
                    if covers(tri, sample_position(spp, seed, width, x, y, s)) {
                        counts[((y * width + x) * spp + s) as usize] += 1;
                    }
                }
            }
        }
    }
    counts
}
// ANCHOR_END: coverage_counts

/// Every sample's nearest triangle after rasterizing a whole frame.
#[derive(Clone, Debug, PartialEq)]
pub struct SampleBuffer {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels: the rows it holds.
    pub height: u32,
    /// The image row its first row is (0 unless the frame is a band of a
    /// larger image): it holds rows `first_row .. first_row + height`.
    pub first_row: u32,
    /// Samples per pixel.
    pub spp: u32,
    /// Seed of the sample positions.
    pub seed: u64,
    /// `width * height * spp` samples, pixel by pixel, row by row.
    pub samples: Vec<Sample>,
}

impl SampleBuffer {
    /// Fixed-point position of sample `s` of pixel (x, y) of the image.
    pub fn position(&self, x: u32, y: u32, s: u32) -> I64Vec2 {
        sample_position(self.spp, self.seed, self.width, x, y, s)
    }

    /// The fraction of each pixel's samples that some triangle covers.
    pub fn coverage(&self) -> Vec<f64> {
        self.samples
            .chunks(self.spp as usize)
            .map(|c| c.iter().filter(|s| s.is_covered()).count() as f64 / self.spp as f64)
            .collect()
    }
}

/// The fast loop: bins triangles into bands of [`BAND_ROWS`] rows, then
/// rasterizes the bands in parallel, each triangle only over its bounding
/// box, with a depth test per sample. The result does not depend on the
/// number of threads or the order of triangles in a band: the depth test
/// breaks ties by triangle index. Only rows `rows` of the image are
/// rasterized (all of them: `0..height`).
// ANCHOR: rasterize
pub fn rasterize(
    tris: &[ScreenTriangle],
    width: u32,
    rows: std::ops::Range<u32>,
    spp: u32,
    seed: u64,
) -> SampleBuffer {
    let height = rows.len() as u32;
    let bands = height.div_ceil(BAND_ROWS) as usize;
    // Bin: each band gets the triangles whose bounding box reaches it.
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); bands];
    for (t, tri) in tris.iter().enumerate() {
        if tri.bbox[3] < rows.start || tri.bbox[1] >= rows.end {
            continue;
        }
        let band_of = |y: u32| (y.clamp(rows.start, rows.end - 1) - rows.start) / BAND_ROWS;
        for bin in &mut bins[band_of(tri.bbox[1]) as usize..=band_of(tri.bbox[3]) as usize] {
            bin.push(t as u32);
        }
    }
    let per_band = (BAND_ROWS * width * spp) as usize;
    let mut samples = vec![Sample::EMPTY; (width * height * spp) as usize];
    samples
        .par_chunks_mut(per_band)
        .zip(bins.par_iter())
        .enumerate()
        .for_each(|(band, (buffer, bin))| {
            let y_band = rows.start + band as u32 * BAND_ROWS;
            let rows = (buffer.len() / (width * spp) as usize) as u32;
            // Sample positions of the band, computed once.
            let offsets: Vec<I64Vec2> = (0..rows * width * spp)
                .map(|i| {
                    let (pixel, s) = (i / spp, i % spp);
                    let (x, y) = (pixel % width, y_band + pixel / width);
                    sample_position(spp, seed, width, x, y, s)
                })
                .collect();
            for &t in bin {
                let tri = &tris[t as usize];
                let y0 = tri.bbox[1].max(y_band);
                let y1 = tri.bbox[3].min(y_band + rows - 1);
                raster_rows(tri, t, y0..=y1, y_band, width, spp, &offsets, buffer);
            }
        });
    SampleBuffer {
        width,
        height,
        first_row: rows.start,
        spp,
        seed,
        samples,
    }
}
// ANCHOR_END: rasterize

/// One triangle over rows `rows` of a band starting at row `y_band`.
// ANCHOR: raster_rows
#[allow(clippy::too_many_arguments)]
fn raster_rows(
    tri: &ScreenTriangle,
    t: u32,
    rows: std::ops::RangeInclusive<u32>,
    y_band: u32,
    width: u32,
    spp: u32,
    positions: &[I64Vec2],
    buffer: &mut [Sample],
) {
    let [v0, v1, v2] = tri.v;
    let bias = [fill_bias(v1, v2), fill_bias(v2, v0), fill_bias(v0, v1)];
    let area = tri.area as f64;
    for y in rows {
        let row = ((y - y_band) * width) as usize;
        for x in tri.bbox[0]..=tri.bbox[2] {
            for s in 0..spp as usize {
                let i = (row + x as usize) * spp as usize + s;
                let p = positions[i];
                let w = [
                    edge_fixed(v1, v2, p),
                    edge_fixed(v2, v0, p),
                    edge_fixed(v0, v1, p),
                ];
                if w[0] + bias[0] < 0 || w[1] + bias[1] < 0 || w[2] + bias[2] < 0 {
                    continue;
                }
                // 1/w is linear on the screen: interpolate it with φ = w / area.
                let inv_w = (w[0] as f64 * tri.inv_w[0]
                    + w[1] as f64 * tri.inv_w[1]
                    + w[2] as f64 * tri.inv_w[2])
                    / area;
                let candidate = Sample {
                    inv_w: inv_w as f32,
                    tri: t,
                };
                if nearer(&candidate, &buffer[i]) {
                    buffer[i] = candidate;
                }
            }
        }
    }
}
// ANCHOR_END: raster_rows
