//! The source layout keeps its promises (`src/lib.rs`, "The layout"):
//! imports only go down, there are no file-level import cycles, every
//! chapter folder has the same shape, and files stay small enough to read.
//!
//! The import graph is read from the source text: every `use` tree and
//! every inline `crate::…` or `super::…` path outside comments, strings
//! and `#[cfg(test)]` modules, resolved to the file that defines it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every `.rs` file under `src/`, as a path relative to `src/`.
fn sources() -> Vec<String> {
    fn walk(dir: &Path, base: &Path, out: &mut Vec<String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            // The shipped exercise stubs are data the grader embeds, not
            // modules of the library.
            if p.ends_with("grading/shipped") {
                continue;
            }
            if p.is_dir() {
                walk(&p, base, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(
                    p.strip_prefix(base)
                        .unwrap()
                        .to_string_lossy()
                        .replace('\\', "/"),
                );
            }
        }
    }
    let src = root().join("src");
    let mut out = Vec::new();
    walk(&src, &src, &mut out);
    out.sort();
    out
}

/// The module path of a source file (`ch3_ray_triangle/obvhs_bvh.rs` →
/// `["ch3_ray_triangle", "obvhs_bvh"]`, `core/mod.rs` → `["core"]`).
fn module_of(file: &str) -> Vec<String> {
    let mut parts: Vec<String> = file
        .trim_end_matches(".rs")
        .split('/')
        .map(String::from)
        .collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts
}

/// The source text without comments, string and char literals, and
/// without anything from the first `#[cfg(test)]` on.
fn code_of(text: &str) -> String {
    let text = match text.find("#[cfg(test)]") {
        Some(i) => &text[..i],
        None => text,
    };
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            let end = text[i + 2..].find("*/").map_or(b.len(), |e| i + 2 + e + 2);
            i = end;
        } else if b[i] == b'"' {
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else if b[i] == b'\'' && i + 2 < b.len() && (b[i + 2] == b'\'' || b[i + 1] == b'\\') {
            // A char literal ('a', '\n'); lifetimes ('a without a closing quote) stay.
            let end = text[i + 1..].find('\'').map_or(b.len(), |e| i + 1 + e + 1);
            i = end;
        } else {
            let ch = text[i..].chars().next().unwrap();
            out.push(ch);
            i += ch.len_utf8();
        }
    }
    out
}

/// Expands a `use` tree (`a::{b, c::{d, e}}`) into its full paths.
fn expand_use(tree: &str) -> Vec<String> {
    // Drop `as alias` renames, keeping any `,` or `}` that follows the alias.
    let mut kept = Vec::new();
    let mut tokens = tree.split_whitespace();
    while let Some(t) = tokens.next() {
        if t == "as" {
            if let Some(alias) = tokens.next() {
                kept.push(alias.trim_start_matches(|c: char| c.is_alphanumeric() || c == '_'));
            }
        } else {
            kept.push(t);
        }
    }
    let tree: String = kept.concat();
    fn go(prefix: &str, t: &str, out: &mut Vec<String>) {
        match t.find('{') {
            None => {
                for part in split_top(t) {
                    out.push(format!("{prefix}{part}"));
                }
            }
            Some(open) => {
                let head = &t[..open];
                let close = t.rfind('}').unwrap();
                for part in split_top(&t[open + 1..close]) {
                    if part.is_empty() {
                        continue;
                    }
                    if part.contains('{') {
                        go(&format!("{prefix}{head}"), part, out);
                    } else {
                        out.push(format!("{prefix}{head}{part}"));
                    }
                }
            }
        }
    }
    fn split_top(s: &str) -> Vec<&str> {
        let (mut depth, mut start, mut parts) = (0, 0, Vec::new());
        for (i, c) in s.char_indices() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    parts.push(&s[start..i]);
                    start = i + 1;
                }
                _ => {}
            }
        }
        parts.push(&s[start..]);
        parts
    }
    let mut out = Vec::new();
    go("", &tree, &mut out);
    out
}

