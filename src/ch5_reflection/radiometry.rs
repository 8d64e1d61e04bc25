//! Radiometry (chapter 5): the quantities light is measured in, and the
//! closed forms the tests and studies check estimators against.
//!
//! | quantity | symbol | unit | what it is |
//! |---|---|---|---|
//! | radiant flux | Φ | W | energy per unit time |
//! | irradiance | E | W/m² | flux per unit area arriving at a surface |
//! | intensity | I | W/sr | flux per unit solid angle leaving a point |
//! | radiance | L | W/(m²·sr) | flux per unit area perpendicular to the ray, per unit solid angle |
//!
//! Lambert's law: a beam of flux Φ spread over a surface tilted by θ
//! covers A = A⊥ / cos θ, so E = Φ cos θ / A⊥. Radiance arriving in a
//! small solid angle dω gives dE = L cos θ dω, and so
//! E = ∫ L cos θ dω over the hemisphere. A Lambertian surface of albedo ρ
//! reflects L_r = ρ/π · E in every direction.
//!
//! Everything here is f64: these are the references the f32 renderer is
//! measured against.

use std::f64::consts::PI;

use glam::DVec3;

/// The solid angle of a cone of half-angle `alpha` (radians): the area it
/// cuts from the unit sphere, 2π(1 − cos α).
// ANCHOR: solid_angles
pub fn cap_solid_angle(alpha: f64) -> f64 {
    2.0 * PI * (1.0 - alpha.cos())
}

/// The solid angle a sphere of `radius` subtends from `distance` to its
/// centre: a cap with sin α = r/d. 2π from its surface, 4π from inside.
pub fn sphere_solid_angle(radius: f64, distance: f64) -> f64 {
    if distance <= radius {
        return if distance < radius {
            4.0 * PI
        } else {
            2.0 * PI
        };
    }
    let s = radius / distance;
    // 1 − cos α = s² / (1 + cos α) avoids cancellation for far spheres.
    let cos_a = (1.0 - s * s).sqrt();
    2.0 * PI * s * s / (1.0 + cos_a)
}
// ANCHOR_END: solid_angles

/// The solid angle of the triangle (a, b, c) seen from the origin (Van
/// Oosterom and Strackee 1983): tan(Ω/2) = |a·(b×c)| / (abc + (a·b)c +
/// (a·c)b + (b·c)a), where a, b, c also name the vectors' lengths.
// ANCHOR: triangle_solid_angle
pub fn triangle_solid_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let numerator = a.dot(b.cross(c)).abs();
    let denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    2.0 * numerator.atan2(denominator)
}
// ANCHOR_END: triangle_solid_angle

/// The power (W) of a spot light of intensity `i` (W/sr) whose falloff is
/// 1 within the half-angle `inner`, 0 beyond `outer` and a smoothstep in
/// cos θ between (radians, 0 ≤ inner ≤ outer ≤ π): 2π I (1 − cos θi) from
/// the inner cone and half the band between the cones, (cos θi − cos θo)/2,
/// since a smoothstep integrates to 1/2. Each 1 − cos θ is written as
/// 2 sin²(θ/2), which keeps its digits for a narrow cone.
// ANCHOR: spot_flux
pub fn spot_flux(i: f64, inner: f64, outer: f64) -> f64 {
    let one_minus_cos = |theta: f64| 2.0 * (theta / 2.0).sin().powi(2);
    PI * i * (one_minus_cos(inner) + one_minus_cos(outer))
}
// ANCHOR_END: spot_flux

/// Irradiance at `p` (unit normal `n`) from a polygon of uniform radiance
/// `le`, by Lambert's formula: E = (L/2) Σᵢ Θᵢ (Γᵢ · n), where Θᵢ is the
/// angle edge i subtends at p and Γᵢ the unit normal of the plane through p
/// and that edge. The polygon must lie wholly above p's tangent plane
/// (nothing is clipped); its winding does not matter.
// ANCHOR: lambert_polygon
pub fn polygon_irradiance(p: DVec3, n: DVec3, vertices: &[DVec3], le: f64) -> f64 {
    let mut sum = 0.0;
    for i in 0..vertices.len() {
        let a = (vertices[i] - p).normalize();
        let b = (vertices[(i + 1) % vertices.len()] - p).normalize();
        let theta = a.dot(b).clamp(-1.0, 1.0).acos();
        let gamma = a.cross(b).normalize_or_zero();
        sum += theta * gamma.dot(n);
    }
    0.5 * le * sum.abs()
}
// ANCHOR_END: lambert_polygon

/// Irradiance from an isotropic point light of intensity `i` at distance
/// `r`, arriving at angle θ to the normal: E = I cos θ / r² (the
/// inverse-square law times Lambert's cosine).
// ANCHOR: point_irradiance
pub fn point_irradiance(i: f64, r: f64, cos_theta: f64) -> f64 {
    i * cos_theta.max(0.0) / (r * r)
}
// ANCHOR_END: point_irradiance

/// Irradiance from a directional light of irradiance `e` at normal
/// incidence, arriving at angle θ: E = E⊥ cos θ.
pub fn directional_irradiance(e: f64, cos_theta: f64) -> f64 {
    e * cos_theta.max(0.0)
}

/// Radiance a Lambertian surface of albedo ρ reflects under irradiance E.
pub fn lambertian_radiance(rho: f64, e: f64) -> f64 {
    rho / PI * e
}
