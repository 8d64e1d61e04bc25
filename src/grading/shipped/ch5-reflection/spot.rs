//! Exercise 5.7: how much power a spot light emits.
//!
//! A spot light sends intensity I (W/sr) times its falloff into each
//! direction: 1 inside the inner cone, 0 beyond the outer one, and the
//! book's smoothstep in cos θ between (`Spot::falloff`, chapter 5,
//! "Lights"). Its power, the flux Φ in watts, is the intensity summed
//! over every direction. A lighting artist who makes a spot's cone wider
//! or its edge softer changes Φ; your function says by how much.
//!
//! Contract (what the grader checks, each channel to 10⁻⁵ of the
//! brightest channel's power):
//! * Φ (W) of a spot of intensity `intensity` (W/sr) on its axis, inner
//!   half-angle `inner` and outer half-angle `outer`, in radians,
//!   0 ≤ inner ≤ outer ≤ π, with the book's falloff;
//! * a hard edge (inner = outer), an edge soft all the way (inner = 0),
//!   a cone of 180° (the whole sphere), and cones as narrow as 10⁻⁵ rad, to
//!   the same 10⁻⁵: f32 keeps about 7 digits; mind what is left of them.
//!
//! Hints: `cargo grade --hint ch5/spot`.
//! Grade it with: `cargo grade ch5`

use glam::Vec3;

/// The power (W, per channel) of a spot light.
pub fn spot_power(intensity: Vec3, inner: f32, outer: f32) -> Vec3 {
    // TODO: integrate I times the falloff over the sphere of directions.
    todo!()
}
