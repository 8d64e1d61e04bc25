//! Exercise 2.2: barycentric coordinates of a point.
//!
//! The lecture's φi, φj, φk: p = φi·pi + φj·pj + φk·pk with
//! φi + φj + φk = 1. Each φ is the (signed) area of the sub-triangle that p
//! makes with the *opposite* edge, divided by the area of the whole
//! triangle. Return `None` when the triangle has no area.
//!
//! Grade it with: `cargo run --release --bin grade -- ch2`

use glam::{Vec2, Vec3};

/// (φi, φj, φk) of `p` in the triangle (pi, pj, pk).
pub fn barycentric(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    // TODO: the doubled signed area of (pi, pj, pk); `None` if it is zero.
    // TODO: φi from the sub-triangle (pj, pk, p), φj from (pk, pi, p),
    //       φk from (pi, pj, p), each divided by the whole area.
    todo!()
}
