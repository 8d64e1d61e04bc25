//! What chapter 5's estimator says about each term it adds, for anyone who
//! wants to watch one estimate: the counts of the rays it traced
//! ([`Counters`]) and its steps ([`ShadingEvent`]), both through one
//! [`Tally`]. The render listens to nothing (for [`Counters`],
//! [`Tally::note`] does nothing and compiles away);
//! [`super::light_terms`] writes the steps down light by light, the inspect
//! mode's story of one pixel, as chapter 6's `path_events` do for a path.

use glam::Vec3;

/// What one estimate cost and caught.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counters {
    /// Shadow rays traced towards sampled lights.
    pub shadow_rays: u64,
    /// Rays traced along sampled directions to find what they see.
    pub direction_rays: u64,
    /// Mirror bounces followed.
    pub mirror_bounces: u64,
    /// Terms that came out NaN or infinite and were dropped.
    pub nonfinite: u64,
}

impl std::ops::AddAssign for Counters {
    fn add_assign(&mut self, o: Counters) {
        self.shadow_rays += o.shadow_rays;
        self.direction_rays += o.direction_rays;
        self.mirror_bounces += o.mirror_bounces;
        self.nonfinite += o.nonfinite;
    }
}

/// One step of one estimate, for anyone who wants to watch it (the
/// inspect mode's story, [`super::light_terms`]). The render listens to
/// nothing: [`Tally::note`] does nothing for [`Counters`] and compiles
/// away.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadingEvent {
    /// A ray found nothing: `sky` is the environment's radiance along it.
    Escaped {
        /// The environment's radiance (0 without one).
        sky: Vec3,
    },
    /// A ray reached a surface that emits `emitted` towards it; `delta`:
    /// an ideal mirror or glass, followed instead of integrated.
    Hit {
        /// Emitted radiance towards the ray.
        emitted: Vec3,
        /// Whether the BSDF is a delta (mirror, glass).
        delta: bool,
    },
    /// A light was sampled: `term` = f L cos w / pdf (0 in shadow or when
    /// not finite), `weight` its MIS weight.
    Light {
        /// Index into the world's lights.
        light: usize,
        /// What was added.
        term: Vec3,
        /// The MIS weight (1 for a delta light or light sampling alone).
        weight: f32,
        /// Whether a shadow ray found something in the way.
        shadowed: bool,
    },
    /// A sampled direction found emitted light: light `light` (`None`: an
    /// emitter that is no sampled light, such as an emissive SDF).
    Found {
        /// Index into the world's lights, if the emitter is one.
        light: Option<usize>,
        /// What was added (0 when not finite).
        term: Vec3,
        /// The MIS weight.
        weight: f32,
    },
}

impl ShadingEvent {
    /// A surface reached, emitting `emitted` towards the ray.
    pub(super) fn hit(emitted: Vec3, delta: bool) -> Self {
        ShadingEvent::Hit { emitted, delta }
    }

    /// Light `light` sampled and blocked.
    pub(super) fn shadowed(light: usize) -> Self {
        let (term, weight, shadowed) = (Vec3::ZERO, 0.0, true);
        ShadingEvent::Light {
            light,
            term,
            weight,
            shadowed,
        }
    }

    /// Light `light` sampled and reached; `term` is `None` when it was not
    /// finite (and so dropped).
    pub(super) fn light(light: usize, term: Option<Vec3>, weight: f32) -> Self {
        let term = term.unwrap_or_default();
        ShadingEvent::Light {
            light,
            term,
            weight,
            shadowed: false,
        }
    }

    /// A sampled direction's find.
    pub(super) fn found(light: Option<usize>, term: Option<Vec3>, weight: f32) -> Self {
        let term = term.unwrap_or_default();
        ShadingEvent::Found {
            light,
            term,
            weight,
        }
    }
}

/// Where an estimate reports what it did: its [`Counters`], and its steps
/// ([`ShadingEvent`]) for a listener.
pub trait Tally {
    /// The counters to add to.
    fn counters(&mut self) -> &mut Counters;

    /// Hears about each step. Does nothing (and costs nothing) unless a
    /// listener overrides it.
    #[inline(always)]
    fn note(&mut self, _event: ShadingEvent) {}
}

impl Tally for Counters {
    #[inline(always)]
    fn counters(&mut self) -> &mut Counters {
        self
    }
}
