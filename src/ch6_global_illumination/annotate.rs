//! Records each stored reference's scene content hash in its text file
//! (`ch6 --annotate-references`): the stored references are matched to a
//! scene by it ([`super::reference`]).

use std::path::{Path, PathBuf};

use super::reference::meta_value;
use crate::core::error::{Error, Result};
use crate::core::film::write_atomically;
use crate::scene::Scene;

/// Records in every reference's text file in `dir` the content hash of its
/// scene (`<scenes>/<scene>.toml`) as a `content = …` line; returns each
/// file and hash (`ch6 --annotate-references`: after a change of what the
/// hash covers that left the pictures as they were).
pub fn annotate_references(dir: &Path, scenes: &Path) -> Result<Vec<(PathBuf, String)>> {
    let mut texts: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| Error::io(dir, e))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "txt"))
        .collect();
    texts.sort();
    let mut done = Vec::new();
    for path in texts {
        let meta = std::fs::read_to_string(&path).map_err(|e| Error::io(&path, e))?;
        let (Some(name), Some(w), Some(h)) = (
            meta_value(&meta, "scene"),
            meta_value(&meta, "width").and_then(|v| v.parse::<u32>().ok()),
            meta_value(&meta, "height").and_then(|v| v.parse::<u32>().ok()),
        ) else {
            continue; // a text file that is not a reference's
        };
        let scene = Scene::load(&scenes.join(format!("{name}.toml")))?.with_resolution(w, h)?;
        let hash = scene.content_hash();
        let mut lines: Vec<String> = meta
            .lines()
            .filter(|l| l.split_once('=').is_none_or(|(k, _)| k.trim() != "content"))
            .map(String::from)
            .collect();
        let at = lines
            .iter()
            .position(|l| l.split_once('=').is_some_and(|(k, _)| k.trim() == "scene"))
            .map_or(0, |i| i + 1);
        lines.insert(at, format!("content = {hash}"));
        let text = lines.join("\n") + "\n";
        write_atomically(&path, |tmp| {
            std::fs::write(tmp, &text).map_err(|e| e.to_string())
        })?;
        done.push((path, hash));
    }
    Ok(done)
}
