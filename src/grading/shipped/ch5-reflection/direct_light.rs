//! Capstone 5: direct lighting from an area light, by sampling the light.
//!
//! One sample of the reflection equation at p: the light arriving from a
//! point y drawn on the light, weighed by the BRDF and the cosine at p,
//! divided by the density of that sample, which was drawn per area of the
//! light while the equation integrates over directions at p.
//!
//! The inputs:
//! * `p`: the shading point; `n`: its unit normal (facing the camera);
//!   `rho`: its Lambertian albedo, each channel in [0, 1] (as a scene
//!   file's `reflectance`);
//! * `y`: a point on the light, drawn uniformly by area over the light's
//!   total area `area` (its density is 1/area per square metre);
//!   `n_light`: the light's unit normal at y;
//! * `le`: the radiance the light emits from its front face, the side
//!   `n_light` points to; its back face emits nothing;
//! * `visible(p, y)`: whether nothing blocks the segment from p to y.
//!
//! Contract (what the grader checks, clause by clause, to 10⁻⁴ relative
//! on hand-worked cases that change one factor at a time, then on the
//! Cornell box with the same light points as the reference):
//! * return the one-sample estimate of the radiance reflected at p
//!   (W/(m²·sr) per channel): the Lambertian BRDF times Le times cos θ at
//!   p, divided by the density of the sample per steradian at p;
//! * exactly 0 when y shows p its back face, when y is below or in the
//!   plane of p's surface, and when `visible(p, y)` is false;
//! * ask `visible` about exactly the segment (p, y), in that order;
//! * finite for every sample (no inf, no NaN), at every scale: scenes
//!   10⁻¹⁵ to 10¹⁵ m across, up to 10⁶ times their size from the origin,
//!   Le from 10⁻¹² to 10⁹ (Le times the area can then pass f32's largest
//!   number where the answer does not), albedos down to 10⁻⁶.
//!
//! Hints: `cargo grade --hint ch5/direct_light`.
//! Grade it with: `cargo grade ch5`, and see it
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
    // TODO: f · Le · cos θ / pdf, with the pdf per steradian at p.
    todo!()
}
