//! Exercise 6.5, solved: turn the normal and the indices to the side the
//! light comes from, then Snell's law in vector form and the mean of the
//! s- and p-reflectances.

use glam::Vec3;

/// The refracted direction of light travelling along `d` through the
/// boundary with outward normal `n`, and the Fresnel reflectance there;
/// `None` under total internal reflection.
pub fn refract(d: Vec3, n: Vec3, eta_outside: f32, eta_inside: f32) -> Option<(Vec3, f32)> {
    // The normal on the side the light comes from, and the indices in the
    // order it crosses them.
    let (m, eta_i, eta_t) = if d.dot(n) < 0.0 {
        (n, eta_outside, eta_inside)
    } else {
        (-n, eta_inside, eta_outside)
    };
    let cos_i = -d.dot(m);
    let eta = eta_i / eta_t;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    // The part of d along the surface shrinks by η; the rest goes on
    // through, against m.
    let t = (eta * d + (eta * cos_i - cos_t) * m).normalize();
    let r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    let r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    Some((t, 0.5 * (r_s * r_s + r_p * r_p)))
}
