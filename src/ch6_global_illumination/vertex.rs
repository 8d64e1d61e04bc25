//! One vertex of a path: the surface point with its BSDF in its local
//! frame, and the direction the path goes on in from there (the
//! "indirect" partition of the path-tracing slide).

use glam::{Vec2, Vec3};

use super::path_events::{PathEvent, Scatter};
use crate::ch5_reflection::direct::Strategy;
use crate::ch5_reflection::material::{Bsdf, Frame};
use crate::ch5_reflection::warp::{uniform_hemisphere, UNIFORM_HEMISPHERE_PDF};
use crate::ch5_reflection::world::{Interaction, World};

/// A surface point a path reached, with its BSDF in its local frame.
pub struct Vertex<'a> {
    /// The surface point.
    pub it: &'a Interaction,
    /// Its BSDF.
    pub bsdf: &'a Bsdf,
    /// Its local frame (z the shading normal).
    pub frame: Frame,
    /// Towards where the path came from, local.
    pub wo: Vec3,
    /// The normal on the side the path arrived from.
    pub n_side: Vec3,
    /// Whether the BSDF is a delta (mirror, glass).
    pub delta: bool,
}

impl<'a> Vertex<'a> {
    /// `None` for a ray exactly in the surface's plane.
    pub fn at(world: &'a World, it: &'a Interaction, wo_world: Vec3) -> Option<Vertex<'a>> {
        let bsdf = &world.bsdfs[it.material];
        let frame = Frame::from_normal(it.n);
        let wo = frame.to_local(wo_world);
        if wo.z == 0.0 {
            return None;
        }
        Some(Vertex {
            it,
            bsdf,
            frame,
            wo,
            n_side: if wo.z > 0.0 { it.n } else { -it.n },
            delta: bsdf.is_delta(),
        })
    }
}

/// A sampled next direction (local) with the BSDF value, pdf and the
/// throughput's factor f cos θ / pdf.
pub struct Step {
    /// The direction, local.
    pub wi: Vec3,
    /// The BSDF's value for it.
    pub f: Vec3,
    /// f cos θ / pdf.
    pub weight: Vec3,
    /// Its density.
    pub pdf: f32,
}

impl Step {
    /// The step as a path event, with the throughput after it.
    pub fn event(&self, v: &Vertex, beta: Vec3) -> PathEvent<'static> {
        PathEvent::Scatter(Scatter {
            wi: v.frame.to_world(self.wi),
            f: self.f,
            pdf: self.pdf,
            cos: self.wi.z.abs(),
            delta: v.delta,
            beta,
        })
    }
}

/// The next direction from `v`: uniform over the hemisphere for the
/// uniform strategy, from the BSDF otherwise (and always for a delta BSDF,
/// whose one direction a uniform one never finds). `None` ends the path.
// ANCHOR: sample_direction
pub fn sample_direction(v: &Vertex, u_lobe: f32, u_dir: Vec2, strategy: Strategy) -> Option<Step> {
    let step = if strategy == Strategy::Uniform && !v.delta {
        let mut wi = uniform_hemisphere(u_dir);
        wi.z = wi.z.copysign(v.wo.z);
        let f = v.bsdf.f(v.wo, wi);
        let weight = f * wi.z.abs() / UNIFORM_HEMISPHERE_PDF;
        Step {
            wi,
            f,
            weight,
            pdf: UNIFORM_HEMISPHERE_PDF,
        }
    } else {
        let s = v.bsdf.sample(v.wo, u_dir, u_lobe)?;
        Step {
            wi: s.wi,
            f: s.f,
            weight: s.weight,
            pdf: s.pdf,
        }
    };
    (step.weight != Vec3::ZERO && step.weight.is_finite()).then_some(step)
}
// ANCHOR_END: sample_direction
