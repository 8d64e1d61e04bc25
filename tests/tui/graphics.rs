//! Which picture the preview uses: the terminal's answers to the query
//! first, the environment as the fallback, a forced `--graphics` choice
//! followed where it can work (with a note where it cannot), and never a
//! protocol inside tmux or screen.

use std::collections::HashMap;

use raystep::tui::graphics::{choose, detect, should_query, Answer, Choice, Graphics};
use raystep::tui::query::{parse, QUERY};

fn env(vars: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
    let map: HashMap<String, String> = vars
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    move |k| map.get(k).cloned()
}

fn with(vars: &[(&str, &str)], font: Option<(u16, u16)>) -> Graphics {
    detect(&env(vars), font)
}

const FONT: Option<(u16, u16)> = Some((9, 18));

// The answers below were recorded under Xvfb (Debian 12) by writing
// `QUERY` to /dev/tty in raw mode and reading until the status report.

/// kitty 0.26.5: graphics OK, XTVERSION, DA1 without sixel, the cell
/// size, the status report.
const KITTY_026: &str =
    "\x1b_Gi=31;OK\x1b\\\x1bP>|kitty(0.26.5)\x1b\\\x1b[?62;c\x1b[6;20;9t\x1b[0n";
/// `xterm -ti vt340` (XTerm 379): sixel (4) in DA1; no cell size (xterm
/// refuses window reports by default: the window size gives it).
const XTERM_VT340: &str = "\x1bP>|XTerm(379)\x1b\\\x1b[?63;1;2;4;6;9;15;16;22;28c\x1b[0n";
/// Plain `xterm` (XTerm 379): DA1 without sixel.
const XTERM: &str = "\x1bP>|XTerm(379)\x1b\\\x1b[?64;1;2;6;9;15;16;17;18;21;22;28c\x1b[0n";

#[test]
fn the_answers_are_read_from_real_terminals_replies() {
    let (kitty, done) = parse(KITTY_026.as_bytes());
    assert!(done);
    assert_eq!(
        kitty,
        Answer {
            kitty: true,
            sixel: false,
            font: Some((9, 20)),
            version: Some("kitty(0.26.5)".into()),
        }
    );
    let (xterm, _) = parse(XTERM_VT340.as_bytes());
    assert!(xterm.sixel && !xterm.kitty);
    assert_eq!(xterm.font, None);
    assert_eq!(xterm.version.as_deref(), Some("XTerm(379)"));
    let (plain, _) = parse(XTERM.as_bytes());
    assert!(!plain.sixel && !plain.kitty && plain.font.is_none());
    // Not complete until the status report arrives.
    assert!(!parse(&KITTY_026.as_bytes()[..20]).1);
    assert!(
        QUERY.ends_with("\x1b[5n"),
        "the status report ends the query"
    );
}

#[test]
fn the_query_answers_choose_the_protocol() {
    let none = env(&[("TERM", "xterm-256color")]);
    let a = |s: &str| parse(s.as_bytes()).0;
    let chosen = choose(Choice::Auto, &none, None, Some(&a(KITTY_026)));
    assert_eq!(chosen.graphics, Graphics::Kitty);
    assert_eq!(chosen.font, Some((9, 20)), "the cell size from the answer");
    // Plain xterm with sixel: TERM says nothing, the attributes do; the
    // cell size comes from the window size.
    let chosen = choose(Choice::Auto, &none, FONT, Some(&a(XTERM_VT340)));
    assert_eq!((chosen.graphics, chosen.font), (Graphics::Sixel, FONT));
    let chosen = choose(Choice::Auto, &none, None, Some(&a(XTERM_VT340)));
    assert_eq!(chosen.graphics, Graphics::HalfBlocks, "no size, no picture");
    // The window size's cell size serves when the answer has none.
    let chosen = choose(Choice::Auto, &none, FONT, Some(&a(XTERM)));
    assert_eq!(chosen.graphics, Graphics::HalfBlocks);
    let sixel_no_size = Answer {
        sixel: true,
        ..Answer::default()
    };
    let chosen = choose(Choice::Auto, &none, FONT, Some(&sixel_no_size));
    assert_eq!((chosen.graphics, chosen.font), (Graphics::Sixel, FONT));
    // No cell size anywhere: half blocks.
    let chosen = choose(Choice::Auto, &none, None, Some(&sixel_no_size));
    assert_eq!(chosen.graphics, Graphics::HalfBlocks);
    // WezTerm answers kitty's query, but ratatui-image's table (and ours)
    // says iTerm2.
    let wez = env(&[("TERM_PROGRAM", "WezTerm")]);
    let chosen = choose(Choice::Auto, &wez, FONT, Some(&a(KITTY_026)));
    assert_eq!(chosen.graphics, Graphics::Iterm2);
}

