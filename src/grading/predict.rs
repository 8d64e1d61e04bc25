//! Predict questions: a number or a choice the student commits to before
//! reading on ("how many samples halve the error?"), answered in
//! `chapters/predictions.toml` and marked by `cargo grade --predict`, which
//! explains each answered question. The questions, their answers and
//! explanations are data a teacher edits (`chapters/questions.toml`, built
//! in); the student's sheet repeats each question without its answer.
//!
//! No student code runs here: the sheet is data, read by the grader.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::OnceLock;

use super::manifest::{line_at, toml_error};
use crate::core::table::wrap;

/// The question bank, as built in.
pub const TEXT: &str = include_str!("../../chapters/questions.toml");
/// Its path in the repository, for messages.
pub const PATH: &str = "chapters/questions.toml";
/// The student's sheet, inside the exercises folder (`chapters/`).
pub const SHEET: &str = "predictions.toml";
/// The sheet as shipped (the blank one: [`blank_sheet`] of the bank; a
/// test keeps the two the same). The book includes its chapters from this
/// copy, never from the student's `chapters/predictions.toml`.
pub const SHIPPED: &str = include_str!("shipped/predictions.toml");
/// The largest sheet read: a sheet of every question fits in a tenth.
const MAX_SHEET: u64 = 256 * 1024;

/// The bank: one `[[question]]` table each.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Bank {
    /// The questions, in course order.
    pub question: Vec<Question>,
}

/// One predict question.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Question {
    /// `chN/short-name`.
    pub id: String,
    /// N.
    pub chapter: u32,
    /// The question as the student reads it.
    pub ask: String,
    /// The options of a choice question (lettered a, b, ...); none for a
    /// number.
    #[serde(default)]
    pub choices: Vec<String>,
    /// The right letters, or the number.
    pub answer: Answer,
    /// How far off a number may be, relative.
    #[serde(default)]
    pub tolerance: f64,
    /// Why, shown once answered.
    pub explain: String,
}

/// A question's answer.
#[derive(Clone, Debug, PartialEq, serde::Deserialize)]
#[serde(untagged)]
pub enum Answer {
    /// A number.
    Number(f64),
    /// The letters of every right option.
    Letters(String),
}

/// How one answer on the sheet stands.
#[derive(Clone, Debug, PartialEq)]
pub enum Mark {
    /// Left empty.
    Unanswered,
    /// Right.
    Right,
    /// Wrong.
    Wrong,
    /// Not an answer of the question's kind: why, with the sheet's line.
    Unreadable(String),
}

/// The built-in bank, parsed once; an error names the file and line.
pub fn bank() -> Result<&'static Bank, &'static str> {
    static PARSED: OnceLock<Result<Bank, String>> = OnceLock::new();
    PARSED
        .get_or_init(|| parse_bank(TEXT))
        .as_ref()
        .map_err(String::as_str)
}

/// Parses bank text.
pub fn parse_bank(text: &str) -> Result<Bank, String> {
    toml::from_str(text).map_err(|e| toml_error(PATH, text, &e))
}

/// `(chapter, name)` of a well-formed id `chN/short-name`.
fn split_id(id: &str) -> Option<(u32, &str)> {
    let (ch, name) = id.strip_prefix("ch")?.split_once('/')?;
    let kebab = !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-');
    Some((ch.parse().ok()?, name)).filter(|_| kebab)
}

/// The letters of an answer, sorted, if every one names an option.
fn letters(text: &str, options: usize) -> Result<Vec<char>, String> {
    let mut out: Vec<char> = text
        .chars()
        .filter(|c| !c.is_whitespace() && *c != ',')
        .map(|c| c.to_ascii_lowercase())
        .collect();
    out.sort_unstable();
    out.dedup();
    let last = (b'a' + options.saturating_sub(1) as u8) as char;
    match out.iter().find(|c| !('a'..=last).contains(*c)) {
        Some(c) => Err(format!(
            "`{c}` is not an option: expected letters a to {last}"
        )),
        None if out.is_empty() => Err(format!("expected letters a to {last}")),
        None => Ok(out),
    }
}

