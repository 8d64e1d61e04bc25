//! The book may only show real code: every Rust block is an mdBook include
//! of a file in this repository with an anchor that exists and is not empty,
//! and every page and figure the book links to exists. (mdBook itself
//! silently renders nothing for a missing anchor.)

use std::path::{Path, PathBuf};

fn book_src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("book/src")
}

fn pages() -> Vec<PathBuf> {
    let mut pages: Vec<PathBuf> = std::fs::read_dir(book_src())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    pages.sort();
    pages
}

/// Fenced blocks as (info string, body, first line number).
fn code_blocks(text: &str) -> Vec<(String, String, usize)> {
    let mut blocks = Vec::new();
    let mut current: Option<(String, String, usize)> = None;
    for (n, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        if let Some(info) = trimmed.strip_prefix("```") {
            match current.take() {
                None => current = Some((info.trim().to_string(), String::new(), n + 1)),
                Some(block) => blocks.push(block),
            }
        } else if let Some((_, body, _)) = current.as_mut() {
            body.push_str(line);
            body.push('\n');
        }
    }
    blocks
}

/// Checks one `{{#include path:anchor}}` and returns what it includes.
fn resolve_include(page: &Path, directive: &str) -> Result<String, String> {
    let inner = directive
        .trim()
        .strip_prefix("{{#include ")
        .or_else(|| directive.trim().strip_prefix("{{#rustdoc_include "))
        .and_then(|s| s.strip_suffix("}}"))
        .ok_or_else(|| format!("not an include: `{directive}`"))?;
    let (file, anchor) = match inner.split_once(':') {
        Some((f, a)) => (f, Some(a)),
        None => (inner, None),
    };
    let path = page.parent().unwrap().join(file);
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let Some(anchor) = anchor else {
        return Ok(text);
    };
    if anchor.chars().all(|c| c.is_ascii_digit()) {
        return Err(format!(
            "`{directive}`: use a named anchor, not line numbers"
        ));
    }
    let start = format!("ANCHOR: {anchor}");
    let end = format!("ANCHOR_END: {anchor}");
    let lines: Vec<&str> = text.lines().collect();
    let begin = lines
        .iter()
        .position(|l| l.trim_end().ends_with(&start))
        .ok_or_else(|| format!("{}: no `{start}`", path.display()))?;
    let stop = lines[begin..]
        .iter()
        .position(|l| l.trim_end().ends_with(&end))
        .ok_or_else(|| format!("{}: no `{end}` after `{start}`", path.display()))?;
    let body: Vec<&str> = lines[begin + 1..begin + stop]
        .iter()
        .filter(|l| !l.contains("ANCHOR"))
        .copied()
        .collect();
    if body.iter().all(|l| l.trim().is_empty()) {
        return Err(format!("{}: anchor `{anchor}` is empty", path.display()));
    }
    Ok(body.join("\n"))
}

#[test]
fn every_rust_block_is_an_include_that_resolves() {
    let mut problems = Vec::new();
    let mut includes = 0;
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        for (info, body, line) in code_blocks(&text) {
            if !info.starts_with("rust") {
                continue;
            }
            let at = format!("{}:{line}", page.display());
            for l in body.lines().filter(|l| !l.trim().is_empty()) {
                if l.trim_start().starts_with("{{#") {
                    match resolve_include(&page, l) {
                        Ok(_) => includes += 1,
                        Err(e) => problems.push(format!("{at}: {e}")),
                    }
                } else {
                    problems.push(format!("{at}: hand-written Rust in the book: `{l}`"));
                }
            }
        }
        // Includes outside code blocks must resolve too.
        for l in text
            .lines()
            .filter(|l| l.trim_start().starts_with("{{#include"))
        {
            if let Err(e) = resolve_include(&page, l) {
                problems.push(format!("{}: {e}", page.display()));
            }
        }
    }
    assert!(
        problems.is_empty(),
        "book problems:\n{}",
        problems.join("\n")
    );
    assert!(includes >= 5, "the book includes only {includes} listings");
}

#[test]
fn every_linked_page_and_figure_exists() {
    let mut missing = Vec::new();
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        // Markdown links and images: ](target)
        for part in text.split("](").skip(1) {
            let target = part.split(')').next().unwrap_or("");
            let target = target.split('#').next().unwrap_or("");
            if target.is_empty() || target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let path = page.parent().unwrap().join(target);
            if !path.exists() {
                missing.push(format!("{}: {target}", page.display()));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "missing link targets:\n{}",
        missing.join("\n")
    );
}

#[test]
fn include_checker_rejects_what_it_should() {
    let page = book_src().join("introduction.md");
    assert!(resolve_include(
        &page,
        "{{#include ../../src/ch1_projection/camera.rs:pinhole}}"
    )
    .is_ok());
    assert!(resolve_include(
        &page,
        "{{#include ../../src/ch1_projection/camera.rs:no_such_anchor}}"
    )
    .is_err());
    assert!(resolve_include(&page, "{{#include ../../src/no_such_file.rs:pinhole}}").is_err());
    assert!(resolve_include(
        &page,
        "{{#include ../../src/ch1_projection/camera.rs:10:20}}"
    )
    .is_err());
}

/// Paragraphs and the blocks between them: (kind, first line, text), kind
/// "code" for a fenced block and "text" for a run of non-blank lines.
fn blocks(text: &str) -> Vec<(&'static str, usize, String)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let l = lines[i].trim_start();
        if l.starts_with("```") {
            let mut j = i + 1;
            while j < lines.len() && !lines[j].trim_start().starts_with("```") {
                j += 1;
            }
            out.push(("code", i + 1, String::new()));
            i = j + 1;
        } else if l.is_empty() {
            i += 1;
        } else {
            let mut j = i;
            while j < lines.len()
                && !lines[j].trim().is_empty()
                && !lines[j].trim_start().starts_with("```")
            {
                j += 1;
            }
            out.push(("text", i + 1, lines[i..j].join("\n")));
            i = j;
        }
    }
    out
}

