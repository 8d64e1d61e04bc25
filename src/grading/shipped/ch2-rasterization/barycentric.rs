//! Exercise 2.2: barycentric coordinates of a point.
//!
//! The lecture's φi, φj, φk: p = φi·pi + φj·pj + φk·pk with
//! φi + φj + φk = 1. The idea: each φ is a ratio of (signed) areas, and an
//! edge function is twice a signed area.
//!
//! The contract (checked within 1e-5; for a point far outside, where some
//! φ are large, within 1e-5 of the largest |φ|):
//! * φi is 1 at pi and 0 on the edge opposite pi (the same for j and k);
//! * they sum to 1 and rebuild p, also for points outside the triangle
//!   (where some φ are negative);
//! * the same φ for either winding (pi, pj, pk) or (pi, pk, pj) of the same
//!   corners, each φ staying with its own corner;
//! * `None` when the triangle has no area (a sliver, however thin, has
//!   one).
//!
//! Grade it with: `cargo grade ch2`

use glam::{Vec2, Vec3};

/// (φi, φj, φk) of `p` in the triangle (pi, pj, pk).
pub fn barycentric(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    // TODO: areas of sub-triangles over the area of the whole.
    todo!()
}