/// The crate-relative module paths (as segment lists) that `code`, the
/// code of the module at `module`, refers to.
fn referenced_paths(code: &str, module: &[String], is_mod_file: bool) -> Vec<Vec<String>> {
    // `super` of a file `a/b.rs` is `a`; of `a/b/mod.rs` it is `a` too
    // (mod.rs is module a::b, whose parent is a).
    let _ = is_mod_file;
    let resolve = |path: &str| -> Option<Vec<String>> {
        let segs: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
        let mut base: Vec<String> = match segs.first() {
            Some(&"crate") => crate_root(module, segs.get(1).copied()),
            Some(&"super") => {
                let mut m = module.to_vec();
                m.pop();
                m
            }
            Some(&"self") => module.to_vec(),
            _ => return None,
        };
        let mut rest = &segs[1..];
        while rest.first() == Some(&"super") {
            base.pop();
            rest = &rest[1..];
        }
        base.extend(rest.iter().map(|s| s.to_string()));
        Some(base)
    };
    let mut out = Vec::new();
    // `use` statements.
    let mut rest = code;
    while let Some(i) = rest.find("use ") {
        let before_ok = i == 0
            || !rest.as_bytes()[i - 1].is_ascii_alphanumeric() && rest.as_bytes()[i - 1] != b'_';
        let after = &rest[i + 4..];
        let end = after.find(';').unwrap_or(after.len());
        if before_ok {
            for p in expand_use(&after[..end]) {
                if let Some(r) = resolve(&p) {
                    out.push(r);
                }
            }
        }
        rest = &after[end.min(after.len())..];
    }
    // Inline paths.
    for start in ["crate::", "super::"] {
        let mut from = 0;
        while let Some(i) = code[from..].find(start) {
            let at = from + i;
            let prev = code[..at].chars().next_back();
            let inline = !matches!(prev, Some(c) if c.is_alphanumeric() || c == '_' || c == ':');
            let end = code[at..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |e| at + e);
            // `crate::a::{b, c}` is read with the `use` trees above.
            if inline && !code[at..end].ends_with("::") {
                if let Some(r) = resolve(&code[at..end]) {
                    out.push(r);
                }
            }
            from = end.max(at + 1);
        }
    }
    out
}

/// Where `crate::{next}…` leads from a file of `module`: the fast
/// engine, the grader and the UI are crates of their own (`src/fast/`,
/// `src/grading/`, `src/tui/`), whose roots name the crates below them as
/// they are named in the lessons (`crate::core`, `crate::chapters`).
fn crate_root(module: &[String], next: Option<&str>) -> Vec<String> {
    let lessons =
        |n: &str| ["core", "scene"].contains(&n) || crate::common::CHAPTER_MODULES.contains(&n);
    let own = module.first().map(String::as_str);
    match next {
        Some(n) if lessons(n) => Vec::new(),
        Some("chapters") if own != Some("fast") => vec!["fast".into()],
        Some("grading" | "fast" | "tui") => Vec::new(),
        _ => match own {
            Some(c @ ("fast" | "grading" | "tui")) => vec![c.to_string()],
            _ => Vec::new(),
        },
    }
}

/// The import graph: file → files it refers to (itself excluded).
fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let files = sources();
    let by_module: BTreeMap<Vec<String>, String> =
        files.iter().map(|f| (module_of(f), f.clone())).collect();
    let mut g = BTreeMap::new();
    for f in &files {
        let text = std::fs::read_to_string(root().join("src").join(f)).unwrap();
        let module = module_of(f);
        let mut deps = BTreeSet::new();
        for path in referenced_paths(&code_of(&text), &module, f.ends_with("mod.rs")) {
            // The longest prefix of the path that is a file.
            for n in (1..=path.len()).rev() {
                if let Some(target) = by_module.get(&path[..n]) {
                    if target != f {
                        deps.insert(target.clone());
                    }
                    break;
                }
            }
        }
        g.insert(f.clone(), deps);
    }
    g
}

