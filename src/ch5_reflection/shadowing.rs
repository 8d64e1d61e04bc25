//! The one question chapter 5 asks the scene before any ray is traced:
//! can anything in it cast a shadow at all? If not, the estimator traces
//! neither shadow rays nor rays along sampled directions
//! ([`Estimator::trace_light_rays`](super::direct::Estimator::trace_light_rays)).

use crate::scene::mesh::Mesh;
use crate::scene::Scene;

/// Whether no surface of `scene` can shadow any other point of it: no
/// SDFs, no emissive surfaces, and one mesh that is flat or convex (a
/// point on a convex surface sees nothing of it above its tangent plane).
/// Such a scene needs no shadow rays.
// ANCHOR: cannot_shadow
pub fn scene_cannot_shadow(scene: &Scene) -> bool {
    scene.sdfs.is_empty()
        && !scene.has_emitters()
        && scene.meshes.len() == 1
        && is_convex(&scene.meshes[0])
}
// ANCHOR_END: cannot_shadow

/// Whether every vertex lies on or behind every face's plane (a single flat
/// polygon passes: all vertices lie on its plane). The test costs triangles
/// × vertices; above [`CONVEXITY_WORK`] (a sphere of 81,920 triangles took
/// seconds) the mesh is taken as possibly self-shadowing, which only costs
/// shadow rays.
fn is_convex(mesh: &Mesh) -> bool {
    if mesh.triangles.len() as u64 * mesh.positions.len() as u64 > CONVEXITY_WORK {
        return false;
    }
    let scale = mesh
        .positions
        .iter()
        .fold(0.0f32, |m, p| m.max(p.abs().max_element()))
        .max(1e-6);
    mesh.triangles.iter().all(|t| {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let Some(n) = (b - a).cross(c - a).try_normalize() else {
            return true;
        };
        mesh.positions
            .iter()
            .all(|p| (*p - a).dot(n) <= 1e-4 * scale)
    })
}

/// The most triangle-vertex pairs the convexity test looks at.
const CONVEXITY_WORK: u64 = 50_000_000;