#[test]
fn without_an_answer_the_environment_decides() {
    let auto = |vars: &[(&str, &str)]| choose(Choice::Auto, &env(vars), FONT, None).graphics;
    assert_eq!(auto(&[("TERM", "xterm-kitty")]), Graphics::Kitty);
    assert_eq!(auto(&[("TERM", "mlterm")]), Graphics::Sixel);
    assert_eq!(auto(&[("TERM", "xterm-256color")]), Graphics::HalfBlocks);
    assert_eq!(with(&[("TERM", "xterm-kitty")], FONT), Graphics::Kitty);
    assert_eq!(with(&[("KITTY_WINDOW_ID", "3")], FONT), Graphics::Kitty);
    assert_eq!(with(&[("TERM_PROGRAM", "WezTerm")], FONT), Graphics::Iterm2);
    assert_eq!(
        with(&[("TERM_PROGRAM", "iTerm.app")], FONT),
        Graphics::Iterm2
    );
    assert_eq!(with(&[("LC_TERMINAL", "iTerm2")], FONT), Graphics::Iterm2);
    assert_eq!(with(&[("TERM", "foot")], FONT), Graphics::Sixel);
    // Over ssh only TERM comes along, and it is enough.
    let ssh = [("TERM", "xterm-kitty"), ("SSH_CONNECTION", "a b c d")];
    assert_eq!(with(&ssh, FONT), Graphics::Kitty);
    assert_eq!(with(&[("TERM", "xterm-kitty")], None), Graphics::HalfBlocks);
    // An empty variable is an unset one.
    assert_eq!(
        with(&[("TERM", "xterm-kitty"), ("TMUX", "")], FONT),
        Graphics::Kitty
    );
}

#[test]
fn inside_tmux_or_screen_nothing_is_asked_and_half_blocks_are_drawn() {
    let kitty = parse(KITTY_026.as_bytes()).0;
    for vars in [
        vec![("TERM", "xterm-kitty"), ("TMUX", "/tmp/tmux-0/default,1,0")],
        vec![("TERM_PROGRAM", "iTerm.app"), ("STY", "1.pts-0")],
        vec![("TERM", "tmux-256color")],
        vec![("TERM", "screen")],
    ] {
        let e = env(&vars);
        assert!(!should_query(Choice::Auto, &e, FONT), "{vars:?}");
        let chosen = choose(Choice::Auto, &e, FONT, Some(&kitty));
        assert_eq!(chosen.graphics, Graphics::HalfBlocks, "{vars:?}");
        assert_eq!(chosen.note, None);
        // Forced: it cannot work there, and the note says why.
        let forced = choose(Choice::Force(Graphics::Kitty), &e, FONT, None);
        assert_eq!(forced.graphics, Graphics::HalfBlocks);
        assert!(forced.note.unwrap().contains("tmux"));
    }
    assert!(should_query(Choice::Auto, &env(&[]), FONT));
}

#[test]
fn a_forced_protocol_is_followed_where_it_can_work() {
    let plain = env(&[("TERM", "xterm-256color")]);
    for g in [Graphics::Kitty, Graphics::Sixel, Graphics::Iterm2] {
        // Followed, with a note: nothing said this terminal shows such
        // pictures, so a blank preview would otherwise go unexplained.
        let forced = choose(Choice::Force(g), &plain, FONT, None);
        assert_eq!((forced.graphics, forced.font), (g, FONT));
        let note = forced.note.unwrap();
        assert!(
            note.contains(&format!("--graphics {}", g.flag())) && note.contains("blank"),
            "{note}"
        );
        // Without a cell size the picture cannot be placed: half blocks,
        // and a note naming the flag and the reason.
        let no_size = choose(Choice::Force(g), &plain, None, None);
        assert_eq!(no_size.graphics, Graphics::HalfBlocks);
        let note = no_size.note.unwrap();
        assert!(note.contains(&format!("--graphics {}", g.flag())), "{note}");
        assert!(note.contains("no cell size in pixels"), "{note}");
        // A forced kitty or sixel asks the terminal (xterm lists sixel in
        // its answer, not in its environment), so the note is said only
        // where the terminal did not list it; iTerm2, which no answer
        // names, asks only for the missing cell size.
        let asks = g != Graphics::Iterm2;
        assert_eq!(should_query(Choice::Force(g), &plain, FONT), asks, "{g:?}");
        assert!(should_query(Choice::Force(g), &plain, None));
    }
    // Where the environment or the terminal's answer says so, no note.
    let kitty_env = env(&[("TERM", "xterm-kitty")]);
    let forced = choose(Choice::Force(Graphics::Kitty), &kitty_env, FONT, None);
    assert_eq!((forced.graphics, forced.note), (Graphics::Kitty, None));
    let answered = parse(KITTY_026.as_bytes()).0;
    let forced = choose(
        Choice::Force(Graphics::Kitty),
        &plain,
        FONT,
        Some(&answered),
    );
    assert_eq!((forced.graphics, forced.note), (Graphics::Kitty, None));
    // xterm -ti vt340, asked: sixel, and no note.
    let xterm = parse(XTERM_VT340.as_bytes()).0;
    let forced = choose(Choice::Force(Graphics::Sixel), &plain, FONT, Some(&xterm));
    assert_eq!((forced.graphics, forced.note), (Graphics::Sixel, None));
    let half = Choice::Force(Graphics::HalfBlocks);
    let chosen = choose(half, &env(&[("TERM", "xterm-kitty")]), FONT, None);
    assert_eq!((chosen.graphics, chosen.note), (Graphics::HalfBlocks, None));
    assert!(!should_query(half, &plain, None));
    // The flag's names.
    for (name, choice) in [
        ("auto", Choice::Auto),
        ("kitty", Choice::Force(Graphics::Kitty)),
        ("sixel", Choice::Force(Graphics::Sixel)),
        ("iterm2", Choice::Force(Graphics::Iterm2)),
        ("halfblocks", half),
    ] {
        assert_eq!(name.parse::<Choice>(), Ok(choice));
    }
    assert!("vt340".parse::<Choice>().is_err());
}
