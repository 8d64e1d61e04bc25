//! What an exercise file may not use, found in its text before it is
//! compiled: the parts of the standard library that reach outside the
//! function (processes, threads, files, the environment, the network, the
//! operating system), `extern` (foreign functions, other crates), and
//! the ways to read other files at compile time (`#[path]`, `mod x;`,
//! `include!`). An exercise is a function of its arguments; none of this
//! is needed to write one. (`unsafe` is refused by the compiler: the
//! exercises are built with `#![forbid(unsafe_code)]`, which also refuses
//! `#[no_mangle]` and `#[export_name]`.)
//!
//! The scan reads tokens, not text: comments and string literals are
//! skipped, so a comment that names `std::thread` is no refusal, and
//! `use std::{thread as t}`, `use std as s` or `::std::fs` are.

/// The modules of `std` (and `core`) an exercise may not name.
pub const DENIED: [&str; 9] = [
    "process",
    "thread",
    "fs",
    "env",
    "net",
    "os",
    "arch",
    "ffi",
    "intrinsics",
];

/// One thing an exercise file may not use: its line (from 1) and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal {
    /// The line it is on, counted from 1.
    pub line: usize,
    /// What it is and why it is refused.
    pub what: String,
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Punct(char),
}

/// The tokens of `text` that matter here, each with its line: identifiers
/// and single punctuation characters; comments, strings, characters,
/// numbers and lifetimes left out.
fn tokens(text: &str) -> Vec<(usize, Tok)> {
    let c: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let (mut i, mut line) = (0usize, 1usize);
    let at = |i: usize| c.get(i).copied().unwrap_or('\0');
    while i < c.len() {
        let ch = c[i];
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch == '/' && at(i + 1) == '/' {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if ch == '/' && at(i + 1) == '*' {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && at(i + 1) == '*' {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && at(i + 1) == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    if c[i] == '\n' {
                        line += 1;
                    }
                    i += 1;
                }
            }
        } else if ch == '"' || ((ch == 'b' || ch == 'c') && at(i + 1) == '"') {
            i += if ch == '"' { 1 } else { 2 };
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    i += 1;
                }
                if at(i) == '\n' {
                    line += 1;
                }
                i += 1;
            }
            i += 1;
        } else if (ch == 'r' || ((ch == 'b' || ch == 'c') && at(i + 1) == 'r'))
            && matches!(at(i + 1 + usize::from(ch != 'r')), '"' | '#')
            && raw_string_start(&c, i + 1 + usize::from(ch != 'r')).is_some()
        {
            let start = i + 1 + usize::from(ch != 'r');
            let hashes = raw_string_start(&c, start).unwrap_or(0);
            i = start + hashes + 1;
            loop {
                if i >= c.len() {
                    break;
                }
                if c[i] == '"' && (0..hashes).all(|k| at(i + 1 + k) == '#') {
                    i += 1 + hashes;
                    break;
                }
                if c[i] == '\n' {
                    line += 1;
                }
                i += 1;
            }
        } else if ch == '\'' {
            // A character literal ('a', '\n', '\u{..}') or a lifetime ('a).
            if at(i + 1) == '\\' {
                i += 2;
                while i < c.len() && c[i] != '\'' {
                    i += 1;
                }
                i += 1;
            } else if at(i + 2) == '\'' {
                i += 3;
            } else {
                i += 1;
                while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                    i += 1;
                }
            }
        } else if ch.is_ascii_digit() {
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_' || c[i] == '.') {
                if c[i] == '.' && !at(i + 1).is_ascii_digit() {
                    break;
                }
                i += 1;
            }
        } else if ch.is_alphabetic() || ch == '_' {
            let mut j = i;
            // A raw identifier, r#name, is the name.
            if ch == 'r' && at(i + 1) == '#' && (at(i + 2).is_alphabetic() || at(i + 2) == '_') {
                j += 2;
            }
            let start = j;
            while j < c.len() && (c[j].is_alphanumeric() || c[j] == '_') {
                j += 1;
            }
            out.push((line, Tok::Ident(c[start..j].iter().collect())));
            i = j;
        } else {
            out.push((line, Tok::Punct(ch)));
            i += 1;
        }
    }
    out
}

