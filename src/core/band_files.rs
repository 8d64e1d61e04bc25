//! The image files of a banded run ([`super::bands`]), written as the
//! bands come: each PNG row by row through [`png`]'s stream writer, the
//! main image's EXR from a scratch file of its linear rows at the end
//! (the EXR writer wants every row in one go).

use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use crate::core::error::{Error, Result};
use crate::core::film::{write_atomically, write_rgb_exr, Film};
use crate::core::outputs::Streamed;
use crate::core::stage::ChapterInfo;

/// The files of a banded run: a PNG per view (and the main image's EXR
/// when it holds radiance), named as the whole run names them.
pub struct ImageFiles {
    pngs: Vec<(Streamed, png::StreamWriter<'static, std::fs::File>)>,
    /// The EXR's path and the scratch file its linear rows wait in.
    exr: Option<(PathBuf, Streamed)>,
    size: (u32, u32),
}

impl ImageFiles {
    /// Starts every file of a run of `info` into `out`, named after
    /// `stem`, for an image of `size`.
    pub fn create(info: &ChapterInfo, out: &Path, stem: &str, size: (u32, u32)) -> Result<Self> {
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
    pub fn add(&mut self, views: &[Film]) -> Result<()> {
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
    pub fn finish(self) -> Result<Vec<PathBuf>> {
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
    // The writer asks for pixels row by row: one row is read at a time.
    let reader = rows.try_clone().map_err(|e| e.to_string())?;
    let cache = Mutex::new(RowCache {
        file: reader,
        row: usize::MAX,
        values: vec![0.0; 3 * w as usize],
        failed: None,
    });
    write_rgb_exr(path, (w, h), |x, y| {
        let mut c = cache.lock().unwrap_or_else(|p| p.into_inner());
        c.load(y, w as usize);
        (c.values[3 * x], c.values[3 * x + 1], c.values[3 * x + 2])
    })?;
    match cache.into_inner().ok().and_then(|c| c.failed) {
        Some(e) => Err(format!("reading its rows back: {e}")),
        None => Ok(()),
    }
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
