//! What the path tracer's loop says about each step it takes, for anyone
//! who wants to watch one path: the surface it reached, the light found
//! there, the direction it went on in. The render ignores these events
//! (the default [`Contributions::note`](super::integrator::Contributions::note)
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
    /// The ray left the scene along `dir`; `le` is the environment's
    /// radiance there (0 without one), `weight` its MIS weight and
    /// `contribution` what was added (β · Le · w).
    Escaped {
        /// The direction the path left in.
        dir: Vec3,
        /// The environment's radiance along it.
        le: Vec3,
        /// Its MIS weight (1 where light sampling could not find it).
        weight: f32,
        /// β · Le · w.
        contribution: Vec3,
    },
    /// The surface just hit emits towards the path: radiance `le`,
    /// weighted by `weight` against light sampling.
    Emission {
        /// Emitted radiance Le.
        le: Vec3,
        /// The MIS weight of the BSDF-sampled direction that found it.
        weight: f32,
        /// β · Le · w.
        contribution: Vec3,
    },
    /// Next-event estimation: light `light` was sampled towards `wi`.
    Light {
        /// Index into the world's lights.
        light: usize,
        /// World direction towards the sampled point.
        wi: Vec3,
        /// The BSDF value f(ωo, ωi).
        f: Vec3,
        /// The radiance Li arriving from the sample.
        li: Vec3,
        /// The sample's pdf (choosing the light times sampling it).
        pdf: f32,
        /// |cos θi|.
        cos: f32,
        /// The MIS weight (1 without MIS or for a delta light).
        weight: f32,
        /// Whether the shadow ray got through.
        visible: bool,
        /// What was added: β f Li cos w / pdf (0 when shadowed).
        contribution: Vec3,
    },
    /// The next direction was sampled.
    Scatter {
        /// World direction the path goes on in.
        wi: Vec3,
        /// The BSDF value (0 for a delta lobe, whose value is in `beta`).
        f: Vec3,
        /// The pdf of the direction (0 for a delta lobe).
        pdf: f32,
        /// |cos θi|.
        cos: f32,
        /// Whether it came from a delta lobe (mirror, glass).
        delta: bool,
        /// The throughput after this bounce (before roulette).
        beta: Vec3,
    },
    /// Russian roulette was played with survival probability `q`.
    Roulette {
        /// Survival probability.
        q: f32,
        /// Whether the path survived (β was then divided by q).
        survived: bool,
    },
}
