//! Chapter 4 stage: sphere tracing the scene's signed distance functions.
//! One ray per pixel marches along f (see [`crate::ch4_implicit_surfaces::march`]); the
//! normal is the normalised gradient; the views show the shaded surface,
//! its normals, depth, the steps each ray took and the residual |f| at
//! the hit.
//!
//! Meshes are chapter 3's: a scene with meshes gets chapter 3's BVH, and
//! each ray's mesh hit and SDF hit meet in [`crate::ch4_implicit_surfaces::hit::nearest_hit`].
//! A scene without meshes builds no BVH; one without SDFs evaluates no f.

use std::sync::Arc;
use std::time::Instant;

use super::march::Ending;
use super::render::{
    hit_range, march_steps, pixel_ray, trace_image, views, MeshTracer, Method, Pixel,
};
use super::report::{chapter_report, ReportInputs};
use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::geometry::Geometry;
use crate::ch4_implicit_surfaces::march::March;
use crate::ch4_implicit_surfaces::normal::NormalScheme;
use crate::core::error::{Error, Result};
use crate::core::film::Film;
use crate::core::format::num;
use crate::core::preview::downsample;
use crate::core::report::Report;
use crate::core::stage::{
    fixed_pass, views_of, Chapter, ChapterInfo, Inspection, Pass, Render, Settings, Snapshot, View,
    ViewScale,
};
use crate::scene::Scene;

/// The views of chapter 4.
pub const VIEWS: &[View] = &[
    View {
        name: "shaded",
        about: "a headlight: brightness is the cosine between the normal and the ray",
    },
    View {
        name: "normals",
        about: "the gradient normal as colour (x, y, z → r, g, b)",
    },
    View {
        name: "depth",
        about: "hit distance: near is bright",
    },
    View {
        name: "steps",
        about: "evaluations of f per ray as a heat map, from 0 (black) to the step budget (white)",
    },
    View {
        name: "error",
        about: "surface distance error |f| at the hit as a heat map, from 0 to ε",
    },
];

/// Chapter 4 with its march settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereTracing {
    /// ε, step budget, maximum distance, step factor.
    pub march: March,
    /// Plain, over-relaxed or fixed-step.
    pub method: Method,
    /// How normals are estimated.
    pub normals: NormalScheme,
}

/// The settings `ch4` uses unless told otherwise.
pub const DEFAULT: SphereTracing = SphereTracing {
    march: March {
        epsilon: 1e-4,
        max_steps: 256,
        max_distance: 100.0,
        step_factor: 1.0,
    },
    method: Method::Plain,
    normals: NormalScheme::Tetrahedron,
};

impl SphereTracing {
    /// Refuses settings no march can use.
    pub fn check(&self) -> Result<()> {
        let m = &self.march;
        let bad = |what: &str| Err(Error::Usage(what.to_string()));
        if !(m.epsilon.is_finite() && m.epsilon > 0.0) {
            return bad("`--epsilon` must be a positive number");
        }
        if m.max_steps == 0 {
            return bad("`--max-steps` must be at least 1");
        }
        if m.max_distance.is_nan() || m.max_distance <= 0.0 {
            return bad("`--max-distance` must be positive");
        }
        if !(m.step_factor > 0.0 && m.step_factor <= 1.0) {
            return bad("`--step-factor` must be in (0, 1]");
        }
        match self.method {
            Method::OverRelaxed(w) if !(1.0..2.0).contains(&w) => {
                bad("`--omega` must be in [1, 2)")
            }
            Method::FixedStep(d) if !(d.is_finite() && d > 0.0) => {
                bad("`--delta` must be a positive number")
            }
            _ => Ok(()),
        }
    }
}

impl Chapter for SphereTracing {
    fn info(&self) -> ChapterInfo {
        ChapterInfo {
            scene: Some("sdf-shapes"),
            ..ChapterInfo::new(
                4,
                "sphere-tracing",
                "Implicit surfaces: signed distance functions and sphere tracing",
                VIEWS,
            )
            .with_memory(336, 272)
            .with_bands()
            .with_scaled_views()
        }
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        self.check()?;
        // ε and the distance marched in the scene's own units.
        let stage = SphereTracing {
            march: self.march.scaled(super::bounds::length_unit(&scene)),
            ..*self
        };
        // A first look in a sixteenth of the time: a quarter of the
        // resolution, enlarged, before the full pass.
        // (Not in a band of a larger image: the whole run shows none.)
        let (w, h) = (scene.camera.width, scene.camera.height);
        let coarse = if w >= 64 && h >= 64 && settings.rows.is_none() {
            Some(Camera::new(scene.camera.with_resolution(w / 4, h / 4)?)?)
        } else {
            None
        };
        Ok(Box::new(SphereTracingRender {
            stage,
            planned: 1 + u32::from(coarse.is_some()),
            done: 0,
            coarse,
            camera: Camera::new(scene.camera)?,
            scene,
            settings: settings.clone(),
            pixels: Vec::new(),
            films: Vec::new(),
            seconds: 0.0,
            geometry: None,
        }))
    }
}

