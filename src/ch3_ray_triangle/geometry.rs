//! What chapter 3 traces against: the scene's triangles, a BVH over them,
//! and how a first hit is shown (depth, normal, barycentrics, triangle id).

use glam::Vec3;

use crate::ch3_ray_triangle::obvhs_bvh::{Bvh, Triangles};
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::{unit_normal, Hit, Intersector};
use crate::core::sampling::mix64;
use crate::scene::Scene;

/// What the stage traces against: the scene's triangles and, when there
/// are any, a BVH over them.
pub struct Geometry {
    /// Every triangle of the scene.
    pub triangles: Triangles,
    /// The BVH, or `None` when the scene has no triangles.
    pub bvh: Option<Bvh>,
    /// The range of distances from the eye to the scene's vertices, for
    /// shading depth.
    pub depth_range: (f32, f32),
}

impl Geometry {
    /// Flattens the scene's meshes and builds a BVH if there is anything to
    /// build it over.
    pub fn new(scene: &Scene) -> Geometry {
        let triangles = Triangles::from_meshes(&scene.meshes);
        let bvh = Bvh::build(&triangles.tris);
        let eye = scene.camera.eye_f32();
        let (mut near, mut far) = (f32::INFINITY, 0.0f32);
        for p in triangles.tris.iter().flatten() {
            let d = p.distance(eye);
            near = near.min(d);
            far = far.max(d);
        }
        Geometry {
            triangles,
            bvh,
            depth_range: (near.min(far), far),
        }
    }

    /// The closest hit along `ray`, through the BVH (or nothing at all
    /// when there is no geometry).
    pub fn closest(&self, ray: &Ray) -> Option<Hit> {
        self.bvh
            .as_ref()
            .and_then(|b| b.closest(ray, f32::INFINITY, Intersector::Watertight))
    }
}

/// The colour of triangle `id` in the id view: a hash, so neighbours differ.
pub fn id_color(id: u32) -> Vec3 {
    let h = mix64(id as u64 + 1);
    let c = |s: u32| 0.2 + 0.8 * ((h >> s) & 0xff) as f32 / 255.0;
    Vec3::new(c(0), c(8), c(16))
}

/// The four view values of one first hit (or of a miss).
// ANCHOR: shade_views
pub fn shade(geometry: &Geometry, hit: Option<Hit>) -> [Vec3; 4] {
    let Some(hit) = hit else {
        return [Vec3::ZERO; 4];
    };
    let n = unit_normal(geometry.triangles.tris[hit.triangle as usize]).unwrap_or(Vec3::ZERO);
    let (near, far) = geometry.depth_range;
    // Depth shaded by 1/t (as in chapter 1): 1 at the nearest vertex,
    // 0.15 at the farthest.
    let s = ((1.0 / hit.t - 1.0 / far) / (1.0 / near - 1.0 / far)).clamp(0.0, 1.0);
    let s = if s.is_finite() { s } else { 1.0 };
    [
        Vec3::splat(0.15 + 0.85 * s),
        (n + 1.0) * 0.5,
        hit.barycentrics(),
        id_color(hit.triangle),
    ]
}
// ANCHOR_END: shade_views
