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

/// Lights times SDF shapes and operations above which a run is warned
/// about: chapter 5 traces a shadow ray to every light at every sample,
/// and each marches through every SDF node at every step.
pub const SHADOW_WORK_WARN: u64 = 4096;
/// A rough rate for the warning's estimate: SDF node evaluations per
/// second per core, and the steps a shadow ray takes.
const NODE_EVALS_PER_CORE_SECOND: f64 = 2e8;
const STEPS_PER_SHADOW_RAY: f64 = 32.0;

/// The warning for a scene whose shadow rays cost lights × SDF nodes per
/// sample, with a rough time for `samples` samples, when that product is
/// at least [`SHADOW_WORK_WARN`].
pub fn shadow_work_warning(scene: &Scene, samples: u64) -> Option<String> {
    let emissive = scene
        .meshes
        .iter()
        .filter(|m| scene.materials[m.material].is_emissive())
        .count();
    let lights = (scene.lights.len() + emissive) as u64;
    let nodes: u64 = scene
        .sdfs
        .iter()
        .map(|s| crate::scene::sdf_nodes(&s.sdf) as u64)
        .sum();
    let product = lights * nodes;
    if product < SHADOW_WORK_WARN {
        return None;
    }
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get()) as f64;
    let seconds = samples as f64 * product as f64 * STEPS_PER_SHADOW_RAY
        / (NODE_EVALS_PER_CORE_SECOND * cores);
    Some(format!(
        "warning: {lights} lights x {nodes} SDF shapes and operations: every sample traces \
         a shadow ray to each light, and each step of it evaluates every SDF node \
         ({product} evaluations a step); {samples} samples may take about {} \
         on {cores} cores. Fewer lights or SDFs (or a smaller --spp) cost less.",
        crate::core::format::format_seconds(seconds)
    ))
}
