//! What the path tracer's loop says about each step it takes, for anyone
//! who wants to watch one path: the surface it reached, the light found
//! there, the direction it went on in. The render ignores these events
//! (the default [`Contributions::note`](super::layers::Contributions::note)
//! does nothing and compiles away); [`super::path_record`] writes them
//! down as a table, the lecture's path-tracing slide for one sample.

use glam::Vec3;

use crate::ch5_reflection::world::Interaction;

/// One step of one path, in the order the loop takes them.
#[derive(Clone, Copy, Debug)]
pub enum PathEvent<'a> {
    /// The ray reached a surface; `beta` is the throughput it arrives
    /// with.
    Hit {
        /// The surface point.
        it: &'a Interaction,
        /// The path throughput β before this vertex.
        beta: Vec3,
    },
    /// The ray left the scene along `dir`, picking up the environment's
    /// radiance there (0 without one).
    Escaped {
        /// The direction the path left in.
        dir: Vec3,
        /// The environment's radiance, its MIS weight (1 where light
        /// sampling could not find it) and what was added.
        emission: Emission,
    },
    /// The surface just hit emits towards the path.
    Emission(Emission),
    /// Next-event estimation: a light was sampled.
    Light(DirectLight),
    /// The next direction was sampled.
    Scatter(Scatter),
    /// Russian roulette was played with survival probability `q`.
    Roulette {
        /// Survival probability.
        q: f32,
        /// Whether the path survived (β was then divided by q).
        survived: bool,
    },
}

/// Emission the path picked up: what a surface emits towards it, or the
/// sky it escaped to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emission {
    /// Emitted radiance Le.
    pub le: Vec3,
    /// The MIS weight against light sampling (1 where light sampling could
    /// not have found it, 0 where it already counted it).
    pub weight: f32,
    /// β · Le · w, what was added to the pixel.
    pub contribution: Vec3,
}

/// Next-event estimation at a vertex: the direct light one light sample
/// brings (`direct_light` in [`super::integrator`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectLight {
    /// Index into the world's lights.
    pub light: usize,
    /// World direction towards the light sample.
    pub wi: Vec3,
    /// BSDF value towards it.
    pub f: Vec3,
    /// Radiance arriving from the sample (before the shadow test).
    pub li: Vec3,
    /// pdf of the sample (choosing the light times sampling a point).
    pub pdf: f32,
    /// |cos θi|.
    pub cos: f32,
    /// MIS weight.
    pub weight: f32,
    /// Whether the shadow ray got through.
    pub visible: bool,
    /// β f Li cos w / pdf: what was added (0 in shadow).
    pub contribution: Vec3,
}

/// The sampled next direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scatter {
    /// World direction.
    pub wi: Vec3,
    /// BSDF value (0 for a delta lobe).
    pub f: Vec3,
    /// Its pdf (0 for a delta lobe).
    pub pdf: f32,
    /// |cos θi|.
    pub cos: f32,
    /// From a delta lobe (mirror, glass).
    pub delta: bool,
    /// Throughput after the bounce, before roulette.
    pub beta: Vec3,
}
