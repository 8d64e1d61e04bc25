//! The warp view (`w`): chapter 5's sampling routines tested in the
//! terminal at every size, its keys, and Esc closing it without quitting.

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::backend::TestBackend;
use ratatui::Terminal;
use raystep::tui::app::{App, Msg};
use raystep::tui::keys::msg_for_key;
use raystep::tui::scenes::SceneEntry;
use raystep::tui::update::update;
use raystep::tui::view::view;

/// A key, then what the event loop does in its thread: a built-in
/// routine's pending test drawn and answered.
fn key(app: App, code: KeyCode) -> App {
    let msg = msg_for_key(&app, KeyEvent::new(code, KeyModifiers::NONE));
    let app = match msg {
        Some(m) => update(app, m),
        None => app,
    };
    match app
        .warp
        .as_ref()
        .and_then(|w| w.pending.map(|s| (w.index, s)))
    {
        Some((index, seed)) => {
            assert!(
                app.warp.as_ref().unwrap().test.is_err(),
                "drawn off the UI thread"
            );
            let test = raystep::tui::warp::builtin_test(index, seed).unwrap();
            update(app, Msg::WarpBuiltin(index, seed, Box::new(test)))
        }
        None => app,
    }
}

fn draw(app: &App, w: u16, h: u16) -> String {
    let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
    terminal.draw(|f| view(app, f)).unwrap();
    let buffer = terminal.backend().buffer();
    let mut out = String::new();
    for y in 0..buffer.area.height {
        for x in 0..buffer.area.width {
            out.push_str(buffer[(x, y)].symbol());
        }
        out.push('\n');
    }
    out
}

#[test]
fn the_warp_view_tests_each_routine_at_every_size() {
    let app = App::new(raystep::chapters::all(), vec![SceneEntry::builtin()], false);
    let app = key(app, KeyCode::Char('w'));
    let w = app.warp.as_ref().expect("w opens the warp view");
    let t = w.test.as_ref().unwrap();
    assert_eq!(t.name, "uniform hemisphere");
    assert!(t.passes(), "{}", t.verdict());
    for (width, height) in [(80, 24), (100, 30), (160, 48)] {
        let t = draw(&app, width, height);
        assert!(t.contains("warp test 1/7: uniform hemisphere"), "{t}");
        assert!(t.contains("accepted"), "{width}x{height}:\n{t}");
        assert!(t.contains("←/→ routine · n new numbers · Esc close"), "{t}");
        assert!(t.contains("drawn per cell"), "{width}x{height}:\n{t}");
        assert!(t.contains("the pdf's prediction"), "{width}x{height}:\n{t}");
        assert!(
            t.contains("directions from above"),
            "{width}x{height}:\n{t}"
        );
        // Braille points are drawn.
        assert!(
            t.chars().any(|c| ('\u{2801}'..='\u{28ff}').contains(&c)),
            "{t}"
        );
    }
    insta::assert_snapshot!("warp_80x24", draw(&app, 80, 24));

    // → the next routine, ← back, n new numbers.
    let test = |app: &App| app.warp.as_ref().unwrap().test.clone().unwrap();
    let app = key(app, KeyCode::Right);
    assert_eq!(test(&app).name, "cosine hemisphere");
    let app = key(app, KeyCode::Right);
    assert_eq!(test(&app).name, "area light");
    assert!(test(&app).passes(), "{}", test(&app).verdict());
    assert!(draw(&app, 100, 30).contains("warp test 3/7: area light"));
    // The glossy and semi-gloss lobes, with their parameters.
    let app = key(app, KeyCode::Right);
    assert!(test(&app).name.starts_with("glossy lobe (n = 20"));
    assert!(test(&app).passes(), "{}", test(&app).verdict());
    let app = key(app, KeyCode::Right);
    assert!(test(&app).name.starts_with("semi-gloss paint (ks = 0.3"));
    assert!(test(&app).passes(), "{}", test(&app).verdict());
    // The square light again, by the solid angle it covers.
    let app = key(app, KeyCode::Right);
    assert_eq!(test(&app).name, "area light, by solid angle");
    assert!(test(&app).passes(), "{}", test(&app).verdict());
    // The student's routine: asked of the event loop, which builds and
    // runs it in a thread; its draws are tested against cos θ / π.
    let app = key(app, KeyCode::Right);
    let w = app.warp.as_ref().unwrap();
    assert_eq!(w.student_requested, Some(1));
    let t = draw(&app, 80, 24);
    assert!(t.contains("warp test 7/7: your cosine_hemisphere"), "{t}");
    assert!(
        t.contains("building and running your cosine_hemisphere"),
        "{t}"
    );
    let drawn = raystep::core::warp_test::draw(
        &|u| Some(raystep::ch5_reflection::warp::cosine_hemisphere(u)),
        20_000,
        1,
    );
    let mut stale = (**app.warp.as_ref().unwrap()).clone();
    stale.student_drawn(7, Ok(drawn.clone()));
    assert!(stale.test.is_err(), "an answer for another seed is dropped");
    let mut failed = stale.reseeded();
    failed.student_drawn(2, Err("ch5/cosine_hemisphere: not started (todo!)".into()));
    assert_eq!(
        failed.test,
        Err("ch5/cosine_hemisphere: not started (todo!)".to_string())
    );
    let app = update(app, Msg::WarpStudent(1, Ok(drawn)));
    assert!(test(&app).passes(), "{}", test(&app).verdict());
    assert_eq!(app.warp.as_ref().unwrap().student_requested, None);
    let mut app = app;
    let shown = app.warp.replace(Box::new(failed));
    assert!(draw(&app, 80, 24).contains("not started (todo!)"));
    app.warp = shown;
    let app = key(app, KeyCode::Right);
    assert_eq!(app.warp.as_ref().unwrap().index, 0, "wraps around");
    let app = key(app, KeyCode::Left);
    let app = key(app, KeyCode::Left);
    assert_eq!(app.warp.as_ref().unwrap().index, 5);
    let before = test(&app).observed;
    let app = key(app, KeyCode::Char('n'));
    assert_eq!(app.warp.as_ref().unwrap().seed, 2);
    assert_ne!(test(&app).observed, before, "new numbers, new counts");
    // Keys of the main view do nothing while it is open; Esc closes it
    // and the app goes on.
    let chapter = app.chapter;
    let app = key(app, KeyCode::Char('3'));
    assert_eq!(app.chapter, chapter);
    let app = key(app, KeyCode::Esc);
    assert!(app.warp.is_none());
    assert!(!app.quit, "Esc closes the view, it does not quit");
    assert!(!draw(&app, 80, 24).contains("warp test"));
}

