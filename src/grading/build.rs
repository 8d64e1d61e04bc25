//! Building the student's exercise files for the grader. The grader
//! copies each file, by content, into a folder of its own named by a hash
//! of all of them (`<target>/raystep-grade/<hash>/`), with the list of
//! modules the exercises crate (`src/grading/crates/student`) includes,
//! and builds the student's process, `raystep-grade-child`, from its own
//! crates: nothing of the student's but the exercise files is built or
//! run, and a file's date never decides whether it is built again (its
//! content does). Each build runs its own link to the binary it made, kept
//! in that folder ([`crate::kept`]): graders that share a target folder
//! (the terminal UI's student mode and `cargo grade` at once) never run
//! each other's build.
//! A file that uses what an exercise may not ([`crate::source_rules`]) or
//! that does not compile is replaced by its shipped stub and reported with
//! the compiler's messages, while the others are built.

use std::collections::BTreeMap;
use std::hash::Hasher;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::AtomicBool;

use crate::child::{run_limited, Ran};
use crate::core::project_root;
use crate::kept::{keep_runner, prune_runners, BuildLock};
use crate::shipped::{Stub, STUBS};
use crate::source_rules::refusals;

/// The folder of chapter folders whose `exercises/` the grader builds:
/// `$RAYSTEP_EXERCISES_DIR` when set (the tests point it at a fresh copy of
/// the shipped stubs), else this repository's `chapters/`.
pub fn exercises_dir() -> PathBuf {
    std::env::var_os("RAYSTEP_EXERCISES_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| project_root().join("chapters"))
}

/// What building the student's process gave.
#[derive(Debug)]
pub struct Built {
    /// The `raystep-grade-child` binary this build made, kept beside the
    /// copies of the files it was built from (no later build replaces it).
    pub runner: PathBuf,
    /// Exercises left out (their shipped stub built instead), with why:
    /// the compiler's messages, or what the file may not use.
    pub broken: BTreeMap<String, String>,
}

/// Where the student's process is built: a target folder and a profile.
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

    /// The profile's name, which is also its folder: `release` or `debug`.
    pub fn profile(&self) -> &'static str {
        if self.release {
            "release"
        } else {
            "debug"
        }
    }

    /// The `raystep-grade-child` binary a build here makes (the next build
    /// replaces it: a grader runs its own link, [`Built::runner`]).
    pub fn runner(&self) -> PathBuf {
        self.target.join(self.profile()).join(format!(
            "raystep-grade-child{}",
            std::env::consts::EXE_SUFFIX
        ))
    }
}

/// Builds the student's process with the exercise files under `dir`,
/// beside the running program ([`Place::current`]); see
/// [`build_exercises_in`].
pub fn build_exercises(dir: &Path) -> Result<Built, String> {
    build_exercises_in(dir, &Place::current()?, None)
}

/// The files the exercises crate is built from: each exercise's text (the
/// student's, or the shipped stub where it is left out), by id.
fn texts(dir: &Path, broken: &mut BTreeMap<String, String>) -> Vec<(Stub, String)> {
    STUBS
        .iter()
        .map(|stub| {
            let path = stub.path_in(dir);
            let id = stub.id();
            let text = match std::fs::read(&path) {
                Err(e) => {
                    broken
                        .entry(id.clone())
                        .or_insert_with(|| format!("cannot read {}: {e}", path.display()));
                    String::new()
                }
                Ok(bytes) => match String::from_utf8(bytes) {
                    Ok(t) => t,
                    Err(_) => {
                        broken
                            .entry(id.clone())
                            .or_insert_with(|| format!("{} is not UTF-8 text", path.display()));
                        String::new()
                    }
                },
            };
            if !broken.contains_key(&id) {
                let refused = refusals(&text);
                if !refused.is_empty() {
                    let shown = format!("{}/exercises/{}.rs", stub.folder, stub.name);
                    let lines: Vec<String> = refused
                        .iter()
                        .map(|r| {
                            format!(
                                "error: {shown}:{}: your file may not use {}",
                                r.line, r.what
                            )
                        })
                        .collect();
                    broken.insert(id.clone(), lines.join("\n") + "\n");
                }
            }
            let text = if broken.contains_key(&id) {
                stub.text.to_string()
            } else {
                text
            };
            (*stub, text)
        })
        .collect()
}

