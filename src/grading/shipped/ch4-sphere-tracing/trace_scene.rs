//! Capstone 4: sphere trace the chapter's scene.
//!
//! The grader shoots one camera ray per pixel through chapter 4's scene of
//! every shape (`scenes/sdf-shapes.toml`) and calls this function for each,
//! then a few rays at walls whose distance functions count every call.
//! Find where the ray r(t) = origin + t·dir (dir is unit length) first
//! meets the surface f = 0 of the distance function `sdf`, and the unit
//! normal there. The origin is outside every shape (f(origin) > 0).
//!
//! Contract (what the grader checks):
//! * March from t = 0, stepping by the value of f itself. (`March` also
//!   has a `step_factor`, for the library's distance functions that
//!   overestimate; it is 1 in every march the grader passes, and this
//!   scene's functions do not overestimate.)
//! * A hit is the first point p the march reaches with
//!   |f(p)| < `march.epsilon_at(p)`: the ε scaled to p's distance from the
//!   world's origin (far away, a point cannot come closer to a surface
//!   than the rounding of its coordinates). Return its t.
//! * A miss (`None`): t beyond `march.max_distance` before a hit, or the
//!   step budget used up: at most `march.max_steps` evaluations of `sdf`
//!   (at least one) while marching, the one at t = 0 included, every one
//!   tested for a hit. The point a step reaches is tested for a hit
//!   first: a step that lands on a surface beyond `max_distance` has
//!   found it.
//! * The normal at a hit: the gradient of f by central differences with
//!   h = max(`march.epsilon_at(p)`, 1e-4), normalised; -dir where the
//!   gradient is zero (a gradient however short, 2^-50 say, still gives
//!   its direction); turned round where it points along dir, so that it
//!   faces the viewer (n · dir ≤ 0). Its six evaluations do not count
//!   against the budget.
//! * Depths to 1e-3 relative and normals to 0.02 in the scene; exactly the
//!   reference's steps on the walls.
//!
//! The idea: the distance function promises that no surface is closer
//! than its value, so that value is a safe step; near a surface the steps
//! shrink and the march stops within ε of it.
//!
//! Grade it with: `cargo grade ch4`, and see it
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
    // TODO: your code here (steps: `cargo grade --hint ch4/trace_scene`).
    todo!()
}
