//! A/B flip: `f` flips the preview between the render and the reference
//! (from a difference view it goes to the reference), at 80x24, 100x30
//! and 160x48, with the title and the key bar saying so.

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use raystep::tui::app::{App, Compare, Msg};
use raystep::tui::keys::msg_for_key;
use raystep::tui::update::update;

use super::layout_and_keys::{app as fake_app, draw, rendered};

fn press(app: App, c: char) -> App {
    let msg = msg_for_key(&app, KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE))
        .expect("the key means something");
    update(app, msg)
}

#[test]
fn f_flips_between_render_and_reference_at_every_size() {
    for (w, h) in [(80u16, 24u16), (100, 30), (160, 48)] {
        let app = update(rendered(fake_app()), Msg::Resize(w, h));
        let before = draw(&app, w, h);
        assert!(
            before.contains("f flip"),
            "the key bar names it, {w}x{h}:\n{before}"
        );
        let flipped = press(app, 'f');
        assert_eq!(flipped.compare, Compare::Reference);
        let screen = draw(&flipped, w, h);
        let title = screen.lines().next().unwrap();
        assert!(title.contains("reference"), "{w}x{h}: {title}");
        assert_ne!(screen, before, "{w}x{h}: the picture changes");
        let back = press(flipped, 'f');
        assert_eq!(back.compare, Compare::Render);
        assert_eq!(draw(&back, w, h), before, "{w}x{h}: flipped back exactly");
        // From a difference view, f shows the reference.
        let diff = press(press(back, 'r'), 'r');
        assert_eq!(diff.compare, Compare::Difference);
        assert_eq!(press(diff, 'f').compare, Compare::Reference);
    }
}

#[test]
fn f_does_nothing_without_a_reference() {
    let ch1 = raystep::chapters::all()[0];
    let app = App::new(
        vec![ch1],
        vec![raystep::tui::scenes::SceneEntry::builtin()],
        false,
    );
    let app = press(app, 'f');
    assert_eq!(app.compare, Compare::Render);
}
