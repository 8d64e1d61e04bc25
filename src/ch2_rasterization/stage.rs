//! Chapter 2 as a stage: one deterministic pass rasterizes the scene at
//! `--spp` samples per pixel and resolves the views.

use std::sync::Arc;

use super::checker::{checker_figures, CHECKER_SIZE, CHECKER_SPP};
use super::frame::{render_frame_with, Frame, MAX_SAMPLES};
use super::report::chapter_report;
use super::views::{depth_range, VIEWS};
use crate::ch1_projection::camera::Camera;
use crate::core::error::{Error, Result};
use crate::core::figure::{Figure, FigureContent};
use crate::core::report::Report;
use crate::core::stage::{
    fixed_pass, views_of, Chapter, ChapterInfo, Pass, Render, Settings, Snapshot, ViewScale,
};
use crate::scene::Scene;

/// Chapter 2: rasterization.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rasterization {
    /// Drop triangles that face away from the camera.
    pub cull_back_faces: bool,
}

/// Chapter 2 with its default options, for the chapter list.
pub const DEFAULT: Rasterization = Rasterization {
    cull_back_faces: false,
};

impl Chapter for Rasterization {
    fn info(&self) -> ChapterInfo {
        ChapterInfo::new(
            2,
            "rasterization",
            "Rasterization: coverage, barycentrics, depth buffer",
            VIEWS,
        )
        .with_memory(256, 832)
        .with_bands()
        .with_scaled_views()
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        crate::core::stage::require_meshes(2, &scene)?;
        let cam = &scene.camera;
        let rows = settings.rows_of(cam.height).len() as u64;
        let samples = cam.width as u64 * rows * settings.spp as u64;
        if settings.spp == 0 || samples > MAX_SAMPLES {
            return Err(Error::Usage(format!(
                "`--spp {}` is out of range at {}x{rows} (1 to {})",
                settings.spp,
                cam.width,
                (MAX_SAMPLES / (cam.width as u64 * rows.max(1))).max(1)
            )));
        }
        Ok(Box::new(RasterRender {
            camera: Camera::new(scene.camera)?,
            scene,
            settings: settings.clone(),
            options: *self,
            frame: None,
        }))
    }
}

struct RasterRender {
    scene: Arc<Scene>,
    camera: Camera,
    settings: Settings,
    options: Rasterization,
    frame: Option<Frame>,
}

impl Render for RasterRender {
    fn pass(&mut self) -> Pass {
        let s = &self.scene;
        // `start` checked the sample count, so this cannot fail.
        let cull = self.options.cull_back_faces;
        let (camera, settings) = (&self.camera, &self.settings);
        self.frame = render_frame_with(camera, &s.meshes, &s.materials, settings, cull).ok();
        fixed_pass(1, 1, 0)
    }

    fn snapshot(&self) -> Snapshot {
        let films = self.frame.as_ref().map_or(&[][..], |f| &f.films[..]);
        Snapshot {
            views: views_of(
                films,
                VIEWS.len(),
                self.settings
                    .film_size(self.camera.width, self.camera.height),
            ),
            pass: fixed_pass(u32::from(self.frame.is_some()), 1, 0),
            ..Snapshot::default()
        }
    }

    /// The visible range of 1/w, the depth view's.
    fn scale(&self) -> Option<ViewScale> {
        self.frame.as_ref().map(|f| depth_range(&f.buffer))
    }

    /// With `--report`, its figures are the checkered floor,
    /// perspective-correct, affine and their difference (the same three
    /// images whatever the scene).
    fn report(&self) -> Report {
        let mut report = chapter_report(
            &self.scene,
            &self.settings,
            self.options.cull_back_faces,
            self.frame.as_ref(),
        );
        if self.settings.studies {
            let (w, h) = CHECKER_SIZE;
            let figures = checker_figures(w, h, CHECKER_SPP, self.settings.seed);
            for (name, film) in [
                ("ch2-checker-floor", figures.perspective),
                ("ch2-checker-floor-affine", figures.affine),
                ("ch2-checker-floor-difference", figures.difference),
            ] {
                report.figures.push(Figure {
                    file: format!("{name}.png"),
                    content: FigureContent::Png(film),
                });
            }
        }
        report
    }
}
