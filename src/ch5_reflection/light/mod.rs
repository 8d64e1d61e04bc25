//! Lights (chapter 5): where light comes from, and how to sample a
//! direction towards it from a shading point.
//!
//! Two kinds, as in the lecture: *delta* lights (point, spot, directional)
//! that reach a point from exactly one direction, so they can only be
//! sampled, never hit; and lights with extent (area lights: emissive
//! surfaces; the environment) that a BSDF-sampled ray can also hit, so both
//! strategies, and their combination by MIS, apply.
//!
//! Every [`LightSample::pdf`] is in solid angle at the shading point. Area
//! lights are sampled by area and converted with d² / |cos θl| in exactly
//! one place, [`area::solid_angle_pdf`]; or, where the scene asks for it,
//! by the solid angle they subtend ([`spherical`]).

pub mod area;
pub mod sky;
pub mod spherical;
pub mod spot;

use glam::{Vec2, Vec3};

use crate::ch5_reflection::warp::{cosine_hemisphere, cosine_hemisphere_pdf};
use crate::scene::file::LightSection;
use crate::scene::mesh::Mesh;
use crate::scene::Scene;

use crate::ch5_reflection::material::Frame;

/// A direction towards a light, drawn from a shading point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Unit direction from the shading point towards the light (world).
    pub wi: Vec3,
    /// Radiance arriving along ωi if nothing blocks it; for a delta light,
    /// the arriving irradiance-equivalent (I/d² or E), so that the
    /// contribution is f · li · |cos θi| / pdf with pdf = 1.
    pub li: Vec3,
    /// Solid-angle pdf of ωi (1 for delta lights, see `delta`).
    pub pdf: f32,
    /// Distance to the light's point (∞ for directional and environment).
    pub dist: f32,
    /// Whether this light is a delta light (no BSDF sample can hit it).
    pub delta: bool,
}

/// One light.
#[derive(Clone, Debug, PartialEq)]
pub enum Light {
    /// An isotropic point light: E = I cos θ / r².
    Point {
        /// Position.
        position: Vec3,
        /// Intensity I (W/sr).
        intensity: Vec3,
    },
    /// A directional light: parallel light of irradiance E at normal
    /// incidence, travelling along `direction`.
    Directional {
        /// Unit direction the light travels.
        direction: Vec3,
        /// Irradiance at normal incidence (W/m²).
        irradiance: Vec3,
    },
    /// An emissive mesh.
    Area(area::AreaLight),
    /// Constant radiance from every direction.
    Environment {
        /// Radiance L (W/(m²·sr)).
        radiance: Vec3,
    },
    /// A point light limited to a cone with a smooth edge (chapter 5).
    Spot(spot::Spot),
    /// A sky-gradient environment (chapter 5).
    Sky(sky::Sky),
}

impl Light {
    /// A direction towards this light from `p` (surface normal `n`, unit),
    /// from two uniform numbers; `None` when this light cannot reach `p`
    /// (behind a one-sided emitter, a zero pdf).
    pub fn sample_li(&self, p: Vec3, n: Vec3, u: Vec2) -> Option<LightSample> {
        match self {
            Light::Point {
                position,
                intensity,
            } => {
                let to = *position - p;
                let d2 = to.length_squared();
                let wi = to.try_normalize()?;
                let li = *intensity / d2;
                li.is_finite().then_some(LightSample {
                    wi,
                    li,
                    pdf: 1.0,
                    dist: d2.sqrt(),
                    delta: true,
                })
            }
            Light::Directional {
                direction,
                irradiance,
            } => Some(LightSample {
                wi: -*direction,
                li: *irradiance,
                pdf: 1.0,
                dist: f32::INFINITY,
                delta: true,
            }),
            Light::Area(a) => a.sample_li(p, u),
            Light::Environment { radiance } => {
                // Cosine-weighted about the normal: the density that
                // matches the cos θ in the reflection equation.
                let frame = Frame::from_normal(n);
                let wi = frame.to_world(cosine_hemisphere(u));
                let pdf = cosine_hemisphere_pdf(wi.dot(n));
                (pdf > 0.0).then_some(LightSample {
                    wi,
                    li: *radiance,
                    pdf,
                    dist: f32::INFINITY,
                    delta: false,
                })
            }
            Light::Spot(s) => s.sample_li(p),
            Light::Sky(sky) => {
                let wi = sky.sample(u);
                let pdf = sky.pdf(wi);
                let li = sky.radiance(wi);
                (pdf > 0.0 && wi.dot(n) != 0.0 && li != Vec3::ZERO).then_some(LightSample {
                    wi,
                    li,
                    pdf,
                    dist: f32::INFINITY,
                    delta: false,
                })
            }
        }
    }

