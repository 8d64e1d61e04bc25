//! Chapter 4: implicit surfaces, evaluated. A surface is the zero level set of a
//! function f: ℝ³ → ℝ; a *signed distance function* (SDF) is the special
//! f whose value is the distance to the surface, negative inside. Then
//! inside/outside is one evaluation (the sign), the normal is the gradient
//! ∇f, and the Eikonal equation ‖∇f‖ = 1 holds wherever f is smooth.
//!
//! Which results stay exact distances and which are only bounds
//! (|f| ≤ true distance, still safe to step by) or unsafe (|f| may exceed
//! the true distance, so a step can jump over the surface):
//!
//! | construction | result | ‖∇f‖ |
//! |---|---|---|
//! | sphere, box, rounded box, torus, plane, capsule, cylinder | exact | 1 |
//! | union `min(a, b)` | exact outside, bound inside the overlap | 1 |
//! | intersection `max(a, b)` | exact inside, bound outside | 1 |
//! | difference `max(a, -b)` | bound | 1 |
//! | smooth union | bound | ≤ 1 (< 1 in the blend) |
//! | translate, rotate | as exact as the input | unchanged |
//! | uniform scale s: `s · f(p / s)` | as exact as the input | unchanged |
//! | per-axis scale with `min(s)`: `min(s) · f(p / s)` | bound | ≤ 1 |
//! | per-axis scale with `max(s)`: `max(s) · f(p / s)` | unsafe | up to max(s)/min(s) |
//!
//! Note that ‖∇f‖ = 1 is necessary but not sufficient for an exact SDF:
//! `max(a, b)` has unit gradient almost everywhere yet underestimates the
//! distance near the edges. The Eikonal check ([`eikonal`](super::eikonal)) catches the
//! cases where it is > 1 (unsafe) or < 1 (a bound), not the rest.

use glam::Vec3;

use super::bounds::Aabb;
use super::operators::{op_difference, op_intersection, op_smooth_union, op_union};
use super::primitives::*;
pub use crate::scene::sdf::{ScaleBound, Sdf, SdfObject};

/// How far a distance function can be trusted.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Exactness {
    /// The true signed distance.
    Exact,
    /// Never more than the true distance: safe, may take more steps.
    Bound,
    /// May exceed the true distance: sphere tracing can overstep.
    Unsafe,
}

impl Exactness {
    /// A word for reports.
    pub fn word(self) -> &'static str {
        match self {
            Exactness::Exact => "exact",
            Exactness::Bound => "bound",
            Exactness::Unsafe => "unsafe",
        }
    }
}

impl Sdf {
    /// f(p): the signed distance (or bound) at `p`.
    pub fn eval(&self, p: Vec3) -> f32 {
        match self {
            Sdf::Sphere { radius } => sd_sphere(p, *radius),
            Sdf::Box { half_size } => sd_box(p, *half_size),
            Sdf::RoundedBox { half_size, radius } => sd_rounded_box(p, *half_size, *radius),
            Sdf::Torus { major, minor } => sd_torus(p, *major, *minor),
            Sdf::Plane { normal, offset } => sd_plane(p, *normal, *offset),
            Sdf::Capsule { a, b, radius } => sd_capsule(p, *a, *b, *radius),
            Sdf::Cylinder {
                radius,
                half_height,
            } => sd_cylinder(p, *radius, *half_height),
            Sdf::Union(of) => of.iter().map(|s| s.eval(p)).fold(f32::INFINITY, op_union),
            Sdf::Intersection(of) => of
                .iter()
                .map(|s| s.eval(p))
                .fold(f32::NEG_INFINITY, op_intersection),
            Sdf::Difference(a, b) => op_difference(a.eval(p), b.eval(p)),
            Sdf::SmoothUnion { k, of } => of
                .iter()
                .map(|s| s.eval(p))
                .reduce(|a, b| op_smooth_union(a, b, *k))
                .unwrap_or(f32::INFINITY),
            Sdf::Translate { offset, of } => of.eval(p - *offset),
            Sdf::Rotate { rotation, of } => of.eval(rotation.inverse() * p),
            Sdf::Scale { factor, of } => scaled(of, p, *factor),
            Sdf::ScaleAxes { factors, bound, of } => scaled_axes(of, p, *factors, *bound),
        }
    }