/// Where the bank is wrong: ids, chapters, answers that are not among the
/// choices, numbers without a tolerance that makes sense.
pub fn problems(bank: &Bank) -> Vec<String> {
    let mut out = Vec::new();
    let mut seen = BTreeMap::new();
    for q in &bank.question {
        let id = &q.id;
        match split_id(id) {
            Some((c, _)) if c == q.chapter && (1..=6).contains(&c) => {}
            _ => out.push(format!(
                "{PATH}: \"{id}\": expected an id chN/short-name with N = its chapter, 1 to 6"
            )),
        }
        if seen.insert(id.clone(), ()).is_some() {
            out.push(format!("{PATH}: \"{id}\" appears twice"));
        }
        match (&q.answer, q.choices.len()) {
            (Answer::Letters(_), 0..=1) => {
                out.push(format!("{PATH}: \"{id}\" needs two choices or more"));
            }
            (Answer::Letters(l), n) => {
                if let Err(e) = letters(l, n) {
                    out.push(format!("{PATH}: \"{id}\": its answer: {e}"));
                }
            }
            (Answer::Number(_), 0) if q.tolerance.is_finite() && q.tolerance >= 0.0 => {}
            (Answer::Number(_), 0) => {
                out.push(format!("{PATH}: \"{id}\": tolerance must be 0 or more"));
            }
            (Answer::Number(_), _) => out.push(format!(
                "{PATH}: \"{id}\": a number answer with choices; give the letters"
            )),
        }
        if q.ask.trim().is_empty() || q.explain.trim().is_empty() {
            out.push(format!("{PATH}: \"{id}\" needs its ask and explain"));
        }
    }
    out
}

/// Marks one answer `given` (as the sheet holds it) to question `q`.
pub fn mark(q: &Question, given: &toml::Value) -> Mark {
    let empty = matches!(given, toml::Value::String(s) if s.trim().is_empty());
    if empty {
        return Mark::Unanswered;
    }
    match &q.answer {
        Answer::Letters(right) => {
            let Some(text) = given.as_str() else {
                return Mark::Unreadable("expected letters in quotes, like \"b\"".into());
            };
            match (
                letters(text, q.choices.len()),
                letters(right, q.choices.len()),
            ) {
                (Ok(g), Ok(r)) if g == r => Mark::Right,
                (Ok(_), _) => Mark::Wrong,
                (Err(e), _) => Mark::Unreadable(e),
            }
        }
        Answer::Number(right) => {
            let number = match given {
                toml::Value::Integer(i) => Some(*i as f64),
                toml::Value::Float(f) => Some(*f),
                toml::Value::String(s) => s.trim().parse::<f64>().ok(),
                _ => None,
            };
            match number.filter(|x| x.is_finite()) {
                None => Mark::Unreadable("expected a number, like 0.25".into()),
                Some(x) if (x - right).abs() <= q.tolerance * right.abs() => Mark::Right,
                Some(_) => Mark::Wrong,
            }
        }
    }
}

/// The student's sheet, read: every question's mark, in bank order.
pub struct Sheet {
    /// Per question of the bank, its mark.
    pub marks: Vec<(&'static Question, Mark)>,
    /// What the sheet holds that is no question's answer, by line.
    pub strays: Vec<String>,
}

/// One `[chN.name]` table of the sheet.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    answer: toml::Spanned<toml::Value>,
}

/// Reads and marks the sheet in `dir` against `bank`. An error names the
/// file (and line) and what was expected.
pub fn read_sheet(dir: &Path, bank: &'static Bank) -> Result<Sheet, String> {
    let path = dir.join(SHEET);
    let shown = path.display();
    let meta = std::fs::metadata(&path).map_err(|e| {
        format!("cannot read {shown}: {e} (a fresh one: `git checkout -- chapters/{SHEET}`)")
    })?;
    if !meta.is_file() || meta.len() > MAX_SHEET {
        return Err(format!(
            "{shown}: expected a text file of at most {} KiB",
            MAX_SHEET / 1024
        ));
    }
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{shown}: {e}"))?;
    let tables: BTreeMap<String, BTreeMap<String, Entry>> =
        toml::from_str(&text).map_err(|e| toml_error(&shown.to_string(), &text, &e))?;
    let mut answers = BTreeMap::new();
    let mut strays = Vec::new();
    for (chapter, entries) in tables {
        for (name, entry) in entries {
            let id = format!("{chapter}/{name}");
            if bank.question.iter().any(|q| q.id == id) {
                answers.insert(id, entry.answer);
            } else {
                let line = line_at(&text, entry.answer.span().start);
                strays.push(format!(
                    "{shown} line {line}: no question `{id}` (see chapters/questions.toml)"
                ));
            }
        }
    }
    let marks = bank
        .question
        .iter()
        .map(|q| {
            let m = match answers.get(&q.id) {
                None => Mark::Unanswered,
                Some(v) => match mark(q, v.get_ref()) {
                    Mark::Unreadable(why) => Mark::Unreadable(format!(
                        "{shown} line {}: {why}",
                        line_at(&text, v.span().start)
                    )),
                    m => m,
                },
            };
            (q, m)
        })
        .collect();
    Ok(Sheet { marks, strays })
}

