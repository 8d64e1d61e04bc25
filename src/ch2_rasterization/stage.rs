//! Chapter 2 as a stage: one deterministic pass rasterizes the scene at
//! `--spp` samples per pixel and resolves the views.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::checker::{checker_figures, CHECKER_SIZE, CHECKER_SPP};
use super::frame::{render_frame, Frame, MAX_SAMPLES};
use super::report::chapter_report;
use super::views::VIEWS;
use crate::ch1_projection::camera::Camera;
use crate::core::error::{Error, Result};
use crate::core::film::Film;
use crate::core::report::Report;
use crate::core::stage::{Chapter, Render, Settings, View};
use crate::scene::Scene;

/// Chapter 2: rasterization.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rasterization {
    /// Drop triangles that face away from the camera.
    pub cull_back_faces: bool,
}

/// Chapter 2 with its default options, for the chapter list.
pub static RASTERIZATION: Rasterization = Rasterization {
    cull_back_faces: false,
};

impl Chapter for Rasterization {
    fn number(&self) -> u32 {
        2
    }
    fn slug(&self) -> &'static str {
        "rasterization"
    }
    fn title(&self) -> &'static str {
        "Rasterization: coverage, barycentrics, depth buffer"
    }
    fn views(&self) -> &'static [View] {
        VIEWS
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        let cam = &scene.camera;
        let samples = cam.width as u64 * cam.height as u64 * settings.spp as u64;
        if settings.spp == 0 || samples > MAX_SAMPLES {
            return Err(Error::Usage(format!(
                "`--spp {}` is out of range at {}x{} (1 to {})",
                settings.spp,
                cam.width,
                cam.height,
                (MAX_SAMPLES / (cam.width as u64 * cam.height as u64)).max(1)
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
    fn pass(&mut self) -> bool {
        let s = &self.scene;
        // `start` checked the sample count, so this cannot fail.
        self.frame = render_frame(
            &self.camera,
            &s.meshes,
            &s.materials,
            self.settings.spp,
            self.settings.seed,
            self.options.cull_back_faces,
        )
        .ok();
        true
    }

    fn progress(&self) -> (u32, u32) {
        (u32::from(self.frame.is_some()), 1)
    }

    fn view(&self, index: usize) -> Film {
        let films = self.frame.as_ref().map_or(&[][..], |f| &f.films[..]);
        crate::core::stage::view_of(films, index, &self.scene.camera)
    }

    fn report(&self) -> Report {
        chapter_report(
            &self.scene,
            &self.settings,
            self.options.cull_back_faces,
            self.frame.as_ref(),
        )
    }

    /// With `--report`: the checkered floor, perspective-correct, affine and
    /// their difference (the same three images whatever the scene).
    fn extra_files(&self, _report: &Report, dir: &Path, _stem: &str) -> Result<Vec<PathBuf>> {
        if !self.settings.studies {
            return Ok(Vec::new());
        }
        let (w, h) = CHECKER_SIZE;
        let figures = checker_figures(w, h, CHECKER_SPP, self.settings.seed);
        let mut files = Vec::new();
        for (name, film) in [
            ("ch2-checker-floor", &figures.perspective),
            ("ch2-checker-floor-affine", &figures.affine),
            ("ch2-checker-floor-difference", &figures.difference),
        ] {
            let path = dir.join(format!("{name}.png"));
            film.write_png(&path)?;
            files.push(path);
        }
        Ok(files)
    }
}
