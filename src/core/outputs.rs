//! How outputs reach the disk: every file is written to a temporary
//! beside its target and renamed into place, a run's files together
//! ([`OutputSet`]) or not at all, and a signal (INT, TERM, HUP) removes
//! every temporary before the process exits. A file written bit by bit
//! while a run goes on (a banded run's images, [`Streamed`]) is a
//! temporary of the same kind until it is finished.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard};

use crate::core::error::{Error, Result};

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
    prepare_folder(path)?;
    // The temporary is made and listed under the list's lock, so that a
    // signal's handler (which takes it) sees every one made.
    let mut temps = temporaries();
    let tmp = listed_temporary(path, &mut temps)?;
    let result = write(&tmp).map_err(|message| Error::Image {
        path: path.to_path_buf(),
        message,
    });
    place(&tmp, path, result, &mut temps)
}

/// Creates the folder `path` will be written in, and sweeps it of stale
/// temporaries (once per folder and process).
fn prepare_folder(path: &Path) -> Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        create_folder(dir)?;
        super::stale::sweep_once(dir);
    }
    Ok(())
}

/// A fresh temporary beside `path`, added to `temps` (the list's lock
/// held); none once a signal is stopping the process.
fn listed_temporary(path: &Path, temps: &mut Vec<PathBuf>) -> Result<PathBuf> {
    if STOPPING.load(Ordering::SeqCst) {
        return Err(Error::Usage(
            "interrupted: no more files are written".into(),
        ));
    }
    let tmp = fresh_temporary(path)?;
    temps.push(tmp.clone());
    Ok(tmp)
}

/// Puts the written temporary `tmp` in place at `path` once `written` is
/// Ok: staged in this thread's [`OutputSet`] if one is open, else renamed
/// now. On failure the temporary is removed and `path` is untouched.
fn place(tmp: &Path, path: &Path, written: Result<()>, temps: &mut Vec<PathBuf>) -> Result<()> {
    let staged = written.is_ok()
        && STAGED.with(|s| match s.borrow_mut().as_mut() {
            Some(set) => {
                set.push((tmp.to_path_buf(), path.to_path_buf()));
                true
            }
            None => false,
        });
    if staged {
        return Ok(());
    }
    let result = written.and_then(|_| std::fs::rename(tmp, path).map_err(|e| Error::io(path, e)));
    if result.is_err() {
        let _ = std::fs::remove_file(tmp);
    }
    temps.retain(|t| t != tmp);
    result
}

/// A file written bit by bit while a run goes on (a banded run's images,
/// [`crate::core::bands`]): a fresh temporary beside its path, removed by a
/// signal like every other, put in place by [`Streamed::finish`] (when the
/// [`OutputSet`] open on this thread commits, if one is), and removed if
/// dropped unfinished (an error, or a scratch file that is never meant to
/// be kept).
pub struct Streamed {
    tmp: PathBuf,
    path: PathBuf,
    file: std::fs::File,
    finished: bool,
}

impl Streamed {
    /// Starts the file that will be `path`.
    pub fn create(path: &Path) -> Result<Streamed> {
        prepare_folder(path)?;
        let tmp = listed_temporary(path, &mut temporaries())?;
        let file = std::fs::OpenOptions::new()
            .read(true)
            .write(true)
            .open(&tmp)
            .map_err(|e| Error::io(path, e));
        // Listed before it was opened: removed again if it cannot be.
        let file = match file {
            Ok(f) => f,
            Err(e) => {
                let _ = std::fs::remove_file(&tmp);
                temporaries().retain(|t| *t != tmp);
                return Err(e);
            }
        };
        Ok(Streamed {
            tmp,
            path: path.to_path_buf(),
            file,
            finished: false,
        })
    }

    /// The path the file will have.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The temporary file, open for reading and writing.
    pub fn file(&self) -> &std::fs::File {
        &self.file
    }

    /// Waits until the system has every byte written (a full disk is an
    /// error here), then puts the file in place.
    pub fn finish(mut self) -> Result<()> {
        self.finished = true;
        let synced = self.file.sync_all().map_err(|e| Error::Image {
            path: self.path.clone(),
            message: format!("writing: {e}"),
        });
        place(&self.tmp, &self.path, synced, &mut temporaries())
    }
}

impl Drop for Streamed {
    fn drop(&mut self) {
        if !self.finished {
            let mut temps = temporaries();
            let _ = std::fs::remove_file(&self.tmp);
            temps.retain(|t| *t != self.tmp);
        }
    }
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
