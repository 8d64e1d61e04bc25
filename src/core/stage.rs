//! The boundary between a chapter's stage and whatever drives it: the
//! headless runner, the terminal UI, the tests and the book's figures all
//! use these two traits and nothing else. A stage knows nothing about
//! terminals or files; a front end knows nothing about rendering.
//!
//! The shape, and why:
//!
//! ```text
//! trait Chapter { info() -> ChapterInfo;  start(scene, settings) -> Render }
//! trait Render  { pass() -> Pass;  snapshot() -> Snapshot;  report() -> Report;
//!                 inspect(pixel, sample) -> Option<Inspection>;  set_spp(spp) }
//! ```
//!
//! - A [`Chapter`] is a description ([`ChapterInfo`]: number, title, views,
//!   variants, whether it samples radiance) and a way to start. Everything
//!   that chooses *how* to render (the variant, the samples, the seed) is in
//!   [`Settings`], so there is one `start`, not one per option.
//! - A [`Render`] is driven by [`Render::pass`], which returns the cheap
//!   facts a driver needs between passes ([`Pass`]: progress, samples, the
//!   noise estimate). Everything shown or written is read at once with
//!   [`Render::snapshot`]; the runner writes files from the snapshot and the
//!   report ([`Report::figures`](crate::core::report::Report::figures)), so no
//!   stage writes files for a front end.
//! - [`Render::inspect`] answers "what happened at this pixel" with the
//!   render's own world and settings: the terminal UI's inspect mode asks
//!   the running render and imports no chapter code.
//! - A stage that cannot render a scene says so from [`Chapter::start`];
//!   there is no separate question to forget to ask.

use std::sync::Arc;

use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::report::Report;
use crate::scene::Scene;

pub use crate::core::refuse::{require_light, require_meshes};

/// Settings every chapter understands. `None` means "what the scene says".
#[derive(Clone, Debug, PartialEq)]
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
    /// Index into [`ChapterInfo::variants`]; `None`: the stage's own
    /// default ([`ChapterInfo::default_variant`]).
    pub variant: Option<usize>,
    /// Render only these rows of the image, a band of a run too large to
    /// hold whole ([`crate::core::bands`]): every view is then a film of the
    /// band's rows, row `y` of the image at row `y - rows.start`, and
    /// every pixel is the same as in the whole render. `None`: all rows.
    pub rows: Option<std::ops::Range<u32>>,
    /// The range of the views scaled over the whole image (chapters 2
    /// and 4 scale their depth views over the depths they see), when a
    /// band is rendered: the range of the whole image, found by rendering
    /// it once before ([`Render::scale`]). `None`: what this render sees.
    pub scale: Option<ViewScale>,
}

/// The least and the greatest value a view is scaled over.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewScale {
    /// The least value.
    pub lo: f32,
    /// The greatest value.
    pub hi: f32,
}

impl ViewScale {
    /// The range of both: bands' ranges merged give the whole image's.
    pub fn merge(self, other: ViewScale) -> ViewScale {
        ViewScale {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }
}

impl Settings {
    /// The rows of a `height`-row image this render draws: [`Settings::rows`]
    /// kept inside the image, or all of them.
    pub fn rows_of(&self, height: u32) -> std::ops::Range<u32> {
        match &self.rows {
            Some(r) => r.start.min(height)..r.end.min(height),
            None => 0..height,
        }
    }

