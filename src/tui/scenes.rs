//! The scene list of the terminal UI: the built-in scene first, then every
//! `*.toml` file of a folder (normally `scenes/`), sorted by name. A scene
//! that fails to load stays in the list with its error, so the UI can show
//! why instead of stopping. The list appears at once: a file is only read
//! when its entry is first chosen (ten heavy scenes used to keep the screen
//! blank for 19 s while every one loaded).

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::SystemTime;

use crate::scene::Scene;

/// One entry of the scene list.
#[derive(Clone, Debug)]
pub struct SceneEntry {
    /// Name shown in the list (the file stem, or the built-in scene's name).
    pub name: String,
    /// Where it came from: a path, or `<built-in>`.
    pub source: String,
    /// The loaded scene, or the loading error as text (until the entry is
    /// loaded, a placeholder error: see `pending`).
    pub scene: Result<Arc<Scene>, String>,
    /// The file still to read, for an entry not chosen yet.
    pub pending: Option<PathBuf>,
    /// When the file read was last modified (`None` for the built-in
    /// scene, or a file whose time cannot be read): a later time means the
    /// file was edited ([`SceneEntry::edited`]), and it is read again.
    pub modified: Option<SystemTime>,
}

impl SceneEntry {
    /// The built-in default scene.
    pub fn builtin() -> SceneEntry {
        let scene = Scene::builtin();
        SceneEntry {
            name: format!("{} (built-in)", scene.name),
            source: scene.source.clone(),
            scene: Ok(Arc::new(scene)),
            pending: None,
            modified: None,
        }
    }

    /// Loads one scene file; a failure is kept as the entry's error.
    pub fn load(path: &Path) -> SceneEntry {
        let mut entry = SceneEntry::listed(path);
        entry.ensure_loaded();
        entry
    }

    /// An entry for a scene file, read when first chosen
    /// ([`SceneEntry::ensure_loaded`]).
    pub fn listed(path: &Path) -> SceneEntry {
        SceneEntry {
            name: path
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default(),
            source: path.display().to_string(),
            scene: Err("not loaded yet: it loads when chosen".into()),
            pending: Some(path.to_path_buf()),
            modified: None,
        }
    }

    /// The name a chapter knows the scene by: the file stem, or the
    /// built-in scene's own name (`cornell-box`).
    pub fn stem(&self) -> &str {
        match (&self.pending, &self.scene) {
            (None, Ok(scene)) if self.source.starts_with("<built-in>") => &scene.name,
            _ => Path::new(&self.source)
                .file_stem()
                .and_then(|s| s.to_str())
                .unwrap_or(&self.name),
        }
    }

    /// Reads the scene file if it has not been read yet, here and now.
    /// The terminal UI reads it in a thread instead ([`read_scene`] and
    /// [`SceneEntry::finish_loading`]), so a heavy scene never freezes it.
    pub fn ensure_loaded(&mut self) {
        if let Some(path) = self.pending.clone() {
            let read = read_scene(&path);
            self.finish_loading(&path, read);
        }
    }

    /// Takes what [`read_scene`] read from `path`, if the entry still
    /// waits for that file; whether it did.
    pub fn finish_loading(&mut self, path: &Path, read: Read) -> bool {
        if self.pending.as_deref() != Some(path) {
            return false;
        }
        self.pending = None;
        (self.scene, self.modified) = read;
        true
    }

    /// Whether its file was edited (or deleted, or made) since it was
    /// read: looks at the file's modification time on disk. The built-in
    /// scene and entries not read yet are never edited.
    pub fn edited(&self) -> bool {
        !(self.pending.is_some() || self.source.starts_with("<built-in>"))
            && modified(Path::new(&self.source)) != self.modified
    }

    /// Marks the entry to be read again (its file was [`edited`](Self::edited)).
    pub fn read_again(&mut self) {
        if !self.source.starts_with("<built-in>") {
            self.pending = Some(PathBuf::from(&self.source));
            self.scene = Err("reading the changed file…".into());
        }
    }
}

/// A scene file read: the scene or its error as text, and the file's
/// modification time.
pub type Read = (Result<Arc<Scene>, String>, Option<SystemTime>);

/// Reads the scene file at `path` (in any thread).
pub fn read_scene(path: &Path) -> Read {
    let when = modified(path);
    let scene = Scene::load(path).map(Arc::new).map_err(|e| e.to_string());
    (scene, when)
}

/// A file's modification time, if it can be read.
fn modified(path: &Path) -> Option<SystemTime> {
    std::fs::metadata(path).and_then(|m| m.modified()).ok()
}

/// The built-in scene, then every `*.toml` in `dir` (none if `dir` cannot
/// be read: the built-in scene is always there).
pub fn scene_list(dir: &Path) -> Vec<SceneEntry> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|e| e == "toml"))
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    std::iter::once(SceneEntry::builtin())
        .chain(files.iter().map(|p| SceneEntry::listed(p)))
        .collect()
}
