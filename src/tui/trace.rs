//! Inspect mode's path table (`t`): one path traced from the inspected
//! pixel with [`record_path`], the very sample the render traced, written
//! out vertex by vertex. Tracing one path takes microseconds, so it runs on
//! the UI thread; the world it traces in is built once per scene and kept
//! ([`Cache`]).

use std::sync::Arc;

use glam::Vec3;

use crate::ch1_projection::camera::Camera;
use crate::ch5_reflection::world::World;
use crate::ch6_global_illumination::path_record::{
    light_name, record_path, surface_name, PathEnd, PathRecord,
};
use crate::ch6_global_illumination::stage::DEFAULT;
use crate::core::format::format_number;
use crate::scene::Scene;

/// A traced path as the panel shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct PathTable {
    /// The record itself (its pixel and sample index among it).
    pub record: PathRecord,
    /// The panel's lines.
    pub lines: Vec<String>,
}

/// What tracing needs, built once per scene.
#[derive(Default)]
pub struct Cache {
    scene: Option<Arc<Scene>>,
    world: Option<World>,
}

impl Cache {
    /// Chapter 5's world of `scene` (built on first use, kept while the
    /// scene stays the same).
    pub fn world(&mut self, scene: &Arc<Scene>) -> &World {
        if !self.scene.as_ref().is_some_and(|s| Arc::ptr_eq(s, scene)) {
            self.world = None;
            self.scene = Some(scene.clone());
        }
        self.world.get_or_insert_with(|| World::new(scene))
    }
}

/// A number with three significant digits.
pub fn num(x: f32) -> String {
    let x = x as f64;
    if x == 0.0 || !x.is_finite() || !(1e-3..1e5).contains(&x.abs()) {
        return format_number(x);
    }
    let digits = (2 - x.abs().log10().floor() as i32).clamp(0, 8) as usize;
    format!("{x:.digits$}")
}

/// An RGB value: one number when grey, else three.
pub fn rgb(v: Vec3) -> String {
    if v.x == v.y && v.y == v.z {
        num(v.x)
    } else {
        format!("{} {} {}", num(v.x), num(v.y), num(v.z))
    }
}

fn dir(v: Vec3) -> String {
    format!("({:.2}, {:.2}, {:.2})", v.x, v.y, v.z)
}

/// Traces sample `sample` of `pixel` with chapter 6's variant `variant`
/// (estimator and sampler) and `seed`, as the render did.
pub fn trace_table(
    scene: &Scene,
    world: &World,
    variant: usize,
    seed: u64,
    pixel: (u32, u32),
    sample: u32,
) -> Result<PathTable, String> {
    let (w, h) = (scene.camera.width, scene.camera.height);
    if pixel.0 >= w || pixel.1 >= h {
        return Err(format!("pixel {pixel:?} is outside the {w}x{h} image"));
    }
    let stage = DEFAULT.with_variant(variant);
    let camera = Camera::new(scene.camera).map_err(|e| e.to_string())?;
    let record = record_path(
        world,
        &camera,
        &stage.path,
        stage.sampler,
        seed,
        pixel,
        sample,
    );
    let nee = stage.path.strategy.samples_lights() && !world.lights.lights.is_empty();
    let lines = table_lines(scene, world, &record, nee);
    Ok(PathTable { record, lines })
}

/// The table: a block per vertex.
pub fn table_lines(scene: &Scene, world: &World, r: &PathRecord, nee: bool) -> Vec<String> {
    let mut out = vec![format!("camera ray {}", dir(r.camera_dir))];
    for (k, v) in r.vertices.iter().enumerate() {
        let material = scene
            .materials
            .get(v.material)
            .map_or("?", |m| m.name.as_str());
        out.push(format!(
            "#{} {} ({material}) t {}",
            k + 1,
            surface_name(scene, v.surface),
            num(v.t)
        ));
        out.push(format!("  β in {}", rgb(v.beta)));
        if let Some(e) = v.emission {
            out.push(format!(
                "  emission Le {} · MIS w {} → +{}",
                rgb(e.le),
                num(e.weight),
                rgb(e.contribution)
            ));
        }
        if let Some(l) = v.light {
            let name = light_name(scene, world, l.light);
            if l.visible {
                out.push(format!(
                    "  NEE light {name}: f {} · Li {} · pdf {} · cos {} · w {} → +{}",
                    rgb(l.f),
                    rgb(l.li),
                    num(l.pdf),
                    num(l.cos),
                    num(l.weight),
                    rgb(l.contribution)
                ));
            } else {
                out.push(format!("  NEE light {name}: in shadow → +0"));
            }
        } else if nee && v.scatter.is_some_and(|s| !s.delta) {
            out.push("  NEE: no light sample reaches this side → +0".into());
        }
        if let Some(s) = v.scatter {
            let how = if s.delta {
                "delta lobe".to_string()
            } else {
                format!("f {} · pdf {} · cos {}", rgb(s.f), num(s.pdf), num(s.cos))
            };
            out.push(format!(
                "  next dir {}: {how} → β {}",
                dir(s.wi),
                rgb(s.beta)
            ));
        }
        if let Some((q, survived)) = v.roulette {
            let verdict = if survived {
                "survived, β / q"
            } else {
                "ended"
            };
            out.push(format!("  roulette q {}: {verdict}", num(q)));
        }
    }
    if let Some((d, e)) = r.escaped {
        out.push(format!(
            "escaped {}: sky Le {} · MIS w {} → +{}",
            dir(d),
            rgb(e.le),
            num(e.weight),
            rgb(e.contribution)
        ));
    }
    let end = match r.end {
        PathEnd::Escaped => "left the scene",
        PathEnd::Roulette => "ended by Russian roulette",
        PathEnd::BounceLimit => "reached the bounce limit",
        PathEnd::Absorbed => "absorbed (no direction carries light)",
    };
    out.push(format!("path {end}"));
    out.push(format!(
        "sum of the + terms: {}",
        rgb(r.contributions_sum())
    ));
    out
}