    /// Whether the light is a delta light.
    pub fn is_delta(&self) -> bool {
        matches!(
            self,
            Light::Point { .. } | Light::Directional { .. } | Light::Spot(_)
        )
    }
}

/// All lights of a scene, with what a renderer needs to pick one and to
/// find the light a ray hit.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Lights {
    /// Every light: `[[lights]]` entries first, then one area light per
    /// emissive mesh.
    pub lights: Vec<Light>,
    /// For each scene mesh, the index of its area light (if it emits).
    pub area_of_mesh: Vec<Option<usize>>,
    /// The index of the environment light, if there is one.
    pub environment: Option<usize>,
}

impl Lights {
    /// The lights of `scene`. Builds nothing for a scene without lights.
    pub fn new(scene: &Scene) -> Lights {
        let mut out = Lights {
            area_of_mesh: vec![None; scene.meshes.len()],
            ..Lights::default()
        };
        for l in &scene.lights {
            let v = |a: &[f64; 3]| glam::DVec3::from(*a).as_vec3();
            let light = match l {
                LightSection::Point {
                    position,
                    intensity,
                } => Light::Point {
                    position: v(position),
                    intensity: v(intensity),
                },
                LightSection::Directional {
                    direction,
                    irradiance,
                } => Light::Directional {
                    direction: v(direction).normalize_or(Vec3::NEG_Y),
                    irradiance: v(irradiance),
                },
                LightSection::Spot {
                    position,
                    direction,
                    intensity,
                    cone_degrees,
                    falloff_degrees,
                } => Light::Spot(spot::Spot::new(
                    v(position),
                    v(direction),
                    v(intensity),
                    *cone_degrees as f32,
                    *falloff_degrees as f32,
                )),
                LightSection::Environment { radiance } => {
                    out.environment = Some(out.lights.len());
                    Light::Environment {
                        radiance: v(radiance),
                    }
                }
                LightSection::Sky {
                    zenith,
                    horizon,
                    ground,
                } => {
                    let sky = sky::Sky {
                        zenith: v(zenith),
                        horizon: v(horizon),
                        ground: v(ground),
                    };
                    if sky.is_dark() {
                        continue;
                    }
                    out.environment = Some(out.lights.len());
                    Light::Sky(sky)
                }
            };
            out.lights.push(light);
        }
        for (m, mesh) in scene.meshes.iter().enumerate() {
            let material = &scene.materials[mesh.material];
            if material.is_emissive() {
                if let Some(a) =
                    area::AreaLight::new(mesh, m, material.emission, material.two_sided)
                {
                    out.area_of_mesh[m] = Some(out.lights.len());
                    out.lights
                        .push(Light::Area(a.sampled_by(scene.light_sampling)));
                }
            }
        }
        out
    }

    /// Whether there is nothing to sample.
    pub fn is_empty(&self) -> bool {
        self.lights.is_empty()
    }

    /// Picks a light uniformly: (index, probability of that choice).
    pub fn choose(&self, u: f32) -> Option<(usize, f32)> {
        let n = self.lights.len();
        (n > 0).then(|| (((u * n as f32) as usize).min(n - 1), 1.0 / n as f32))
    }

    /// The probability that [`Lights::choose`] picks light `index`.
    pub fn choose_pdf(&self, _index: usize) -> f32 {
        if self.lights.is_empty() {
            0.0
        } else {
            1.0 / self.lights.len() as f32
        }
    }

    /// Radiance arriving along a ray that leaves the scene in direction
    /// `dir` (zero without an environment light).
    pub fn environment_radiance(&self, dir: Vec3) -> Vec3 {
        match self.environment.map(|i| &self.lights[i]) {
            Some(Light::Environment { radiance }) => *radiance,
            Some(Light::Sky(sky)) => sky.radiance(dir),
            _ => Vec3::ZERO,
        }
    }

    /// The solid-angle pdf with which the environment light's
    /// [`Light::sample_li`] returns `wi` at a point with normal `n`.
    pub fn environment_pdf(&self, n: Vec3, wi: Vec3) -> f32 {
        match self.environment.map(|i| &self.lights[i]) {
            Some(Light::Environment { .. }) => cosine_hemisphere_pdf(wi.dot(n)),
            Some(Light::Sky(sky)) => sky.pdf(wi),
            _ => 0.0,
        }
    }
}

/// Whether `mesh` is worth an area light: it has faces of non-zero area.
pub fn has_area(mesh: &Mesh) -> bool {
    mesh.triangles.iter().any(|t| {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        (b - a).cross(c - a).length_squared() > 0.0
    })
}
