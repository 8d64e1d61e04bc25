//! Inspect mode on chapter 6: the cursor moves and stays on the image,
//! and the panel tells the pixel's story (mean, standard error, its light
//! by bounce adding up to the whole, the reference and the difference).

use std::sync::Arc;
use std::time::Duration;

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use raystep::core::stage::Settings;
use raystep::scene::Scene;
use raystep::tui::app::{App, Msg};
use raystep::tui::inspect::inspect_lines;
use raystep::tui::keys::msg_for_key;
use raystep::tui::scenes::SceneEntry;
use raystep::tui::update::update;
use raystep::tui::worker::{Progress, Snapshot};

/// Chapter 6 on the 64x64 Cornell box (the stored reference's size), 2 spp.
fn rendered() -> App {
    let ch6 = raystep::chapters::all()[5];
    let scene = Scene::builtin().with_resolution(64, 64).unwrap();
    let entry = SceneEntry {
        name: "cornell-box".into(),
        source: "<built-in>".into(),
        scene: Ok(Arc::new(scene)),
    };
    let app = App::new(vec![ch6], vec![entry], false);
    let job = app.job().unwrap();
    let settings = Settings {
        spp: 2,
        ..Settings::default()
    };
    let mut render = ch6
        .start_variant(job.scene, &settings, job.variant)
        .unwrap();
    while !render.pass() {}
    let snap = Snapshot::capture(ch6, &*render, job.generation, Duration::ZERO, true);
    update(app, Msg::Progress(Progress::Snapshot(Box::new(snap))))
}

#[test]
fn the_cursor_starts_in_the_middle_and_stays_on_the_image() {
    let app = update(rendered(), Msg::ToggleInspect);
    assert_eq!(app.inspect, Some((32, 32)));
    let app = update(app, Msg::CursorMove(-100, 5));
    assert_eq!(app.inspect, Some((0, 37)));
    let app = update(app, Msg::CursorMove(100, 100));
    assert_eq!(app.inspect, Some((63, 63)));
    let app = update(app, Msg::ToggleInspect);
    assert_eq!(app.inspect, None);
    // Nothing to inspect before the first picture.
    let ch6 = raystep::chapters::all()[5];
    let empty = App::new(vec![ch6], vec![SceneEntry::builtin()], false);
    assert_eq!(update(empty, Msg::ToggleInspect).inspect, None);
}

#[test]
fn keys_move_the_cursor_while_inspecting_and_the_lists_otherwise() {
    let app = rendered();
    let key = |c, m| KeyEvent::new(c, m);
    let none = KeyModifiers::NONE;
    assert!(matches!(
        msg_for_key(&app, key(KeyCode::Char('k'), none)),
        Some(Msg::Up)
    ));
    assert!(matches!(
        msg_for_key(&app, key(KeyCode::Char('i'), none)),
        Some(Msg::ToggleInspect)
    ));
    let app = update(app, Msg::ToggleInspect);
    let moved = |k| match msg_for_key(&app, k) {
        Some(Msg::CursorMove(dx, dy)) => (dx, dy),
        _ => panic!("{k:?} does not move the cursor"),
    };
    assert_eq!(moved(key(KeyCode::Char('k'), none)), (0, -1));
    assert_eq!(moved(key(KeyCode::Char('l'), none)), (1, 0));
    assert_eq!(moved(key(KeyCode::Left, none)), (-1, 0));
    assert_eq!(moved(key(KeyCode::Down, KeyModifiers::SHIFT)), (0, 8));
    assert_eq!(moved(key(KeyCode::Char('H'), KeyModifiers::SHIFT)), (-8, 0));
    assert!(matches!(
        msg_for_key(&app, key(KeyCode::Esc, none)),
        Some(Msg::ToggleInspect)
    ));
}

#[test]
fn the_panel_tells_the_pixels_story() {
    let app = update(rendered(), Msg::ToggleInspect);
    let lines = inspect_lines(&app);
    let text = lines.join("\n");
    assert_eq!(lines[0], "pixel (32, 32)");
    assert!(text.contains("image: "), "{text}");
    assert!(text.contains("± std error: "), "{text}");
    assert!(text.contains(" direct: "), "{text}");
    assert!(text.contains("reference: "), "{text}");
    assert!(text.contains("difference: "), "{text}");
    // The bounce shares of a pixel add up to all of its light.
    let shares: f64 = lines
        .iter()
        .filter(|l| l.starts_with(' ') && l.ends_with('%'))
        .map(|l| {
            l.rsplit(": ")
                .next()
                .unwrap()
                .trim_end_matches('%')
                .parse::<f64>()
                .unwrap()
        })
        .sum();
    assert!((shares - 100.0).abs() < 0.5, "{shares}: {text}");
    // The panel and the cursor are drawn.
    let mut t = ratatui::Terminal::new(ratatui::backend::TestBackend::new(120, 40)).unwrap();
    t.draw(|f| raystep::tui::view::view(&app, f)).unwrap();
    let screen: String = t
        .backend()
        .buffer()
        .content()
        .iter()
        .map(|c| c.symbol().to_string())
        .collect();
    assert!(screen.contains("pixel (i: close)"));
    assert!(screen.contains("pixel (32, 32)"));
    assert!(screen.contains('+'));
}
