//! Strings from files and flags, made safe to print on a terminal.
//!
//! A scene file can name a material `"\u001b[2J"`: printed as it is, the
//! escape sequence would clear the screen or throw a terminal UI out of its
//! alternate screen. Everything a user's file or flag says that raystep
//! echoes (errors, warnings, names in the UI) goes through [`escape`], which
//! writes control characters as visible Rust-style escapes.

use std::borrow::Cow;
use std::fmt;

/// `s` with every control character (C0, DEL, C1, and the Unicode line and
/// paragraph separators and bidirectional overrides that reorder text)
/// written as `\u{..}`, `\n`, `\r` or `\t`. Borrowed when nothing changes.
pub fn escape(s: &str) -> Cow<'_, str> {
    if !s.chars().any(needs_escape) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        push_escaped(&mut out, c);
    }
    Cow::Owned(out)
}

/// [`escape`], but keeping line breaks (`\n`), for multi-line messages.
pub fn escape_keep_newlines(s: &str) -> Cow<'_, str> {
    if !s.chars().any(|c| c != '\n' && needs_escape(c)) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if c == '\n' {
            out.push(c);
        } else {
            push_escaped(&mut out, c);
        }
    }
    Cow::Owned(out)
}

/// Characters of a name an error message quotes in full; a longer one is
/// cut ([`shorten`]).
pub const NAME_CHARS: usize = 96;

/// `s` if it has at most `max` characters; else its first `max - 24` and
/// how many there were (`abc… (1000000 characters)`).
pub fn shorten(s: &str, max: usize) -> Cow<'_, str> {
    match s.char_indices().nth(max) {
        None => Cow::Borrowed(s),
        Some(_) => {
            let keep = max.saturating_sub(24).max(1);
            let cut = s.char_indices().nth(keep).map_or(s.len(), |(i, _)| i);
            Cow::Owned(format!("{}… ({} characters)", &s[..cut], s.chars().count()))
        }
    }
}

fn needs_escape(c: char) -> bool {
    c.is_control()
        || matches!(c, '\u{2028}' | '\u{2029}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

fn push_escaped(out: &mut String, c: char) {
    use std::fmt::Write;
    match c {
        '\n' => out.push_str("\\n"),
        '\r' => out.push_str("\\r"),
        '\t' => out.push_str("\\t"),
        c if needs_escape(c) => {
            let _ = write!(out, "\\u{{{:x}}}", c as u32);
        }
        c => out.push(c),
    }
}

/// Displays a string with [`escape`] applied, for `format!` arguments.
pub struct Escaped<'a>(pub &'a str);

impl fmt::Display for Escaped<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&escape(self.0))
    }
}
