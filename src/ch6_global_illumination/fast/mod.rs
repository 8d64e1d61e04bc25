//! Making it fast: the engine `ch6`, `raystep` and the terminal UI use
//! unless told `--engine readable`.
//!
//! The path loop is the lesson's own ([`trace_path`](super::integrator::trace_path)):
//! what changes is what answers its ray queries. The readable engine asks
//! chapter 3's tree, collapsed four-wide, with glam's four-lane vectors.
//! The fast engine asks an eight-wide tree ([`bvh8`]) whose box and
//! triangle tests run over eight lanes at once, compiled for the widest
//! vector instructions the CPU has ([`simd`]). Both compute each lane
//! with the same arithmetic in the same order, so the two engines find the
//! same hits and make the same images, byte for byte (a test renders every
//! scene with both), and the readable engine stays the reference the fast
//! one is checked against.
//!
//! Scenes with SDFs are marched as chapter 4 teaches either way; only
//! their triangles go through the eight-wide tree.

pub mod bvh8;
pub mod lanes;
pub mod level;
pub mod shade8;
#[allow(unsafe_code)]
pub mod simd;
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
