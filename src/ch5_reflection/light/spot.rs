//! A spot light: an isotropic point light seen through a cone. Inside the
//! inner cone it sends its full intensity I; between the inner and outer
//! cone the intensity falls smoothly (a smoothstep in cos θ) to zero.

use glam::Vec3;

use super::LightSample;

/// A point light limited to a cone around `axis`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spot {
    /// Position.
    pub position: Vec3,
    /// Unit direction the light travels along the cone's axis.
    pub axis: Vec3,
    /// Intensity I on the axis (W/sr).
    pub intensity: Vec3,
    /// cos of the outer half-angle: no light beyond it.
    pub cos_outer: f32,
    /// cos of the inner half-angle: full intensity within it.
    pub cos_inner: f32,
}

impl Spot {
    /// A spot of half-angle `cone_degrees` whose edge softens over the last
    /// `falloff_degrees` inside the cone (clamped to [0, cone]).
    pub fn new(
        position: Vec3,
        direction: Vec3,
        intensity: Vec3,
        cone_degrees: f32,
        falloff_degrees: f32,
    ) -> Spot {
        let cone = cone_degrees.clamp(0.0, 180.0);
        let inner = (cone - falloff_degrees.clamp(0.0, cone)).max(0.0);
        Spot {
            position,
            axis: direction.normalize_or(Vec3::NEG_Y),
            intensity,
            cos_outer: cone.to_radians().cos(),
            cos_inner: inner.to_radians().cos(),
        }
    }

    /// The fraction of I sent along the unit direction `w` (away from the
    /// light): 1 inside the inner cone, 0 outside the outer one, a
    /// smoothstep between.
    // ANCHOR: spot_falloff
    pub fn falloff(&self, w: Vec3) -> f32 {
        let c = w.dot(self.axis);
        if c >= self.cos_inner {
            return 1.0;
        }
        if c <= self.cos_outer {
            return 0.0;
        }
        let t = ((c - self.cos_outer) / (self.cos_inner - self.cos_outer)).clamp(0.0, 1.0);
        t * t * (3.0 - 2.0 * t)
    }
    // ANCHOR_END: spot_falloff

    /// The direction to the light from `p` with I·falloff / d² as `li`.
    pub fn sample_li(&self, p: Vec3) -> Option<LightSample> {
        let to = self.position - p;
        let d2 = to.length_squared();
        let wi = to.try_normalize()?;
        let li = self.intensity * self.falloff(-wi) / d2;
        (li.is_finite() && li != Vec3::ZERO).then_some(LightSample {
            wi,
            li,
            pdf: 1.0,
            dist: d2.sqrt(),
            delta: true,
        })
    }
}
