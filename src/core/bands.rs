//! Runs too large to hold whole, rendered band by band. Every chapter
//! renders any band of rows alone with every pixel as in the whole image
//! ([`Settings::rows`], [`ChapterInfo::bands`]): the ray tracers trace the
//! band's pixels, the rasterizer and the wireframe draw every triangle and
//! edge but write only the band's rows. When a run's pixels would need
//! more than [`BAND_BYTES`] in one piece, or more than this process may
//! still get, the headless runner renders it in bands that fit, one after
//! another, and streams each band's rows into the image files: a 16384²
//! render needs a band's memory, not the image's.
//!
//! Chapters 2 and 4 scale their depth views over the depths the whole
//! image sees ([`ChapterInfo::scaled_views`]): they render every band
//! twice, first to find that range ([`Render::scale`]), then with it
//! ([`Settings::scale`]).
//!
//! The PNGs are written row by row as the bands come ([`png`]'s stream
//! writer); the main image's EXR needs its rows in one go at the end, so
//! its linear values wait in a scratch file beside it. A band's report
//! counts only its own rows: the run's report keeps the facts every band
//! agrees on, adds the totals, and names the per-band counts it left out.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use glam::Vec3;

use crate::core::band_files::ImageFiles;
use crate::core::error::{Error, Result};
use crate::core::film::{Film, OutputSet};
use crate::core::format::format_seconds;
use crate::core::memory::{available, BASE_BYTES};
use crate::core::report::Report;
use crate::core::stage::{Chapter, ChapterInfo, Pass, Render, Settings, ViewScale};
use crate::core::text::escape;
use crate::scene::Scene;

/// The most bytes a run's pixels may take at once (the chapter's bytes per
/// pixel times the pixels held): larger runs are rendered in bands.
pub const BAND_BYTES: u64 = 1 << 30;

/// Rows per band for a run of `info` on `scene`, or `None` when it is
/// rendered whole: the chapter cannot render bands, or its pixels fit in
/// [`BAND_BYTES`] and in what this process may still get. `room` is that
/// memory (`None`: unknown, only [`BAND_BYTES`] counts).
pub fn rows_per_band(info: &ChapterInfo, scene: &Scene, room: Option<u64>) -> Option<u32> {
    if !info.bands {
        return None;
    }
    let (w, h) = (scene.camera.width as u64, scene.camera.height as u64);
    let row = w.saturating_mul(info.bytes_per_pixel).max(1);
    let others = BASE_BYTES
        .saturating_add((scene.triangle_count() as u64).saturating_mul(info.bytes_per_triangle));
    let budget = room.map_or(BAND_BYTES, |r| r.saturating_sub(others).min(BAND_BYTES));
    if row.saturating_mul(h) <= budget {
        return None;
    }
    // A run that cannot hold even the thinnest band is refused by the
    // memory check.
    Some((budget / row).clamp(MIN_BAND_ROWS as u64, h) as u32)
}

/// The fewest rows a band has: thinner bands would spend more time
/// starting renders (each builds its world) than rendering.
pub const MIN_BAND_ROWS: u32 = 16;

impl ChapterInfo {
    /// Refuses a run of this chapter on `scene` that would need more memory
    /// than this process may still get ([`crate::core::memory`]).
    pub fn check_memory(&self, scene: &Scene) -> Result<()> {
        self.check_memory_rows(scene, scene.camera.height)
    }

    /// [`Self::check_memory`] for a run that holds `rows` rows of the image
    /// at a time (a band of a banded run, [`crate::core::bands`]).
    pub fn check_memory_rows(&self, scene: &Scene, rows: u32) -> Result<()> {
        let run = crate::core::memory::Run {
            pixels: scene.camera.width as u64 * rows.min(scene.camera.height) as u64,
            triangles: scene.triangle_count() as u64,
            per_pixel: self.bytes_per_pixel,
            per_triangle: self.bytes_per_triangle,
        };
        let band = if rows < scene.camera.height {
            let s = if rows == 1 { "" } else { "s" };
            format!(", {rows} row{s} at a time")
        } else {
            String::new()
        };
        let what = format!(
            "chapter {} on {} ({}x{} pixels{band}, {} triangles)",
            self.number,
            crate::core::text::escape(&scene.name),
            scene.camera.width,
            scene.camera.height,
            scene.triangle_count()
        );
        crate::core::memory::check(&what, &run)
    }
}