/// A paragraph that ends in ":" announces what follows it: a listing, an
/// include, a list, a table, a figure or a displayed formula (one line
/// with an `=`). When a listing moves (to "Check your solution", say), the
/// sentence left behind must change too.
fn colon_problems(page: &str, text: &str) -> Vec<String> {
    let blocks = blocks(text);
    let mut problems = Vec::new();
    for (k, (kind, line, body)) in blocks.iter().enumerate() {
        if *kind != "text" || !body.trim_end().ends_with(':') {
            continue;
        }
        let announced = match blocks.get(k + 1) {
            Some(("code", _, _)) => true,
            Some((_, _, next)) => {
                let t = next.trim_start();
                t.starts_with("- ")
                    || t.starts_with("* ")
                    || t.starts_with('|')
                    || t.starts_with("{{#include")
                    || t.starts_with("![")
                    || t.split_once(". ")
                        .is_some_and(|(n, _)| n.chars().all(|c| c.is_ascii_digit()))
                    || (!next.contains('\n') && t.contains(" = "))
            }
            None => false,
        };
        if !announced {
            let end = line + body.lines().count() - 1;
            problems.push(format!(
                "{page}:{end}: ends in \":\" but no listing, list or table follows"
            ));
        }
    }
    problems
}

#[test]
fn a_paragraph_ending_in_a_colon_is_followed_by_what_it_announces() {
    let mut problems = Vec::new();
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        problems.extend(colon_problems(&page.display().to_string(), &text));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_colon_check_catches_a_listing_that_moved() {
    let moved = "The sphere is this:\n\n*(Exercise 4.1: the code is under Check your solution.)*\n";
    assert_eq!(colon_problems("p", moved).len(), 1);
    let listing = "The sphere is this:\n\n```rust\n{{#include x.rs:a}}\n```\n";
    assert!(colon_problems("p", listing).is_empty());
    let list = "Three things:\n\n- one\n- two\n";
    assert!(colon_problems("p", list).is_empty());
    let formula = "Similar triangles give:\n\n  u = x / (-z).\n";
    assert!(colon_problems("p", formula).is_empty());
    let at_the_end = "And then:\n";
    assert_eq!(colon_problems("p", at_the_end).len(), 1);
}

/// The book's listings and the files agree line for line: mdBook drops
/// every line that names an anchor, so a line of code may never carry
/// one (that hid grader guards and counters from the listings once). A
/// line that mentions `ANCHOR` must be an anchor marker and nothing else.
#[test]
fn no_code_line_is_hidden_from_a_listing() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut hidden = Vec::new();
    let mut markers = 0;
    let files = [root.join("src"), root.join("chapters")]
        .iter()
        .flat_map(|d| crate::common::files_under(d, "rs"))
        .collect::<Vec<_>>();
    for p in files {
        let text = std::fs::read_to_string(&p).unwrap();
        for (i, line) in text.lines().enumerate() {
            if !line.contains("ANCHOR") {
                continue;
            }
            let t = line.trim();
            let name = t
                .strip_prefix("// ANCHOR: ")
                .or_else(|| t.strip_prefix("// ANCHOR_END: "));
            let marker = name.is_some_and(|n| {
                !n.is_empty()
                    && n.chars()
                        .all(|c| c.is_alphanumeric() || c == '_' || c == '-')
            });
            match marker {
                true => markers += 1,
                false => hidden.push(format!(
                    "{}:{}: {t}",
                    p.strip_prefix(root).unwrap().display(),
                    i + 1
                )),
            }
        }
    }
    assert!(markers > 100, "{markers} anchor markers");
    assert!(
        hidden.is_empty(),
        "lines hidden from the book's listings: {hidden:#?}"
    );
}

/// A reader can hold a listing of 30 lines: in the lecture's chapters every
/// code block, its includes resolved, is at most that long. Longer code is
/// shown in parts with prose between them; test harness, studies and report
/// dumps live in the appendix "How raystep checks itself" (checks.md).
#[test]
fn no_listing_in_a_chapter_is_longer_than_30_lines() {
    let mut long = Vec::new();
    let mut listings = 0;
    for page in pages() {
        let name = page.file_name().unwrap().to_string_lossy().to_string();
        if !(1..=6).any(|n| name.starts_with(&format!("ch{n}-"))) {
            continue;
        }
        let text = std::fs::read_to_string(&page).unwrap();
        for (_, body, line) in code_blocks(&text) {
            let includes: Vec<&str> = body
                .lines()
                .filter(|l| l.trim_start().starts_with("{{#"))
                .collect();
            if includes.is_empty() {
                continue;
            }
            listings += 1;
            let mut length = body.lines().count() - includes.len();
            for directive in &includes {
                match resolve_include(&page, directive) {
                    Ok(text) => length += text.lines().count(),
                    Err(e) => panic!("{name}:{line}: {e}"),
                }
            }
            if length > 30 {
                long.push(format!(
                    "{name}:{line}: {} is {length} lines",
                    includes.join(" ")
                ));
            }
        }
    }
    assert!(
        listings >= 30,
        "the chapters include only {listings} listings"
    );
    assert!(
        long.is_empty(),
        "listings longer than 30 lines in the chapters:\n{}",
        long.join("\n")
    );
}