    /// What the construction guarantees (the table in the module docs).
    pub fn exactness(&self) -> Exactness {
        let worst = |of: &[Sdf]| {
            of.iter()
                .map(Sdf::exactness)
                .max()
                .unwrap_or(Exactness::Exact)
        };
        match self {
            Sdf::Sphere { .. }
            | Sdf::Box { .. }
            | Sdf::RoundedBox { .. }
            | Sdf::Torus { .. }
            | Sdf::Plane { .. }
            | Sdf::Capsule { .. }
            | Sdf::Cylinder { .. } => Exactness::Exact,
            Sdf::Union(of) => worst(of).max(if of.len() > 1 {
                Exactness::Bound
            } else {
                Exactness::Exact
            }),
            Sdf::Intersection(of) | Sdf::SmoothUnion { of, .. } => worst(of).max(Exactness::Bound),
            Sdf::Difference(a, b) => a.exactness().max(b.exactness()).max(Exactness::Bound),
            Sdf::Translate { of, .. } | Sdf::Rotate { of, .. } | Sdf::Scale { of, .. } => {
                of.exactness()
            }
            Sdf::ScaleAxes { factors, bound, of } => {
                let uniform = factors.min_element() == factors.max_element();
                let own = match (uniform, bound) {
                    (true, _) => Exactness::Exact,
                    (false, ScaleBound::Min) => Exactness::Bound,
                    (false, ScaleBound::Max) => Exactness::Unsafe,
                };
                own.max(of.exactness())
            }
        }
    }

    /// The largest ‖∇f‖ the construction allows (its Lipschitz constant):
    /// 1 unless a per-axis scale multiplies by its largest factor.
    pub fn lipschitz(&self) -> f32 {
        let most = |of: &[Sdf]| of.iter().map(Sdf::lipschitz).fold(1.0, f32::max);
        match self {
            Sdf::Union(of) | Sdf::Intersection(of) | Sdf::SmoothUnion { of, .. } => most(of),
            Sdf::Difference(a, b) => a.lipschitz().max(b.lipschitz()),
            Sdf::Translate { of, .. } | Sdf::Rotate { of, .. } | Sdf::Scale { of, .. } => {
                of.lipschitz()
            }
            Sdf::ScaleAxes { factors, bound, of } => {
                let own = match bound {
                    ScaleBound::Min => 1.0,
                    ScaleBound::Max => factors.max_element() / factors.min_element(),
                };
                own * of.lipschitz()
            }
            _ => 1.0,
        }
    }

    /// A box that holds the surface and everything inside it (infinite
    /// for a plane).
    pub fn bounds(&self) -> Aabb {
        super::bounds::of(self)
    }

    /// A short description: the primitive or operator and its parts.
    pub fn describe(&self) -> String {
        let list = |of: &[Sdf]| of.iter().map(Sdf::describe).collect::<Vec<_>>().join(", ");
        match self {
            Sdf::Sphere { .. } => "sphere".into(),
            Sdf::Box { .. } => "box".into(),
            Sdf::RoundedBox { .. } => "rounded box".into(),
            Sdf::Torus { .. } => "torus".into(),
            Sdf::Plane { .. } => "plane".into(),
            Sdf::Capsule { .. } => "capsule".into(),
            Sdf::Cylinder { .. } => "cylinder".into(),
            Sdf::Union(of) => format!("union({})", list(of)),
            Sdf::Intersection(of) => format!("intersection({})", list(of)),
            Sdf::Difference(a, b) => format!("difference({}, {})", a.describe(), b.describe()),
            Sdf::SmoothUnion { of, .. } => format!("smooth union({})", list(of)),
            Sdf::Translate { of, .. } | Sdf::Rotate { of, .. } => of.describe(),
            Sdf::Scale { of, .. } => format!("scaled {}", of.describe()),
            Sdf::ScaleAxes { bound, of, .. } => format!(
                "{} scaled per axis ({})",
                of.describe(),
                match bound {
                    ScaleBound::Min => "min",
                    ScaleBound::Max => "max",
                }
            ),
        }
    }
}

/// Uniform scale: evaluate the shape at p / s, where it is s times
/// smaller, and scale the distance back up. Exact.
// ANCHOR: scaled
fn scaled(of: &Sdf, p: Vec3, s: f32) -> f32 {
    of.eval(p / s) * s
}
// ANCHOR_END: scaled

/// Per-axis scale: distances stretch by a different factor per axis, so
/// no single factor is exact. The smallest is a safe bound; the largest
/// overestimates.
// ANCHOR: scaled_axes
fn scaled_axes(of: &Sdf, p: Vec3, s: Vec3, bound: ScaleBound) -> f32 {
    let correction = match bound {
        ScaleBound::Min => s.min_element(),
        ScaleBound::Max => s.max_element(),
    };
    of.eval(p / s) * correction
}
// ANCHOR_END: scaled_axes

/// f for a whole scene: the union of its objects, and which object is
/// nearest. Empty: +∞ everywhere.
pub fn scene_distance(objects: &[SdfObject], p: Vec3) -> (f32, usize) {
    let mut best = (f32::INFINITY, 0);
    for (i, o) in objects.iter().enumerate() {
        let d = o.sdf.eval(p);
        if d < best.0 {
            best = (d, i);
        }
    }
    best
}
