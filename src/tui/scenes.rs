//! The scene list of the terminal UI: the built-in scene first, then every
//! `*.toml` file of a folder (normally `scenes/`), sorted by name. A scene
//! that fails to load stays in the list with its error, so the UI can show
//! why instead of stopping.

use std::path::Path;
use std::sync::Arc;

use crate::scene::Scene;

/// One entry of the scene list.
#[derive(Clone, Debug)]
pub struct SceneEntry {
    /// Name shown in the list (the file stem, or the built-in scene's name).
    pub name: String,
    /// Where it came from: a path, or `<built-in>`.
    pub source: String,
    /// The loaded scene, or the loading error as text.
    pub scene: Result<Arc<Scene>, String>,
}

impl SceneEntry {
    /// The built-in default scene.
    pub fn builtin() -> SceneEntry {
        let scene = Scene::builtin();
        SceneEntry {
            name: format!("{} (built-in)", scene.name),
            source: scene.source.clone(),
            scene: Ok(Arc::new(scene)),
        }
    }

    /// Loads one scene file; a failure is kept as the entry's error.
    pub fn load(path: &Path) -> SceneEntry {
        SceneEntry {
            name: path
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default(),
            source: path.display().to_string(),
            scene: Scene::load(path).map(Arc::new).map_err(|e| e.to_string()),
        }
    }
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
        .chain(files.iter().map(|p| SceneEntry::load(p)))
        .collect()
}