    /// The size of the films of a render of a `width` x `height` image:
    /// its width by the rows [`Self::rows_of`] gives.
    pub fn film_size(&self, width: u32, height: u32) -> (u32, u32) {
        (width, self.rows_of(height).len() as u32)
    }
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            width: None,
            height: None,
            spp: 1,
            seed: 0,
            studies: false,
            variant: None,
            rows: None,
            scale: None,
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

/// The view of the stages that catch samples which are not finite
/// (chapters 5 and 6): where they were. Its film holds, in every channel,
/// how many of a pixel's contributions were NaN or infinite; they were
/// counted and left out of the image ([`caught_film`]).
pub const CAUGHT_VIEW: View = View {
    name: "non-finite",
    about:
        "where samples were NaN or infinite: per pixel the count caught and left out (black: none)",
};

/// The film of [`CAUGHT_VIEW`]: `caught[i]`, pixel i's count, in every
/// channel.
pub fn caught_film(width: u32, height: u32, caught: &[u32]) -> Film {
    Film {
        width,
        height,
        pixels: caught
            .iter()
            .map(|&c| glam::Vec3::splat(c as f32))
            .collect(),
    }
}

/// One way of rendering a stage offers (an estimator, a sampler): the
/// front ends switch between them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Variant {
    /// Short name, e.g. `mis-sobol`.
    pub name: &'static str,
    /// One line for help texts.
    pub about: &'static str,
}

/// A render's films as its snapshot's views: `count` of them, each a black
/// film of `width` x `height` (the rows it renders) before the first
/// pass, NaN or Inf scrubbed out. The common body of [`Render::snapshot`]
/// for stages that keep one film per view.
pub fn views_of(films: &[Film], count: usize, (width, height): (u32, u32)) -> Vec<Film> {
    (0..count)
        .map(|i| {
            let mut film = films
                .get(i)
                .cloned()
                .unwrap_or_else(|| Film::new(width, height));
            film.scrub_nonfinite();
            film
        })
        .collect()
}

/// The [`Pass`] of a stage that renders in a fixed number of passes and
/// samples nothing progressively.
pub fn fixed_pass(done: u32, planned: u32, rays: u64) -> Pass {
    Pass {
        done,
        planned: planned.max(done),
        rays,
        complete: done >= planned,
        ..Pass::default()
    }
}

/// What a chapter is, for menus, reports and the runner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChapterInfo {
    /// 1 to 6.
    pub number: u32,
    /// The folder and binary slug, e.g. `projection`.
    pub slug: &'static str,
    /// A title for menus and reports.
    pub title: &'static str,
    /// The views this stage can show; the first is the main image.
    pub views: &'static [View],
    /// The estimators or samplers a front end may switch between; empty
    /// when the stage has only one way of rendering.
    pub variants: &'static [Variant],
    /// The variant used when [`Settings::variant`] is `None`: the best the
    /// stage has, while the others stay one key away.
    pub default_variant: usize,
    /// Whether the image keeps improving with more samples per pixel, so a
    /// front end may go on until a noise target or a sample budget
    /// ([`Render::set_spp`], [`Pass::noise`]).
    pub progressive: bool,
    /// Whether the main image holds radiance sampled `spp` times per pixel
    /// (then it is also written as EXR).
    pub radiance: bool,
    /// Whether snapshots carry per-bounce layers ([`Snapshot::layers`]).
    pub bounces: bool,
    /// The shipped scene (its file stem) the chapter's lesson is told on,
    /// when the chapter draws something most scenes lack (chapter 4: SDF
    /// objects): a front end opens the chapter there the first time, if
    /// its list has that scene.
    pub scene: Option<&'static str>,
    /// Samples per pixel a headless run renders besides the settings'
    /// `spp` (chapter 6's spp-doubling figure), counted by the sample limit
    /// and warning.
    pub extra_spp: u32,
    /// Bytes a run allocates per pixel of its image, at most (measured
    /// peaks at 1024² and 2048², rounded up with room to spare): the
    /// memory check's ([`crate::core::memory`]).
    pub bytes_per_pixel: u64,
    /// Bytes a run allocates per triangle of its scene, at most (measured
    /// at 82k and 328k triangles, rounded up).
    pub bytes_per_triangle: u64,
    /// Whether the stage renders a band of rows alone ([`Settings::rows`])
    /// with every pixel as in the whole image (given the whole image's
    /// [`Settings::scale`] if it has [`Self::scaled_views`]), so that a
    /// run too large to hold whole can be rendered band by band
    /// ([`crate::core::bands`]).
    pub bands: bool,
    /// Whether some view is scaled over the whole image ([`Settings::scale`]):
    /// a banded run then renders every band twice, first to find the
    /// range.
    pub scaled_views: bool,
}

impl ChapterInfo {
    /// A chapter with one view set and no variants, not progressive, not
    /// radiance, without bounces: fill in what differs.
    pub const fn new(
        number: u32,
        slug: &'static str,
        title: &'static str,
        views: &'static [View],
    ) -> ChapterInfo {
        ChapterInfo {
            number,
            slug,
            title,
            views,
            variants: &[],
            default_variant: 0,
            progressive: false,
            radiance: false,
            bounces: false,
            scene: None,
            extra_spp: 0,
            bytes_per_pixel: 256,
            bytes_per_triangle: 512,
            bands: false,
            scaled_views: false,
        }
    }

    /// This chapter's measured memory use: bytes per pixel and per
    /// triangle, at most.
    pub const fn with_memory(self, per_pixel: u64, per_triangle: u64) -> ChapterInfo {
        ChapterInfo {
            bytes_per_pixel: per_pixel,
            bytes_per_triangle: per_triangle,
            ..self
        }
    }

    /// This chapter renders bands of rows alone ([`ChapterInfo::bands`]).
    pub const fn with_bands(self) -> ChapterInfo {
        ChapterInfo {
            bands: true,
            ..self
        }
    }

    /// Some view of this chapter is scaled over the whole image
    /// ([`ChapterInfo::scaled_views`]).
    pub const fn with_scaled_views(self) -> ChapterInfo {
        ChapterInfo {
            scaled_views: true,
            ..self
        }
    }

