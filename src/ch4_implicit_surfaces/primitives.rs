//! The primitive signed distance functions, each in its own object space
//! (centred at the origin). All of them are *exact*: f(p) is the signed
//! Euclidean distance from p to the surface, negative inside, so
//! ‖∇f‖ = 1 wherever f is differentiable (the Eikonal equation).

use glam::{Vec2, Vec3};

/// Sphere of radius `r` around the origin: the distance to the centre,
/// minus the radius.
// ANCHOR: sd_sphere
pub fn sd_sphere(p: Vec3, r: f32) -> f32 {
    p.length() - r
}
// ANCHOR_END: sd_sphere

/// Axis-aligned box with half-extents `b`. Outside, the distance to the
/// nearest point of the box (only the axes where p sticks out count);
/// inside, minus the distance to the nearest face.
// ANCHOR: sd_box
pub fn sd_box(p: Vec3, b: Vec3) -> f32 {
    let q = p.abs() - b; // per axis: how far p is past the face
    let outside = q.max(Vec3::ZERO).length();
    let inside = q.max_element().min(0.0);
    outside + inside
}
// ANCHOR_END: sd_box

/// A box with half-extents `b` whose edges are rounded with radius `r`
/// (r ≤ the smallest half-extent): a smaller box, inflated by r.
pub fn sd_rounded_box(p: Vec3, b: Vec3, r: f32) -> f32 {
    sd_box(p, b - Vec3::splat(r)) - r
}

/// Torus around the y axis: a circle of radius `major` in the xz plane,
/// thickened to a tube of radius `minor`.
pub fn sd_torus(p: Vec3, major: f32, minor: f32) -> f32 {
    // Distance to the core circle, measured in the plane through the y axis.
    let q = Vec2::new(Vec2::new(p.x, p.z).length() - major, p.y);
    q.length() - minor
}

/// Half-space below the plane n·p = h (n unit length): positive on the
/// side `n` points to.
pub fn sd_plane(p: Vec3, n: Vec3, h: f32) -> f32 {
    n.dot(p) - h
}

/// Capsule: the segment a-b thickened by `r`; the distance to the nearest
/// point of the segment, minus r.
pub fn sd_capsule(p: Vec3, a: Vec3, b: Vec3, r: f32) -> f32 {
    let (pa, ba) = (p - a, b - a);
    let len2 = ba.length_squared();
    let h = if len2 > 0.0 {
        (pa.dot(ba) / len2).clamp(0.0, 1.0)
    } else {
        0.0 // a == b: a sphere
    };
    (pa - ba * h).length() - r
}

/// Capped cylinder around the y axis: radius `r`, from y = -h to y = h.
/// A 2D box in (distance from the axis, height).
pub fn sd_cylinder(p: Vec3, r: f32, h: f32) -> f32 {
    let d = Vec2::new(Vec2::new(p.x, p.z).length() - r, p.y.abs() - h);
    d.max_element().min(0.0) + d.max(Vec2::ZERO).length()
}
