//! Building the exercises crate (`raystep-exercises`, `chapters/`) for the
//! grader: the files that do not compile are found from the compiler's
//! messages, left out of the build (`RAYSTEP_BROKEN`, read by the crate's
//! `build.rs`), and reported with those messages, while the rest is built.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The repository root (where `Cargo.toml` and `chapters/` are).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// What building the exercises crate gave.
#[derive(Debug)]
pub struct Built {
    /// The `grade-student` binary.
    pub runner: PathBuf,
    /// Exercises left out because they do not compile, with the
    /// compiler's messages about them.
    pub broken: BTreeMap<String, String>,
}

/// Builds `raystep-exercises` with the exercise files under `dir`; an
/// exercise whose file (or whose call in the crate's table) draws a
/// compiler error is left out (`RAYSTEP_BROKEN`) and the crate rebuilt.
pub fn build_exercises(dir: &Path) -> Result<Built, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let bin_dir = exe
        .parent()
        .ok_or("no folder for the grader")?
        .to_path_buf();
    // `grade` lives in <target>/<profile>/: build beside it, same profile.
    let target = bin_dir.parent().ok_or("no target folder")?.to_path_buf();
    let release = !cfg!(debug_assertions);
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let dir = dir
        .canonicalize()
        .map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut broken: BTreeMap<String, String> = BTreeMap::new();
    for _round in 0..6 {
        let mut cmd = Command::new(&cargo);
        cmd.args([
            "build",
            "--quiet",
            "--color",
            "never",
            "-p",
            "raystep-exercises",
        ])
        .args(["--bin", "grade-student", "--manifest-path"])
        .arg(root().join("Cargo.toml"))
        .arg("--target-dir")
        .arg(&target)
        .env("RAYSTEP_EXERCISES_DIR", &dir)
        .env(
            "RAYSTEP_BROKEN",
            broken.keys().cloned().collect::<Vec<_>>().join(","),
        )
        .stdin(Stdio::null());
        if release {
            cmd.arg("--release");
        }
        let output = cmd.output().map_err(|e| format!("cannot run cargo: {e}"))?;
        let runner = bin_dir.join(format!("grade-student{}", std::env::consts::EXE_SUFFIX));
        if output.status.success() {
            return Ok(Built { runner, broken });
        }
        let stderr = String::from_utf8_lossy(&output.stderr);
        let (found, other) = attribute_errors(&stderr);
        let new: Vec<_> = found
            .into_iter()
            .filter(|(id, _)| !broken.contains_key(id))
            .collect();
        if new.is_empty() {
            return Err(format!(
                "cargo build failed and no exercise file is to blame:\n{}",
                if other.is_empty() {
                    stderr.to_string()
                } else {
                    other.join("\n")
                }
            ));
        }
        broken.extend(new);
    }
    Err("the exercises still do not compile after leaving out the broken files".into())
}

/// Splits cargo's error output into messages and assigns each to the
/// exercise it is about: by the file it points at
/// (`chN-…/exercises/<name>.rs`), or by the exercise's path in the crate's
/// table (`chN::<name>::`). Returns (by exercise id, the rest).
pub fn attribute_errors(stderr: &str) -> (BTreeMap<String, String>, Vec<String>) {
    let mut blocks: Vec<String> = Vec::new();
    for line in stderr.lines() {
        let starts = line.starts_with("error") || line.starts_with("warning");
        if starts || blocks.is_empty() {
            blocks.push(String::new());
        }
        let b = blocks.last_mut().expect("one block");
        b.push_str(line);
        b.push('\n');
    }
    let mut found: BTreeMap<String, String> = BTreeMap::new();
    let mut other = Vec::new();
    for b in blocks.into_iter().filter(|b| b.starts_with("error")) {
        if b.starts_with("error: could not compile") || b.starts_with("error: aborting") {
            continue;
        }
        match blame(&b) {
            Some((id, false)) => found.entry(id).or_default().push_str(&b),
            Some((id, true)) => {
                let text = found.entry(id).or_default();
                if text.is_empty() {
                    text.push_str(
                        "the signature of your function does not match the one shipped \
                         (keep its name, argument and return types); the grader calls it here:\n",
                    );
                }
                text.push_str(&b);
            }
            None => other.push(b),
        }
    }
    (found, other)
}

/// The exercise one compiler message is about, and whether it was found
/// through the crate's table (a changed signature) rather than its file.
fn blame(block: &str) -> Option<(String, bool)> {
    for line in block.lines() {
        let Some(at) = line.trim_start().strip_prefix("--> ") else {
            continue;
        };
        let path = at.replace('\\', "/");
        if let Some((before, after)) = path.split_once("/exercises/") {
            let chapter = before.rsplit('/').next()?.split('-').next()?;
            let name = after.split(".rs").next()?;
            if chapter.starts_with("ch") {
                return Some((format!("{chapter}/{name}"), false));
            }
        }
    }
    // A call in the crate's table: `chN::name::function`.
    let bytes = block.as_bytes();
    for (i, _) in block.match_indices("ch") {
        if i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_') {
            continue;
        }
        let rest = &block[i + 2..];
        let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
        let Some(tail) = rest[digits.len()..].strip_prefix("::") else {
            continue;
        };
        let name: String = tail
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if !digits.is_empty() && tail[name.len()..].starts_with("::") {
            return Some((format!("ch{digits}/{name}"), true));
        }
    }
    None
}