/// The sheet in `dir` marked against the built-in bank; an error says
/// what is wrong with either (every problem of the bank, one per line).
pub fn read(dir: &Path) -> Result<Sheet, String> {
    let bank = bank()?;
    let problems = problems(bank);
    if !problems.is_empty() {
        return Err(problems.join("\nerror: "));
    }
    read_sheet(dir, bank)
}

impl Sheet {
    /// (answered, right) over the sheet.
    pub fn counts(&self) -> (usize, usize) {
        let answered = self
            .marks
            .iter()
            .filter(|(_, m)| *m != Mark::Unanswered)
            .count();
        let right = self.marks.iter().filter(|(_, m)| *m == Mark::Right).count();
        (answered, right)
    }

    /// The one line `cargo grade` adds to the course's progress.
    pub fn summary(&self) -> String {
        let (answered, right) = self.counts();
        let n = self.marks.len();
        format!(
            "predict: {answered} of {n} questions answered, {right} right \
             (chapters/{SHEET}; `cargo grade --predict` explains each answered one)\n"
        )
    }
}

/// `text` wrapped to `width` columns after `indent`, its later lines
/// `hang` more spaces in.
fn wrap_hung(text: &str, width: usize, indent: &str, hang: usize) -> String {
    wrap(
        text,
        indent,
        &format!("{indent}{}", " ".repeat(hang)),
        width,
    )
}

/// The answer, as the student would write it.
fn shown_answer(q: &Question) -> String {
    match &q.answer {
        Answer::Number(x) => format!("{x}"),
        Answer::Letters(l) => format!("\"{l}\""),
    }
}

/// What `--predict` prints: per question its mark, and for each
/// answered one the right answer and why.
pub fn explain(sheet: &Sheet) -> String {
    let mut out = String::new();
    for (q, m) in &sheet.marks {
        let verdict = match m {
            Mark::Unanswered => "not answered yet".to_string(),
            Mark::Right => "right".to_string(),
            Mark::Wrong => format!("not quite: the answer is {}", shown_answer(q)),
            Mark::Unreadable(why) => format!("cannot read the answer: {why}"),
        };
        out += &format!("{} {verdict}\n", q.id);
        out += &wrap_hung(&q.ask, 76, "  ", 0);
        for (i, c) in q.choices.iter().enumerate() {
            out += &wrap_hung(&format!("{}) {c}", (b'a' + i as u8) as char), 76, "    ", 3);
        }
        if matches!(m, Mark::Right | Mark::Wrong) {
            out += &wrap_hung(&format!("why: {}", q.explain), 76, "  ", 5);
        }
        out += "\n";
    }
    for s in &sheet.strays {
        out += &format!("note: {s}\n");
    }
    out += &sheet.summary();
    out
}

/// The sheet a student starts from: every question without its answer,
/// each chapter between mdBook anchors (`ch1` ...) so the book shows them.
pub fn blank_sheet(bank: &Bank) -> String {
    // mdBook's markers, spelled so that this file holds none itself.
    const START: &str = concat!("ANCH", "OR");
    const END: &str = concat!("ANCH", "OR_END");
    let mut out = String::from(
        "# Predict, then check. Answer each question before you read on (or run\n\
         # the code): a number (`answer = 0.25`), or the letters of every right\n\
         # option (`answer = \"b\"`, or `answer = \"ac\"` where two are right).\n\
         # Then `cargo grade --predict` says which are right and explains each\n\
         # one you answered. (The questions are chapters/questions.toml, with\n\
         # their answers: predict first.)\n",
    );
    let mut chapter = 0;
    for q in &bank.question {
        if q.chapter != chapter {
            if chapter != 0 {
                out += &format!("# {END}: ch{chapter}\n");
            }
            chapter = q.chapter;
            out += &format!("\n# {START}: ch{chapter}\n");
        } else {
            out += "\n";
        }
        let (_, name) = q.id.split_once('/').unwrap_or(("", &q.id));
        out += &format!("[ch{chapter}.{name}]\n");
        out += &wrap_hung(&q.ask, 72, "# ", 0);
        for (i, c) in q.choices.iter().enumerate() {
            out += &wrap_hung(&format!("{}) {c}", (b'a' + i as u8) as char), 72, "#   ", 3);
        }
        out += "answer = \"\"\n";
    }
    if chapter != 0 {
        out += &format!("# {END}: ch{chapter}\n");
    }
    out
}
