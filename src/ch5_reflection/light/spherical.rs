//! A direction drawn uniformly in the solid angle a triangle subtends
//! (Arvo 1995, "Stratified sampling of spherical triangles").
//!
//! Seen from a shading point p, a triangle covers a spherical triangle on
//! the unit sphere around p (exercise 5.6 works out its area Ω). Drawing
//! directions uniformly over that patch gives pdf_ω = 1/Ω for every
//! direction that reaches the light: the 1/d² and cos θl that area
//! sampling divides by are gone from the estimate, and what is left to
//! vary is the BRDF and cos θ at p.
//!
//! The sampler works on the sphere in two steps, each by inverting an
//! area: first a point c' on the edge a→c such that the smaller spherical
//! triangle (a, b, c') has the fraction u.x of the whole area; then a
//! point on the arc from b to c', spaced so that the strip it sweeps is
//! uniform too. Everything is f64: a spherical triangle's area is the sum
//! of its angles minus π (Girard), and for a small patch that difference
//! loses in f32 most of the digits it has.

use std::f64::consts::PI;

use glam::{DVec3, Vec2};

/// A unit direction drawn uniformly in the spherical triangle with unit
/// corners `a`, `b`, `c` (seen from the sphere's centre), from two
/// uniform numbers in [0, 1); `None` for a triangle with no area on the
/// sphere (corners on one great circle).
// ANCHOR: sample_spherical_triangle
pub fn sample_spherical_triangle([a, b, c]: [DVec3; 3], u: Vec2) -> Option<DVec3> {
    // The planes through p and each edge, by their normals.
    let n_ab = a.cross(b).try_normalize()?;
    let n_bc = b.cross(c).try_normalize()?;
    let n_ca = c.cross(a).try_normalize()?;
    // The angles at the corners: between the planes that meet there.
    let alpha = angle_between(n_ab, -n_ca);
    let beta = angle_between(n_bc, -n_ab);
    let gamma = angle_between(n_ca, -n_bc);
    // Girard: the area is how far the angles' sum exceeds π.
    let area = alpha + beta + gamma - PI;
    if area.is_nan() || area <= 0.0 {
        return None;
    }
    // Step 1: the corner c' on the arc a→c whose triangle (a, b, c') has
    // the area u.x · Ω; Arvo's closed form for the cosine of its arc a→c'.
    let sub = u.x as f64 * area;
    let (s, t) = (sub - alpha).sin_cos();
    let (sin_a, cos_a) = alpha.sin_cos();
    let k1 = t - cos_a;
    let k2 = s + sin_a * a.dot(b);
    let q = ((k2 * t - k1 * s) * cos_a - k2) / ((k2 * s + k1 * t) * sin_a);
    let q = q.clamp(-1.0, 1.0);
    let c_sub = q * a + (1.0 - q * q).max(0.0).sqrt() * away(c, a)?;
    // Step 2: a point on the arc b→c', uniform in the area it sweeps.
    let z = 1.0 - u.y as f64 * (1.0 - c_sub.dot(b));
    let w = z * b + (1.0 - z * z).max(0.0).sqrt() * away(c_sub, b)?;
    Some(w.normalize())
}
// ANCHOR_END: sample_spherical_triangle

/// The unit part of `v` perpendicular to the unit `from` (one step of
/// Gram-Schmidt): the direction to walk from `from` towards `v`.
fn away(v: DVec3, from: DVec3) -> Option<DVec3> {
    (v - v.dot(from) * from).try_normalize()
}

/// The angle between unit vectors, accurate near 0 and π too (a chord's
/// half-length is the sine of half the angle; the arc cosine of a dot
/// product is not).
fn angle_between(v: DVec3, w: DVec3) -> f64 {
    if v.dot(w) < 0.0 {
        PI - 2.0 * ((v + w).length() / 2.0).min(1.0).asin()
    } else {
        2.0 * ((w - v).length() / 2.0).min(1.0).asin()
    }
}
