//! Exercise 5.4: converting an area-sampled pdf to solid angle.
//!
//! A point y sampled on a light with density `pdf_area` per square metre,
//! seen from the shading point x, covers the solid angle
//! dω = |cos θl| dA / d², where d = |y − x| and θl is the angle between
//! the light's normal `n_light` and the direction from y to x. So the same
//! sample's density per steradian is pdf_area · d² / |cos θl|.
//! A light seen exactly edge-on (cos θl = 0) shows no area: return 0.
//!
//! Grade it with: `cargo run --release --bin grade -- ch5`

use glam::Vec3;

/// The solid-angle pdf at `x` of a point `y` sampled with `pdf_area`.
pub fn area_to_solid_angle(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    // TODO: d² and the unit direction between x and y.
    // TODO: |cos θl| from the light's normal; 0 → return 0.
    // TODO: pdf_area · d² / |cos θl|.
    todo!()
}
