//! The grader's hints as data: `chapters/hints.toml`, which a teacher
//! edits without touching Rust, holds every exercise's three tiers of
//! hints and the hint for each symptom its check recognises. The checks
//! (Rust, in [`super::exercises`]) name exercises and symptoms; the words
//! shown for them are read from here. The file is built into the grader,
//! and [`problems`] (run by the tests) says where it and the checks
//! disagree.

use std::collections::BTreeMap;
use std::sync::OnceLock;

use super::exercise::{Exercise, Symptom};

/// The file, as built in.
pub const TEXT: &str = include_str!("../../chapters/hints.toml");
/// Its path in the repository, for messages.
pub const PATH: &str = "chapters/hints.toml";

/// The file's contents.
#[derive(Debug, Default, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Manifest {
    /// Per exercise id (`chN/name`), its hints.
    #[serde(default)]
    pub exercises: BTreeMap<String, Hints>,
}

/// One exercise's hints.
#[derive(Debug, Default, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Hints {
    /// A nudge (which slide, which idea), the idea worked out, the
    /// formula.
    pub hints: Vec<String>,
    /// Per symptom name, the hint shown when the check names it.
    #[serde(default)]
    pub symptoms: BTreeMap<String, String>,
}

/// The built-in manifest, parsed once; an error names the file, the line
/// and what is wrong.
pub fn manifest() -> Result<&'static Manifest, &'static str> {
    static PARSED: OnceLock<Result<Manifest, String>> = OnceLock::new();
    PARSED
        .get_or_init(|| parse(TEXT))
        .as_ref()
        .map_err(String::as_str)
}

/// Parses manifest text.
pub fn parse(text: &str) -> Result<Manifest, String> {
    toml::from_str(text).map_err(|e| toml_error(PATH, text, &e))
}

/// The line of `text` that byte `at` lies on (from 1).
pub(crate) fn line_at(text: &str, at: usize) -> usize {
    text[..at.min(text.len())].matches('\n').count() + 1
}

/// A TOML error in the grader's data file `file` (of text `text`), as
/// `file: line N: message`.
pub(crate) fn toml_error(file: &str, text: &str, e: &toml::de::Error) -> String {
    let at = e.span().map_or(String::new(), |s| {
        format!(" line {}:", line_at(text, s.start))
    });
    format!("{file}:{at} {}", e.message())
}

/// What to show where the manifest has no text: says where it belongs.
fn missing(what: String) -> &'static str {
    Box::leak(format!("(no hint: {PATH} has none for {what})").into_boxed_str())
}

impl Exercise {
    /// Its three tiers of hints.
    pub fn hints(&self) -> [&'static str; 3] {
        let id = self.id();
        let tiers = manifest().ok().and_then(|m| m.exercises.get(&id));
        std::array::from_fn(|i| match tiers.and_then(|t| t.hints.get(i)) {
            Some(h) => h.as_str(),
            None => missing(format!("{id}, tier {}", i + 1)),
        })
    }

    /// The hint for `symptom`, as this exercise's check names it: this
    /// exercise's, else that of another exercise of its chapter that
    /// lists the symptom (checks of one chapter share some).
    pub fn symptom_hint(&self, symptom: &Symptom) -> &'static str {
        let id = self.id();
        let Ok(m) = manifest() else {
            return missing(format!("{id}, symptom \"{}\"", symptom.name));
        };
        let chapter = format!("ch{}/", self.chapter);
        let own = m.exercises.get(&id).into_iter();
        let siblings = m
            .exercises
            .iter()
            .filter(|(k, _)| k.starts_with(&chapter))
            .map(|(_, v)| v);
        match own
            .chain(siblings)
            .find_map(|t| t.symptoms.get(symptom.name))
        {
            Some(h) => h.as_str(),
            None => missing(format!("{id}, symptom \"{}\"", symptom.name)),
        }
    }
}

/// Where `manifest` and `exercises` disagree: an exercise without three
/// non-empty tiers, a symptom a check names without a hint, and an
/// exercise or symptom the manifest names that does not exist.
pub fn problems(manifest: &Manifest, exercises: &[Exercise]) -> Vec<String> {
    let mut out = Vec::new();
    for ex in exercises {
        let id = ex.id();
        let Some(h) = manifest.exercises.get(&id) else {
            out.push(format!("{PATH}: no [exercises.\"{id}\"]"));
            continue;
        };
        if h.hints.len() != 3 || h.hints.iter().any(|t| t.trim().is_empty()) {
            out.push(format!("{PATH}: {id} needs three hints, none empty"));
        }
        for s in ex.symptoms {
            if !h.symptoms.contains_key(s.name) {
                out.push(format!(
                    "{PATH}: {id} has no hint for symptom \"{}\"",
                    s.name
                ));
            }
        }
        for name in h.symptoms.keys() {
            if !ex.symptoms.iter().any(|s| s.name == name) {
                out.push(format!(
                    "{PATH}: {id} names symptom \"{name}\", which its check does not"
                ));
            }
        }
    }
    for id in manifest.exercises.keys() {
        if !exercises.iter().any(|e| e.id() == *id) {
            out.push(format!("{PATH}: exercise \"{id}\" does not exist"));
        }
    }
    out
}