/// What a file is, for the import rule.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Place {
    /// `core/`: film, report, plots, sampling, the stage boundary, the runner.
    Core,
    /// `scene/`: scene file → Scene.
    Scene,
    /// A lesson file of chapter N (the slides' algorithms).
    Lesson(u32),
    /// Chapter N's stage, report, studies, stability or bench.
    Harness(u32),
    /// The fast engine (`fast/`): answers chapter 6's engine questions
    /// with the lessons' formulas; the only module with `unsafe` code. It
    /// may use the chapters, and only the front ends (and itself) may use
    /// it: no chapter knows it exists.
    Fast,
    /// The terminal UI (`tui/`): drives the chapters through the stage
    /// boundary only (`core::stage`), so it may use core/, scene/, the
    /// chapter list and the grader's student mode, and no chapter's files.
    Ui,
    /// The other front ends and the crate root: may use anything.
    Top,
}

/// The file names that play the same role in every chapter.
const HARNESS: [&str; 6] = [
    "stage.rs",
    "inspect.rs",
    "report.rs",
    "studies.rs",
    "stability.rs",
    "bench.rs",
];

fn place(file: &str) -> Place {
    let first = file.split('/').next().unwrap();
    if first == "core" {
        return Place::Core;
    }
    if first == "scene" {
        return Place::Scene;
    }
    if first == "tui" {
        return Place::Ui;
    }
    // The chapter registry, where the front ends choose chapter 6's
    // engine, is a front end's file that lives in the fast engine's crate.
    if file == "fast/chapters.rs" {
        return Place::Top;
    }
    if first == "fast" {
        return Place::Fast;
    }
    if let Some(n) = first
        .strip_prefix("ch")
        .and_then(|r| r.split('_').next())
        .and_then(|n| n.parse().ok())
    {
        let name = file.rsplit('/').next().unwrap();
        let depth = file.matches('/').count();
        return if depth == 1 && HARNESS.contains(&name) {
            Place::Harness(n)
        } else {
            Place::Lesson(n)
        };
    }
    Place::Top
}

/// Whether a file at `from` may import one at `to`.
fn allowed(from: Place, to: Place) -> bool {
    use Place::*;
    match (from, to) {
        (Top, _) => true,
        (Fast, Top | Ui) => false,
        (Fast, _) => true,
        (_, Fast) => false,
        (Ui, Core | Scene | Ui | Top) => true,
        (Ui, Lesson(_) | Harness(_)) => false,
        (_, Top | Ui) => false,
        // The foundation is core/ and scene/: the stage boundary and the
        // headless runner take a Scene, and the scene reports core errors.
        (Core | Scene, Core | Scene) => true,
        (Core, _) => false,
        (Scene, _) => false,
        (Lesson(_) | Harness(_), Core | Scene) => true,
        // A lesson file uses earlier chapters' lessons and its own, never a
        // harness file (that is where the old cycles came from).
        (Lesson(n), Lesson(m)) => m <= n,
        (Lesson(_), Harness(_)) => false,
        (Harness(n), Lesson(m)) => m <= n,
        (Harness(n), Harness(m)) => m == n,
    }
}

