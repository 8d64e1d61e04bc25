//! Capstone 5, solved: one light sample, its density turned from per area
//! into per steradian.

use glam::Vec3;

/// One light-sampling estimate of the radiance reflected at `p`.
#[allow(clippy::too_many_arguments)]
pub fn direct_light(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: &dyn Fn(Vec3, Vec3) -> bool,
) -> Vec3 {
    let to = y - p;
    let d2 = to.length_squared();
    let wi = to / d2.sqrt();
    let cos = n.dot(wi);
    let cos_light = n_light.dot(-wi);
    if cos <= 0.0 || cos_light <= 0.0 || !visible(p, y) {
        return Vec3::ZERO;
    }
    let f = rho / std::f32::consts::PI;
    let pdf = d2 / (cos_light * area);
    f * le * cos / pdf
}
