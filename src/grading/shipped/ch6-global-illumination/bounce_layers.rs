//! Exercise 6.6: one path's light, layer by layer.
//!
//! The lecture shows one-, two-, four-, eight- and sixteen-bounce global
//! illumination; raystep renders them all at once by filing every
//! contribution a path adds under its bounce count k (book "Bounce by
//! bounce"): light that scattered at k + 1 surfaces between an emitter
//! and the camera. Here a path is handed over as a list of what it
//! gathered, each item saying at which vertex and how; which bounce count
//! that is follows from counting the surfaces the light scattered at.
//!
//! Contract (what the grader checks):
//! * `path` lists one path's contributions in the order it gathered them.
//!   Each `Gathered` has four public fields: `vertex: u32` (0: the first
//!   surface the camera ray reaches, 1: the surface the next ray
//!   reaches, …), `how: How`, how it was gathered there (`How::Found`:
//!   emission that the ray arriving at that vertex found, the surface's
//!   own, or the sky's where the ray left the scene; `How::LightSample`:
//!   next-event estimation at that vertex), `value: Vec3`, what it brings
//!   before MIS, and `weight: f32`, its MIS weight;
//! * return the layer slots: each contribution adds value · weight to the
//!   slot of its bounce count: `SLOT_EMITTED` for emitters the camera
//!   sees directly, slot k + 1 for bounce count k up to `LAYERS_SHOWN`,
//!   `SLOT_BEYOND` for every larger k;
//! * a contribution whose value · weight is NaN or infinite is left out
//!   (as the render leaves it out): the product as f32 forms it, where
//!   10³⁰ · 10¹⁰ is infinite;
//! * each slot within 10⁻⁵ of the sum of the magnitudes filed into it (so
//!   any order of summing in f32 passes), and exactly 0 where nothing is;
//! * on paths drawn anew for every grading run (up to 40 vertices), and on
//!   real paths of the Cornell box traced by the render's own loop, whose
//!   slots must be what the render filed.
//!
//! Hints: `cargo grade --hint ch6/bounce_layers`.
//! Grade it with: `cargo grade ch6`

use glam::Vec3;
use raystep::ch6_global_illumination::layers::{
    LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND, SLOT_EMITTED,
};
use raystep::grading::exercises::bounce_layers::{Gathered, How};

/// The path's light per layer slot.
pub fn bounce_layers(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    // TODO: the bounce count of each contribution, and its slot.
    todo!()
}