/// At `i` (after `r`), the number of `#` of a raw string's start
/// (`#…#"`), or `None` when it is not one.
fn raw_string_start(c: &[char], i: usize) -> Option<usize> {
    let mut n = 0;
    while c.get(i + n) == Some(&'#') {
        n += 1;
    }
    (c.get(i + n) == Some(&'"')).then_some(n)
}

fn is_punct(t: Option<&(usize, Tok)>, p: char) -> bool {
    matches!(t, Some((_, Tok::Punct(q))) if *q == p)
}

/// Everything `text` (an exercise file) may not use, in order.
pub fn refusals(text: &str) -> Vec<Refusal> {
    let toks = tokens(text);
    let mut out = Vec::new();
    let mut refuse = |line: usize, what: String| {
        if !out
            .iter()
            .any(|r: &Refusal| r.line == line && r.what == what)
        {
            out.push(Refusal { line, what });
        }
    };
    for (k, (line, tok)) in toks.iter().enumerate() {
        let Tok::Ident(name) = tok else {
            continue;
        };
        let next = toks.get(k + 1);
        match name.as_str() {
            "extern" => refuse(
                *line,
                "`extern` (foreign functions and other crates are not part of an exercise)".into(),
            ),
            "include" | "include_str" | "include_bytes" if is_punct(next, '!') => refuse(
                *line,
                format!("`{name}!` (an exercise reads no other file)"),
            ),
            "path"
                if k >= 2
                    && is_punct(toks.get(k - 1), '[')
                    && (is_punct(toks.get(k - 2), '#')
                        || (is_punct(toks.get(k - 2), '!')
                            && k >= 3
                            && is_punct(toks.get(k - 3), '#'))) =>
            {
                refuse(*line, "`#[path]` (an exercise reads no other file)".into())
            }
            "mod" if matches!(next, Some((_, Tok::Ident(_)))) && is_punct(toks.get(k + 2), ';') => {
                refuse(
                    *line,
                    "`mod name;` (an exercise is one file: write the module inline)".into(),
                )
            }
            "std" | "core" | "alloc" => {
                let path = is_punct(next, ':') && is_punct(toks.get(k + 2), ':');
                if !path {
                    refuse(
                        *line,
                        format!("`{name}` other than as a path (`{name}::…`)"),
                    );
                    continue;
                }
                match toks.get(k + 3) {
                    Some((_, Tok::Ident(module))) if DENIED.contains(&module.as_str()) => {
                        refuse(*line, denied(name, module))
                    }
                    Some((_, Tok::Ident(_))) => {}
                    Some((_, Tok::Punct('{'))) => {
                        // A group: every name inside it, at any depth.
                        let mut depth = 0;
                        for (l, t) in &toks[k + 3..] {
                            match t {
                                Tok::Punct('{') => depth += 1,
                                Tok::Punct('}') => {
                                    depth -= 1;
                                    if depth == 0 {
                                        break;
                                    }
                                }
                                Tok::Ident(m) if DENIED.contains(&m.as_str()) => {
                                    refuse(*l, denied(name, m))
                                }
                                Tok::Ident(m) if m == "self" => refuse(
                                    *l,
                                    format!("`{name}::{{self}}` (naming `{name}` by another name)"),
                                ),
                                _ => {}
                            }
                        }
                    }
                    _ => refuse(
                        *line,
                        format!("`{name}::` followed by something else than a module"),
                    ),
                }
            }
            _ => {}
        }
    }
    out
}

fn denied(root: &str, module: &str) -> String {
    format!(
        "`{root}::{module}` (an exercise does not start processes or threads, or reach files, \
         the environment, the network or the operating system)"
    )
}
