//! Exercise 5.4, solved: pdf_ω = pdf_A · d² / |cos θl|.

use glam::Vec3;

/// The solid-angle pdf at `x` of a point `y` sampled with `pdf_area`.
pub fn area_to_solid_angle(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    let to = x - y;
    let d2 = to.length_squared();
    let cos = n_light.dot(to / d2.sqrt()).abs();
    if cos == 0.0 {
        0.0
    } else {
        pdf_area * d2 / cos
    }
}
