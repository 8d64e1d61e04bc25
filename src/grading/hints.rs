//! Hints in tiers, as rustlings gives them: a failure shows the first
//! nudge (which slide, which idea); `cargo grade --hint chN/name` shows the next
//! tier each time it is asked, and the formula only at the last. Which
//! tier a student has seen is remembered in `<out>/hints-seen.txt`, one
//! `chN/name tier` per line.

use std::collections::BTreeMap;
use std::path::Path;

use crate::exercise::Exercise;

/// The file that remembers the tiers seen, inside the grader's output dir.
pub const FILE: &str = "hints-seen.txt";

/// The tiers seen so far, by exercise id (1 = the nudge only).
pub fn seen(out: &Path) -> BTreeMap<String, usize> {
    let text = std::fs::read_to_string(out.join(FILE)).unwrap_or_default();
    text.lines()
        .filter_map(|l| {
            let (id, n) = l.split_once(' ')?;
            Some((id.to_string(), n.trim().parse().ok()?))
        })
        .collect()
}

/// Shows the next tier of `ex`'s hints and remembers it: the text to print.
pub fn next_hint(ex: &Exercise, out: &Path) -> std::io::Result<String> {
    let mut seen = seen(out);
    let hints = ex.hints();
    let last = hints.len();
    let tier = (seen.get(&ex.id()).copied().unwrap_or(1) + 1).min(last);
    seen.insert(ex.id(), tier);
    let text: String = seen.iter().map(|(id, n)| format!("{id} {n}\n")).collect();
    crate::safe_out::write(&out.join(FILE), text.as_bytes()).map_err(std::io::Error::other)?;
    let mut s = format!("{} hint {tier} of {last}: {}\n", ex.id(), hints[tier - 1]);
    if tier == last {
        s += "that was the last hint: the formula itself. Try writing it without looking again.\n";
    } else {
        s += &format!("for the next: cargo grade --hint {}\n", ex.id());
    }
    Ok(s)
}