/// [`rows_per_band`] with the memory this process may still get.
pub fn plan(info: &ChapterInfo, scene: &Scene) -> Option<u32> {
    rows_per_band(info, scene, available().map(|(bytes, _)| bytes))
}

/// What a banded run made: its files (in the order a whole run lists
/// them), its seconds, its report and the main image reduced for a
/// preview.
pub struct Banded {
    /// The files written.
    pub files: Vec<PathBuf>,
    /// Wall-clock seconds of the bands (rendering and streaming).
    pub seconds: f64,
    /// The run's report ([`run_report`]).
    pub report: Report,
    /// The main image at most 1024 pixels wide.
    pub preview: Film,
}

/// Renders `scene` (at its final size) with `chapter` in bands of
/// `rows_per_band` rows and streams the views into `out` under `stem`, as
/// the whole run's files would be.
pub fn render_in_bands(
    chapter: &dyn Chapter,
    scene: Scene,
    settings: &Settings,
    out: &Path,
    stem: &str,
    rows_per_band: u32,
) -> Result<Banded> {
    let info = chapter.info();
    let (width, height) = (scene.camera.width, scene.camera.height);
    let bands = height.div_ceil(rows_per_band.max(1));
    if settings.studies {
        return Err(Error::Usage(format!(
            "`--report` runs its studies on the whole image, and at {width}x{height} this run \
             renders in {bands} bands of {rows_per_band} rows to fit in memory: run the studies \
             at a smaller --width and --height"
        )));
    }
    info.check_memory_rows(&scene, rows_per_band)?;
    let scene = Arc::new(scene);
    let set = OutputSet::begin();
    let mut files = ImageFiles::create(&info, out, stem, (width, height))?;
    let mut small = Reduced::new(width, height);
    let mut reports = Vec::new();
    let mut rays = 0;
    let start = Instant::now();
    let progress = Progress::new(stem);
    let band_rows = |band: u32| band * rows_per_band..((band + 1) * rows_per_band).min(height);
    let band_settings = |band: u32, scale: Option<ViewScale>| Settings {
        rows: Some(band_rows(band)),
        scale,
        ..settings.clone()
    };
    // Views scaled over the whole image: a first sweep finds the range.
    let mut scale = None;
    if info.scaled_views {
        for band in 0..bands {
            let step = ("scale", band, bands);
            let (render, _) =
                render_band(chapter, &scene, &band_settings(band, None), &progress, step)?;
            let own = render.scale();
            scale = match (scale, own) {
                (Some(a), Some(b)) => Some(ViewScale::merge(a, b)),
                (a, b) => a.or(b),
            };
        }
    }
    for band in 0..bands {
        let step = ("band", band, bands);
        let (render, pass) = render_band(
            chapter,
            &scene,
            &band_settings(band, scale),
            &progress,
            step,
        )?;
        rays += pass.rays;
        let snapshot = render.snapshot();
        files.add(&snapshot.views)?;
        small.add(&snapshot.views[0], band_rows(band).start);
        reports.push(render.report());
    }
    progress.end();
    let seconds = start.elapsed().as_secs_f64();
    let written = files.finish()?;
    set.commit()?;
    Ok(Banded {
        files: written,
        seconds,
        report: run_report(&reports, (bands, rows_per_band), rays, seconds),
        preview: small.film(),
    })
}

/// Starts a render of `scene` with `settings` (a band's) and runs it to
/// completion, showing `step` (what for, which band of how many).
fn render_band(
    chapter: &dyn Chapter,
    scene: &Arc<Scene>,
    settings: &Settings,
    progress: &Progress,
    step: (&str, u32, u32),
) -> Result<(Box<dyn Render>, Pass)> {
    let mut render = chapter.start(Arc::clone(scene), settings)?;
    loop {
        let pass = render.pass();
        progress.show(step, (pass.done, pass.planned));
        if pass.complete {
            return Ok((render, pass));
        }
    }
}

