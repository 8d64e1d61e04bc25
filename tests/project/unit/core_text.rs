//! Unit tests of `src/core/text.rs`.

use raystep::core::text::*;

#[test]
fn escapes_controls_and_keeps_the_rest() {
    assert_eq!(escape("plain é ✓"), "plain é ✓");
    assert_eq!(escape("\u{1b}[2J\u{7}a\tb\n"), "\\u{1b}[2J\\u{7}a\\tb\\n");
    assert_eq!(escape("\u{9b}x\u{202e}"), "\\u{9b}x\\u{202e}");
    assert_eq!(escape_keep_newlines("a\nb\u{1b}"), "a\nb\\u{1b}");
}
