//! The film: linear HDR RGB pixels, and how they leave the renderer.
//!
//! Colour stays linear inside raystep. Only when writing an 8-bit PNG do we
//! apply the sRGB transfer curve; EXR files keep the linear f32 values.
//! Every write goes to a temporary file beside the target and is renamed
//! into place, so a failed or interrupted run never leaves half an image.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard};

use glam::Vec3;

use crate::core::error::{Error, Result};

/// A width x height grid of linear RGB values, row by row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` pixels, row-major, top row first.
    pub pixels: Vec<Vec3>,
}

impl Film {
    /// A black film. Sizes are checked by the camera before we get here.
    pub fn new(width: u32, height: u32) -> Film {
        Film {
            width,
            height,
            pixels: vec![Vec3::ZERO; width as usize * height as usize],
        }
    }

    /// The pixel at column `x`, row `y`.
    pub fn get(&self, x: u32, y: u32) -> Vec3 {
        self.pixels[(y * self.width + x) as usize]
    }

    /// A mutable reference to the pixel at column `x`, row `y`.
    pub fn get_mut(&mut self, x: u32, y: u32) -> &mut Vec3 {
        &mut self.pixels[(y * self.width + x) as usize]
    }

    /// Replaces every NaN or infinite channel by 0 and returns how many
    /// pixels had one. Called before any image leaves the renderer.
    pub fn scrub_nonfinite(&mut self) -> u64 {
        let mut caught = 0;
        for p in &mut self.pixels {
            if !p.is_finite() {
                caught += 1;
                *p = Vec3::select(p.is_finite_mask(), *p, Vec3::ZERO);
            }
        }
        caught
    }

    /// Root-mean-square difference to another film of the same size, over
    /// all channels.
    pub fn rmse(&self, other: &Film) -> f64 {
        assert_eq!((self.width, self.height), (other.width, other.height));
        let sum: f64 = self
            .pixels
            .iter()
            .zip(&other.pixels)
            .map(|(a, b)| (*a - *b).as_dvec3().length_squared())
            .sum();
        (sum / (3.0 * self.pixels.len().max(1) as f64)).sqrt()
    }

    /// 8-bit sRGB bytes (RGB, row-major), values clamped to [0, 1].
    pub fn to_srgb8(&self) -> Vec<u8> {
        self.pixels
            .iter()
            .flat_map(|p| p.to_array().map(encode_srgb))
            .collect()
    }

    /// Writes an 8-bit sRGB PNG, atomically.
    pub fn write_png(&self, path: &Path) -> Result<()> {
        write_rgb8_png(&self.to_srgb8(), self.width, self.height, path)
    }

    /// Writes a linear f32 OpenEXR file, atomically.
    pub fn write_exr(&self, path: &Path) -> Result<()> {
        write_atomically(path, |tmp| {
            use exr::prelude::*;
            let channels = SpecificChannels::rgb(|Vec2(x, y): Vec2<usize>| {
                let p = self.pixels[y * self.width as usize + x];
                (p.x, p.y, p.z)
            });
            // Compressed one block after another: the parallel writer stores
            // blocks in the order they finish, so the same image would not
            // always give the same bytes.
            let mut bytes = std::io::Cursor::new(Vec::new());
            Image::from_channels((self.width as usize, self.height as usize), channels)
                .write()
                .non_parallel()
                .to_buffered(&mut bytes)
                .map_err(|e| e.to_string())?;
            write_all_synced(tmp, bytes.get_ref())
        })
    }

