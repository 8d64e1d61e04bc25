//! One path, written down. [`record_path`] traces the very sample a render
//! traced for a pixel (same seed, pixel, sample index and so the same
//! random numbers) through the render's own loop, [`trace_path`], with a
//! [`PathRecord`] listening to its [`PathEvent`]s. The record is a table:
//! per vertex what was hit, the light that next-event estimation found
//! there, the emission the path picked up, the direction it went on in,
//! and Russian roulette. Its contributions add up to exactly what the
//! render added to the pixel for that sample (a test checks it).

use glam::Vec3;

use crate::ch1_projection::camera::Camera;
use crate::ch4_implicit_surfaces::hit::Surface;
use crate::ch5_reflection::world::World;

use super::engine::camera_sample;
use super::integrator::{trace_path, PathSettings, PathStats};
use super::layers::{Contributions, LAYER_SLOTS};
pub use super::path_events::{DirectLight, Emission, PathEvent, Scatter};
use super::sampler::SamplerKind;
pub use crate::ch5_reflection::names::{light_name, surface_name};

/// One surface the path reached.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    /// Which object.
    pub surface: Surface,
    /// Index into the scene's materials.
    pub material: usize,
    /// Distance along the ray that reached it.
    pub t: f32,
    /// The point.
    pub p: Vec3,
    /// Throughput β with which the path arrived.
    pub beta: Vec3,
    /// Emission found here by the ray that arrived.
    pub emission: Option<Emission>,
    /// Light sampling here (none after a delta surface or without lights).
    pub light: Option<DirectLight>,
    /// The direction the path went on in.
    pub scatter: Option<Scatter>,
    /// Russian roulette: (survival probability, survived).
    pub roulette: Option<(f32, bool)>,
}

/// Why the path ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathEnd {
    /// It left the scene.
    Escaped,
    /// Russian roulette ended it.
    Roulette,
    /// It reached the bounce limit.
    BounceLimit,
    /// The surface sent it nowhere (the BSDF drew no direction, or one
    /// carrying nothing).
    Absorbed,
}

/// One path, as a table of vertices.
#[derive(Clone, Debug, PartialEq)]
pub struct PathRecord {
    /// The pixel.
    pub pixel: (u32, u32),
    /// The sample index.
    pub sample: u32,
    /// Direction of the camera ray.
    pub camera_dir: Vec3,
    /// Every surface reached, in order.
    pub vertices: Vec<Vertex>,
    /// The sky (or nothing) found when the path left the scene.
    pub escaped: Option<(Vec3, Emission)>,
    /// Why it ended.
    pub end: PathEnd,
    /// What the render added per layer slot (see [`super::integrator`]).
    pub layers: [Vec3; LAYER_SLOTS],
    /// Counts: rays, dropped non-finite contributions.
    pub stats: PathStats,
}

impl PathRecord {
    fn empty(pixel: (u32, u32), sample: u32, camera_dir: Vec3) -> PathRecord {
        PathRecord {
            pixel,
            sample,
            camera_dir,
            vertices: Vec::new(),
            escaped: None,
            end: PathEnd::Absorbed,
            layers: [Vec3::ZERO; LAYER_SLOTS],
            stats: PathStats::default(),
        }
    }

    /// The sum of the table's contributions (those the render kept: finite
    /// ones): the sample's radiance.
    pub fn contributions_sum(&self) -> Vec3 {
        let escaped = self.escaped.map(|(_, e)| e.contribution);
        self.vertices
            .iter()
            .flat_map(|v| {
                [
                    v.emission.map(|e| e.contribution),
                    v.light.map(|l| l.contribution),
                ]
            })
            .chain([escaped])
            .flatten()
            .filter(|c| c.is_finite())
            .sum()
    }

    /// The radiance the render added, by layer, summed.
    pub fn radiance(&self) -> Vec3 {
        self.layers.iter().sum()
    }

    fn last(&mut self) -> Option<&mut Vertex> {
        self.vertices.last_mut()
    }
}

impl Contributions for PathRecord {
    fn add_to(&mut self, slot: usize, c: Vec3) {
        self.layers[slot] += c;
    }

    fn note(&mut self, event: PathEvent<'_>) {
        match event {
            PathEvent::Hit { it, beta } => self.vertices.push(Vertex {
                surface: it.surface,
                material: it.material,
                t: it.t,
                p: it.p,
                beta,
                emission: None,
                light: None,
                scatter: None,
                roulette: None,
            }),
            PathEvent::Escaped { dir, emission } => self.escaped = Some((dir, emission)),
            PathEvent::Emission(e) => {
                if let Some(v) = self.last() {
                    v.emission = Some(e);
                }
            }
            PathEvent::Light(l) => {
                if let Some(v) = self.last() {
                    v.light = Some(l);
                }
            }
            PathEvent::Scatter(sc) => {
                if let Some(v) = self.last() {
                    v.scatter = Some(sc);
                }
            }
            PathEvent::Roulette { q, survived } => {
                if let Some(v) = self.last() {
                    v.roulette = Some((q, survived));
                }
            }
        }
    }
}

/// Traces sample `sample` of pixel `pixel` exactly as
/// [`Accumulator::add_samples`](super::accumulate::Accumulator::add_samples)
/// does (same camera ray, same random numbers, same loop) and writes the
/// path down.
// ANCHOR: record_path
pub fn record_path(
    world: &World,
    camera: &Camera,
    settings: &PathSettings,
    kind: SamplerKind,
    seed: u64,
    pixel: (u32, u32),
    sample: u32,
) -> PathRecord {
    let (x, y) = (pixel.0 as usize, pixel.1 as usize);
    let (mut sampler, ray) = camera_sample(camera, kind, seed, x, y, sample);
    let mut record = PathRecord::empty(pixel, sample, ray.dir);
    let mut stats = PathStats::default();
    trace_path(world, ray, &mut sampler, settings, &mut record, &mut stats);
    record.stats = stats;
    let limit = settings.max_bounces.map(|k| k as usize + 1);
    record.end = match record.vertices.last() {
        None => PathEnd::Escaped,
        Some(v) if v.roulette.is_some_and(|(_, survived)| !survived) => PathEnd::Roulette,
        // Went on in a direction and found nothing (or only the sky).
        Some(v) if v.scatter.is_some() => PathEnd::Escaped,
        Some(_) if Some(record.vertices.len()) > limit => PathEnd::BounceLimit,
        Some(_) => PathEnd::Absorbed,
    };
    record
}
// ANCHOR_END: record_path
