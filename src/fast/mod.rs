//! Making it fast: the engine `ch6`, `raystep` and the terminal UI use
//! unless told `--engine readable`. It lives beside the chapters, not in
//! them: it answers chapter 6's [`PathEngine`] questions, and no lesson
//! file imports it. This module and its [`simd`] dispatch are the only
//! place with `unsafe` code.
//!
//! Two things change. What answers the ray queries: the readable engine
//! asks chapter 3's tree, collapsed four-wide, with glam's four-lane
//! vectors; the fast engine asks an eight-wide tree ([`bvh8`]) whose box
//! and triangle tests run over eight lanes at once, compiled for the
//! widest vector instructions the CPU has ([`simd`]). Both compute each
//! lane with the same arithmetic in the same order, so they find the same
//! hits. And the path loop: on triangle scenes the fast engine extends
//! thousands of paths a bounce at a time ([`wave`]). It shades diffuse
//! hits with MIS (the benchmark's) eight at once ([`shade8`]), with the
//! lesson's formulas and the lesson's random numbers, so it follows the
//! same paths as the lesson's
//! [`trace_path`](crate::ch6_global_illumination::integrator::trace_path) to the last bits of a
//! sine; every other vertex runs `trace_path`'s own steps ([`step`]), bit
//! for bit. Scenes with SDFs run `trace_path` itself over the eight-wide
//! tree and make the readable engine's images byte for byte. A test
//! checks both, and that the fast engine makes the same bytes on every
//! SIMD path.
//!
//! Scenes with SDFs are marched as chapter 4 teaches either way; only
//! their triangles go through the eight-wide tree.

#![deny(unsafe_code)]
#![warn(missing_docs)]

// The lessons under their own names, so that paths read as in them
// (`crate::ch3_ray_triangle::…`).
use raystep_lessons::{
    ch1_projection, ch2_rasterization, ch3_ray_triangle, ch4_implicit_surfaces, ch5_reflection,
    ch6_global_illumination, core, scene,
};

pub mod chapters;

pub mod bench;
pub mod bvh8;
pub mod gather8;
pub mod kernels;
pub mod lane_rays;
pub mod lanes;
pub mod level;
pub mod packet;
pub mod pick8;
mod portable;
pub mod shade8;
#[allow(unsafe_code)]
pub mod simd;
pub mod sobol8;
pub mod starts;
pub mod step;
pub mod wave;

use std::sync::Arc;

use glam::Vec3;

use crate::ch5_reflection::world::{Queries, World};
use crate::ch6_global_illumination::engine::{
    trace_row, EngineChoice, PassSpec, PathEngine, RowSums,
};
use crate::ch6_global_illumination::integrator::{Path, PathSettings, PathStats};
use crate::ch6_global_illumination::layers::{Contributions, LAYER_SLOTS};
use crate::scene::Scene;

use bvh8::Bvh8;
use level::Level;

/// The fast engine, as a front end chooses it (`--engine fast`, the
/// default of `ch6`, `raystep` and the terminal UI).
pub const FAST: EngineChoice = EngineChoice {
    name: "fast",
    build: |scene| Box::new(FastEngine::new(scene)),
};

/// The fast engine: the world's ray queries answered by the eight-wide
/// tree, and the wavefront loop for the scenes it covers
/// ([`wave::supports`]); elsewhere the lesson's row loop over that tree.
pub struct FastEngine {
    world: World,
    /// The world's tree (`None`: no triangles), shared with the world's
    /// queries.
    tree: Option<Arc<Bvh8>>,
}

impl FastEngine {
    /// The fast engine for `scene`, with the CPU's best instructions.
    pub fn new(scene: &Scene) -> FastEngine {
        FastEngine::at(scene, simd::best())
    }

    /// The fast engine for `scene` with `level`'s instructions (the
    /// portable ones if this CPU lacks them).
    pub fn at(scene: &Scene, level: Level) -> FastEngine {
        let mut tree = None;
        let world = World::with_queries(scene, |tris| {
            let built = Arc::new(Bvh8::build(tris, level)?);
            tree = Some(built.clone());
            Some(Box::new(simd::SharedTree(built)) as Box<Queries>)
        });
        FastEngine { world, tree }
    }

    /// Its eight-wide tree, if the scene has triangles.
    pub fn tree(&self) -> Option<&Bvh8> {
        self.tree.as_deref()
    }

