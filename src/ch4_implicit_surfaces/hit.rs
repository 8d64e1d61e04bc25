//! One surface hit, whatever the surface, and "the nearest hit wins" for
//! scenes that mix SDF objects with meshes.
//!
//! Chapter 4 sphere-traces the SDF part. The mesh part (ray-triangle and
//! the BVH) is chapter 3's; the renderer passes its hit, or `None` for a
//! scene without meshes, to [`nearest_hit`].

use glam::Vec3;

use crate::scene::Scene;

/// What kind of surface was hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    /// SDF object `index` of the scene.
    Sdf(usize),
    /// Mesh `index` of the scene.
    Mesh(usize),
}

/// A hit on any surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceHit {
    /// Distance along the (unit) ray.
    pub t: f32,
    /// Unit normal, facing against the ray.
    pub normal: Vec3,
    /// Index into the scene's materials.
    pub material: usize,
    /// Which surface.
    pub surface: Surface,
}

/// The nearer of an SDF hit and a mesh hit; either may be missing. On a
/// tie the SDF hit wins, so the result does not depend on the order the
/// two were found in.
// ANCHOR: nearest_hit
pub fn nearest_hit(sdf: Option<SurfaceHit>, mesh: Option<SurfaceHit>) -> Option<SurfaceHit> {
    match (sdf, mesh) {
        (Some(s), Some(m)) => Some(if m.t < s.t { m } else { s }),
        (s, m) => s.or(m),
    }
}
// ANCHOR_END: nearest_hit

/// A surface's name for a table: "mesh 3 \"short box\"".
pub fn surface_name(scene: &Scene, surface: Surface) -> String {
    match surface {
        Surface::Mesh(i) => match scene.meshes.get(i) {
            Some(m) if !m.name.is_empty() => format!("mesh {i} \"{}\"", m.name),
            _ => format!("mesh {i}"),
        },
        Surface::Sdf(i) => match scene.sdfs.get(i) {
            Some(o) if !o.name.is_empty() => format!("sdf {i} \"{}\"", o.name),
            _ => format!("sdf {i}"),
        },
    }
}
