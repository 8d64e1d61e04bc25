//! raystep's answers to chapter 5's exercises, each in its exercise's
//! form: what a check's reference run grades, and what the probes of
//! [`twins`](super::super::twins) compare near answers with (all but the
//! cosine map's, a sampling exercise with no twins).

use glam::{Vec2, Vec3};

use crate::ch5_reflection::light::area::solid_angle_pdf;
use crate::ch5_reflection::material::lambert::Lambertian;
use crate::ch5_reflection::radiometry::{point_irradiance, spot_flux, triangle_solid_angle};
use crate::ch5_reflection::warp::{cosine_hemisphere, cosine_hemisphere_pdf};

/// The Lambertian BRDF.
pub fn reference_lambert(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    Lambertian { rho }.f(wo, wi)
}

/// A cosine-weighted direction and its pdf.
pub fn reference_cosine(u: Vec2) -> (Vec3, f32) {
    let w = cosine_hemisphere(u);
    (w, cosine_hemisphere_pdf(w.z))
}

/// The irradiance from a point light of intensity `i`.
pub fn reference_point(i: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    i * point_irradiance(1.0, to.length() as f64, n.dot(to.normalize()) as f64) as f32
}

/// An area density turned into a solid-angle one.
pub fn reference_area_pdf(pdf: f32, x: Vec3, y: Vec3, n: Vec3) -> f32 {
    let to = y - x;
    solid_angle_pdf(pdf, to.length(), n.dot(to.normalize()))
}

/// The solid angle a triangle subtends, in f64.
pub fn reference_solid_angle(p: Vec3, t: [Vec3; 3]) -> f32 {
    let [a, b, c] = t.map(|v| v.as_dvec3() - p.as_dvec3());
    triangle_solid_angle(a, b, c) as f32
}

/// A spot light's power.
pub fn reference_spot(i: Vec3, inner: f32, outer: f32) -> Vec3 {
    (i.as_dvec3() * spot_flux(1.0, inner.into(), outer.into())).as_vec3()
}
