//! What traces a render pass's paths. The lesson's answer is
//! [`PathLoop`]: chapter 3's tree answers the ray queries and
//! [`trace_path`] follows one path at a time. A faster engine (the `raystep-fast`
//! crate, `src/fast/`) answers the same [`PathEngine`] questions
//! with the same images; a front end chooses one engine, once, with an
//! [`EngineChoice`], and nothing in the chapters asks which it got.

use glam::Vec3;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::render;
use crate::ch5_reflection::world::World;
use crate::scene::Scene;

use super::integrator::{trace_path, PathSettings, PathStats};
use super::layers::LAYER_SLOTS;
use super::sampler::{PathSampler, SamplerKind};

/// The random numbers and the camera ray of sample `sample` of pixel
/// (`x`, `y`): the first two numbers place the ray in the pixel, the path
/// goes on with the rest. Anything that wants to trace the very sample a
/// render traced starts here.
pub fn camera_sample(
    camera: &Camera,
    kind: SamplerKind,
    seed: u64,
    x: usize,
    y: usize,
    sample: u32,
) -> (PathSampler, Ray) {
    render::camera_sample(camera, (x as u32, y as u32), |pixel| {
        PathSampler::new(kind, seed, pixel, sample as u64)
    })
}

/// The samples one render pass asks for: samples `first .. first + count`
/// of every pixel, with these settings.
#[derive(Clone, Copy)]
pub struct PassSpec<'a> {
    /// The camera the paths start from.
    pub camera: &'a Camera,
    /// Bounces, estimator, roulette.
    pub settings: &'a PathSettings,
    /// Where the random numbers come from, and the render's seed.
    pub sampler: (SamplerKind, u64),
    /// The first sample of this pass, per pixel.
    pub first: u32,
    /// Samples per pixel in this pass.
    pub count: u32,
}

/// One row of the film's sums, for one pass to add to.
pub struct RowSums<'a> {
    /// The row.
    pub y: usize,
    /// Σ L per pixel.
    pub sum: &'a mut [Vec3],
    /// Σ L² per pixel and channel.
    pub sum_sq: &'a mut [Vec3],
    /// Σ L per pixel and layer slot, if layers are kept.
    pub layers: Option<&'a mut [[Vec3; LAYER_SLOTS]]>,
    /// Per pixel, the contributions that were not finite (NaN or
    /// infinite): counted, and left out of the sums.
    pub caught: &'a mut [u32],
}

/// An engine: a world built for its ray queries, and a way to trace one
/// row's samples of a pass. Each pixel's samples are added in order, so
/// the images do not depend on how rows are shared among threads.
pub trait PathEngine: Send + Sync {
    /// The world the paths are traced in.
    fn world(&self) -> &World;

    /// Traces `pass`'s samples of row `row.y`, adding them to `row`.
    fn trace_row(&self, pass: &PassSpec, row: RowSums<'_>, stats: &mut PathStats);

    /// For the report: what this engine uses with `settings` (the first
    /// list) and what it leaves out (the second).
    fn notes(&self, _settings: &PathSettings) -> (Vec<String>, Vec<String>) {
        (Vec::new(), Vec::new())
    }
}

/// The lesson's engine: the world as chapter 5 builds it (chapter 3's
/// tree), each path traced by [`trace_path`].
pub struct PathLoop {
    world: World,
}

impl PathLoop {
    /// The lesson's engine for `scene`.
    pub fn new(scene: &Scene) -> PathLoop {
        PathLoop {
            world: World::new(scene),
        }
    }
}

impl PathEngine for PathLoop {
    fn world(&self) -> &World {
        &self.world
    }

    fn trace_row(&self, pass: &PassSpec, row: RowSums<'_>, stats: &mut PathStats) {
        trace_row(&self.world, pass, row, stats);
    }
}

/// The lesson's row: each pixel's samples one path at a time.
// ANCHOR: trace_row
pub fn trace_row(world: &World, pass: &PassSpec, mut row: RowSums<'_>, stats: &mut PathStats) {
    let (kind, seed) = pass.sampler;
    for x in 0..row.sum.len() {
        let caught_before = stats.nonfinite;
        for s in pass.first..pass.first + pass.count {
            let (mut sampler, ray) = camera_sample(pass.camera, kind, seed, x, row.y, s);
            let l = match row.layers.as_deref_mut() {
                Some(layers) => {
                    let mut path = [Vec3::ZERO; LAYER_SLOTS];
                    trace_path(world, ray, &mut sampler, pass.settings, &mut path, stats);
                    for (acc, v) in layers[x].iter_mut().zip(path) {
                        *acc += v;
                    }
                    path.iter().sum()
                }
                None => {
                    let mut l = Vec3::ZERO;
                    trace_path(world, ray, &mut sampler, pass.settings, &mut l, stats);
                    l
                }
            };
            row.sum[x] += l;
            row.sum_sq[x] += l * l;
        }
        row.caught[x] += (stats.nonfinite - caught_before) as u32;
    }
}
// ANCHOR_END: trace_row

/// How a front end names an engine and makes it for a scene: chosen once
/// (from `--engine`, or the default), then handed to the stage.
#[derive(Clone, Copy)]
pub struct EngineChoice {
    /// A short name for tables and messages.
    pub name: &'static str,
    /// Builds the engine's world for a scene.
    pub build: fn(&Scene) -> Box<dyn PathEngine>,
}

impl EngineChoice {
    /// The lesson's engine ([`PathLoop`], `--engine readable`): chapter
    /// 5's world, whose queries chapter 3's four-wide tree answers (not
    /// the binary tree of exercise 3.4), and [`trace_path`].
    pub const READABLE: EngineChoice = EngineChoice {
        name: "readable",
        build: |scene| Box::new(PathLoop::new(scene)),
    };

    /// The engine for `scene`.
    pub fn make(&self, scene: &Scene) -> Box<dyn PathEngine> {
        (self.build)(scene)
    }
}

impl PartialEq for EngineChoice {
    fn eq(&self, other: &EngineChoice) -> bool {
        self.name == other.name
    }
}

impl Eq for EngineChoice {}

impl std::fmt::Debug for EngineChoice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}