/// Writes the exercise files `files` and the module list into a folder
/// named by their hash under `root` (kept if it is there already, written
/// whole or not at all otherwise); returns the module list's path.
fn write_sources(root: &Path, files: &[(Stub, String)]) -> Result<PathBuf, String> {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for (stub, text) in files {
        h.write(stub.folder.as_bytes());
        h.write(stub.name.as_bytes());
        h.write(text.as_bytes());
        h.write_u8(0);
    }
    let dir = root.join(format!("{:016x}", h.finish()));
    let modules = dir.join("modules.rs");
    if modules.is_file() {
        return Ok(modules);
    }
    let io =
        |e: std::io::Error| format!("cannot write the grader's copy in {}: {e}", root.display());
    std::fs::create_dir_all(root).map_err(io)?;
    let tmp = root.join(format!("tmp-{}-{:016x}", std::process::id(), h.finish()));
    let _ = std::fs::remove_dir_all(&tmp);
    let mut list = String::from("// Written by the grader: the exercise files, as copied.\n");
    let mut chapter = "";
    for (stub, text) in files {
        let ch = stub.folder.split('-').next().unwrap_or(stub.folder);
        if ch != chapter {
            if !chapter.is_empty() {
                list += "}\n";
            }
            list += &format!("pub mod {ch} {{\n");
            chapter = ch;
        }
        let file = tmp
            .join(stub.folder)
            .join("exercises")
            .join(format!("{}.rs", stub.name));
        std::fs::create_dir_all(file.parent().unwrap_or(&tmp)).map_err(io)?;
        std::fs::write(&file, text).map_err(io)?;
        let final_path = dir
            .join(stub.folder)
            .join("exercises")
            .join(format!("{}.rs", stub.name));
        list += &format!(
            "    #[path = {:?}]\n    pub mod {};\n",
            final_path.display().to_string(),
            stub.name
        );
    }
    list += "}\n";
    std::fs::write(tmp.join("modules.rs"), list).map_err(io)?;
    match std::fs::rename(&tmp, &dir) {
        Ok(()) => Ok(modules),
        // Another grader wrote the same folder first: the same content.
        Err(_) if modules.is_file() => {
            let _ = std::fs::remove_dir_all(&tmp);
            Ok(modules)
        }
        Err(e) => Err(io(e)),
    }
}

/// Builds the student's process with the exercise files under `dir` at
/// `place`; an exercise whose file draws a compiler error is replaced by
/// its stub and the crate rebuilt. Setting `cancel` stops cargo and
/// returns an error.
pub fn build_exercises_in(
    dir: &Path,
    place: &Place,
    cancel: Option<&AtomicBool>,
) -> Result<Built, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let dir = dir
        .canonicalize()
        .map_err(|e| format!("{}: {e}", dir.display()))?;
    let sources = place.target.join("raystep-grade");
    // One grader builds here at a time, from its first build to its own
    // link to the binary that build made: the binary cargo writes is one
    // file for every grader of this target folder, and another grader's
    // build would replace it while this one still starts it.
    let _building = BuildLock::take(&sources, cancel)?;
    let mut broken: BTreeMap<String, String> = BTreeMap::new();
    for _round in 0..STUBS.len() + 1 {
        let files = texts(&dir, &mut broken);
        let modules = write_sources(&sources, &files)?;
        let mut cmd = Command::new(&cargo);
        cmd.args([
            "build",
            "--quiet",
            "--color",
            "never",
            "-p",
            "raystep-grade-child",
        ])
        .arg("--manifest-path")
        .arg(project_root().join("Cargo.toml"))
        .arg("--target-dir")
        .arg(&place.target)
        .env("RAYSTEP_GRADE_MODULES", &modules);
        if place.release {
            cmd.arg("--release");
        }
        let (ok, stderr) = match run_limited(&mut cmd, b"", None, cancel) {
            Ok(Ran::Exited { status, stderr, .. }) => (status.success(), stderr),
            Ok(_) => return Err("the build was cancelled".into()),
            Err(e) => return Err(format!("cannot run cargo: {e}")),
        };
        if ok {
            let runner = keep_runner(&place.runner(), place.profile(), &modules)?;
            prune_runners(&sources);
            return Ok(Built { runner, broken });
        }
        let copies = sources.display().to_string();
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
        for (id, message) in new {
            // Name the student's file, not the grader's copy of it.
            broken.insert(id, strip_copies(&message, &copies));
        }
    }
    Err("the exercises still do not compile after leaving out the broken files".into())
}

/// `message` with the grader's copies' folder (`…/raystep-grade/<hash>/`)
/// taken out of its paths, which then start at the chapter folder.
fn strip_copies(message: &str, copies: &str) -> String {
    message
        .lines()
        .map(|line| match line.find(copies) {
            Some(i) => {
                let rest = &line[i + copies.len()..];
                // Past `/<hash>/`.
                let rest = rest.trim_start_matches('/');
                let rest = rest.split_once('/').map_or(rest, |(_, r)| r);
                format!("{}{rest}", &line[..i])
            }
            None => line.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
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
