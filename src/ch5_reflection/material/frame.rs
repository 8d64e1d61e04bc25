//! A local shading frame: an orthonormal basis (s, t, n) whose z axis is
//! the surface normal, so that cos θ of a direction is just its z.

use glam::Vec3;

/// An orthonormal basis with `n` as its z axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// First tangent (local x).
    pub s: Vec3,
    /// Second tangent (local y).
    pub t: Vec3,
    /// The normal (local z).
    pub n: Vec3,
}

impl Frame {
    /// A frame around the unit normal `n` (Duff et al. 2017, "Building an
    /// orthonormal basis, revisited": no branch on a small component, so no
    /// seam where a naive choice of helper axis flips).
    pub fn from_normal(n: Vec3) -> Frame {
        let sign = 1.0f32.copysign(n.z);
        let a = -1.0 / (sign + n.z);
        let b = n.x * n.y * a;
        Frame {
            s: Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
            t: Vec3::new(b, sign + n.y * n.y * a, -n.y),
            n,
        }
    }

    /// World direction → local coordinates.
    #[inline]
    pub fn to_local(&self, v: Vec3) -> Vec3 {
        Vec3::new(v.dot(self.s), v.dot(self.t), v.dot(self.n))
    }

    /// Local coordinates → world direction.
    #[inline]
    pub fn to_world(&self, v: Vec3) -> Vec3 {
        v.x * self.s + v.y * self.t + v.z * self.n
    }
}
