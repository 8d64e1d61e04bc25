//! Capstone 5: direct lighting from an area light, by sampling the light.
//!
//! The grader renders the Cornell box (`scenes/cornell-box.toml`) lit
//! only directly by its ceiling light: at the first surface each camera
//! ray meets, it draws points on the light and calls this function once
//! per point; the pixel is the average. Your answer is checked
//! statistically against the reference (Monte Carlo is never exact).
//!
//! * `p`: the shading point; `n`: its unit normal (facing the camera);
//!   `rho`: its Lambertian albedo.
//! * `y`: a point on the light, drawn uniformly by area over the light's
//!   total area `area`, so its density is 1/area per square metre;
//!   `n_light`: the light's unit normal there. The light emits radiance
//!   `le` from its front face only (the side `n_light` points to).
//! * `visible(p, y)`: whether nothing blocks the segment from p to y.
//!
//! Return the one-sample estimate of the reflected radiance at p
//! (W/(m²·sr) per channel): the lecture's f · Le · cos θ / pdf, with the
//! density turned from per area into per solid angle.
//!
//! Grade it with: `cargo run --release --bin grade -- ch5`, and see it
//! render with `cargo run --release --bin ch5 -- --student`.

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
    // TODO: the direction wi from p to y and the distance d.
    // TODO: the two cosines: at p (with n) and at the light (with
    //       n_light, looking back along -wi); nothing if either is not
    //       positive, or if y is not visible from p.
    // TODO: the Lambertian BRDF.
    // TODO: the density of y per solid angle seen from p, and the
    //       estimate f · Le · cos θ / pdf.
    todo!()
}
