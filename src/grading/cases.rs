//! The checks' hand-worked cases as data: `src/grading/cases.toml` holds,
//! per exercise, the inputs of each case worked out by hand, the value
//! expected (where a closed form gives it; otherwise the check asks
//! raystep's reference) and what the case is about, in the way Nori's
//! test scenes list inputs, expected values and tolerances. A teacher adds
//! or changes a case there without touching Rust. What stays in Rust is
//! what cannot be a table: the inputs drawn anew every run over the whole
//! contract (their seed is never printed), the models of mistakes that
//! name a symptom, and the instrumented trees and furnaces.
//!
//! The file is built into the grader, not read from the student's folder:
//! a student's files can never change what they are checked against.
//! `cargo grade` names a broken file before it grades anything
//! ([`problems`]), and a check whose cases do not read as its kind says so
//! in its verdict, as a fault of the course's, not the student's.

use std::sync::OnceLock;

use serde::de::DeserializeOwned;

use super::exercise::Check;
use super::manifest::{line_at, toml_error};

/// The file, as built in.
pub const TEXT: &str = include_str!("cases.toml");
/// Its path in the repository, for messages.
pub const PATH: &str = "src/grading/cases.toml";

/// The whole file, parsed once.
fn table() -> Result<&'static toml::Table, &'static str> {
    static PARSED: OnceLock<Result<toml::Table, String>> = OnceLock::new();
    PARSED
        .get_or_init(|| toml::from_str(TEXT).map_err(|e| toml_error(PATH, TEXT, &e)))
        .as_ref()
        .map_err(String::as_str)
}

/// The line in `text` of the `k`-th (from 0) `[["id"]]` header, for
/// messages.
fn line_of(text: &str, id: &str, k: usize) -> usize {
    let header = format!("[[\"{id}\"]]");
    text.match_indices(&header)
        .nth(k)
        .map_or(0, |(at, _)| line_at(text, at))
}

/// One hand-worked case: what it is about (its `why`, shown when it
/// fails) and the rest of its table, read as the check's own kind.
#[derive(Debug)]
pub struct Case<T> {
    /// What the case is about.
    pub why: String,
    /// Its inputs (and expected value), as the check reads them.
    pub case: T,
}

/// The hand-worked cases of exercise `id` (`chN/name`), one per
/// `[["chN/name"]]` table of the built-in file, each with its `why` and
/// the rest read as a `T` (whose fields are the table's other keys). An
/// error names the file, the line and what is wrong.
pub fn of<T: DeserializeOwned>(id: &str) -> Result<Vec<Case<T>>, String> {
    read(table().map_err(str::to_string)?, TEXT, id)
}

/// [`of`] on a file's `text` (a teacher's draft, a test's).
pub fn of_text<T: DeserializeOwned>(text: &str, id: &str) -> Result<Vec<Case<T>>, String> {
    let parsed: toml::Table = toml::from_str(text).map_err(|e| toml_error(PATH, text, &e))?;
    read(&parsed, text, id)
}

fn read<T: DeserializeOwned>(
    all: &toml::Table,
    text: &str,
    id: &str,
) -> Result<Vec<Case<T>>, String> {
    let Some(list) = all.get(id).and_then(toml::Value::as_array) else {
        return Err(format!("{PATH}: no [[\"{id}\"]] cases"));
    };
    let one = |value: &toml::Value| {
        let mut table = value.as_table().cloned().unwrap_or_default();
        let why = match table.remove("why") {
            Some(toml::Value::String(why)) => why,
            _ => return Err("no `why = \"…\"` (what the case is about)".to_string()),
        };
        let case = T::deserialize(toml::Value::Table(table))
            .map_err(|e| e.message().trim_end().to_string())?;
        Ok(Case { why, case })
    };
    list.iter()
        .enumerate()
        .map(|(k, value)| {
            one(value).map_err(|e| {
                format!(
                    "{PATH}: line {}: case {} of {id}: {e}",
                    line_of(text, id, k),
                    k + 1
                )
            })
        })
        .collect()
}

/// The worst of exercise `id`'s hand-worked cases as `judge` scores them
/// (`(error, what it saw)`; a NaN counts as infinite), the detail led by
/// the case's `why`; `(0, "all cases match")` when none is off. `Err`: the
/// verdict for cases that do not read ([`unreadable`]).
pub fn worst<T: DeserializeOwned>(
    id: &str,
    mut judge: impl FnMut(&T) -> (f64, String),
) -> Result<(f64, String), Check> {
    let cases = of::<T>(id).map_err(unreadable)?;
    Ok(super::exercises::worst_of(cases.iter().map(|c| {
        let (error, what) = judge(&c.case);
        (error, format!("{}: {what}", c.why))
    })))
}

/// What is wrong with the built-in file ([`problems_in`]).
pub fn problems(ids: &[String]) -> Vec<String> {
    match table() {
        Ok(t) => problems_in(t, ids),
        Err(e) => vec![e.to_string()],
    }
}

/// What is wrong with a parsed case file: a table that names no exercise
/// in `ids`, or is not a list of cases.
pub fn problems_in(all: &toml::Table, ids: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    for (key, value) in all {
        if !ids.contains(key) {
            out.push(format!("{PATH}: exercise \"{key}\" does not exist"));
        } else if !value
            .as_array()
            .is_some_and(|a| a.iter().all(toml::Value::is_table))
        {
            out.push(format!(
                "{PATH}: \"{key}\" must be a list of [[\"{key}\"]] tables"
            ));
        }
    }
    out
}

/// A 3-vector as the file writes it.
pub type V3 = [f32; 3];

/// `v` as a vector.
pub fn v3(v: V3) -> glam::Vec3 {
    glam::Vec3::from_array(v)
}

/// `v` as a unit vector (cases may write a direction unnormalised, as
/// `[1, 0, 1]`).
pub fn unit(v: V3) -> glam::Vec3 {
    glam::Vec3::from_array(v).normalize()
}

/// The verdict of a check whose cases in the file do not read (`error`,
/// from [`of`]): a failure that says it is the course's fault, not the
/// student's.
pub fn unreadable(error: String) -> Check {
    Check {
        error: f64::INFINITY,
        tolerance: 0.0,
        detail: format!(
            "the grader's own case file is broken (not your code; tell your teacher): {error}"
        ),
        images: None,
        symptom: None,
    }
}