    /// Reads an 8-bit PNG back as linear values (for graders and tests).
    pub fn read_png(path: &Path) -> Result<Film> {
        let img = image::open(path)
            .map_err(|e| Error::Image {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?
            .to_rgb8();
        Ok(Film {
            width: img.width(),
            height: img.height(),
            pixels: img
                .pixels()
                .map(|p| Vec3::from(p.0.map(decode_srgb)))
                .collect(),
        })
    }

    /// Reads a linear RGB EXR file (for references and tests).
    pub fn read_exr(path: &Path) -> Result<Film> {
        use exr::prelude::*;
        let image = read_first_rgba_layer_from_file(
            path,
            |res, _| Film::new(res.width() as u32, res.height() as u32),
            |film: &mut Film, pos, (r, g, b, _a): (f32, f32, f32, f32)| {
                *film.get_mut(pos.x() as u32, pos.y() as u32) = Vec3::new(r, g, b);
            },
        )
        .map_err(|e| crate::core::error::Error::Image {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        Ok(image.layer_data.channel_data.pixels)
    }
}

/// Linear [0, 1] → sRGB-encoded 8-bit value.
pub fn encode_srgb(linear: f32) -> u8 {
    let c = if linear.is_nan() {
        0.0
    } else {
        linear.clamp(0.0, 1.0)
    };
    let s = if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0 + 0.5) as u8
}

/// 8-bit sRGB value → linear [0, 1].
pub fn decode_srgb(v: u8) -> f32 {
    let s = v as f32 / 255.0;
    if s <= 0.04045 {
        s / 12.92
    } else {
        ((s + 0.055) / 1.055).powf(2.4)
    }
}

/// Temporary files on disk right now, process-wide, for
/// [`remove_temporaries_and_exit`]. Its lock is held for the whole of one
/// write, and for the whole of a set's renames, so a signal handler that
/// takes it lets the current write finish and never sees half a set.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());
/// Set once a signal handler has started cleaning up: no new write starts.
static STOPPING: AtomicBool = AtomicBool::new(false);

/// Whether a signal has asked the process to stop: its handler is removing
/// the temporaries and exits with 128 + the signal's number.
pub fn stopping() -> bool {
    STOPPING.load(Ordering::SeqCst)
}
/// Distinguishes temporaries of one process.
static COUNTER: AtomicU64 = AtomicU64::new(0);

thread_local! {
    /// The set this thread is writing, if any: (temporary, final path).
    static STAGED: RefCell<Option<Vec<(PathBuf, PathBuf)>>> = const { RefCell::new(None) };
}

fn temporaries() -> MutexGuard<'static, Vec<PathBuf>> {
    TEMPORARIES
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Writes 8-bit RGB `pixels` as a PNG at `path`, atomically: encoded in
/// memory, then written whole and synced, so that a full disk is an error
/// and never a short file renamed into place.
pub fn write_rgb8_png(pixels: &[u8], width: u32, height: u32, path: &Path) -> Result<()> {
    use image::ImageEncoder;
    write_atomically(path, |tmp| {
        let mut bytes = Vec::new();
        image::codecs::png::PngEncoder::new(&mut bytes)
            .write_image(pixels, width, height, image::ExtendedColorType::Rgb8)
            .map_err(|e| e.to_string())?;
        write_all_synced(tmp, &bytes)
    })
}

/// Writes `bytes` to a new file at `path` and waits until the system has
/// them: a short write, a failed flush or a failed sync (a full disk) is
/// an error naming what failed.
pub fn write_all_synced(path: &Path, bytes: &[u8]) -> std::result::Result<(), String> {
    use std::io::Write;
    let mut file = std::fs::File::create(path).map_err(|e| e.to_string())?;
    file.write_all(bytes)
        .and_then(|_| file.flush())
        .and_then(|_| file.sync_all())
        .map_err(|e| format!("writing {} bytes: {e}", bytes.len()))
}

/// Creates the folder `dir` (and its parents) for outputs; a path on the
/// way that is a file is named as such (`--out` pointing at a file used to
/// say only "File exists").
pub fn create_folder(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| {
        let file = dir
            .ancestors()
            .find(|a| std::fs::metadata(a).is_ok_and(|m| !m.is_dir()));
        match file {
            Some(file) => Error::Usage(format!(
                "{}: is a file, not a folder: outputs need a folder there (choose another --out)",
                file.display()
            )),
            None => Error::io(dir, e),
        }
    })
}

/// Creates the directory of `path`, lets `write` fill a temporary file next
/// to it, and renames that into place. On failure the temporary is removed
/// and `path` is untouched. Inside an [`OutputSet`] the rename waits for
/// [`OutputSet::commit`].
pub fn write_atomically(
    path: &Path,
    write: impl FnOnce(&Path) -> std::result::Result<(), String>,
) -> Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        create_folder(dir)?;
        super::stale::sweep_once(dir);
    }
    // The temporary is made and listed under the list's lock, so that a
    // signal's handler (which takes it) sees every one made.
    let mut temps = temporaries();
    if STOPPING.load(Ordering::SeqCst) {
        return Err(Error::Usage(
            "interrupted: no more files are written".into(),
        ));
    }
    let tmp = fresh_temporary(path)?;
    temps.push(tmp.clone());
    let result = write(&tmp).map_err(|message| Error::Image {
        path: path.to_path_buf(),
        message,
    });
    let staged = result.is_ok()
        && STAGED.with(|s| match s.borrow_mut().as_mut() {
            Some(set) => {
                set.push((tmp.clone(), path.to_path_buf()));
                true
            }
            None => false,
        });
    if staged {
        return Ok(());
    }
    let result = result.and_then(|_| std::fs::rename(&tmp, path).map_err(|e| Error::io(path, e)));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    temps.retain(|t| *t != tmp);
    result
}

/// A set of outputs that appear together or not at all: while it is alive,
/// [`write_atomically`] on this thread leaves each file as a temporary;
/// [`OutputSet::commit`] renames them all into place, and dropping the set
/// uncommitted (an error, a panic) removes them.
pub struct OutputSet {
    committed: bool,
}

impl OutputSet {
    /// Starts staging this thread's writes. Sets do not nest.
    pub fn begin() -> OutputSet {
        STAGED.with(|s| *s.borrow_mut() = Some(Vec::new()));
        OutputSet { committed: false }
    }

