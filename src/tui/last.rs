//! What the UI remembers between runs: the last chapter, scene and view,
//! in a small TOML file in the user's config folder
//! (`$XDG_CONFIG_HOME/raystep/last.toml`, else
//! `~/.config/raystep/last.toml`; [`CONFIG_DIR_ENV`] overrides the folder,
//! which is how the tests keep away from the real home). A file that
//! cannot be read or parsed is ignored: the UI opens as if there were
//! none, and the warning is printed after the terminal is restored.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

/// Set this environment variable to a folder to keep `last.toml` there
/// instead of the user's config folder.
pub const CONFIG_DIR_ENV: &str = "RAYSTEP_CONFIG_DIR";

/// The file's name in its folder.
pub const FILE_NAME: &str = "last.toml";

/// The last chapter, scene and view.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Last {
    /// The chapter's lecture number.
    pub chapter: u32,
    /// The scene: its file as the list shows it, or `<built-in>`.
    pub scene: String,
    /// The view's name (`image`, `depth`, …).
    pub view: String,
}

/// Where `last.toml` lives, from the environment `env` gives: the folder
/// [`CONFIG_DIR_ENV`] names, else `$XDG_CONFIG_HOME/raystep`, else
/// `$HOME/.config/raystep`; `None` when none of them is set.
pub fn path(env: &dyn Fn(&str) -> Option<String>) -> Option<PathBuf> {
    let set = |k: &str| env(k).filter(|v| !v.is_empty()).map(PathBuf::from);
    let dir = set(CONFIG_DIR_ENV)
        .or_else(|| set("XDG_CONFIG_HOME").map(|d| d.join("raystep")))
        .or_else(|| set("HOME").map(|d| d.join(".config").join("raystep")))?;
    Some(dir.join(FILE_NAME))
}

/// Reads `file`: `Ok(None)` when there is none, an error (to print as a
/// warning) when it cannot be read or is not a valid `last.toml`.
pub fn load(file: &Path) -> Result<Option<Last>, String> {
    let text = match std::fs::read_to_string(file) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(format!("{}: {e}", file.display())),
    };
    toml::from_str(&text)
        .map(Some)
        .map_err(|e| format!("{}: {}", file.display(), e.message()))
}

/// Writes `last` to `file`, making its folder.
pub fn store(file: &Path, last: &Last) -> Result<(), String> {
    let text = toml::to_string(last).map_err(|e| e.to_string())?;
    if let Some(dir) = file.parent() {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(file, text).map_err(|e| format!("{}: {e}", file.display()))
}

/// What the UI shows now, to remember.
pub fn of(app: &super::app::App) -> Option<Last> {
    Some(Last {
        chapter: app.current_chapter()?.info().number,
        scene: app.current_scene()?.source.clone(),
        view: app.view_name().to_string(),
    })
}