struct SphereTracingRender {
    stage: SphereTracing,
    scene: Arc<Scene>,
    /// The camera of the coarse first pass, until it has run.
    coarse: Option<Camera>,
    /// Passes planned (2 with a coarse first pass) and done.
    planned: u32,
    done: u32,
    camera: Camera,
    settings: Settings,
    pixels: Vec<Pixel>,
    films: Vec<Film>,
    seconds: f64,
    /// Chapter 3's triangles and BVH with the seconds they took to build;
    /// only for scenes with meshes.
    geometry: Option<(Geometry, f64)>,
}

impl Render for SphereTracingRender {
    fn pass(&mut self) -> Pass {
        let start = Instant::now();
        if self.geometry.is_none() && !self.scene.meshes.is_empty() {
            self.geometry = Some((Geometry::new(&self.scene), start.elapsed().as_secs_f64()));
        }
        let meshes = self.geometry.as_ref().map(|(geometry, _)| MeshTracer {
            geometry,
            meshes: &self.scene.meshes,
        });
        let s = &self.stage;
        let coarse = self.coarse.take();
        let cam = coarse.as_ref().unwrap_or(&self.camera);
        let rows = self.settings.rows_of(cam.height);
        let size = (cam.width, rows.len() as u32);
        let sdfs = &self.scene.sdfs;
        self.pixels = trace_image(cam, rows, sdfs, &s.march, s.method, s.normals, meshes);
        let depth = self
            .settings
            .scale
            .unwrap_or_else(|| hit_range(&self.pixels));
        self.films = views(&self.pixels, size, &self.scene.materials, &s.march, depth);
        self.done += 1;
        if coarse.is_some() {
            let (w, h) = (self.camera.width, self.camera.height);
            self.films = self.films.iter().map(|f| downsample(f, w, h)).collect();
        } else {
            self.seconds = start.elapsed().as_secs_f64();
        }
        fixed_pass(self.done, self.planned, self.pixels.len() as u64)
    }

    /// One primary ray per traced pixel (the single pass).
    fn snapshot(&self) -> Snapshot {
        Snapshot {
            views: views_of(
                &self.films,
                VIEWS.len(),
                self.settings
                    .film_size(self.camera.width, self.camera.height),
            ),
            pass: fixed_pass(self.done, self.planned, self.pixels.len() as u64),
            ..Snapshot::default()
        }
    }

    /// The sphere-tracing steps of the pixel's ray (one ray per pixel, so
    /// `sample` is ignored): t and f at each, how the march ended.
    fn inspect(&self, pixel: (u32, u32), sample: u32) -> Option<Inspection> {
        let outside = pixel.0 >= self.camera.width || pixel.1 >= self.camera.height;
        if outside || self.films.is_empty() {
            return None;
        }
        let stage = &self.stage;
        let meshes = self.geometry.as_ref().map(|(geometry, _)| MeshTracer {
            geometry,
            meshes: &self.scene.meshes,
        });
        let ray = pixel_ray(&self.camera, pixel.0, pixel.1);
        let sdfs = &self.scene.sdfs;
        let m = march_steps(
            &ray,
            sdfs,
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
        let mut lines = if sdfs.is_empty() {
            vec!["no SDF objects: nothing to march".to_string()]
        } else {
            vec![format!("sphere tracing: {} steps, {ending}", m.steps.len())]
        };
        let n = m.steps.len();
        for (i, (t, d)) in m.steps.iter().enumerate() {
            if i < 4 || i + 3 >= n {
                lines.push(format!(" {i:>3}: t {} f {}", num(*t), num(*d)));
            } else if i == 4 {
                lines.push("  …".into());
            }
        }
        lines.push(match m.pixel.hit {
            Some(h) => format!(
                "nearest hit t {} ({})",
                num(h.t),
                super::hit::surface_name(&self.scene, h.surface)
            ),
            None => "nearest hit: none".into(),
        });
        Some(Inspection {
            pixel,
            sample,
            lines,
        })
    }

    /// The range of its hits' distances, the depth view's.
    fn scale(&self) -> Option<ViewScale> {
        (!self.films.is_empty()).then(|| hit_range(&self.pixels))
    }

    fn report(&self) -> Report {
        chapter_report(&ReportInputs {
            march: &self.stage.march,
            method: self.stage.method,
            normals: self.stage.normals,
            scene: &self.scene,
            settings: &self.settings,
            pixels: &self.pixels,
            films: &self.films,
            seconds: self.seconds,
            geometry: self.geometry.as_ref(),
        })
    }
}