    /// The variant `settings` asks for, checked against [`Self::variants`]
    /// (the default when it asks for none).
    pub fn variant(&self, settings: &Settings) -> Result<usize> {
        match settings.variant {
            None => Ok(self.default_variant),
            Some(v) if v < self.variants.len().max(1) => Ok(v),
            Some(v) => Err(crate::core::error::Error::Usage(format!(
                "ch{} has {} variants; variant {v} does not exist",
                self.number,
                self.variants.len()
            ))),
        }
    }
}

/// A chapter of the lecture, as a renderer stage.
pub trait Chapter: Sync {
    /// What the chapter is.
    fn info(&self) -> ChapterInfo;
    /// Prepares a render of `scene`, or says why this stage cannot render
    /// it. Cheap: the work happens in passes.
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>>;
}

/// What a driver needs between passes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pass {
    /// Passes done.
    pub done: u32,
    /// Passes planned (at least `done`).
    pub planned: u32,
    /// Samples per pixel taken so far, for progressive stages; 0 for the
    /// others.
    pub samples: u32,
    /// Rays traced so far; 0 when the stage does not count.
    pub rays: u64,
    /// The render's own estimate of the RMSE of view 0 against the
    /// converged image, from its sample variance, with the mean value of
    /// view 0 it is relative to: `(noise, mean)`. `None` when the stage
    /// keeps no variance or has too few samples.
    pub noise: Option<(f64, f64)>,
    /// Whether the render is complete.
    pub complete: bool,
}

/// Everything a front end shows, or the runner writes, of a render.
#[derive(Clone, Debug, Default)]
pub struct Snapshot {
    /// Every view, in the order of [`ChapterInfo::views`], NaN/Inf removed.
    pub views: Vec<Film>,
    /// Per-bounce layers of the main image, for stages with bounces:
    /// `layers[k]` holds the light that reached the camera after exactly
    /// `k` bounces (`k = 0` is direct illumination, emitters seen directly
    /// included), the last everything beyond; so the sum of
    /// `layers[0..=k]` is the image "up to k bounces".
    pub layers: Option<Vec<Film>>,
    /// A reference for the main image (analytic, or a stored high-sample
    /// render), the same size as view 0.
    pub reference: Option<Film>,
    /// The reference's standard error per pixel and channel (a stored
    /// render's own noise), where the stage knows it: with the render's
    /// own (a view named "stderr") it makes the z view.
    pub reference_stderr: Option<Film>,
    /// How many pixels of the render, per side, one pixel of the stored
    /// reference covers: `reference` is the stored one enlarged by it (0
    /// or 1: the reference has the render's size). Statistics compare at
    /// the reference's own resolution.
    pub reference_factor: u32,
    /// The error of the main image against the reference as the render
    /// went on: (seconds since the start, error) per pass, oldest first.
    pub error_series: Vec<(f64, f64)>,
    /// Where the render is.
    pub pass: Pass,
}

impl Snapshot {
    /// The RMSE of view 0 against the reference: the last point of the
    /// error series where the stage keeps one (at the reference's own
    /// resolution), else pixel by pixel when the sizes agree.
    pub fn rmse(&self) -> Option<f64> {
        self.error_series.last().map(|p| p.1).or_else(|| {
            let (image, reference) = (self.views.first()?, self.reference.as_ref()?);
            ((image.width, image.height) == (reference.width, reference.height))
                .then(|| image.rmse(reference))
        })
    }
}

/// What a render says about one pixel: lines of text, computed by the
/// chapter's own code with the render's own world and settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Inspection {
    /// The pixel.
    pub pixel: (u32, u32),
    /// The sample of that pixel the lines describe.
    pub sample: u32,
    /// The lines, for a panel.
    pub lines: Vec<String>,
}

/// A render in progress.
pub trait Render: Send {
    /// Renders one more pass and says where the render is.
    fn pass(&mut self) -> Pass;
    /// Everything to show or write, as of now.
    fn snapshot(&self) -> Snapshot;
    /// The report; with `settings.studies` it includes the error-against-time
    /// and stability studies, which may take a while.
    fn report(&self) -> Report;
    /// The story of sample `sample` of `pixel`, as this render traced it:
    /// chapter 3 the primary ray's hit, chapter 4 the sphere-tracing steps,
    /// chapter 5 each light's share, chapter 6 the path vertex by vertex.
    /// `None` (the default) for stages without one, for a pixel outside the
    /// image, or before the render has what it needs (its first pass).
    fn inspect(&self, pixel: (u32, u32), sample: u32) -> Option<Inspection> {
        let _ = (pixel, sample);
        None
    }
    /// Changes the sample target of a progressive render without starting
    /// over: [`Render::pass`] keeps going until `spp` samples per pixel (or
    /// reports it complete at once when there are already that many).
    /// Ignored by default.
    fn set_spp(&mut self, spp: u32) {
        let _ = spp;
    }
    /// The range of this render's own pixels for the views scaled over
    /// the whole image ([`ChapterInfo::scaled_views`]), once it has them;
    /// `None` (the default) for stages without such views.
    fn scale(&self) -> Option<ViewScale> {
        None
    }
}
