//! Where a path's light goes: every contribution is filed under its
//! bounce count k (light that scattered at k + 1 surfaces; see the
//! integrator's module doc), in one *layer slot* per pixel: the slot
//! [`SLOT_EMITTED`] holds emitters seen directly (layer E), slot k + 1
//! bounce count k up to [`LAYERS_SHOWN`], and [`SLOT_BEYOND`] the rest.

use glam::Vec3;

use super::path_events::PathEvent;

/// The highest bounce count k with a layer of its own.
pub const LAYERS_SHOWN: u32 = 16;
/// The layer slot of emitters seen directly (layer E).
pub const SLOT_EMITTED: usize = 0;
/// The slot of light with more than [`LAYERS_SHOWN`] bounces.
pub const SLOT_BEYOND: usize = LAYERS_SHOWN as usize + 2;
/// Slots per pixel: E, k = 0 ..= LAYERS_SHOWN, beyond.
pub const LAYER_SLOTS: usize = LAYERS_SHOWN as usize + 3;
/// The layers a render hands its front ends (`Render::layers`): one fewer
/// than [`LAYER_SLOTS`], because the boundary's layer k is bounce k with
/// the emitters seen directly (slot E) counted into layer 0, direct
/// illumination. The per-slot files keep E apart.
pub const RENDER_LAYERS: usize = LAYER_SLOTS - 1;

/// The layer slot of light with bounce count `k`; `None`: emitters seen
/// directly ([`SLOT_EMITTED`]).
#[inline]
pub fn slot_of(k: Option<u32>) -> usize {
    match k {
        None => SLOT_EMITTED,
        Some(k) => (k as usize + 1).min(SLOT_BEYOND),
    }
}

/// Where a path's contributions go: into the layer of their bounce count
/// (`[Vec3; LAYER_SLOTS]`), or, when only the final image is wanted,
/// straight into one sum (`Vec3`, with nothing per layer to clear or add).
pub trait Contributions {
    /// Adds `c`, which belongs to layer slot `slot`.
    fn add_to(&mut self, slot: usize, c: Vec3);

    /// Hears about each step of the path. Does nothing (and costs nothing)
    /// unless a recorder ([`super::path_record`]) listens.
    #[inline(always)]
    fn note(&mut self, _event: PathEvent<'_>) {}

    /// Hears that a contribution was NaN or infinite (and left out). Does
    /// nothing unless the owner counts them per path, as the fast engine's
    /// rows do.
    #[inline(always)]
    fn caught(&mut self) {}
}

impl Contributions for [Vec3; LAYER_SLOTS] {
    #[inline(always)]
    fn add_to(&mut self, slot: usize, c: Vec3) {
        self[slot] += c;
    }
}

impl Contributions for Vec3 {
    #[inline(always)]
    fn add_to(&mut self, _slot: usize, c: Vec3) {
        *self += c;
    }
}
