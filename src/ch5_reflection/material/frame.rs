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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orthonormal_for_every_normal_even_minus_z() {
        let ns = [
            Vec3::Z,
            -Vec3::Z,
            Vec3::X,
            Vec3::new(1.0, 2.0, -3.0).normalize(),
            Vec3::new(1e-7, 0.0, -1.0).normalize(),
        ];
        for n in ns {
            let f = Frame::from_normal(n);
            for (a, b) in [(f.s, f.t), (f.t, f.n), (f.s, f.n)] {
                assert!(a.dot(b).abs() < 1e-5, "{n}");
            }
            for v in [f.s, f.t] {
                assert!((v.length() - 1.0).abs() < 1e-5, "{n}");
            }
            assert!((f.s.cross(f.t) - n).length() < 1e-5, "right-handed for {n}");
            let w = Vec3::new(0.3, -0.4, 0.5);
            assert!((f.to_world(f.to_local(w)) - w).length() < 1e-5);
        }
    }
}
