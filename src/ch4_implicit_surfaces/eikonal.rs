//! The Eikonal check: sample ‖∇f‖ over an object's bounds. An exact SDF
//! has ‖∇f‖ = 1 almost everywhere; a bound has ‖∇f‖ ≤ 1 (< 1 somewhere);
//! ‖∇f‖ > 1 means f overestimates distances somewhere and sphere tracing
//! can step through the surface there.
//!
//! Finite differences straddling a crease of f (the medial axis: the
//! centre of a sphere, the diagonals inside a box) average two gradients
//! and read < 1 even for an exact SDF, so the verdict uses the 1st and
//! 99th percentiles; the minimum and maximum are reported too.

use glam::Vec3;

use super::bounds::Aabb;
use super::distance::{Exactness, SdfObject};
use super::normal::gradient_central;
use crate::core::sampling::random;

/// ‖∇f‖ over the samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GradientRange {
    /// Smallest.
    pub min: f32,
    /// 1st percentile.
    pub p01: f32,
    /// 99th percentile.
    pub p99: f32,
    /// Largest.
    pub max: f32,
    /// Points sampled.
    pub samples: usize,
}

/// Tolerance of the verdict: within 1 ± this counts as ≈ 1.
pub const TOLERANCE: f32 = 0.01;

impl GradientRange {
    /// "> 1: unsafe", "< 1: a bound", or "≈ 1" (consistent with an exact
    /// SDF, though not a proof of one).
    pub fn verdict(&self) -> &'static str {
        if self.p99 > 1.0 + TOLERANCE {
            "> 1: unsafe"
        } else if self.p01 < 1.0 - TOLERANCE {
            "< 1: a bound"
        } else {
            "≈ 1"
        }
    }
}

/// Samples ‖∇f‖ at `n` points spread over `region` (deterministic: the
/// points come from the seeded sampler). `h` is the difference step.
// ANCHOR: eikonal
pub fn gradient_range(f: &dyn Fn(Vec3) -> f32, region: &Aabb, n: usize, h: f32) -> GradientRange {
    let size = region.size();
    let mut norms: Vec<f32> = (0..n as u64)
        .map(|i| {
            let u = Vec3::new(random(4, i, 0, 0), random(4, i, 0, 1), random(4, i, 0, 2));
            let p = region.min + u * size;
            gradient_central(f, p, h).length()
        })
        .filter(|g| g.is_finite())
        .collect();
    norms.sort_by(f32::total_cmp);
    let at = |q: f32| norms[((norms.len() - 1) as f32 * q).round() as usize];
    if norms.is_empty() {
        return GradientRange {
            min: f32::NAN,
            p01: f32::NAN,
            p99: f32::NAN,
            max: f32::NAN,
            samples: 0,
        };
    }
    GradientRange {
        min: norms[0],
        p01: at(0.01),
        p99: at(0.99),
        max: norms[norms.len() - 1],
        samples: norms.len(),
    }
}
// ANCHOR_END: eikonal

/// Where to sample an object: its bounds cut to `scene_box` (planes are
/// infinite) and grown by a quarter of their size, so the outside counts
/// as much as the inside.
pub fn sample_region(bounds: &Aabb, scene_box: &Aabb) -> Aabb {
    let b = if bounds.is_finite() {
        *bounds
    } else {
        bounds.intersect(scene_box)
    };
    b.inflate(0.25 * b.size().max_element().max(1e-3))
}

/// One object's row of the Eikonal check.
#[derive(Clone, Debug, PartialEq)]
pub struct EikonalRow {
    /// The object's name.
    pub name: String,
    /// What it is built from.
    pub construction: String,
    /// What the construction guarantees.
    pub declared: Exactness,
    /// The largest ‖∇f‖ it allows.
    pub lipschitz: f32,
    /// What was measured.
    pub range: GradientRange,
}

/// Samples ‖∇f‖ over every object's bounds (4096 points each).
pub fn eikonal_check(objects: &[SdfObject]) -> Vec<EikonalRow> {
    // Planes are infinite: sample them over the box around everything else.
    let finite = objects
        .iter()
        .map(|o| o.sdf.bounds())
        .filter(Aabb::is_finite)
        .reduce(|a, b| a.union(&b))
        .unwrap_or(Aabb::around(glam::Vec3::ZERO, glam::Vec3::splat(2.0)));
    objects
        .iter()
        .map(|o| {
            let region = sample_region(&o.sdf.bounds(), &finite);
            let h = 1e-3 * region.size().max_element().max(1e-3);
            EikonalRow {
                name: o.name.clone(),
                construction: o.sdf.describe(),
                declared: o.sdf.exactness(),
                lipschitz: o.sdf.lipschitz(),
                range: gradient_range(&|p| o.sdf.eval(p), &region, 4096, h),
            }
        })
        .collect()
}
