//! Exercise 5.6, solved: Van Oosterom and Strackee's formula,
//! tan(Ω/2) = |a·(b×c)| / (abc + (a·b)c + (a·c)b + (b·c)a) with a, b, c
//! the corners seen from p (and their lengths). The triple product is
//! taken with the edges, a·((b−a)×(c−a)), the same number: b×c of two
//! nearly parallel vectors (a small triangle far away) cancels in f32.

use glam::Vec3;

/// The solid angle (sr) the triangle `tri` subtends at `p`.
pub fn solid_angle(p: Vec3, tri: [Vec3; 3]) -> f32 {
    let (a, b, c) = (tri[0] - p, tri[1] - p, tri[2] - p);
    let normal = (tri[1] - tri[0]).cross(tri[2] - tri[0]);
    let numerator = a.dot(normal).abs();
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    2.0 * numerator.atan2(denominator)
}