    /// Renames every staged file into place, under the lock a signal
    /// handler waits for, so an interrupt sees all of them or none; and
    /// under a lock on each output folder, so that two
    /// runs into one folder leave one run's set, not a mix. A rename that
    /// fails part-way puts back what the set had replaced and removes what
    /// it had added: the folder is as it was.
    pub fn commit(mut self) -> Result<()> {
        self.committed = true;
        let staged = STAGED.with(|s| s.borrow_mut().take()).unwrap_or_default();
        let mut temps = temporaries();
        let _locks = lock_folders(staged.iter().map(|(_, path)| path.as_path()));
        // Keep each file about to be replaced under a second name (a hard
        // link: nothing is copied) until the whole set is in place.
        let mut done: Vec<(&Path, Option<PathBuf>)> = Vec::new();
        let mut result = Ok(());
        for (tmp, path) in &staged {
            if result.is_ok() {
                let old = sibling(path, "old");
                let kept = std::fs::hard_link(path, &old).is_ok().then_some(old);
                match std::fs::rename(tmp, path) {
                    Ok(()) => {
                        temps.extend(kept.clone());
                        done.push((path, kept));
                    }
                    Err(e) => {
                        // This one was not replaced: its copy goes.
                        if let Some(old) = kept {
                            let _ = std::fs::remove_file(old);
                        }
                        result = Err(Error::io(path, e));
                    }
                }
            }
            if result.is_err() {
                let _ = std::fs::remove_file(tmp);
            }
            temps.retain(|t| t != tmp);
        }
        for (path, kept) in done {
            match (&result, kept) {
                (Ok(()), Some(b)) => {
                    let _ = std::fs::remove_file(&b);
                    temps.retain(|t| *t != b);
                }
                (Err(_), Some(b)) => {
                    let _ = std::fs::rename(&b, path);
                    temps.retain(|t| *t != b);
                }
                (Err(_), None) => {
                    let _ = std::fs::remove_file(path);
                }
                (Ok(()), None) => {}
            }
        }
        result
    }
}

/// A hidden name beside `path` for this process's `kind` of file
/// (`.1234.tmp7-image.png`): a temporary, or the copy of a file a set is
/// replacing. The extension stays last, for encoders that look at it.
/// A new, empty temporary file next to `path`, created here (never one
/// that was there: a link planted at a guessed name is not written
/// through), with a name no one can guess.
fn fresh_temporary(path: &Path) -> Result<PathBuf> {
    use std::hash::{BuildHasher, Hasher};
    for _ in 0..16 {
        let mut h = std::collections::hash_map::RandomState::new().build_hasher();
        h.write_u64(COUNTER.load(Ordering::Relaxed));
        let tmp = sibling(path, &format!("tmp{:016x}.", h.finish()));
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)
        {
            Ok(_) => return Ok(tmp),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(Error::io(path, e)),
        }
    }
    Err(Error::Usage(format!(
        "{}: cannot create a temporary file beside it",
        path.display()
    )))
}

fn sibling(path: &Path, kind: &str) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    path.with_file_name(format!(".{}.{kind}{n}-{name}", std::process::id()))
}

/// Exclusive locks on each folder of `paths` (the folder itself, opened
/// read-only: no lock file is left behind), taken in sorted order so two
/// runs cannot deadlock, released when dropped. Best effort: where a
/// folder cannot be opened as a file (not on Unix), it is not locked.
fn lock_folders<'a>(paths: impl Iterator<Item = &'a Path>) -> Vec<std::fs::File> {
    let mut dirs: Vec<PathBuf> = paths
        .filter_map(|p| p.parent())
        .map(|d| {
            if d.as_os_str().is_empty() {
                PathBuf::from(".")
            } else {
                d.to_path_buf()
            }
        })
        .collect();
    dirs.sort();
    dirs.dedup();
    dirs.into_iter()
        .filter_map(|d| {
            let folder = std::fs::File::open(&d).ok()?;
            folder.lock().ok()?;
            Some(folder)
        })
        .collect()
}

impl Drop for OutputSet {
    fn drop(&mut self) {
        if self.committed {
            return;
        }
        let staged = STAGED.with(|s| s.borrow_mut().take()).unwrap_or_default();
        let mut temps = temporaries();
        for (tmp, _) in &staged {
            let _ = std::fs::remove_file(tmp);
            temps.retain(|t| t != tmp);
        }
    }
}

/// For a signal handler (INT, TERM, HUP; the TUI's too): waits for the write in progress, removes
/// every temporary file of this process and exits with `code`. No file is
/// renamed into place afterwards.
pub fn remove_temporaries_and_exit(code: i32) -> ! {
    STOPPING.store(true, Ordering::SeqCst);
    let temps = temporaries();
    for t in temps.iter() {
        let _ = std::fs::remove_file(t);
    }
    std::process::exit(code)
}

/// How many temporary files this process has on disk (for tests).
pub fn temporaries_on_disk() -> usize {
    temporaries().iter().filter(|t| t.exists()).count()
}

/// The mean value of a film over pixels and channels.
pub fn film_mean(film: &Film) -> f64 {
    let n = film.pixels.len().max(1) as f64 * 3.0;
    film.pixels
        .iter()
        .map(|p| p.as_dvec3().element_sum())
        .sum::<f64>()
        / n
}
