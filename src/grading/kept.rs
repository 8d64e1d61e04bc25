//! The binary each grader build keeps: graders that share a target folder
//! (the terminal UI's student mode and `cargo grade` at once) build one
//! at a time (`BuildLock`), and each runs its own link to the binary its
//! build made (`keep_runner`), kept beside the copies of the exercise files
//! it was built from ([`kept_runner`]), so no later build replaces it under
//! a grader still starting it. Links unused for an hour are removed
//! (`prune_runners`).

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;

/// Where a build of `profile` keeps its binary in the folder of the files
/// it was built from ([`Built::runner`](crate::build::Built::runner)).
pub fn kept_runner(folder: &Path, profile: &str) -> PathBuf {
    let suffix = std::env::consts::EXE_SUFFIX;
    folder.join(format!("raystep-grade-child-{profile}{suffix}"))
}

/// The file whose date says when a grader last used that binary.
pub fn used_marker(folder: &Path, profile: &str) -> PathBuf {
    folder.join(format!("used-{profile}"))
}

/// An exclusive lock on a target folder's grader builds (a file lock, so
/// it holds between processes, and the system releases it if the process
/// dies); released when dropped.
pub(crate) struct BuildLock {
    _file: std::fs::File,
}

impl BuildLock {
    /// Waits for the lock of `sources` (or until `cancel` is set).
    pub(crate) fn take(sources: &Path, cancel: Option<&AtomicBool>) -> Result<BuildLock, String> {
        let io = |e: std::io::Error| format!("cannot lock {}: {e}", sources.display());
        std::fs::create_dir_all(sources).map_err(io)?;
        let file = std::fs::File::options()
            .create(true)
            .truncate(false)
            .write(true)
            .open(sources.join("build.lock"))
            .map_err(io)?;
        loop {
            match file.try_lock() {
                Ok(()) => return Ok(BuildLock { _file: file }),
                Err(std::fs::TryLockError::WouldBlock) => {}
                Err(std::fs::TryLockError::Error(e)) => return Err(io(e)),
            }
            if cancel.is_some_and(|c| c.load(std::sync::atomic::Ordering::Relaxed)) {
                return Err("the build was cancelled".into());
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
    }
}

/// Keeps `built`, the binary a build of `profile` made from the module
/// list `modules`, beside the exercise files it was built from
/// ([`kept_runner`]): later builds replace the file cargo writes, never
/// this one. A hard link, so no file is written that a new child of
/// another thread could hold open when the grader starts it (the linkers
/// cargo uses write a new file, which the test of two builds in one
/// folder checks); a copy where links fail. Marks it used now, for
/// [`prune_runners`].
pub(crate) fn keep_runner(built: &Path, profile: &str, modules: &Path) -> Result<PathBuf, String> {
    let folder = modules.parent().ok_or("no folder for the module list")?;
    let kept = kept_runner(folder, profile);
    let tmp = folder.join(format!("tmp-{}-{profile}", std::process::id()));
    let io = |e: std::io::Error| format!("cannot keep {}: {e}", built.display());
    let _ = std::fs::remove_file(&tmp);
    if std::fs::hard_link(built, &tmp).is_err() {
        std::fs::copy(built, &tmp).map_err(io)?;
    }
    std::fs::rename(&tmp, &kept).map_err(io)?;
    std::fs::write(used_marker(folder, profile), b"").map_err(io)?;
    Ok(kept)
}

/// Removes the kept binaries (see [`keep_runner`]) of builds no grader has
/// used for an hour: a grading run is done with its binary within minutes
/// (every build, the TUI's too, marks its binary used again), and a
/// student who edits often keeps no more than an hour's builds.
pub(crate) fn prune_runners(sources: &Path) {
    let hour = std::time::Duration::from_secs(3600);
    let Ok(folders) = std::fs::read_dir(sources) else {
        return;
    };
    for folder in folders.flatten().map(|e| e.path()) {
        for profile in ["release", "debug"] {
            let used = used_marker(&folder, profile);
            let age = std::fs::metadata(&used)
                .and_then(|m| m.modified())
                .ok()
                .and_then(|t| t.elapsed().ok());
            if age.is_some_and(|a| a > hour) {
                let _ = std::fs::remove_file(kept_runner(&folder, profile));
                let _ = std::fs::remove_file(used);
            }
        }
    }
}
