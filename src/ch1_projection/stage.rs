//! Chapter 1 as a stage: every vertex of the scene goes through the camera
//! (world → camera space → image plane → pixels) and every edge is drawn as
//! a line between its projected ends, after the part behind the camera has
//! been clipped away.

use std::sync::Arc;
use std::time::Instant;

use super::camera::Camera;
use super::report::chapter_report;
use super::wireframe::{draw_scene, DrawStats};
use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::report::Report;
use crate::core::stage::{
    fixed_pass, views_of, Chapter, ChapterInfo, Pass, Render, Settings, Snapshot, View,
};
use crate::scene::Scene;

/// The three views of chapter 1.
pub const VIEWS: &[View] = &[
    View {
        name: "wireframe",
        about: "edges in their material's colour; vertices as dots that shrink with distance",
    },
    View {
        name: "depth",
        about: "edges shaded by 1/depth, interpolated along each edge: near is bright",
    },
    View {
        name: "points",
        about: "vertices only: farther is smaller",
    },
];

/// Chapter 1 as a stage.
pub struct Projection;

/// Chapter 1 for the chapter list (it has no options).
pub const DEFAULT: Projection = Projection;

impl Chapter for Projection {
    fn info(&self) -> ChapterInfo {
        ChapterInfo::new(1, "projection", "Projection: the pinhole camera", VIEWS)
            .with_memory(128, 192)
            .with_bands()
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        crate::core::stage::require_meshes(1, &scene)?;
        Ok(Box::new(ProjectionRender {
            camera: Camera::new(scene.camera)?,
            scene,
            settings: settings.clone(),
            films: Vec::new(),
            stats: DrawStats::default(),
            seconds: 0.0,
        }))
    }
}

struct ProjectionRender {
    scene: Arc<Scene>,
    camera: Camera,
    settings: Settings,
    films: Vec<Film>,
    stats: DrawStats,
    seconds: f64,
}

impl Render for ProjectionRender {
    fn pass(&mut self) -> Pass {
        let start = Instant::now();
        let rows = self.settings.rows_of(self.camera.height);
        let (films, stats) = draw_scene(
            &self.camera,
            &self.scene.meshes,
            &self.scene.materials,
            rows,
        );
        self.seconds = start.elapsed().as_secs_f64();
        self.films = films;
        self.stats = stats;
        fixed_pass(1, 1, 0)
    }

    fn snapshot(&self) -> Snapshot {
        Snapshot {
            views: views_of(
                &self.films,
                VIEWS.len(),
                self.settings
                    .film_size(self.camera.width, self.camera.height),
            ),
            pass: fixed_pass(u32::from(!self.films.is_empty()), 1, 0),
            ..Snapshot::default()
        }
    }

    fn report(&self) -> Report {
        chapter_report(
            &self.scene,
            &self.camera,
            &self.settings,
            &self.stats,
            self.seconds,
            &self.films,
        )
    }
}
