//! How paths are traced ([`PathSettings`]): the estimator, the bounce
//! limit, and when and how hard Russian roulette plays.

pub use crate::ch5_reflection::direct::Strategy;

use super::sampler::SamplerKind;

/// With "unlimited" bounces only Russian roulette ends a path; a path
/// whose next bounce count would exceed this ends anyway (counted in
/// [`PathStats::cut`](super::integrator::PathStats::cut)), so a scene of perfect mirrors cannot hang a render.
/// With ρ = 0.999 the chance of reaching it is about e^-65.
pub const SAFETY_BOUNCES: u32 = (1 << 16) - 1;

/// Whether Russian roulette can never end a path in `scene`: every
/// material keeps all the light it reflects in every channel (reflectance
/// 1, or glass), so the survival probability, the throughput's largest
/// channel, never drops below 1. Paths then end only by leaving the scene;
/// in a closed one, each runs to [`SAFETY_BOUNCES`].
pub fn roulette_cannot_end(scene: &crate::scene::Scene) -> bool {
    use crate::scene::file::MaterialKind;
    !scene.materials.is_empty()
        && scene
            .materials
            .iter()
            .all(|m| m.kind == MaterialKind::Glass || m.reflectance.min_element() >= 1.0)
}

/// How paths are traced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PathSettings {
    /// Which rung of the ladder: how directions are drawn and light found.
    pub strategy: Strategy,
    /// The largest bounce count k a path may contribute to; `None`:
    /// unlimited, Russian roulette alone ends paths.
    pub max_bounces: Option<u32>,
    /// Russian roulette may end a path before it gathers light of this
    /// bounce count or more (1: direct light is never cut; `--rr-after`).
    pub rr_min_bounce: u32,
    /// Russian roulette's scale s: a path survives with probability
    /// q = min(1, s · max β), so roulette plays only once β has fallen
    /// below 1/s (`--rr-scale`). `None`: the sampler's own
    /// ([`SamplerKind::roulette_scale`]).
    pub rr_scale: Option<u32>,
}

impl PathSettings {
    /// Roulette's scale s with numbers of kind `kind`.
    pub fn rr_scale_for(&self, kind: SamplerKind) -> u32 {
        self.rr_scale.unwrap_or(kind.roulette_scale())
    }

    /// The roulette policy in words, for reports: with numbers of kind
    /// `kind`, or with either kind's scale where `kind` is `None`.
    pub fn roulette_text(&self, kind: Option<SamplerKind>) -> String {
        let s = match (self.rr_scale, kind) {
            (Some(s), _) => s.to_string(),
            (None, Some(kind)) => kind.roulette_scale().to_string(),
            (None, None) => "the sampler's (1 independent, 2 Sobol)".into(),
        };
        format!("after {} scatterings, scale {s}", self.rr_min_bounce)
    }

    /// The largest bounce count a path gathers.
    pub fn bounce_limit(&self) -> u32 {
        self.max_bounces
            .unwrap_or(SAFETY_BOUNCES)
            .min(SAFETY_BOUNCES)
    }
}

impl Default for PathSettings {
    fn default() -> Self {
        PathSettings {
            strategy: Strategy::Mis,
            max_bounces: Some(16),
            rr_min_bounce: 1,
            rr_scale: None,
        }
    }
}
