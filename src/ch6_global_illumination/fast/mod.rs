//! Making it fast: the engine `ch6`, `raystep` and the terminal UI use
//! unless told `--engine readable`.
//!
//! Two things change. What answers the ray queries: the readable engine
//! asks chapter 3's tree, collapsed four-wide, with glam's four-lane
//! vectors; the fast engine asks an eight-wide tree ([`bvh8`]) whose box
//! and triangle tests run over eight lanes at once, compiled for the
//! widest vector instructions the CPU has ([`simd`]). Both compute each
//! lane with the same arithmetic in the same order, so they find the same
//! hits. And the path loop: on diffuse scenes with MIS (the benchmark's)
//! the fast engine extends thousands of paths a bounce at a time and
//! shades their hits eight at once ([`wave`], [`shade8`]), with the
//! lesson's formulas and the lesson's random numbers, so it follows the
//! same paths as the lesson's
//! [`trace_path`](super::integrator::trace_path) to the last bits of a
//! sine; elsewhere it runs `trace_path` itself over the eight-wide tree
//! and makes the readable engine's images byte for byte. A test checks
//! both, and that the fast engine makes the same bytes on every SIMD path.
//!
//! Scenes with SDFs are marched as chapter 4 teaches either way; only
//! their triangles go through the eight-wide tree.

pub mod bvh8;
pub mod lanes;
pub mod level;
pub mod packet;
pub mod pick8;
pub mod shade8;
#[allow(unsafe_code)]
pub mod simd;
pub mod sobol8;
pub mod starts;
pub mod wave;

use crate::ch5_reflection::world::{Queries, World};
use crate::scene::Scene;

use bvh8::Bvh8;
use level::Level;

/// Which engine traces the paths.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Engine {
    /// The eight-wide tree with run-time SIMD (the default).
    #[default]
    Fast,
    /// The lesson's four-wide tree.
    Readable,
}

impl Engine {
    /// A short name for tables and messages.
    pub fn name(self) -> &'static str {
        match self {
            Engine::Fast => "fast",
            Engine::Readable => "readable",
        }
    }

    /// The world of `scene` as this engine traces it; the fast engine's
    /// queries use `level`'s instructions ([`simd::best`] for the CPU's
    /// best).
    pub fn world_at(self, scene: &Scene, level: Level) -> World {
        match self {
            Engine::Fast => World::with_queries(scene, |tris| {
                Bvh8::build(tris, level).map(|b| Box::new(b) as Box<Queries>)
            }),
            Engine::Readable => World::new(scene),
        }
    }

    /// The world of `scene` as this engine traces it, with the CPU's best
    /// instructions.
    pub fn world(self, scene: &Scene) -> World {
        self.world_at(scene, simd::best())
    }
}
