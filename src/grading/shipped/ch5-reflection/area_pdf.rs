//! Exercise 5.4: converting an area-sampled pdf to solid angle.
//!
//! A point y drawn on a light with density `pdf_area` per square metre is
//! also a direction from the shading point x; the reflection equation
//! integrates over directions, so the estimator needs the density of that
//! direction per steradian. The two differ by how much solid angle a small
//! patch of the light covers seen from x.
//!
//! Contract (what the grader checks, to 10⁻⁴ relative):
//! * return the density per steradian at x of the point y, sampled with
//!   `pdf_area`, where the light's unit normal at y is `n_light`;
//! * which face of the light x sees does not matter here (a density is
//!   never negative): a light seen from behind has the same density;
//! * a light seen exactly edge-on shows no area: return 0 (not inf or NaN).
//!
//! Hints: `cargo grade --hint ch5/area_pdf`.
//! Grade it with: `cargo grade ch5`

use glam::Vec3;

/// The solid-angle pdf at `x` of a point `y` sampled with `pdf_area`.
pub fn area_to_solid_angle(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    // TODO: the Jacobian between area at y and solid angle at x.
    todo!()
}
