//! The image of chapter 5: every pixel averages camera rays through
//! jittered positions, each ray's radiance from the reflection equation
//! ([`super::direct`]); and the one question the scene answers before any
//! ray is traced: can anything cast a shadow at all?

use glam::Vec3;
use rayon::prelude::*;

use super::direct::{Counters, Estimator};
use super::world::World;
use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::render::camera_sample;
use crate::core::sampling::Sampler;
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

/// Adds sample `sample` of every pixel to `sums`, rows in parallel; every
/// random number comes from (seed, pixel, sample), so the result does not
/// depend on the number of threads.
// ANCHOR: render_pass
pub fn render_pass(
    world: &World,
    cam: &Camera,
    estimator: &Estimator,
    seed: u64,
    sample: u32,
    sums: &mut [Vec3],
) -> Counters {
    let w = cam.width as usize;
    sums.par_chunks_mut(w)
        .enumerate()
        .map(|(y, row)| {
            let mut c = Counters::default();
            for (x, px) in row.iter_mut().enumerate() {
                let (mut s, ray) = camera_sample(cam, (x as u32, y as u32), |pixel| {
                    Sampler::new(seed, pixel, sample as u64)
                });
                let l = estimator.radiance(world, &ray, &mut s, &mut c);
                if l.is_finite() {
                    *px += l;
                } else {
                    c.nonfinite += 1;
                }
            }
            c
        })
        .reduce(Counters::default, |mut a, b| {
            a += b;
            a
        })
}
// ANCHOR_END: render_pass
