//! How the grader writes into its output folder (`out/grade/`): only into
//! a real folder, never through a link, and every file whole or not at
//! all (a fresh temporary of an unpredictable name, created exclusively,
//! renamed into place: see [`crate::core::film::write_atomically`]). A
//! link or anything but a regular file where a file of the grader's should
//! go is refused with a message, and left as it is.

use std::path::Path;

/// Creates `dir` (and its parents) and checks that it is a folder and not
/// a link to one.
pub fn ensure_dir(dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    match std::fs::symlink_metadata(dir) {
        Ok(m) if m.file_type().is_symlink() => Err(format!(
            "{} is a link: the grader writes only into a real folder (remove the link)",
            dir.display()
        )),
        Ok(m) if m.is_dir() => Ok(()),
        Ok(_) => Err(format!("{} is not a folder", dir.display())),
        Err(e) => Err(format!("{}: {e}", dir.display())),
    }
}

/// `Err` when something other than a regular file (a link, a folder, a
/// FIFO) is at `path`, where the grader is about to write a file.
pub fn refuse_in_way(path: &Path) -> Result<(), String> {
    match std::fs::symlink_metadata(path) {
        Ok(m) if !m.file_type().is_file() => Err(format!(
            "{} exists and is not a regular file (a link?): the grader does not write \
             through it; remove it",
            path.display()
        )),
        _ => Ok(()),
    }
}

/// Writes `bytes` to `path` whole, in a real folder, refusing whatever is
/// in its way ([`refuse_in_way`]).
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), String> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        ensure_dir(dir)?;
    }
    refuse_in_way(path)?;
    crate::core::film::write_atomically(path, |tmp| {
        std::fs::write(tmp, bytes).map_err(|e| e.to_string())
    })
    .map_err(|e| e.to_string())
}