    /// The tree, if the wavefront loop traces this scene's paths.
    fn wave_tree(&self) -> Option<&Bvh8> {
        self.tree().filter(|_| wave::supports(&self.world))
    }
}

impl PathEngine for FastEngine {
    fn world(&self) -> &World {
        &self.world
    }

    fn trace_row(&self, pass: &PassSpec, row: RowSums<'_>, stats: &mut PathStats) {
        match self.wave_tree() {
            Some(tree) => wave_row(&self.world, tree, pass, row, stats),
            None => trace_row(&self.world, pass, row, stats),
        }
    }

    fn notes(&self, settings: &PathSettings) -> (Vec<String>, Vec<String>) {
        let lanes = match wave::lanes_shade(&self.world, settings) {
            true => "diffuse hits shaded eight at once, the others by the lesson's steps",
            false => "every hit shaded by the lesson's steps, one path at a time",
        };
        match (self.tree(), self.wave_tree()) {
            (_, Some(_)) => (
                vec![format!(
                    "the fast engine's wavefront loop: paths extended a bounce at a time, {lanes}"
                )],
                Vec::new(),
            ),
            (Some(_), None) => (
                Vec::new(),
                vec![
                    "the wavefront loop: it covers scenes without SDFs; the lesson's path loop \
                     runs instead"
                        .into(),
                ],
            ),
            (None, None) => (Vec::new(), Vec::new()),
        }
    }
}

/// One path's light, and how many of its contributions were NaN or
/// infinite (left out, and counted for the row's pixel).
#[derive(Clone, Copy)]
struct Counted<C> {
    light: C,
    caught: u32,
}

impl<C: Contributions> Contributions for Counted<C> {
    #[inline(always)]
    fn add_to(&mut self, slot: usize, c: Vec3) {
        self.light.add_to(slot, c);
    }

    #[inline(always)]
    fn caught(&mut self) {
        self.caught += 1;
    }
}

/// One row's samples through the wavefront loop, a few thousand paths at
/// a time; each pixel's samples are then added in order, as the
/// one-path-at-a-time loop adds them. With layers each path keeps its
/// light per layer; without, one sum.
fn wave_row(world: &World, tree: &Bvh8, pass: &PassSpec, row: RowSums<'_>, stats: &mut PathStats) {
    let RowSums {
        y,
        sum,
        sum_sq,
        mut layers,
        caught,
    } = row;
    let per_pixel = pass.count as usize;
    let chunk = (4096 / per_pixel).max(1);
    let settings = (pass.settings, pass.settings.rr_scale_for(pass.sampler.0));
    let mut lanes = Vec::new();
    for x0 in (0..sum.len()).step_by(chunk) {
        let x1 = (x0 + chunk).min(sum.len());
        lanes.clear();
        starts::camera_lanes(
            (pass.camera, tree.level()),
            pass.sampler,
            (x0..x1, y),
            (pass.first, pass.count),
            |ray| Path::from_camera(ray, pass.settings.strategy, world),
            &mut lanes,
        );
        let n = (x1 - x0) * per_pixel;
        match layers.as_deref_mut() {
            None => {
                let empty = Counted {
                    light: Vec3::ZERO,
                    caught: 0,
                };
                let mut outs = vec![empty; n];
                wave::trace_paths(world, tree, &mut lanes, settings, &mut outs, stats);
                for (x, ls) in (x0..x1).zip(outs.chunks(per_pixel)) {
                    for l in ls {
                        sum[x] += l.light;
                        sum_sq[x] += l.light * l.light;
                        caught[x] += l.caught;
                    }
                }
            }
            Some(layers) => {
                let empty = Counted {
                    light: [Vec3::ZERO; LAYER_SLOTS],
                    caught: 0,
                };
                let mut outs = vec![empty; n];
                wave::trace_paths(world, tree, &mut lanes, settings, &mut outs, stats);
                for (x, ls) in (x0..x1).zip(outs.chunks(per_pixel)) {
                    for path in ls {
                        for (acc, v) in layers[x].iter_mut().zip(path.light) {
                            *acc += v;
                        }
                        let l: Vec3 = path.light.iter().sum();
                        sum[x] += l;
                        sum_sq[x] += l * l;
                        caught[x] += path.caught;
                    }
                }
            }
        }
    }
}
