//! Chapter 3 as a stage: ray tracing the first hit. Passes of one sample
//! per pixel accumulate into four views of that hit: its depth, the
//! triangle's normal, the barycentric coordinates and the triangle's id.

use std::sync::Arc;
use std::time::Instant;

use glam::Vec3;

use super::geometry::Geometry;
use super::render::{films_from_sums, render_sum, TraceStats};
use super::report::{add_studies, chapter_report};
use super::studies::StudySize;
use crate::ch1_projection::camera::Camera;
use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::report::Report;
use crate::core::stage::{Chapter, Render, Settings, View};
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
pub struct RayTriangle {
    /// How big the report's studies are: [`StudySize::full`] for the
    /// report, smaller in tests of the report's layout.
    pub study_size: fn() -> StudySize,
}

/// Chapter 3 with the report's full studies.
pub const DEFAULT: RayTriangle = RayTriangle {
    study_size: StudySize::full,
};

impl Chapter for RayTriangle {
    fn number(&self) -> u32 {
        3
    }
    fn slug(&self) -> &'static str {
        "ray-triangle"
    }
    fn title(&self) -> &'static str {
        "Ray-triangle intersection and a BVH"
    }
    fn views(&self) -> &'static [View] {
        VIEWS
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        let geometry = Geometry::new(&scene);
        let n = scene.camera.width as usize * scene.camera.height as usize;
        Ok(Box::new(RayTriangleRender {
            camera: Camera::new(scene.camera)?,
            scene,
            settings: settings.clone(),
            study_size: self.study_size,
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
    study_size: fn() -> StudySize,
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
    fn pass(&mut self) -> bool {
        if self.done < self.planned() {
            let start = Instant::now();
            let g = &self.geometry;
            let (sums, stats) = render_sum(
                &self.camera,
                g,
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
        self.done >= self.planned()
    }

    fn progress(&self) -> (u32, u32) {
        (self.done, self.planned())
    }

    /// Primary rays: pixels × samples done.
    fn rays(&self) -> u64 {
        self.stats.rays
    }

    fn view(&self, index: usize) -> Film {
        let films = films_from_sums(&self.camera, &self.sums, self.done);
        let mut film = films
            .into_iter()
            .nth(index)
            .unwrap_or_else(|| Film::new(self.scene.camera.width, self.scene.camera.height));
        film.scrub_nonfinite();
        film
    }

    fn report(&self) -> Report {
        let nonfinite = films_from_sums(&self.camera, &self.sums, self.done)
            .iter_mut()
            .map(Film::scrub_nonfinite)
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
            add_studies(
                &mut report,
                &self.scene,
                &self.settings,
                &(self.study_size)(),
            );
        }
        report
    }
}
