//! Signed distance function objects as a scene file describes them: a tree
//! of primitives, operators and transforms, each with a name and a
//! material. The scene only *describes* the shapes; chapter 4 says how far
//! a point is from each ([`crate::ch4_implicit_surfaces::distance`]).

use glam::{Quat, Vec3};

/// How a per-axis scale turns the distance of the unscaled shape into one
/// for the scaled shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ScaleBound {
    /// Multiply by the smallest factor: never overestimates (a bound).
    Min,
    /// Multiply by the largest factor: overestimates along the squeezed
    /// axes, so sphere tracing can overstep. Kept to show what breaks.
    Max,
}

/// A signed distance function built from primitives, operators and
/// transforms.
#[derive(Clone, Debug, PartialEq)]
pub enum Sdf {
    /// `sd_sphere`.
    Sphere {
        /// Radius.
        radius: f32,
    },
    /// `sd_box`.
    Box {
        /// Half-extents.
        half_size: Vec3,
    },
    /// `sd_rounded_box`.
    RoundedBox {
        /// Half-extents, including the rounding.
        half_size: Vec3,
        /// Edge radius.
        radius: f32,
    },
    /// `sd_torus`.
    Torus {
        /// Radius of the core circle.
        major: f32,
        /// Radius of the tube.
        minor: f32,
    },
    /// `sd_plane`.
    Plane {
        /// Unit normal.
        normal: Vec3,
        /// n·p = offset on the plane.
        offset: f32,
    },
    /// `sd_capsule`.
    Capsule {
        /// One end of the core segment.
        a: Vec3,
        /// The other end.
        b: Vec3,
        /// Radius.
        radius: f32,
    },
    /// `sd_cylinder`.
    Cylinder {
        /// Radius.
        radius: f32,
        /// Half of the height along y.
        half_height: f32,
    },
    /// Union of all.
    Union(Vec<Sdf>),
    /// Intersection of all.
    Intersection(Vec<Sdf>),
    /// The first minus the second.
    Difference(Box<Sdf>, Box<Sdf>),
    /// Smooth union of all with blend radius `k`.
    SmoothUnion {
        /// Blend radius.
        k: f32,
        /// The shapes.
        of: Vec<Sdf>,
    },
    /// The shape moved by `offset`.
    Translate {
        /// World offset.
        offset: Vec3,
        /// The shape.
        of: Box<Sdf>,
    },
    /// The shape rotated by `rotation` (world from object).
    Rotate {
        /// world_from_object rotation.
        rotation: Quat,
        /// The shape.
        of: Box<Sdf>,
    },
    /// The shape scaled by `factor` on every axis.
    Scale {
        /// Scale factor (> 0).
        factor: f32,
        /// The shape.
        of: Box<Sdf>,
    },
    /// The shape scaled per axis.
    ScaleAxes {
        /// Scale factors (> 0).
        factors: Vec3,
        /// Which factor corrects the distance.
        bound: ScaleBound,
        /// The shape.
        of: Box<Sdf>,
    },
}

/// An SDF object of a scene: a name, a distance function and a material.
#[derive(Clone, Debug, PartialEq)]
pub struct SdfObject {
    /// A name for reports.
    pub name: String,
    /// Its distance function, in world space.
    pub sdf: Sdf,
    /// Index into the scene's materials.
    pub material: usize,
}