#[test]
fn imports_only_go_down() {
    let mut bad = Vec::new();
    for (from, deps) in graph() {
        for to in deps {
            if !allowed(place(&from), place(&to)) {
                bad.push(format!(
                    "{from} ({:?}) uses {to} ({:?})",
                    place(&from),
                    place(&to)
                ));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "imports that go up or sideways:\n{}",
        bad.join("\n")
    );
}

#[test]
fn no_file_level_import_cycles() {
    let g = graph();
    // Tarjan's strongly connected components.
    struct State<'a> {
        g: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on: BTreeSet<&'a str>,
        next: usize,
        cycles: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        s.index.insert(v, s.next);
        s.low.insert(v, s.next);
        s.next += 1;
        s.stack.push(v);
        s.on.insert(v);
        for w in s.g[v].iter() {
            if !s.index.contains_key(w.as_str()) {
                visit(s, w);
                let lw = s.low[w.as_str()];
                let lv = s.low[v];
                s.low.insert(v, lv.min(lw));
            } else if s.on.contains(w.as_str()) {
                let iw = s.index[w.as_str()];
                let lv = s.low[v];
                s.low.insert(v, lv.min(iw));
            }
        }
        if s.low[v] == s.index[v] {
            let mut comp = Vec::new();
            loop {
                let w = s.stack.pop().unwrap();
                s.on.remove(w);
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                s.cycles.push(comp);
            }
        }
    }
    let mut s = State {
        g: &g,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        next: 0,
        cycles: Vec::new(),
    };
    for v in g.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    let shown: Vec<String> = s.cycles.iter().map(|c| c.join(" <-> ")).collect();
    assert!(
        shown.is_empty(),
        "file-level import cycles:\n{}",
        shown.join("\n")
    );
}

#[test]
fn the_import_reader_sees_what_it_should() {
    // A small self-check of the parser, so the two tests above cannot pass
    // by reading nothing.
    let code = code_of(
        "use crate::a::{b, c::{d, E}};\n// use crate::zz;\nfn f() { crate::x::y(); let s = \"crate::q\"; super::w::v(); }\n#[cfg(test)]\nmod tests { use crate::t; }",
    );
    let module = vec!["m".to_string(), "n".to_string()];
    let got: BTreeSet<String> = referenced_paths(&code, &module, false)
        .iter()
        .map(|p| p.join("::"))
        .collect();
    let want: BTreeSet<String> = ["a::b", "a::c::d", "a::c::E", "x::y", "m::w::v"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(got, want);
    // And the real graph has edges: the chapter-6 path loop uses chapter 5's BSDFs.
    let g = graph();
    assert!(g["ch6_global_illumination/integrator.rs"]
        .iter()
        .any(|d| d.starts_with("ch5_reflection/")));
}

#[test]
fn every_chapter_folder_has_the_same_shape() {
    let files = sources();
    let chapters: BTreeSet<&str> = files
        .iter()
        .filter_map(|f| f.split_once('/').map(|(d, _)| d))
        .filter(|d| d.starts_with("ch"))
        .collect();
    assert_eq!(chapters.len(), 6, "one folder per chapter: {chapters:?}");
    let mut missing = Vec::new();
    for ch in &chapters {
        for role in [
            "mod.rs",
            "stage.rs",
            "report.rs",
            "studies.rs",
            "stability.rs",
        ] {
            if !files.contains(&format!("{ch}/{role}")) {
                missing.push(format!("{ch}/{role}"));
            }
        }
        let doc = std::fs::read_to_string(root().join("src").join(ch).join("mod.rs")).unwrap();
        if !doc.contains("| slide") {
            missing.push(format!("{ch}/mod.rs: the slide → file table"));
        }
    }
    assert!(missing.is_empty(), "missing: {missing:?}");
}

/// Lines before the file's tests.
fn code_lines(text: &str) -> usize {
    let text = match text.find("#[cfg(test)]") {
        Some(i) => &text[..i],
        None => text,
    };
    text.lines().count()
}

#[test]
fn files_a_reader_can_hold() {
    // About 450 lines before the tests, unless the module doc says why one
    // concept reads better whole ("reads better whole").
    let mut long = Vec::new();
    for f in sources() {
        let text = std::fs::read_to_string(root().join("src").join(&f)).unwrap();
        let n = code_lines(&text);
        if n > 460 && !text.contains("reads better whole") {
            long.push(format!("{f}: {n} lines"));
        }
    }
    assert!(
        long.is_empty(),
        "files over ~450 lines before their tests:\n{}",
        long.join("\n")
    );
}

#[test]
fn src_root_stays_small() {
    // The folders, the two crate roots (`lib.rs`, `lessons.rs`), the
    // lessons' `Cargo.toml` and `summary.rs`.
    let n = std::fs::read_dir(root().join("src")).unwrap().count();
    assert!(n <= 17, "src/ holds {n} entries");
}

/// `[lib] test = false`: a `#[test]` written beside the code would never
/// run, so none may be there (the library's tests live in
/// `tests/<chapter>/unit/`). Every attribute in the code (outside comments
/// and strings) is read: `#[test]`, any `#[…::test]`, and any `cfg` or
/// `cfg_attr` that names `test` (`#[cfg(test)]`, `#![cfg(all(test, unix))]`)
/// is reported by file and line.
#[test]
fn no_test_hides_in_the_library() {
    let mut hidden = Vec::new();
    for f in sources() {
        let text = std::fs::read_to_string(root().join("src").join(&f)).unwrap();
        for (line, attr) in test_attributes(&text) {
            hidden.push(format!("src/{f}:{line}: {attr}"));
        }
    }
    assert!(
        hidden.is_empty(),
        "tests under src/ never run ([lib] test = false in Cargo.toml); move them to \
         tests/<chapter>/unit/:\n  {}",
        hidden.join("\n  ")
    );
}

#[test]
fn the_terminal_ui_is_checked_and_uses_no_chapter_files() {
    let g = graph();
    let ui: Vec<_> = g.keys().filter(|f| f.starts_with("tui/")).collect();
    assert!(ui.len() >= 10, "the tui/ files are in the graph: {ui:?}");
    assert!(ui.iter().all(|f| place(f) == Place::Ui));
    assert!(
        g["tui/worker.rs"].contains("core/stage.rs"),
        "the worker drives renders through the boundary"
    );
    // The rule itself: a chapter's lesson or harness file is out of reach.
    assert!(!allowed(Place::Ui, Place::Lesson(6)));
    assert!(!allowed(Place::Ui, Place::Harness(3)));
    assert!(allowed(Place::Ui, Place::Core));
}

/// The reader behind [`no_test_hides_in_the_library`] finds what it must
/// and nothing else.
#[test]
fn the_hidden_test_reader_sees_what_it_should() {
    let text = "fn a() {}\n#[test]\nfn b() {}\n# [ test ]\nfn c() {}\n\
                #[cfg(test)]\nmod t {}\n#![cfg(all(unix, test))]\n#[tokio::test]\n\
                #[cfg_attr(test, derive(Debug))]\n\
                // #[test] in a comment\n/* #[cfg(test)] */\n\
                const S: &str = \"#[test]\";\n#[cfg(feature = \"test\")]\n\
                #[derive(Debug)]\n#[cfg(testing)]\n#[allow(dead_code)]\n";
    let found: Vec<usize> = test_attributes(text).into_iter().map(|(l, _)| l).collect();
    assert_eq!(found, vec![2, 4, 6, 8, 9, 10]);
}

/// The line and text of every attribute in `text` that makes a test or
/// compiles only under `cfg(test)`.
fn test_attributes(text: &str) -> Vec<(usize, String)> {
    let code = blank_comments_and_strings(text);
    let b = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i] != b'#' {
            i += 1;
            continue;
        }
        let mut j = i + 1;
        while j < b.len() && (b[j].is_ascii_whitespace() || b[j] == b'!') {
            j += 1;
        }
        if j >= b.len() || b[j] != b'[' {
            i += 1;
            continue;
        }
        // The attribute up to its matching `]`.
        let (start, mut depth, mut k) = (j + 1, 1, j + 1);
        while k < b.len() && depth > 0 {
            depth += match b[k] {
                b'[' => 1,
                b']' => -1,
                _ => 0,
            };
            k += 1;
        }
        let attr: String = code[start..k.saturating_sub(1)]
            .split_whitespace()
            .collect();
        let words: Vec<&str> = attr
            .split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .filter(|w| !w.is_empty())
            .collect();
        let path = attr.split('(').next().unwrap_or("");
        let is_test = path == "test"
            || path.ends_with("::test")
            || ((path == "cfg" || path == "cfg_attr") && words.contains(&"test"));
        if is_test {
            let line = code[..i].matches('\n').count() + 1;
            out.push((
                line,
                text.lines().nth(line - 1).unwrap_or("").trim().to_string(),
            ));
        }
        i = k;
    }
    out
}

