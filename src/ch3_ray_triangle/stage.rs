//! Chapter 3 as a stage: ray tracing the first hit. Passes of one sample
//! per pixel accumulate into four views of that hit: its depth, the
//! triangle's normal, the barycentric coordinates and the triangle's id.

use std::sync::Arc;
use std::time::Instant;

use glam::Vec3;

use super::geometry::Geometry;
use super::render::{films_from_sums, pixel_hit, render_sum, TraceStats};
use super::report::{add_studies, chapter_report};
use super::studies::StudySize;
use crate::ch1_projection::camera::Camera;
use crate::core::error::Result;
use crate::core::format::num;
use crate::core::report::Report;
use crate::core::stage::{
    fixed_pass, views_of, Chapter, ChapterInfo, Inspection, Pass, Render, Settings, Snapshot, View,
};
use crate::scene::Scene;

/// The four views of chapter 3.
pub const VIEWS: &[View] = &[
    View {
        name: "depth",
        about: "distance to the first hit: near is bright, misses are black",
    },
    View {
        name: "normal",
        about: "the hit triangle's unit normal n, shown as (n + 1) / 2",
    },
    View {
        name: "barycentrics",
        about: "the hit's barycentric weights (1 - u - v, u, v) as red, green, blue",
    },
    View {
        name: "id",
        about: "one colour per triangle",
    },
];

/// Chapter 3 as a stage.
pub struct RayTriangle;

/// Chapter 3 (its report runs the full studies).
pub const DEFAULT: RayTriangle = RayTriangle;

impl Chapter for RayTriangle {
    fn info(&self) -> ChapterInfo {
        ChapterInfo::new(
            3,
            "ray-triangle",
            "Ray-triangle intersection and a BVH",
            VIEWS,
        )
        .with_memory(224, 272)
        .with_bands()
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        crate::core::stage::require_meshes(3, &scene)?;
        let geometry = Geometry::new(&scene);
        let rows = settings.rows_of(scene.camera.height);
        let n = scene.camera.width as usize * rows.len();
        Ok(Box::new(RayTriangleRender {
            camera: Camera::new(scene.camera)?,
            scene,
            settings: settings.clone(),
            geometry,
            sums: vec![[Vec3::ZERO; 4]; n],
            done: 0,
            stats: TraceStats::default(),
            seconds: 0.0,
        }))
    }
}

struct RayTriangleRender {
    scene: Arc<Scene>,
    camera: Camera,
    settings: Settings,
    geometry: Geometry,
    sums: Vec<[Vec3; 4]>,
    done: u32,
    stats: TraceStats,
    seconds: f64,
}

impl RayTriangleRender {
    fn planned(&self) -> u32 {
        self.settings.spp.max(1)
    }
}

impl Render for RayTriangleRender {
    /// One pass traces one sample of every pixel.
    fn pass(&mut self) -> Pass {
        if self.done < self.planned() {
            let start = Instant::now();
            let g = &self.geometry;
            let (sums, stats) = render_sum(
                &self.camera,
                g,
                self.settings.rows_of(self.camera.height),
                self.done..self.done + 1,
                self.planned(),
                self.settings.seed,
                &|r| g.closest(r),
            );
            for (acc, s) in self.sums.iter_mut().zip(sums) {
                for (a, v) in acc.iter_mut().zip(s) {
                    *a += v;
                }
            }
            self.stats.rays += stats.rays;
            self.stats.hits += stats.hits;
            self.seconds += start.elapsed().as_secs_f64();
            self.done += 1;
        }
        fixed_pass(self.done, self.planned(), self.stats.rays)
    }

    fn snapshot(&self) -> Snapshot {
        let films = films_from_sums(&self.camera, &self.sums, self.done);
        Snapshot {
            views: views_of(
                &films,
                VIEWS.len(),
                self.settings
                    .film_size(self.camera.width, self.camera.height),
            ),
            pass: fixed_pass(self.done, self.planned(), self.stats.rays),
            ..Snapshot::default()
        }
    }

    /// The primary ray of sample `sample` at `pixel`: the triangle it hits,
    /// its distance and barycentric coordinates.
    fn inspect(&self, pixel: (u32, u32), sample: u32) -> Option<Inspection> {
        if pixel.0 >= self.camera.width || pixel.1 >= self.camera.height {
            return None;
        }
        let spp = self.planned();
        let h = pixel_hit(
            &self.camera,
            &self.geometry,
            pixel,
            spp,
            self.settings.seed,
            sample,
        );
        let lines = match h.hit {
            None => vec!["primary ray: miss".into()],
            Some(hit) => vec![
                format!("primary ray hits triangle {}", hit.triangle),
                format!(" of mesh {}", h.mesh.map_or("?".into(), |m| m.to_string())),
                format!(" t = {}", num(hit.t)),
                format!(" u = {}, v = {}", num(hit.u), num(hit.v)),
                format!(" 1-u-v = {}", num(1.0 - hit.u - hit.v)),
            ],
        };
        Some(Inspection {
            pixel,
            sample,
            lines,
        })
    }

    fn report(&self) -> Report {
        let nonfinite = films_from_sums(&self.camera, &self.sums, self.done)
            .iter_mut()
            .map(crate::core::film::Film::scrub_nonfinite)
            .sum();
        let mut report = chapter_report(
            &self.scene,
            &self.geometry,
            self.stats,
            self.seconds,
            self.done,
        );
        report.nonfinite_caught = nonfinite;
        if self.settings.studies {
            add_studies(&mut report, &self.scene, &self.settings, &StudySize::full());
        }
        report
    }
}
