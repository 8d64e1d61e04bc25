//! Unit tests of `src/core/table.rs`.

use raystep::core::table::*;

#[test]
fn wrap_breaks_at_spaces_with_a_hanging_indent() {
    let w = wrap("aaa bbb ccc ddd", "  ", "    ", 10);
    assert_eq!(w, "  aaa bbb\n    ccc\n    ddd\n");
    // A word longer than a line gets a line of its own.
    assert_eq!(wrap("x 0123456789ab y", "", "", 8), "x\n0123456789ab\ny\n");
}

#[test]
fn wide_tables_keep_within_the_columns() {
    let mut t = Table::new("t", &["name", "value", "notes"]);
    t.row(vec!["a".into(), "1".into(), "note ".repeat(30)]);
    let text = t.to_text();
    assert!(text.lines().all(|l| l.chars().count() <= COLUMNS), "{text}");
    // The notes go under their row.
    assert!(text.contains("  a     1\n      notes: note note"), "{text}");
    let mut wide = Table::new("w", &["case", "expected", "measured"]);
    wide.row(vec!["c".into(), "e ".repeat(60), "m ".repeat(60)]);
    let text = wide.to_text();
    assert!(text.lines().all(|l| l.chars().count() <= COLUMNS), "{text}");
    assert!(text.contains("  - case: c\n      expected: e e"), "{text}");
}
