//! Building the exercises crate (`raystep-exercises`, `chapters/`) for the
//! grader: the files that do not compile are found from the compiler's
//! messages, left out of the build (`RAYSTEP_BROKEN`, read by the crate's
//! `build.rs`), and reported with those messages, while the rest is built.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::AtomicBool;

use crate::grading::child::{run_limited, Ran};

/// The repository root (where `Cargo.toml` and `chapters/` are).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The folder of chapter folders whose `exercises/` the grader builds:
/// `$RAYSTEP_EXERCISES_DIR` when set (the tests point it at a fresh copy of
/// the shipped stubs), else this repository's `chapters/`.
pub fn exercises_dir() -> PathBuf {
    std::env::var_os("RAYSTEP_EXERCISES_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root().join("chapters"))
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

/// Where the exercises crate is built: a target folder and a profile.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Place {
    /// The target folder (`target/`).
    pub target: PathBuf,
    /// The release profile (else the dev profile, in `debug/`).
    pub release: bool,
}

impl Place {
    /// Beside the running program, with its profile: the grader, the TUI
    /// and the chapter binaries live in `<target>/<profile>/`, a test in
    /// `<target>/<profile>/deps/`. Building there reuses the library
    /// they were built with.
    pub fn current() -> Result<Place, String> {
        let exe = std::env::current_exe().map_err(|e| e.to_string())?;
        let mut dir = exe.parent().ok_or("no folder for this program")?;
        if dir.file_name().is_some_and(|n| n == "deps") {
            dir = dir.parent().ok_or("no profile folder")?;
        }
        Ok(Place {
            target: dir.parent().ok_or("no target folder")?.to_path_buf(),
            release: !cfg!(debug_assertions),
        })
    }

    /// The `grade-student` binary a build here makes.
    pub fn runner(&self) -> PathBuf {
        let profile = if self.release { "release" } else { "debug" };
        self.target
            .join(profile)
            .join(format!("grade-student{}", std::env::consts::EXE_SUFFIX))
    }
}

/// Builds `raystep-exercises` with the exercise files under `dir`, beside
/// the running program ([`Place::current`]); see [`build_exercises_in`].
pub fn build_exercises(dir: &Path) -> Result<Built, String> {
    build_exercises_in(dir, &Place::current()?, None)
}

/// Builds `raystep-exercises` with the exercise files under `dir` at
/// `place`; an exercise whose file (or whose call in the crate's table)
/// draws a compiler error is left out (`RAYSTEP_BROKEN`) and the crate
/// rebuilt. Setting `cancel` stops cargo and returns an error.
pub fn build_exercises_in(
    dir: &Path,
    place: &Place,
    cancel: Option<&AtomicBool>,
) -> Result<Built, String> {
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
        .arg(&place.target)
        .env("RAYSTEP_EXERCISES_DIR", &dir)
        .env(
            "RAYSTEP_BROKEN",
            broken.keys().cloned().collect::<Vec<_>>().join(","),
        );
        if place.release {
            cmd.arg("--release");
        }
        let (ok, stderr) = match run_limited(&mut cmd, b"", None, cancel) {
            Ok(Ran::Exited { status, stderr, .. }) => (status.success(), stderr),
            Ok(_) => return Err("the build was cancelled".into()),
            Err(e) => return Err(format!("cannot run cargo: {e}")),
        };
        if ok {
            let runner = place.runner();
            return Ok(Built { runner, broken });
        }
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
