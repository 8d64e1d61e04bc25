//! Warps: turning uniform numbers in [0, 1)² into directions and points
//! with a known density. Every warp comes with its pdf, in the measure its
//! name says (solid angle for directions, area for points), so an
//! estimator can divide by exactly the density it sampled from.
//!
//! Directions are in a local frame whose z axis is the surface normal
//! (see [`crate::ch5_reflection::material::Frame`]).

use std::f32::consts::{FRAC_1_PI, PI};

use glam::{Vec2, Vec3};

/// A direction uniformly distributed over the hemisphere z ≥ 0.
// ANCHOR: uniform_hemisphere
pub fn uniform_hemisphere(u: Vec2) -> Vec3 {
    let z = u.x; // cos θ is uniform for a uniform hemisphere
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}
// ANCHOR_END: uniform_hemisphere

/// The pdf of [`uniform_hemisphere`] in solid angle: 1 / (2π).
pub const UNIFORM_HEMISPHERE_PDF: f32 = 0.5 * FRAC_1_PI;

/// A direction uniformly distributed over the whole sphere.
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// The pdf of [`uniform_sphere`] in solid angle: 1 / (4π).
pub const UNIFORM_SPHERE_PDF: f32 = 0.25 * FRAC_1_PI;

/// A point uniformly distributed on the unit disk, by Shirley and Chiu's
/// concentric map (it keeps neighbouring samples neighbours).
// ANCHOR: concentric_disk
pub fn concentric_disk(u: Vec2) -> Vec2 {
    let o = 2.0 * u - Vec2::ONE;
    if o == Vec2::ZERO {
        return Vec2::ZERO;
    }
    let (r, theta) = if o.x.abs() > o.y.abs() {
        (o.x, 0.25 * PI * (o.y / o.x))
    } else {
        (o.y, 0.5 * PI - 0.25 * PI * (o.x / o.y))
    };
    r * Vec2::new(theta.cos(), theta.sin())
}
// ANCHOR_END: concentric_disk

/// A cosine-weighted direction on the hemisphere z ≥ 0 (Malley's method:
/// a uniform point on the disk, lifted to the hemisphere).
// ANCHOR: cosine_hemisphere
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let d = concentric_disk(u);
    let z = (1.0 - d.length_squared()).max(0.0).sqrt();
    Vec3::new(d.x, d.y, z)
}

/// The pdf of [`cosine_hemisphere`] in solid angle: cos θ / π (zero below
/// the horizon).
pub fn cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    cos_theta.max(0.0) * FRAC_1_PI
}
// ANCHOR_END: cosine_hemisphere

/// Barycentric weights (b0, b1, b2) of a point uniformly distributed over
/// a triangle (the square-root parametrisation).
pub fn uniform_triangle(u: Vec2) -> Vec3 {
    let s = u.x.sqrt();
    let b1 = 1.0 - s;
    let b2 = u.y * s;
    Vec3::new(1.0 - b1 - b2, b1, b2)
}
