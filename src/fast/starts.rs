//! The camera rays that start the fast engine's paths, eight at a time.

use glam::Vec3;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::render::camera_sample;
use crate::ch6_global_illumination::integrator::Path;
use crate::ch6_global_illumination::sampler::{PathSampler, SamplerKind};

use super::gather8::{sobol_lanes, Lane};
use super::lanes::W;
use super::level::Level;

/// The paths of samples `first .. first + count` of pixels `xs` of row
/// `y`, in that order, pushed on `lanes` (each lane's `out` its place in
/// that order): what chapter 6's `camera_sample` gives (chapter 3's, which
/// hands the closure this same pixel index), eight at a time where eight
/// samplers draw from the tables or independent numbers alike (their
/// pixel positions drawn at once, [`sobol_groups8_wanted_at`](super::simd::sobol_groups8_wanted_at)
/// or [`independent8_wanted_at`](super::simd::independent8_wanted_at), and
/// their rays made at once, [`rays8`]: the same bits). The eight may belong
/// to different pixels: a pass of fewer than eight samples per pixel (the
/// terminal UI's) is drawn eight at a time too.
pub(super) fn camera_lanes(
    (camera, level): (&Camera, Level),
    (kind, seed): (SamplerKind, u64),
    (xs, y): (std::ops::Range<usize>, usize),
    (first, count): (u32, u32),
    new_path: impl Fn(&Ray) -> Path,
    lanes: &mut Vec<Lane>,
) {
    // Every camera ray leaves the eye, so every path starts alike: one
    // start, copied (built once, it is also never read back while its
    // fields are still being written).
    let start = new_path(&camera.ray(glam::Vec2::ZERO));
    let total = xs.len() * count as usize;
    lanes.reserve(total);
    // Every (pixel, sample) in order: sample `first .. first + count` of
    // each pixel of `xs`.
    let mut all = xs.flat_map(|x| (first..first + count).map(move |s| (x, s)));
    let sampler = |(x, s): (usize, u32)| {
        let pixel = (y * camera.width as usize + x) as u64;
        PathSampler::new(kind, seed, pixel, s as u64)
    };
    let push = |ray: Ray, sampler: PathSampler, lanes: &mut Vec<Lane>| {
        let out = lanes.len() as u32;
        lanes.push(Lane {
            path: start.clone(),
            ray,
            sampler,
            out,
        });
    };
    let mut left = total;
    while left > 0 {
        if left < W {
            // The last few, one at a time.
            for (x, s) in all.by_ref() {
                let (sampler, ray) =
                    camera_sample(camera, (x as u32, y as u32), |_| sampler((x, s)));
                push(ray, sampler, lanes);
            }
            break;
        }
        left -= W;
        let at: [(usize, u32); W] = std::array::from_fn(|_| all.next().unwrap_or((0, 0)));
        let mut samplers = at.map(sampler);
        let Some(u) = pixel_numbers(level, &samplers) else {
            // Sobol points and independent numbers mixed (indices past
            // the tables): the lesson's steps, one at a time.
            for ((x, _), sampler) in at.into_iter().zip(samplers) {
                let (sampler, ray) = camera_sample(camera, (x as u32, y as u32), |_| sampler);
                push(ray, sampler, lanes);
            }
            continue;
        };
        // `jittered`: the pixel's corner plus the first two numbers.
        let raster_x = std::array::from_fn(|j| at[j].0 as f32 + u[0][j]);
        let raster_y = std::array::from_fn(|j| y as f32 + u[1][j]);
        // The numbers taken, before the samplers are copied into the lanes.
        for sampler in &mut samplers {
            sampler.skip(2);
        }
        let rays = rays8(camera, &raster_x, &raster_y);
        for (ray, sampler) in rays.iter().zip(&samplers) {
            push(*ray, sampler.clone(), lanes);
        }
    }
}

/// The first two numbers (the pixel position) of eight samplers,
/// `u[d][j]`, drawn at once: where all eight draw Sobol points from the
/// tables, or all eight independent numbers (`None` otherwise).
fn pixel_numbers(level: Level, samplers: &[PathSampler; W]) -> Option<[[f32; W]; 2]> {
    if let Some((sample, scramble)) = sobol_lanes(|j| &samplers[j]) {
        let [g] = super::simd::sobol_groups8_wanted_at(level, &sample, &scramble, 0, 0b11);
        return Some([g[0], g[1]]);
    }
    let prefix: [Option<u64>; W] = std::array::from_fn(|j| samplers[j].independent_prefix());
    prefix.iter().all(Option::is_some).then(|| {
        let prefix = prefix.map(|p| p.unwrap_or(0));
        let u = super::simd::independent8_wanted_at(level, &prefix, 0, 0b11);
        [u[0], u[1]]
    })
}

/// Eight camera rays through the raster positions (`raster_x[j]`,
/// `raster_y[j]`): [`Camera::ray`]'s steps, one pass over eight lanes
/// each, in the same order (so the same bits: the image plane's point,
/// glam's `transform_vector3` as its sums fall, and `normalize` as one
/// over the square root of x² + y² + z², times each component).
// Lane loops index several arrays by lane, on purpose (vector code).
#[allow(clippy::needless_range_loop)]
pub fn rays8(camera: &Camera, raster_x: &[f32; W], raster_y: &[f32; W]) -> [Ray; W] {
    let m = &camera.world_from_camera;
    let origin = m.transform_point3(Vec3::ZERO);
    let (t, aspect) = (camera.tan_half_fov, camera.aspect);
    let (w, h) = (camera.width as f32, camera.height as f32);
    let mut d = [[0.0f32; W]; 3];
    for j in 0..W {
        let u = (raster_x[j] / w * 2.0 - 1.0) * aspect * t;
        let v = (1.0 - raster_y[j] / h * 2.0) * t;
        // The camera-space direction (u, v, -1) in world space (z's
        // axis times -1 is its negation, exactly).
        for (c, d) in d.iter_mut().enumerate() {
            d[j] = -m.z_axis[c] + (m.y_axis[c] * v + m.x_axis[c] * u);
        }
    }
    let mut r = [0.0f32; W];
    for j in 0..W {
        r[j] = 1.0 / (d[0][j] * d[0][j] + d[1][j] * d[1][j] + d[2][j] * d[2][j]).sqrt();
    }
    std::array::from_fn(|j| Ray {
        origin,
        dir: Vec3::new(d[0][j] * r[j], d[1][j] * r[j], d[2][j] * r[j]),
    })
}