#[test]
fn the_book_states_the_warp_tests_constants() {
    use raystep::core::warp_test::{COS_CELLS, DEFAULT_DRAWS, PHI_CELLS, SIGNIFICANCE};
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("book/src/running.md");
    let book = std::fs::read_to_string(path).unwrap().replace('\n', " ");
    assert_eq!(DEFAULT_DRAWS, 100_000);
    assert!(book.contains("It draws 100,000 directions"));
    assert!(book.contains(&format!("each of {COS_CELLS} × {PHI_CELLS} cells")));
    assert!(book.contains(&format!("a p-value below {SIGNIFICANCE} rejects")));
}

/// A student build the view no longer wants stops: the event loop sets its
/// cancel flag when a newer request comes (or the view closes), and the
/// build ends at once with a cancellation, not minutes later.
#[test]
fn a_cancelled_student_build_stops_at_once() {
    let dir = crate::common::temp_dir("warp-cancel");
    let cancel = std::sync::atomic::AtomicBool::new(true);
    let start = std::time::Instant::now();
    let out = raystep::tui::warp::student_draws(&dir, 1, &cancel);
    let Err(e) = out else {
        panic!("a cancelled build draws nothing")
    };
    assert!(e.contains("cancel"), "{e}");
    assert!(
        start.elapsed() < std::time::Duration::from_secs(30),
        "{:?}",
        start.elapsed()
    );
    let _ = std::fs::remove_dir_all(dir);
}

/// What the view asks of the event loop: opening it, another routine or
/// new numbers draw the routine shown (once); the student's routine is
/// built, and its build cancelled when the view moves on or closes.
#[test]
fn the_view_asks_for_the_draws_it_shows() {
    use raystep::tui::effect::Effect;
    let effects_of = |mut app: App, msg| {
        app.effects.clear();
        let mut app = update(app, msg);
        let effects = std::mem::take(&mut app.effects);
        (app, effects)
    };
    let app = App::new(raystep::chapters::all(), vec![SceneEntry::builtin()], false);
    let (app, asked) = effects_of(app, Msg::ToggleWarp);
    assert!(
        matches!(asked[..], [Effect::WarpBuiltin { index: 0, seed: 1 }]),
        "{asked:?}"
    );
    let (app, asked) = effects_of(app, Msg::WarpReseed);
    assert!(
        matches!(asked[..], [Effect::WarpBuiltin { index: 0, seed: 2 }]),
        "{asked:?}"
    );
    // The student's routine is the last: built with the same seed, and
    // cancelled when the view closes.
    let (app, asked) = effects_of(app, Msg::WarpStep(-1));
    assert!(
        matches!(asked[..], [Effect::WarpStudent(Some(2))]),
        "{asked:?}"
    );
    let (app, asked) = effects_of(app, Msg::ToggleWarp);
    assert!(app.warp.is_none());
    assert!(
        matches!(asked[..], [Effect::WarpStudent(None)]),
        "{asked:?}"
    );
    let (_, asked) = effects_of(app, Msg::WarpReseed);
    assert!(asked.is_empty(), "closed: {asked:?}");
}

/// The event loop's part, as it runs it: opening the view draws the
/// first routine in a thread once, and the answer comes back as the
/// message that fills the view.
#[test]
fn the_threads_draw_a_builtin_routine_once() {
    let mut threads = raystep::tui::threads::Threads::spawn();
    let app = App::new(raystep::chapters::all(), vec![SceneEntry::builtin()], false);
    let mut app = threads.handle(app, Msg::ToggleWarp);
    assert!(
        app.warp.as_ref().unwrap().test.is_err(),
        "not drawn on the UI thread"
    );
    let start = std::time::Instant::now();
    let mut answers = 0;
    while app.warp.as_ref().unwrap().test.is_err() {
        assert!(start.elapsed().as_secs() < 60, "no answer");
        for msg in threads.messages(&app) {
            answers += 1;
            app = threads.handle(app, msg);
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    assert_eq!(answers, 1, "started once, answered once");
    let t = app.warp.as_ref().unwrap().test.as_ref().unwrap();
    assert_eq!(t.name, "uniform hemisphere");
    assert!(t.passes());
    std::thread::sleep(std::time::Duration::from_millis(50));
    assert!(threads.messages(&app).is_empty(), "nothing more to do");
}
