//! The camera rays that start the fast engine's paths, with the pixel
//! positions of eight Sobol samples drawn at once.

use glam::Vec2;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::render::camera_sample;
use crate::ch6_global_illumination::sampler::{PathSampler, SamplerKind};

use super::lanes::W;
use super::level::Level;

/// The camera rays and samplers of samples `first .. first + count` of
/// pixels `xs` of row `y`, in that order: what chapter 6's `camera_sample`
/// gives (chapter 3's, which hands the closure this same pixel index), with
/// the pixel positions of eight Sobol samples drawn at once
/// ([`sobol_groups8_wanted_at`](super::simd::sobol_groups8_wanted_at), the same bits). The
/// eight may belong to different pixels: a pass of fewer than eight
/// samples per pixel (the terminal UI's) is drawn eight at a time too
/// (`across_pixels`).
pub fn camera_starts(
    camera: &Camera,
    level: Level,
    (kind, seed): (SamplerKind, u64),
    (xs, y): (std::ops::Range<usize>, usize),
    (first, count): (u32, u32),
) -> Vec<(Ray, PathSampler)> {
    if count < W as u32 {
        return across_pixels(camera, level, (kind, seed), (xs, y), (first, count));
    }
    let mut starts = Vec::with_capacity(xs.len() * count as usize);
    for x in xs {
        let pixel = (y * camera.width as usize + x) as u64;
        let one_by_one =
            |sampler: PathSampler| camera_sample(camera, (x as u32, y as u32), |_| sampler);
        let mut s = first;
        while s < first + count {
            if s + W as u32 > first + count {
                // The last few samples of the pixel.
                let (sampler, ray) = one_by_one(PathSampler::new(kind, seed, pixel, s as u64));
                starts.push((ray, sampler));
                s += 1;
                continue;
            }
            let samplers: [PathSampler; W] =
                std::array::from_fn(|j| PathSampler::new(kind, seed, pixel, (s + j as u32) as u64));
            s += W as u32;
            eight_starts((camera, level), ([x; W], y), samplers, &mut starts);
        }
    }
    starts
}

/// [`camera_starts`] for fewer than eight samples per pixel: eight starts
/// at once whatever pixels they belong to.
fn across_pixels(
    camera: &Camera,
    level: Level,
    (kind, seed): (SamplerKind, u64),
    (xs, y): (std::ops::Range<usize>, usize),
    (first, count): (u32, u32),
) -> Vec<(Ray, PathSampler)> {
    let total = xs.len() * count as usize;
    let mut starts = Vec::with_capacity(total);
    // Every (pixel, sample) in order: sample `first .. first + count` of
    // each pixel of `xs`.
    let mut all = xs.flat_map(|x| (first..first + count).map(move |s| (x, s)));
    let sampler = |(x, s): (usize, u32)| {
        let pixel = (y * camera.width as usize + x) as u64;
        PathSampler::new(kind, seed, pixel, s as u64)
    };
    let one_by_one = |(x, s): (usize, u32)| {
        let (sampler, ray) = camera_sample(camera, (x as u32, y as u32), |_| sampler((x, s)));
        (ray, sampler)
    };
    let mut left = total;
    while left > 0 {
        if left < W {
            // The last few.
            starts.extend(all.by_ref().map(one_by_one));
            break;
        }
        left -= W;
        let at: [(usize, u32); W] = std::array::from_fn(|_| all.next().unwrap_or((0, 0)));
        eight_starts(
            (camera, level),
            (at.map(|(x, _)| x), y),
            at.map(sampler),
            &mut starts,
        );
    }
    starts
}

/// The camera rays of eight samplers, lane j's in pixel (`xs[j]`, `y`),
/// pushed on `starts` in order: their pixel positions drawn at once where
/// all eight draw Sobol points from the tables, one at a time by
/// `camera_sample` otherwise.
#[inline(always)]
fn eight_starts(
    (camera, level): (&Camera, Level),
    (xs, y): ([usize; W], usize),
    samplers: [PathSampler; W],
    starts: &mut Vec<(Ray, PathSampler)>,
) {
    let Some((sample, scramble)) = sobol_lanes(|j| &samplers[j]) else {
        // Independent numbers, or Sobol indices past the tables.
        for (x, sampler) in xs.into_iter().zip(samplers) {
            let (sampler, ray) = camera_sample(camera, (x as u32, y as u32), |_| sampler);
            starts.push((ray, sampler));
        }
        return;
    };
    // Only the first two numbers: the pixel position.
    let [g] = super::simd::sobol_groups8_wanted_at(level, &sample, &scramble, 0, 0b11);
    for (j, (x, mut sampler)) in xs.into_iter().zip(samplers).enumerate() {
        // `jittered`: the pixel's corner plus the first two numbers.
        let raster = Vec2::new(x as f32, y as f32) + Vec2::new(g[0][j], g[1][j]);
        sampler.skip(2);
        starts.push((camera.ray(raster), sampler));
    }
}

/// The sample indices and pixel scrambles of eight samplers (`sampler(j)`
/// for lane j), when all of them draw Sobol points from the tables: what
/// [`sobol_groups8_at`](super::simd::sobol_groups8_at) needs to draw for them.
pub(super) fn sobol_lanes<'a>(
    sampler: impl Fn(usize) -> &'a PathSampler,
) -> Option<([u32; W], [u64; W])> {
    let index: [Option<u32>; W] = std::array::from_fn(|j| sampler(j).sobol_index());
    index.iter().all(Option::is_some).then(|| {
        let sample = std::array::from_fn(|j| index[j].unwrap_or(0));
        (sample, std::array::from_fn(|j| sampler(j).pixel_scramble()))
    })
}