/// The run's report from its bands' reports: the title, lists and facts
/// every band agrees on (the scene, the size, what was built), the totals
/// of the counts added up, and the names of the facts that counted one
/// band's rows only, which are left out.
pub fn run_report(
    reports: &[Report],
    (bands, rows_per_band): (u32, u32),
    rays: u64,
    seconds: f64,
) -> Report {
    let mut report = reports.last().cloned().unwrap_or_default();
    let (same, per_band): (Vec<_>, Vec<_>) = report
        .facts
        .iter()
        .cloned()
        .partition(|f| reports.iter().all(|r| r.facts.contains(f)));
    report.facts = same;
    report.facts.push((
        "bands".into(),
        format!(
            "{bands} of up to {rows_per_band} rows, rendered one after another: the whole \
             image does not fit in memory at once"
        ),
    ));
    report
        .facts
        .push(("render time, all bands".into(), format_seconds(seconds)));
    if rays > 0 {
        report
            .facts
            .push(("rays, all bands".into(), rays.to_string()));
    }
    if !per_band.is_empty() {
        let names: Vec<String> = per_band.into_iter().map(|(k, _)| k).collect();
        report.facts.push((
            "per band only".into(),
            format!(
                "{} (not shown: each band counts its own rows)",
                names.join(", ")
            ),
        ));
    }
    report.nonfinite_caught = reports.iter().map(|r| r.nonfinite_caught).sum();
    report.figures.clear();
    report
}

/// The main image at most 1024 pixels wide, box-filtered from the bands
/// as they come: what the printed preview is made from.
struct Reduced {
    factor: u32,
    width: u32,
    sums: Vec<Vec3>,
    counts: Vec<u32>,
}

impl Reduced {
    fn new(width: u32, height: u32) -> Reduced {
        let factor = width.div_ceil(1024).max(1);
        let (w, h) = (width.div_ceil(factor), height.div_ceil(factor));
        let n = w as usize * h as usize;
        Reduced {
            factor,
            width: w,
            sums: vec![Vec3::ZERO; n],
            counts: vec![0; n],
        }
    }

    /// Adds `band`, whose first row is row `first_row` of the image.
    fn add(&mut self, band: &Film, first_row: u32) {
        for y in 0..band.height {
            let row = ((first_row + y) / self.factor) as usize * self.width as usize;
            for x in 0..band.width {
                let i = row + (x / self.factor) as usize;
                self.sums[i] += band.get(x, y);
                self.counts[i] += 1;
            }
        }
    }

    fn film(&self) -> Film {
        Film {
            width: self.width,
            height: (self.sums.len() / self.width.max(1) as usize) as u32,
            pixels: self
                .sums
                .iter()
                .zip(&self.counts)
                .map(|(s, &n)| *s / n.max(1) as f32)
                .collect(),
        }
    }
}

/// The band and pass counter on stderr, once a run has taken a second
/// (and only on a terminal).
struct Progress<'a> {
    stem: &'a str,
    start: Instant,
    shown: std::cell::Cell<bool>,
    terminal: bool,
}

impl<'a> Progress<'a> {
    fn new(stem: &'a str) -> Self {
        use std::io::IsTerminal;
        Progress {
            stem,
            start: Instant::now(),
            shown: std::cell::Cell::new(false),
            terminal: std::io::stderr().is_terminal(),
        }
    }

    /// Shows `what` ("band", or "scale" in the sweep that finds the
    /// range) `band` of `bands`, pass `done` of `planned`.
    fn show(&self, (what, band, bands): (&str, u32, u32), (done, planned): (u32, u32)) {
        if self.terminal && self.start.elapsed().as_secs_f64() > 1.0 {
            eprint!(
                "\r{}: {what} {}/{bands}, pass {done}/{planned}  ",
                escape(self.stem),
                band + 1
            );
            self.shown.set(true);
        }
    }

    fn end(&self) {
        if self.shown.get() {
            eprintln!();
        }
    }
}
