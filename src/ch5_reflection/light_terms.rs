//! One pixel's reflection equation, light by light: for the camera ray of
//! one sample, what each light adds at the point it hits, split into the
//! light-sampling term and the BRDF-sampling term (each with its MIS
//! weight). Nothing here estimates anything: the render's own estimator
//! ([`Estimator::radiance`]) runs on the sample, and a listener
//! ([`Tally::note`]) writes down the terms it adds, as chapter 6's
//! `PathRecord` does for a path. The terms therefore add up to the render's
//! value for that sample (a test checks it).

use glam::Vec3;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::render::camera_sample;
use crate::ch5_reflection::direct::Estimator;
use crate::ch5_reflection::shading_events::{Counters, ShadingEvent, Tally};
use crate::ch5_reflection::world::World;
use crate::core::sampling::Sampler;

/// What one light adds to the pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LightTerm {
    /// Index into the world's lights.
    pub light: usize,
    /// The light-sampling term (f L cos w / pdf; 0 in shadow).
    pub sampled: Vec3,
    /// Its MIS weight (1 for a delta light or light sampling alone).
    pub weight: f32,
    /// Whether the light sample was in shadow.
    pub shadowed: bool,
    /// The BRDF-sampling term that found this light, with its weight.
    pub found: Vec3,
    /// The weight of the BRDF-sampling term.
    pub found_weight: f32,
}

/// The story of one pixel's sample.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PixelLight {
    /// Whether the camera ray hit anything.
    pub hit: bool,
    /// Whether the surface is a mirror or glass (then no per-light split:
    /// the pixel shows what the reflected ray sees).
    pub delta: bool,
    /// Emission seen directly (or the sky for a miss).
    pub emitted: Vec3,
    /// Per light, in the world's order.
    pub lights: Vec<LightTerm>,
    /// What the BRDF-sampled direction found on an emitter that is no
    /// sampled light (an emissive SDF).
    pub other: Vec3,
    /// The radiance of the sample, as the render computes it.
    pub total: Vec3,
}

/// Sample `sample` of pixel (`x`, `y`), as chapter 5's render pass draws
/// it, light by light.
pub fn pixel_light(
    world: &World,
    camera: &Camera,
    est: &Estimator,
    seed: u64,
    (x, y): (u32, u32),
    sample: u32,
) -> PixelLight {
    let (mut s, ray) = camera_sample(camera, (x, y), |pixel| {
        Sampler::new(seed, pixel, sample as u64)
    });
    let mut listener = Listener {
        counters: Counters::default(),
        lights: world.lights.lights.len(),
        story: None,
    };
    let total = est.radiance(world, &ray, &mut s, &mut listener);
    PixelLight {
        total,
        ..listener.story.unwrap_or_default()
    }
}

/// Hears the estimator's steps for the camera ray and writes them down.
struct Listener {
    counters: Counters,
    /// How many lights the world has.
    lights: usize,
    /// Filled in from the first event on (the camera ray's hit or escape).
    story: Option<PixelLight>,
}

impl Tally for Listener {
    fn counters(&mut self) -> &mut Counters {
        &mut self.counters
    }

    fn note(&mut self, event: ShadingEvent) {
        let Some(story) = &mut self.story else {
            // The camera ray's own hit or escape.
            self.story = Some(match event {
                ShadingEvent::Escaped { sky } => PixelLight {
                    emitted: sky,
                    ..PixelLight::default()
                },
                ShadingEvent::Hit { emitted, delta } => PixelLight {
                    hit: true,
                    delta,
                    emitted,
                    lights: (0..self.lights)
                        .map(|light| LightTerm {
                            light,
                            ..LightTerm::default()
                        })
                        .collect(),
                    ..PixelLight::default()
                },
                _ => PixelLight::default(),
            });
            return;
        };
        if story.delta {
            return; // what a mirror sees is not split light by light
        }
        match event {
            ShadingEvent::Light {
                light,
                term,
                weight,
                shadowed,
            } => {
                if let Some(t) = story.lights.get_mut(light) {
                    (t.sampled, t.weight, t.shadowed) = (term, weight, shadowed);
                }
            }
            ShadingEvent::Found {
                light,
                term,
                weight,
            } => match light.and_then(|i| story.lights.get_mut(i)) {
                Some(t) => (t.found, t.found_weight) = (term, weight),
                None => story.other = term,
            },
            ShadingEvent::Escaped { .. } | ShadingEvent::Hit { .. } => {}
        }
    }
}

impl PixelLight {
    /// Emission plus every light's terms.
    pub fn sum(&self) -> Vec3 {
        self.emitted
            + self.other
            + self
                .lights
                .iter()
                .map(|t| t.sampled + t.found)
                .sum::<Vec3>()
    }
}