/// `text` with comments and the insides of string and char literals
/// replaced by spaces (newlines kept, so lines still count).
fn blank_comments_and_strings(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = b.to_vec();
    let blank = |out: &mut Vec<u8>, from: usize, to: usize| {
        for c in &mut out[from..to.min(b.len())] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
    };
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            let end = text[i..].find('\n').map_or(b.len(), |e| i + e);
            blank(&mut out, i, end);
            i = end;
        } else if b[i..].starts_with(b"/*") {
            let end = text[i + 2..].find("*/").map_or(b.len(), |e| i + 2 + e + 2);
            blank(&mut out, i, end);
            i = end;
        } else if b[i] == b'r' && b.get(i + 1).is_some_and(|c| *c == b'"' || *c == b'#') {
            // A raw string r"…" or r#"…"#.
            let hashes = b[i + 1..].iter().take_while(|c| **c == b'#').count();
            if b.get(i + 1 + hashes) != Some(&b'"') {
                i += 1;
                continue;
            }
            let close = format!("\"{}", "#".repeat(hashes));
            let from = i + 2 + hashes;
            let end = text[from..]
                .find(&close)
                .map_or(b.len(), |e| from + e + close.len());
            blank(&mut out, from, end);
            i = end;
        } else if b[i] == b'"' {
            let mut k = i + 1;
            while k < b.len() && b[k] != b'"' {
                k += if b[k] == b'\\' { 2 } else { 1 };
            }
            blank(&mut out, i + 1, k);
            i = k + 1;
        } else if b[i] == b'\'' && i + 2 < b.len() && (b[i + 2] == b'\'' || b[i + 1] == b'\\') {
            let end = text[i + 1..].find('\'').map_or(b.len(), |e| i + 1 + e + 1);
            blank(&mut out, i + 1, end - 1);
            i = end;
        } else {
            i += 1;
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Every `mod.rs` whose doc has a file table (`//! | … |`) lists every
/// module its folder declares, as `[`name`]` or `(mod@name)`: a reader
/// who starts from the table finds every file.
#[test]
fn every_mod_table_lists_every_module() {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut missing = Vec::new();
    let mut tables = 0;
    for p in crate::common::files_under(&src, "rs") {
        if p.file_name().is_none_or(|n| n != "mod.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&p).unwrap();
        let table: String = text
            .lines()
            .filter(|l| l.starts_with("//! |"))
            .collect::<Vec<_>>()
            .join("\n");
        if table.is_empty() {
            continue;
        }
        tables += 1;
        for line in text.lines() {
            let decl = line
                .trim()
                .strip_prefix("pub mod ")
                .or_else(|| line.trim().strip_prefix("mod "));
            let Some(name) = decl.and_then(|d| d.strip_suffix(';')) else {
                continue;
            };
            let listed =
                table.contains(&format!("[`{name}`]")) || table.contains(&format!("(mod@{name})"));
            if !listed {
                let file = p.strip_prefix(&src).unwrap().display().to_string();
                missing.push(format!("{file}: {name}"));
            }
        }
    }
    assert!(tables >= 6, "{tables} tables");
    assert!(
        missing.is_empty(),
        "modules missing from their table: {missing:#?}"
    );
}

/// The terminal UI reads in short functions (#45): none in `src/tui/` is
/// 100 lines or longer, from its `fn` line to its closing brace.
#[test]
fn no_function_in_the_tui_reaches_100_lines() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/tui");
    let mut long = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "rs") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let lines: Vec<String> = blank_comments_and_strings(&text)
            .lines()
            .map(str::to_string)
            .collect();
        for (n, line) in lines.iter().enumerate() {
            let words: Vec<&str> = line.split_whitespace().collect();
            let Some(at) = words.iter().position(|w| *w == "fn") else {
                continue;
            };
            let before_ok = words[..at]
                .iter()
                .all(|w| w.starts_with("pub") || ["const", "async", "unsafe"].contains(w));
            if !before_ok {
                continue;
            }
            let (mut depth, mut opened) = (0i32, false);
            for (k, l) in lines.iter().enumerate().skip(n) {
                for c in l.chars() {
                    match c {
                        '{' => (depth, opened) = (depth + 1, true),
                        '}' => depth -= 1,
                        _ => {}
                    }
                }
                if opened && depth == 0 {
                    if k - n + 1 >= 100 {
                        long.push(format!("{}:{} {} lines", path.display(), n + 1, k - n + 1));
                    }
                    break;
                }
                if !opened && l.trim_end().ends_with(';') {
                    break;
                }
            }
        }
    }
    assert!(long.is_empty(), "functions of 100 lines or more: {long:?}");
}
