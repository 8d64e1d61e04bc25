//! The ideal specular reflector: all light from ωi leaves along the mirror
//! direction, a delta distribution.

use glam::Vec3;

use super::BsdfSample;

/// A perfect mirror with reflectance `r` per channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mirror {
    /// Fraction reflected.
    pub r: Vec3,
}

/// The mirror direction of `wo` about the local normal (0, 0, 1).
#[inline]
pub fn reflect_local(wo: Vec3) -> Vec3 {
    Vec3::new(-wo.x, -wo.y, wo.z)
}

impl Mirror {
    /// The one direction a mirror sends light to, with weight r.
    pub fn sample(&self, wo: Vec3) -> Option<BsdfSample> {
        (wo.z != 0.0).then(|| BsdfSample {
            wi: reflect_local(wo),
            f: Vec3::ZERO,
            pdf: 0.0,
            weight: self.r,
            delta: true,
        })
    }
}
