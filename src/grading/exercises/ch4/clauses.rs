//! What chapter 4's contract cases are made of ([`super::contract`]):
//! the clause each tests, and one ray against one wall.

use glam::Vec3;

use crate::ch4_implicit_surfaces::march::March;

/// Which clause a case tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Clause {
    /// The step budget.
    Budget,
    /// The maximum distance.
    MaxDistance,
    /// The distance-scaled ε.
    ScaledEpsilon,
    /// The normal (unit length, facing the viewer, -dir where flat).
    Normal,
    /// A step that lands inside: a hit is |f| < ε, not f < ε.
    Overshoot,
    /// A curved surface's normal, where the difference step h matters
    /// (h = max(ε at p, 10⁻⁴)): hits agree to a few ε, normals to 0.02.
    Curved,
    /// A ray that skims a surface, f just above ε step after step, on its
    /// way to another: the march goes on while |f| ≥ ε.
    Skim,
    /// A ray marched on its own terms: nothing carried over from the ray
    /// before it, no limit that overflows.
    Fresh,
}

/// One ray against one wall.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    /// What it is, for the message.
    pub what: &'static str,
    /// The clause it tests.
    pub clause: Clause,
    /// The distance function.
    pub sdf: fn(Vec3) -> f32,
    /// The ray.
    pub origin: Vec3,
    /// Its unit direction.
    pub dir: Vec3,
    /// The limits.
    pub march: March,
}
