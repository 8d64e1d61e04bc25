//! The boundary between a chapter's stage and whatever drives it: the
//! headless runner, the terminal UI, the tests and the book's figures all
//! use these two traits and nothing else. A stage knows nothing about
//! terminals; a front end knows nothing about rendering.

use std::sync::Arc;

use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::report::Report;
use crate::scene::Scene;

/// Settings every chapter understands. `None` means "what the scene says".
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Settings {
    /// Override of the scene's image width.
    pub width: Option<u32>,
    /// Override of the scene's image height.
    pub height: Option<u32>,
    /// Samples per pixel (chapters without sampling ignore it).
    pub spp: u32,
    /// Seed for every random number.
    pub seed: u64,
    /// Run the error-against-time and stability studies for the report.
    pub studies: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            width: None,
            height: None,
            spp: 1,
            seed: 0,
            studies: false,
        }
    }
}

/// One way of looking at a stage's result (the image, depth, normals, ...).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct View {
    /// Short name, used in file names (`ch1-scene-<name>.png`).
    pub name: &'static str,
    /// One line for help texts.
    pub about: &'static str,
}

/// View `index` of a render's films, or a black film of the camera's size
/// before the first pass; any NaN or Inf scrubbed out. The common body of
/// [`Render::view`] for stages that keep one film per view.
pub fn view_of(films: &[Film], index: usize, camera: &crate::scene::camera::CameraDesc) -> Film {
    let mut film = films
        .get(index)
        .cloned()
        .unwrap_or_else(|| Film::new(camera.width, camera.height));
    film.scrub_nonfinite();
    film
}

/// A chapter of the lecture, as a renderer stage.
pub trait Chapter: Sync {
    /// 1 to 6.
    fn number(&self) -> u32;
    /// The folder and binary slug, e.g. `projection`.
    fn slug(&self) -> &'static str;
    /// A title for menus and reports.
    fn title(&self) -> &'static str;
    /// The views this stage can show; the first is the main image.
    fn views(&self) -> &'static [View];
    /// Whether results carry per-bounce layers (chapter 6).
    fn has_bounces(&self) -> bool {
        false
    }
    /// Whether the main image holds radiance (then it is also written as EXR).
    fn is_radiance(&self) -> bool {
        false
    }
    /// Why this stage cannot render `scene`, if it cannot.
    fn unsupported(&self, _scene: &Scene) -> Option<String> {
        None
    }
    /// Prepares a render of `scene`. Cheap: the work happens in passes.
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>>;
    /// The estimators or samplers a front end may switch between (e.g.
    /// "BRDF sampling", "light sampling", "MIS"); empty when the stage has
    /// only one way of rendering. [`Chapter::start_variant`] takes an index
    /// into this list.
    fn variants(&self) -> &'static [View] {
        &[]
    }
    /// The variant a front end opens with (index into
    /// [`Chapter::variants`]): the best the stage has, while the others
    /// stay one key away. 0 by default.
    fn default_variant(&self) -> usize {
        0
    }
    /// Whether the image keeps improving with more samples per pixel, so a
    /// front end may go on rendering until a noise target or a sample
    /// budget ([`Render::set_spp`], [`Render::noise`]). `false` by default.
    fn progressive(&self) -> bool {
        false
    }
    /// Like [`Chapter::start`], with the estimator or sampler
    /// `variants()[variant]`. The default ignores `variant`, which is right
    /// for stages without variants.
    fn start_variant(
        &self,
        scene: Arc<Scene>,
        settings: &Settings,
        variant: usize,
    ) -> Result<Box<dyn Render>> {
        let _ = variant;
        self.start(scene, settings)
    }
}

/// A render in progress.
pub trait Render: Send {
    /// Renders one more pass; returns `true` when the render is complete.
    fn pass(&mut self) -> bool;
    /// (passes done, passes planned).
    fn progress(&self) -> (u32, u32);
    /// The current image of a view (index into [`Chapter::views`]), with any
    /// NaN or Inf already removed and counted.
    fn view(&self, index: usize) -> Film;
    /// The report; with `settings.studies` it includes the error-against-time
    /// and stability studies, which may take a while.
    fn report(&self) -> Report;
    /// Per-bounce layers of the main image, for stages with bounces
    /// ([`Chapter::has_bounces`]): `layers[k]` holds the light that reached
    /// the camera after exactly `k` bounces (`k = 0` is direct illumination,
    /// emitters seen directly included), so the sum of `layers[0..=k]` is the
    /// image "up to k bounces". Same size as view 0, NaN/Inf removed.
    /// `None` (the default) for stages without bounces.
    fn layers(&self) -> Option<Vec<Film>> {
        None
    }
    /// A reference for the main image (analytic, or a stored high-sample
    /// render), the same size as view 0, for compare and difference views
    /// and the error shown while rendering. `None` (the default) when the
    /// stage knows none.
    fn reference(&self) -> Option<Film> {
        None
    }
    /// The error of the main image against [`Render::reference`] as the
    /// render went on: (seconds since the start, error) per pass so far,
    /// oldest first. Empty (the default) when there is no reference.
    fn error_series(&self) -> Vec<(f64, f64)> {
        Vec::new()
    }
    /// Rays traced so far, for the status line; 0 when the stage does not
    /// count. Stages count cheaply (e.g. per pass: pixels × samples done).
    fn rays(&self) -> u64 {
        0
    }
    /// Samples per pixel taken so far, for progressive stages
    /// ([`Chapter::progressive`]); 0 (the default) for the others.
    fn samples(&self) -> u32 {
        0
    }
    /// The render's own estimate of the RMSE of view 0 against the
    /// converged image, from its sample variance: √(mean over pixels and
    /// channels of the variance of each pixel's mean), at the resolution
    /// [`Render::error_series`] measures at. `None` (the default) when the
    /// stage keeps no variance.
    fn noise(&self) -> Option<f64> {
        None
    }
    /// Changes the sample target of a progressive render without starting
    /// over: [`Render::pass`] keeps going until `spp` samples per pixel (or
    /// reports done at once when there are already that many). Ignored by
    /// default.
    fn set_spp(&mut self, spp: u32) {
        let _ = spp;
    }

    /// Files a headless run writes besides the views (and the EXR of a
    /// radiance image): chapter 6's bounce strip and layers, say. `report`
    /// is the report the run is about to print, so figures of its studies
    /// need not run them again. Returns the paths written; none by default.
    fn extra_files(
        &self,
        report: &Report,
        dir: &std::path::Path,
        stem: &str,
    ) -> Result<Vec<std::path::PathBuf>> {
        let _ = (report, dir, stem);
        Ok(Vec::new())
    }
}
