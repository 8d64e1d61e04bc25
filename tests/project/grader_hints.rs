//! The hints are data (`chapters/hints.toml`): every exercise and symptom
//! has its text there, and nothing there is left over.
//!
//! Hints cite what a student can open: a lecture slide by its real title
//! (`slide "…"`) or a section of the book by its heading (`book "…"`). The
//! slide titles cited are listed in `lecture-slides.txt` beside this file,
//! and each of them is checked against the lecture itself
//! (`../shared/lecture-11-rendering.txt`, beside the checkout, where a
//! course keeps it; CI always has it).

use std::collections::BTreeSet;

use raystep::grading;

use crate::common;

/// The quoted titles after `kind "` in `text`.
pub(super) fn cited<'a>(text: &'a str, kind: &str) -> Vec<&'a str> {
    let open = format!("{kind} \"");
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find(&open) {
        rest = &rest[i + open.len()..];
        if let Some(end) = rest.find('"') {
            out.push(&rest[..end]);
            rest = &rest[end + 1..];
        }
    }
    out
}

/// Every hint text: the three tiers and the symptoms', with where it is.
fn hints() -> Vec<(String, &'static str, bool)> {
    let mut all = Vec::new();
    for ex in grading::all() {
        for (tier, h) in ex.hints().iter().enumerate() {
            all.push((format!("{} tier {}", ex.id(), tier + 1), *h, tier == 0));
        }
        for s in ex.symptoms {
            let hint = ex.symptom_hint(s);
            all.push((format!("{} symptom {}", ex.id(), s.name), hint, true));
        }
    }
    all
}

fn squash(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

pub(super) fn slide_list() -> BTreeSet<String> {
    let path = common::root().join("tests/project/lecture-slides.txt");
    std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(str::to_string)
        .collect()
}

pub(super) fn book_headings() -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let dir = common::root().join("book/src");
    for entry in std::fs::read_dir(&dir).unwrap().flatten() {
        let path = entry.path();
        if path.extension().is_none_or(|e| e != "md") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let mut fenced = false;
        for line in text.lines() {
            if line.starts_with("```") {
                fenced = !fenced;
            }
            if !fenced && line.starts_with('#') {
                out.insert(line.trim_start_matches('#').trim().to_string());
            }
        }
    }
    out
}

#[test]
fn every_hint_cites_a_real_slide_or_book_section() {
    let slides = slide_list();
    let headings = book_headings();
    let mut wrong = Vec::new();
    for (at, hint, must_cite) in hints() {
        let s = cited(hint, "slide");
        let b = cited(hint, "book");
        if must_cite && s.is_empty() && b.is_empty() {
            wrong.push(format!("{at}: cites no slide and no book section: {hint}"));
        }
        for title in s {
            if !slides.contains(title) {
                wrong.push(format!(
                    "{at}: slide \"{title}\" is not in lecture-slides.txt"
                ));
            }
        }
        for heading in b {
            if !headings.contains(heading) {
                wrong.push(format!(
                    "{at}: book \"{heading}\" is no heading of book/src"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn every_listed_slide_title_is_in_the_lecture() {
    let path = common::root().join("../shared/lecture-11-rendering.txt");
    let Ok(lecture) = std::fs::read_to_string(&path) else {
        // A student's clone has no lecture beside it; CI always has.
        assert!(
            std::env::var_os("CI").is_none(),
            "CI has the lecture at {}",
            path.display()
        );
        eprintln!("skipped: no lecture at {}", path.display());
        return;
    };
    let lecture = squash(&lecture);
    let missing: Vec<String> = slide_list()
        .into_iter()
        .filter(|t| !lecture.contains(&squash(t)))
        .collect();
    assert!(missing.is_empty(), "not in the lecture: {missing:?}");
}

#[test]
fn every_symptom_is_named_once_per_exercise() {
    for ex in grading::all() {
        let names: BTreeSet<&str> = ex.symptoms.iter().map(|s| s.name).collect();
        assert_eq!(names.len(), ex.symptoms.len(), "{}", ex.id());
    }
}

#[test]
fn the_hints_file_has_every_hint_and_nothing_else() {
    let manifest = grading::manifest::manifest().unwrap();
    let problems = grading::manifest::problems(manifest, &grading::all());
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    // And the check finds what is wrong with a file that is.
    let broken =
        grading::manifest::TEXT.replacen("\"mirrored image\" =", "\"mirrored images\" =", 1)
            + "\n[exercises.\"ch1/nothing\"]\nhints = [\"a\", \"b\"]\n";
    let found =
        grading::manifest::problems(&grading::manifest::parse(&broken).unwrap(), &grading::all());
    for expected in [
        "ch1/project_point has no hint for symptom \"mirrored image\"",
        "ch1/project_point names symptom \"mirrored images\", which its check does not",
        "exercise \"ch1/nothing\" does not exist",
    ] {
        assert!(
            found.iter().any(|p| p.contains(expected)),
            "{expected}: {found:?}"
        );
    }
}

#[test]
fn a_broken_hints_file_is_named_with_its_line() {
    let e = grading::manifest::parse("[exercises.\"ch1/x\"]\nhints = [\"a\", \n").unwrap_err();
    assert!(e.starts_with("chapters/hints.toml: line 2:"), "{e}");
    let e = grading::manifest::parse("[exercises.\"ch1/x\"]\nhint = [\"a\"]\n").unwrap_err();
    assert!(
        e.contains("chapters/hints.toml") && e.contains("hint"),
        "{e}"
    );
}
