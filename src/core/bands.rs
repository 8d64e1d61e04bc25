//! Runs too large to hold whole, rendered band by band. A chapter whose
//! pixels do not depend on one another ([`ChapterInfo::bands`]: chapters 3,
//! 5 and 6) renders any band of rows alone with every pixel as in the
//! whole image ([`Settings::rows`]). When a run's pixels would need more
//! than [`BAND_BYTES`] in one piece, or more than this process may still
//! get, the headless runner renders it in bands that fit, one after
//! another, and streams each band's rows into the image files: a 16384²
//! render needs a band's memory, not the image's.
//!
//! The PNGs are written row by row as the bands come ([`png`]'s stream
//! writer); the main image's EXR needs its rows in one go at the end, so
//! its linear values wait in a scratch file beside it. A band's report
//! counts only its own rows: the run's report keeps the facts every band
//! agrees on, adds the totals, and names the per-band counts it left out.

use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use glam::Vec3;

use crate::core::error::{Error, Result};
use crate::core::film::{write_atomically, Film, OutputSet};
use crate::core::format::format_seconds;
use crate::core::memory::{available, BASE_BYTES};
use crate::core::outputs::Streamed;
use crate::core::report::Report;
use crate::core::stage::{Chapter, ChapterInfo, Settings};
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
    // At least one row: a run that cannot hold even that is refused by the
    // memory check.
    Some((budget / row).clamp(1, h) as u32)
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
    for band in 0..bands {
        let rows = band * rows_per_band..((band + 1) * rows_per_band).min(height);
        let mut render = chapter.start(
            Arc::clone(&scene),
            &Settings {
                rows: Some(rows.clone()),
                ..settings.clone()
            },
        )?;
        let pass = loop {
            let pass = render.pass();
            progress.show(start, (band, bands), (pass.done, pass.planned));
            if pass.complete {
                break pass;
            }
        };
        rays += pass.rays;
        let snapshot = render.snapshot();
        files.add(&snapshot.views)?;
        small.add(&snapshot.views[0], rows.start);
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

/// The files of a banded run, written as the bands come: a PNG per view
/// (and the main image's EXR when it holds radiance), named as the whole
/// run names them.
struct ImageFiles {
    pngs: Vec<(Streamed, png::StreamWriter<'static, std::fs::File>)>,
    /// The EXR's path and the scratch file its linear rows wait in.
    exr: Option<(PathBuf, Streamed)>,
    size: (u32, u32),
}

impl ImageFiles {
    fn create(info: &ChapterInfo, out: &Path, stem: &str, size: (u32, u32)) -> Result<Self> {
        let mut pngs = Vec::new();
        let mut exr = None;
        for (i, view) in info.views.iter().enumerate() {
            let name = if i == 0 {
                stem.to_string()
            } else {
                format!("{stem}-{}", view.name)
            };
            let path = out.join(format!("{name}.png"));
            let file = Streamed::create(&path)?;
            let writer = png_rows(&file, size).map_err(|e| image_error(&path, e))?;
            pngs.push((file, writer));
            if i == 0 && info.radiance {
                let path = out.join(format!("{name}.exr"));
                let scratch = Streamed::create(&path.with_extension("exr.rows"))?;
                exr = Some((path, scratch));
            }
        }
        Ok(ImageFiles { pngs, exr, size })
    }

    /// Appends a band's views, rows in order.
    fn add(&mut self, views: &[Film]) -> Result<()> {
        for ((file, writer), film) in self.pngs.iter_mut().zip(views) {
            writer
                .write_all(&film.to_srgb8())
                .map_err(|e| image_error(file.path(), e))?;
        }
        if let (Some((path, scratch)), Some(film)) = (&self.exr, views.first()) {
            let bytes: Vec<u8> = film
                .pixels
                .iter()
                .flat_map(|p| p.to_array())
                .flat_map(f32::to_le_bytes)
                .collect();
            scratch
                .file()
                .write_all(&bytes)
                .map_err(|e| image_error(path, e))?;
        }
        Ok(())
    }

    /// Ends every file and puts it in place (inside the run's output
    /// set); the paths in the order the whole run lists them.
    fn finish(self) -> Result<Vec<PathBuf>> {
        let mut written = Vec::new();
        for (i, (file, writer)) in self.pngs.into_iter().enumerate() {
            let path = file.path().to_path_buf();
            writer.finish().map_err(|e| image_error(&path, e))?;
            file.finish()?;
            written.push(path);
            if let (0, Some((exr, scratch))) = (i, &self.exr) {
                write_atomically(exr, |tmp| exr_from_rows(scratch.file(), self.size, tmp))?;
                written.push(exr.clone());
            }
        }
        Ok(written)
    }
}

/// A PNG writer that takes 8-bit sRGB rows as they come, into `file`.
fn png_rows(
    file: &Streamed,
    (w, h): (u32, u32),
) -> std::result::Result<png::StreamWriter<'static, std::fs::File>, png::EncodingError> {
    let handle = file.file().try_clone()?;
    let mut encoder = png::Encoder::new(handle, w, h);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder
        .write_header()?
        .into_stream_writer_with_size(1 << 20)
}

/// Writes the linear rows in `rows` (RGB f32, little-endian, row by row)
/// as the EXR [`Film::write_exr`] writes, to `path`.
fn exr_from_rows(
    rows: &std::fs::File,
    (w, h): (u32, u32),
    path: &Path,
) -> std::result::Result<(), String> {
    use exr::prelude::*;
    let w = w as usize;
    // The writer asks for pixels row by row: one row is read at a time.
    let reader = rows.try_clone().map_err(|e| e.to_string())?;
    let cache = Mutex::new(RowCache {
        file: reader,
        row: usize::MAX,
        values: vec![0.0; 3 * w],
        failed: None,
    });
    let channels = SpecificChannels::rgb(|Vec2(x, y): Vec2<usize>| {
        let mut c = cache.lock().unwrap_or_else(|p| p.into_inner());
        c.load(y, w);
        (c.values[3 * x], c.values[3 * x + 1], c.values[3 * x + 2])
    });
    let mut file = std::fs::File::create(path).map_err(|e| e.to_string())?;
    Image::from_channels((w, h as usize), channels)
        .write()
        .non_parallel()
        .to_buffered(std::io::BufWriter::new(&mut file))
        .map_err(|e| e.to_string())?;
    if let Some(e) = cache.into_inner().ok().and_then(|c| c.failed) {
        return Err(format!("reading its rows back: {e}"));
    }
    file.sync_all().map_err(|e| format!("writing: {e}"))
}

/// One row of the EXR's scratch file, read when asked for.
struct RowCache {
    file: std::fs::File,
    row: usize,
    values: Vec<f32>,
    failed: Option<std::io::Error>,
}

impl RowCache {
    fn load(&mut self, y: usize, w: usize) {
        if self.row == y || self.failed.is_some() {
            return;
        }
        let mut bytes = vec![0u8; 12 * w];
        let read = self
            .file
            .seek(SeekFrom::Start((12 * w * y) as u64))
            .and_then(|_| self.file.read_exact(&mut bytes));
        match read {
            Ok(()) => {
                for (v, b) in self.values.iter_mut().zip(bytes.chunks_exact(4)) {
                    *v = f32::from_le_bytes([b[0], b[1], b[2], b[3]]);
                }
                self.row = y;
            }
            Err(e) => self.failed = Some(e),
        }
    }
}

fn image_error(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::Image {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
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
    shown: std::cell::Cell<bool>,
    terminal: bool,
}

impl<'a> Progress<'a> {
    fn new(stem: &'a str) -> Self {
        use std::io::IsTerminal;
        Progress {
            stem,
            shown: std::cell::Cell::new(false),
            terminal: std::io::stderr().is_terminal(),
        }
    }

    fn show(&self, start: Instant, (band, bands): (u32, u32), (done, planned): (u32, u32)) {
        if self.terminal && start.elapsed().as_secs_f64() > 1.0 {
            eprint!(
                "\r{}: band {}/{bands}, pass {done}/{planned}  ",
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
