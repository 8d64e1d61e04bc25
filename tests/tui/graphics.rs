//! Which picture the preview uses, from the environment alone: a graphics
//! protocol only where the terminal is known to speak it and reports its
//! cell size, never inside tmux or screen; half blocks otherwise.

use std::collections::HashMap;

use raystep::tui::graphics::{detect, picker, Graphics};

fn with(vars: &[(&str, &str)], font: Option<(u16, u16)>) -> Graphics {
    let map: HashMap<String, String> = vars
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    detect(&|k| map.get(k).cloned(), font)
}

const FONT: Option<(u16, u16)> = Some((9, 18));

#[test]
fn known_terminals_get_their_protocol() {
    assert_eq!(with(&[("TERM", "xterm-kitty")], FONT), Graphics::Kitty);
    assert_eq!(with(&[("KITTY_WINDOW_ID", "3")], FONT), Graphics::Kitty);
    assert_eq!(with(&[("TERM_PROGRAM", "WezTerm")], FONT), Graphics::Kitty);
    assert_eq!(
        with(&[("TERM_PROGRAM", "iTerm.app")], FONT),
        Graphics::Iterm2
    );
    assert_eq!(with(&[("LC_TERMINAL", "iTerm2")], FONT), Graphics::Iterm2);
    assert_eq!(with(&[("TERM", "foot")], FONT), Graphics::Sixel);
    // Over ssh only TERM comes along, and it is enough.
    assert_eq!(
        with(
            &[("TERM", "xterm-kitty"), ("SSH_CONNECTION", "a b c d")],
            FONT
        ),
        Graphics::Kitty
    );
}

#[test]
fn everything_else_gets_half_blocks() {
    assert_eq!(
        with(&[("TERM", "xterm-256color")], FONT),
        Graphics::HalfBlocks
    );
    assert_eq!(with(&[], FONT), Graphics::HalfBlocks);
    // Inside a multiplexer, whatever the outer terminal.
    assert_eq!(
        with(
            &[("TERM", "xterm-kitty"), ("TMUX", "/tmp/tmux-0/default,1,0")],
            FONT
        ),
        Graphics::HalfBlocks
    );
    assert_eq!(
        with(&[("TERM_PROGRAM", "iTerm.app"), ("STY", "1.pts-0")], FONT),
        Graphics::HalfBlocks
    );
    // No cell size in pixels: no picture can be placed.
    assert_eq!(with(&[("TERM", "xterm-kitty")], None), Graphics::HalfBlocks);
    // An empty variable is an unset one.
    assert_eq!(
        with(&[("TERM", "xterm-kitty"), ("TMUX", "")], FONT),
        Graphics::Kitty
    );
}

#[test]
fn half_blocks_need_no_picker() {
    assert!(picker(Graphics::HalfBlocks, (9, 18)).is_none());
    assert!(picker(Graphics::Kitty, (9, 18)).is_some());
}

#[test]
fn with_a_picker_the_preview_is_sent_as_a_kitty_image() {
    use ratatui::backend::TestBackend;
    use ratatui::Terminal;
    use raystep::tui::app::{App, Msg};
    use raystep::tui::scenes::SceneEntry;
    use raystep::tui::update::update;
    use raystep::tui::worker::{Progress, RenderState};

    let ch1 = raystep::chapters::all()[0];
    let app = App::new(vec![ch1], vec![SceneEntry::builtin()], true);
    let job = app.job().unwrap();
    let mut render = ch1.start(job.scene, &job.settings).unwrap();
    while !render.pass().complete {}
    let snap = RenderState::capture(&*render, job.generation, Default::default(), true);
    let mut app = update(app, Msg::Progress(Progress::State(Box::new(snap))));
    let cells = |app: &App| {
        let mut t = Terminal::new(TestBackend::new(100, 40)).unwrap();
        t.draw(|f| raystep::tui::view::view(app, f)).unwrap();
        let buffer = t.backend().buffer().clone();
        buffer
            .content()
            .iter()
            .map(|c| c.symbol().to_string())
            .collect::<String>()
    };
    let plain = cells(&app);
    assert!(plain.contains('▀') && !plain.contains("\u{1b}_G"));
    app.graphics = Graphics::Kitty;
    app.picker = picker(Graphics::Kitty, (8, 16));
    let kitty = cells(&app);
    assert!(kitty.contains("\u{1b}_G"), "a kitty graphics escape");
    assert!(kitty.contains("kitty graphics"), "the title says so");
    assert!(!kitty.contains('▀'), "no half blocks");
}
