//! Inspect mode's per-pixel story for chapters 3 to 5, computed by each
//! chapter's library function for the inspected pixel: chapter 3 the
//! primary ray's hit (triangle, t, barycentrics), chapter 4 the sphere
//! tracing steps, chapter 5 each light's share of the pixel. One ray each,
//! so it runs on the UI thread whenever the cursor moves.

use std::sync::Arc;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::geometry::Geometry;
use crate::ch3_ray_triangle::render::pixel_hit;
use crate::ch4_implicit_surfaces::march::Ending;
use crate::ch4_implicit_surfaces::render::{march_steps, pixel_ray, MeshTracer};
use crate::ch5_reflection::direct::{Estimator, Strategy};
use crate::ch5_reflection::light_terms::pixel_light;
use crate::ch5_reflection::shadowing::scene_cannot_shadow;
use crate::ch6_global_illumination::path_record::light_name;
use crate::core::stage::Settings;
use crate::scene::Scene;

use super::trace::{num, rgb, Cache};

/// What chapter 3's geometry of a scene is, built once per scene.
#[derive(Default)]
pub struct GeometryCache {
    scene: Option<Arc<Scene>>,
    geometry: Option<Geometry>,
}

impl GeometryCache {
    fn get(&mut self, scene: &Arc<Scene>) -> &Geometry {
        if !self.scene.as_ref().is_some_and(|s| Arc::ptr_eq(s, scene)) {
            self.geometry = None;
            self.scene = Some(scene.clone());
        }
        self.geometry.get_or_insert_with(|| Geometry::new(scene))
    }
}

/// The story's lines for chapter `chapter` at `pixel`; `None` for chapters
/// without one (1, 2 and 6, whose panel has its own lines).
pub fn story_lines(
    chapter: u32,
    scene: &Arc<Scene>,
    settings: &Settings,
    variant: usize,
    pixel: (u32, u32),
    worlds: &mut Cache,
    geometries: &mut GeometryCache,
) -> Option<Vec<String>> {
    let camera = Camera::new(scene.camera).ok()?;
    if pixel.0 >= camera.width || pixel.1 >= camera.height {
        return None;
    }
    Some(match chapter {
        3 => {
            let g = geometries.get(scene);
            let spp = settings.spp.max(1);
            let h = pixel_hit(&camera, g, pixel, spp, settings.seed, 0);
            match h.hit {
                None => vec!["primary ray: miss".into()],
                Some(hit) => vec![
                    format!("primary ray hits triangle {}", hit.triangle),
                    format!(" of mesh {}", h.mesh.map_or("?".into(), |m| m.to_string())),
                    format!(" t = {}", num(hit.t)),
                    format!(" u = {}, v = {}", num(hit.u), num(hit.v)),
                    format!(" 1-u-v = {}", num(1.0 - hit.u - hit.v)),
                ],
            }
        }
        4 => {
            let stage = crate::ch4_implicit_surfaces::stage::DEFAULT;
            let meshes = (!scene.meshes.is_empty()).then(|| MeshTracer {
                geometry: geometries.get(scene),
                meshes: &scene.meshes,
            });
            let ray = pixel_ray(&camera, pixel.0, pixel.1);
            let m = march_steps(
                &ray,
                &scene.sdfs,
                &stage.march,
                stage.method,
                stage.normals,
                meshes,
            );
            let ending = match m.pixel.trace.ending {
                Ending::Hit => "hit".to_string(),
                Ending::Escaped => "escaped".to_string(),
                Ending::Budget => format!("budget of {} steps exhausted", stage.march.max_steps),
            };
            let mut out = if scene.sdfs.is_empty() {
                vec!["no SDF objects: nothing to march".to_string()]
            } else {
                vec![format!("sphere tracing: {} steps, {ending}", m.steps.len())]
            };
            let n = m.steps.len();
            for (i, (t, d)) in m.steps.iter().enumerate() {
                if i < 4 || i + 3 >= n {
                    out.push(format!(" {i:>3}: t {} f {}", num(*t), num(*d)));
                } else if i == 4 {
                    out.push("  …".into());
                }
            }
            match m.pixel.hit {
                Some(h) => out.push(format!("nearest hit t {} ({:?})", num(h.t), h.surface)),
                None => out.push("nearest hit: none".into()),
            }
            out
        }
        5 => {
            let world = worlds.world(scene);
            let est = Estimator {
                strategy: Strategy::ALL[variant.min(3)],
                max_mirror_bounces: crate::ch5_reflection::stage::DEFAULT.max_mirror_bounces,
                trace_light_rays: !scene_cannot_shadow(scene),
            };
            let p = pixel_light(world, &camera, &est, settings.seed, pixel, 0);
            let mut out = vec![format!("sample 0: L = {}", rgb(p.total))];
            if !p.hit {
                out.push(" miss: the sky".into());
            } else if p.delta {
                out.push(" mirror/glass: what its ray sees".into());
            }
            out.push(format!(" emitted {}", rgb(p.emitted)));
            for t in &p.lights {
                out.push(format!("light {}", light_name(scene, world, t.light)));
                let shadow = if t.shadowed { " (shadow)" } else { "" };
                out.push(format!(
                    "  light smp {} w {}{shadow}",
                    rgb(t.sampled),
                    num(t.weight)
                ));
                if t.found_weight > 0.0 {
                    out.push(format!(
                        "  brdf smp {} w {}",
                        rgb(t.found),
                        num(t.found_weight)
                    ));
                }
            }
            out
        }
        _ => return None,
    })
}
