//! Capstone 4: sphere trace the chapter's scene.
//!
//! The grader shoots one camera ray per pixel through chapter 4's scene of
//! every shape (`scenes/sdf-shapes.toml`) and calls this function for each.
//! Find where the ray r(t) = origin + t·dir (dir is unit length) first
//! meets the surface f = 0 of the distance function `sdf`, and the unit
//! normal there. The camera is outside every shape (f(origin) > 0).
//!
//! * March: step by the distance f itself, as the lecture's sphere
//!   tracing does. Every evaluation of `sdf` counts against the step
//!   budget `march.max_steps` (the first one, at t = 0, included).
//! * A hit is |f(p)| < `march.epsilon_at(p)`; a miss is t beyond
//!   `march.max_distance`, or the budget used up first.
//! * The normal is the gradient of f by central differences with
//!   h = max(`march.epsilon_at(p)`, 1e-4), normalised (where the gradient
//!   is zero, use -dir), and turned to face the viewer (n · dir < 0).
//!
//! Grade it with: `cargo run --release --bin grade -- ch4`, and see it
//! render with `cargo run --release --bin ch4 -- --student`.

use glam::Vec3;
use raystep::ch4_implicit_surfaces::march::March;

/// The first hit of the ray: `Some((t, normal))`, or `None` for a miss.
pub fn trace_scene(
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    march: &March,
) -> Option<(f32, Vec3)> {
    // TODO: start at t = 0 with one evaluation of sdf at the origin.
    // TODO: loop: at p = origin + t·dir, a hit when |f| is below
    //       march.epsilon_at(p); a miss past march.max_distance; a miss
    //       when the budget of march.max_steps evaluations is used up.
    // TODO: otherwise step t += f and evaluate again.
    // TODO: at the hit, the gradient by central differences (three axes),
    //       normalised, facing the viewer.
    todo!()
}
