//! Axis-aligned boxes around SDFs: where the Eikonal check samples, and
//! where the report says each object is. A plane's box is infinite.

use glam::Vec3;

use crate::scene::sdf::Sdf;
use crate::scene::Scene;

/// An axis-aligned box; `min > max` on some axis means empty.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Lower corner.
    pub min: Vec3,
    /// Upper corner.
    pub max: Vec3,
}

impl Aabb {
    /// Everything.
    pub const INFINITE: Aabb = Aabb {
        min: Vec3::NEG_INFINITY,
        max: Vec3::INFINITY,
    };

    /// A cube of half-size `h` around `c`.
    pub fn around(c: Vec3, h: Vec3) -> Aabb {
        Aabb {
            min: c - h,
            max: c + h,
        }
    }

    /// Whether every coordinate is finite.
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    /// The smallest box holding both.
    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    /// The overlap (may be empty).
    pub fn intersect(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.max(o.min),
            max: self.max.min(o.max),
        }
    }

    /// Grown by `d` on every side.
    pub fn inflate(&self, d: f32) -> Aabb {
        Aabb {
            min: self.min - Vec3::splat(d),
            max: self.max + Vec3::splat(d),
        }
    }

    /// max - min.
    pub fn size(&self) -> Vec3 {
        self.max - self.min
    }

    /// The box around the eight transformed corners; infinite boxes stay
    /// infinite (no ∞ · 0).
    pub fn map(&self, f: impl Fn(Vec3) -> Vec3) -> Aabb {
        if !self.is_finite() {
            return Aabb::INFINITE;
        }
        let mut out = Aabb {
            min: Vec3::INFINITY,
            max: Vec3::NEG_INFINITY,
        };
        for i in 0..8 {
            let c = Vec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            );
            let q = f(c);
            out.min = out.min.min(q);
            out.max = out.max.max(q);
        }
        out
    }
}

/// The bounds of an SDF's inside and surface.
pub fn of(sdf: &Sdf) -> Aabb {
    let all = |of: &[Sdf], pick: fn(&Aabb, &Aabb) -> Aabb| {
        of.iter()
            .map(Sdf::bounds)
            .reduce(|a, b| pick(&a, &b))
            .unwrap_or(Aabb::INFINITE)
    };
    match sdf {
        Sdf::Sphere { radius } => Aabb::around(Vec3::ZERO, Vec3::splat(*radius)),
        Sdf::Box { half_size } | Sdf::RoundedBox { half_size, .. } => {
            Aabb::around(Vec3::ZERO, *half_size)
        }
        Sdf::Torus { major, minor } => {
            Aabb::around(Vec3::ZERO, Vec3::new(major + minor, *minor, major + minor))
        }
        Sdf::Plane { .. } => Aabb::INFINITE,
        Sdf::Capsule { a, b, radius } => Aabb {
            min: a.min(*b) - Vec3::splat(*radius),
            max: a.max(*b) + Vec3::splat(*radius),
        },
        Sdf::Cylinder {
            radius,
            half_height,
        } => Aabb::around(Vec3::ZERO, Vec3::new(*radius, *half_height, *radius)),
        Sdf::Union(of) => all(of, Aabb::union),
        Sdf::Intersection(of) => all(of, Aabb::intersect),
        Sdf::Difference(a, _) => a.bounds(),
        Sdf::SmoothUnion { k, of } => all(of, Aabb::union).inflate(*k * 0.25),
        Sdf::Translate { offset, of } => of.bounds().map(|c| c + *offset),
        Sdf::Rotate { rotation, of } => of.bounds().map(|c| *rotation * c),
        Sdf::Scale { factor, of } => of.bounds().map(|c| c * *factor),
        Sdf::ScaleAxes { factors, of, .. } => of.bounds().map(|c| c * *factors),
    }
}

/// The reach (eye to the farthest bounded thing, [`reach`]) the
/// shipped SDF scenes are built around.
pub const UNIT_REACH: f64 = 9.0;

/// How far the scene reaches from its camera: the distance to the
/// farthest mesh vertex or corner of a bounded SDF's box (an infinite
/// plane has none); the viewing distance (eye to target) for a scene
/// with neither.
pub fn reach(scene: &Scene) -> f64 {
    let eye = scene.camera.eye;
    let mut far = 0.0f64;
    for o in &scene.sdfs {
        let b = o.sdf.bounds();
        if b.is_finite() {
            for c in [b.min, b.max] {
                far = far.max((c.as_dvec3() - eye).length());
            }
        }
    }
    for m in &scene.meshes {
        for p in &m.positions {
            far = far.max((p.as_dvec3() - eye).length());
        }
    }
    if far > 0.0 && far.is_finite() {
        far
    } else {
        (scene.camera.target - eye).length()
    }
}

/// How large this scene is against the shipped ones, as a power of
/// four of its [`reach`] over [`UNIT_REACH`]: 1 for every reach
/// from 4.5 to 18, 4⁵ for a shipped scene scaled by 1,000. Lengths a
/// renderer fixes in scene units (chapter 4's ε and how far it
/// marches) are multiplied by it, so a scaled scene gives the same
/// picture. A power of two is exact in floating point; steps of four
/// keep every shipped SDF scene at 1.
pub fn length_unit(scene: &Scene) -> f32 {
    unit_of_reach(reach(scene))
}

/// [`length_unit`] of a scene whose [`reach`] is `reach`.
pub fn unit_of_reach(reach: f64) -> f32 {
    if !(reach.is_finite() && reach > 0.0) {
        return 1.0;
    }
    let k = (reach / UNIT_REACH).log(4.0).round().clamp(-60.0, 60.0) as i32;
    4f64.powi(k) as f32
}
