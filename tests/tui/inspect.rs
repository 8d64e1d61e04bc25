//! Inspect mode on chapter 6: the cursor moves and stays on the image,
//! and the panel tells the pixel's story (mean, standard error, its light
//! by bounce adding up to the whole, the reference and the difference).

use std::sync::Arc;
use std::time::Duration;

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use raystep::core::stage::{Inspection, Settings};
use raystep::scene::Scene;
use raystep::tui::app::{App, Msg};
use raystep::tui::effect::Effect;
use raystep::tui::inspect::inspect_lines;
use raystep::tui::keys::msg_for_key;
use raystep::tui::scenes::SceneEntry;
use raystep::tui::update::update;
use raystep::tui::worker::{Progress, RenderState};

/// The UI on chapter `chapter` alone, over the built-in Cornell box at
/// `size` x `size` pixels.
fn cornell_app(chapter: &'static dyn raystep::core::stage::Chapter, size: u32) -> App {
    let scene = Scene::builtin().with_resolution(size, size).unwrap();
    app_on(chapter, scene)
}

/// The UI on chapter `chapter` alone, over `scene` (listed as the
/// built-in Cornell box).
pub(crate) fn app_on(chapter: &'static dyn raystep::core::stage::Chapter, scene: Scene) -> App {
    let entry = SceneEntry {
        name: "cornell-box".into(),
        source: "<built-in>".into(),
        scene: Ok(Arc::new(scene)),
        pending: None,
        modified: None,
    };
    App::new(vec![chapter], vec![entry], false)
}

/// The state of the render `app` asks for, rendered by its chapter's real
/// stage to `spp` samples per pixel.
pub(crate) fn render_state(app: &App, spp: u32) -> RenderState {
    let chapter = app.current_chapter().unwrap();
    let job = app.job().unwrap();
    let settings = Settings {
        spp,
        variant: Some(job.variant),
        ..Settings::default()
    };
    let mut render = chapter.start(job.scene, &settings).unwrap();
    while !render.pass().complete {}
    RenderState::capture(&*render, job.generation, Duration::ZERO, true)
}

/// Chapter 6 on the 64x64 Cornell box (the stored reference's size), 2 spp.
pub(crate) fn rendered() -> App {
    let ch6 = raystep::chapters::all()[5];
    let app = cornell_app(ch6, 64);
    // The render is the same every time (same scene, seed and samples):
    // made once per test binary, the many clicks of the click test cost a
    // UI update each, not a render each.
    static SNAPSHOT: std::sync::OnceLock<RenderState> = std::sync::OnceLock::new();
    let snap = SNAPSHOT.get_or_init(|| render_state(&app, 2));
    update(app, Msg::Progress(Progress::State(Box::new(snap.clone()))))
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
    // Esc closes inspect mode (and never quits).
    assert!(matches!(
        msg_for_key(&app, key(KeyCode::Esc, none)),
        Some(Msg::Close)
    ));
    let closed = update(app, Msg::Close);
    assert!(closed.inspect.is_none() && !closed.quit);
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
    assert!(screen.contains("Esc: close"));
    assert!(screen.contains("pixel (32, 32)"));
    assert!(screen.contains('+'));
}

/// The screen as text, one string per row.
fn screen_rows(app: &App, w: u16, h: u16) -> Vec<String> {
    let mut t = ratatui::Terminal::new(ratatui::backend::TestBackend::new(w, h)).unwrap();
    t.draw(|f| raystep::tui::view::view(app, f)).unwrap();
    let buf = t.backend().buffer().clone();
    (0..h)
        .map(|y| (0..w).map(|x| buf[(x, y)].symbol().to_string()).collect())
        .collect()
}

#[test]
fn a_click_on_the_picture_puts_the_cursor_on_that_pixel() {
    // Inspecting: the layout the clicks land on (the panel widens the
    // left column).
    let app = update(rendered(), Msg::ToggleInspect);
    let (w, h) = (120u16, 40u16);
    let screen = ratatui::layout::Rect::new(0, 0, w, h);
    // Click every cell of the screen: inside the picture the cursor goes
    // to a pixel whose drawn cursor is that very cell; outside nothing.
    let mut inside = 0;
    for row in (0..h).step_by(3) {
        for column in (0..w).step_by(7) {
            let click = Msg::Click {
                column,
                row,
                width: w,
                height: h,
            };
            let expected = raystep::tui::view::pixel_at(&app, screen, column, row);
            let after = update(update(rendered(), Msg::ToggleInspect), click.clone());
            match expected {
                Some(p) => {
                    inside += 1;
                    assert_eq!(after.inspect, Some(p));
                    // The cursor is drawn on the clicked cell (on an enlarged
                    // picture: the first cell of that pixel, at most one off).
                    let mut after = after;
                    after.color = true;
                    let rows = screen_rows(&after, w, h);
                    let at: Vec<(usize, usize)> = rows
                        .iter()
                        .enumerate()
                        .flat_map(|(y, r)| {
                            r.chars()
                                .enumerate()
                                .filter(|(_, c)| *c == '+')
                                .map(move |(x, _)| (x, y))
                        })
                        .filter(|&(x, _)| x >= raystep::tui::screen::panel_width(w) as usize)
                        .collect();
                    assert_eq!(at.len(), 1, "{at:?}");
                    let (cx, cy) = at[0];
                    let near = |a: usize, b: u16| a <= b as usize && a + 1 >= b as usize;
                    assert!(
                        near(cx, column) && near(cy, row),
                        "click ({column}, {row}) -> {p:?} drawn at {:?}",
                        at[0]
                    );
                }
                None => assert_eq!(after.inspect, Some((32, 32)), "({column}, {row})"),
            }
        }
    }
    assert!(inside > 20, "{inside}");
    // The picture's corners map to the image's corners, and a click on
    // the sidebar changes nothing.
    let _ = app;
    let app = update(rendered(), Msg::ToggleInspect);
    let side = Msg::Click {
        column: 2,
        row: 2,
        width: w,
        height: h,
    };
    assert_eq!(update(app, side).inspect, Some((32, 32)));
}

#[test]
fn t_traces_a_path_and_the_panel_shows_its_table() {
    // A pixel of the floor, lit by the ceiling light.
    let app = update(
        update(rendered(), Msg::ToggleInspect),
        Msg::CursorMove(0, 18),
    );
    let key = KeyEvent::new(KeyCode::Char('t'), KeyModifiers::NONE);
    let msg = msg_for_key(&app, key).unwrap();
    assert!(matches!(msg, Msg::TracePath));
    let mut app = update(app, msg);
    let asked = std::mem::take(&mut app.effects);
    let [Effect::Trace {
        generation,
        pixel: (x, y),
        sample,
    }] = asked[..]
    else {
        panic!("one trace: {asked:?}")
    };
    assert_eq!((generation, x, y, sample), (app.generation, 32, 50, 0));
    // What the event loop does: ask the running render (through the
    // worker, here directly) for sample `sample` of the pixel.
    let table = inspected(&app, (x, y), sample);
    let app = update(app, Msg::Traced(Ok(Box::new(table))));
    let t = app.trace.as_ref().unwrap();
    assert!(t.lines[1].starts_with("#1 "), "{:?}", t.lines);
    assert!(t.lines.iter().any(|l| l.contains("NEE")), "{:?}", t.lines);
    assert!(t.lines.last().unwrap().starts_with("sum of the + terms"));
    let rows = screen_rows(&app, 160, 50);
    let text = rows.join("\n");
    assert!(text.contains("path: sample 0 of pixel (32, 50)"), "{text}");
    assert!(text.contains("#1 "), "{text}");
    // Again: the next sample; moving the cursor clears the table.
    let app = update(app, Msg::TracePath);
    assert!(
        matches!(
            app.effects[..],
            [Effect::Trace {
                pixel: (32, 50),
                sample: 1,
                ..
            }]
        ),
        "{:?}",
        app.effects
    );
    let app = update(app, Msg::CursorMove(1, 0));
    assert!(app.trace.is_none());
    insta::assert_snapshot!("inspect_trace_160x50", text);
}

/// What the current job's render answers for sample `sample` of `pixel`
/// after its first pass.
pub(crate) fn inspected(app: &App, pixel: (u32, u32), sample: u32) -> Inspection {
    let job = app.job().unwrap();
    let settings = Settings {
        variant: Some(job.variant),
        ..job.settings.clone()
    };
    let mut render = job.chapter.start(job.scene, &settings).unwrap();
    assert!(
        render.inspect(pixel, sample).is_none(),
        "nothing to inspect before the first pass"
    );
    render.pass();
    render.inspect(pixel, sample).unwrap()
}

/// Chapter `n`'s story of sample 0 of `pixel` in `scene`, from its render.
fn story(n: usize, scene: &Arc<Scene>, pixel: (u32, u32)) -> Vec<String> {
    let chapter = raystep::chapters::all()[n - 1];
    let settings = Settings {
        variant: Some(3.min(chapter.info().variants.len().saturating_sub(1))),
        ..Settings::default()
    };
    let mut render = chapter.start(scene.clone(), &settings).unwrap();
    while !render.pass().complete {}
    assert!(
        render.inspect((scene.camera.width, 0), 0).is_none(),
        "outside"
    );
    let i = render.inspect(pixel, 0).unwrap();
    assert_eq!((i.pixel, i.sample), (pixel, 0));
    i.lines
}

#[test]
fn chapters_3_to_5_tell_their_own_story_in_the_panel() {
    let scene = Arc::new(Scene::builtin().with_resolution(32, 32).unwrap());
    let settings = Settings::default();
    let ch3 = story(3, &scene, (16, 20));
    assert!(ch3[0].starts_with("primary ray hits triangle"), "{ch3:?}");
    assert!(ch3.iter().any(|l| l.contains("u = ")));
    let ch4 = story(4, &scene, (16, 20));
    assert!(ch4[0].starts_with("no SDF objects"), "{ch4:?}");
    assert!(ch4[1].starts_with("nearest hit t "), "{ch4:?}");
    // The surface by its scene name, not a Rust name such as Mesh(3).
    assert!(
        ch4[1].contains("(mesh ") && !ch4[1].contains("Mesh("),
        "{ch4:?}"
    );
    let ch5 = story(5, &scene, (16, 20));
    assert!(ch5[0].starts_with("sample 0: L = "), "{ch5:?}");
    assert!(ch5.iter().any(|l| l.starts_with("light 0 area")), "{ch5:?}");
    let sdf = Arc::new(crate::common::shipped_scene("sdf-shapes", 32, 24));
    let ch4 = story(4, &sdf, (16, 12));
    assert!(ch4[0].starts_with("sphere tracing: "), "{ch4:?}");
    assert!(ch4.iter().any(|l| l.starts_with("   0: t 0 f ")), "{ch4:?}");
    let hit = ch4
        .iter()
        .find(|l| l.starts_with("nearest hit t "))
        .unwrap();
    assert!(hit.contains("(sdf ") && !hit.contains("Sdf("), "{hit}");
    // The panel shows the story of the pixel under the cursor.
    let ch3_stage = raystep::chapters::all()[2];
    let entry = SceneEntry {
        name: "cornell-box".into(),
        source: "<built-in>".into(),
        scene: Ok(scene.clone()),
        pending: None,
        modified: None,
    };
    let app = App::new(vec![ch3_stage], vec![entry], false);
    let job = app.job().unwrap();
    let mut render = ch3_stage.start(job.scene, &settings).unwrap();
    while !render.pass().complete {}
    let snap = RenderState::capture(&*render, job.generation, Duration::ZERO, true);
    let app = update(app, Msg::Progress(Progress::State(Box::new(snap))));
    let app = update(app, Msg::ToggleInspect);
    let app = update(app, Msg::CursorMove(0, 4));
    let app = update(app, Msg::Story(16, 20, ch3.clone()));
    let lines = inspect_lines(&app);
    assert!(lines.contains(&ch3[0]), "{lines:?}");
}

#[test]
fn with_a_graphics_protocol_a_click_maps_through_the_scaled_picture() {
    // A 64x64 film with 10x20-pixel cells is enlarged by a whole factor
    // and centred (raystep::tui::placement::place): its corner cells map to
    // its corner pixels, cells beside it miss.
    let mut app = update(rendered(), Msg::ToggleInspect);
    app.color = true;
    app.graphics = raystep::tui::graphics::Graphics::Kitty;
    app.font = Some((10, 20));
    let screen = ratatui::layout::Rect::new(0, 0, 120, 40);
    let preview = raystep::tui::view::areas(&app, screen).preview;
    let inner = ratatui::widgets::Block::bordered().inner(preview);
    let p = raystep::tui::placement::place(inner, 64, 64, (10, 20));
    assert!(p.width >= 128 && p.width.is_multiple_of(64), "{p:?}");
    let r = p.cells;
    let at = |c, r| raystep::tui::view::pixel_at(&app, screen, c, r);
    assert_eq!(at(r.x, r.y), Some((0, 0)));
    assert_eq!(at(r.right() - 1, r.bottom() - 1), Some((63, 63)));
    let (mx, my) = at(r.x + r.width / 2, r.y + r.height / 2).unwrap();
    assert!(mx.abs_diff(32) <= 2 && my.abs_diff(32) <= 2, "({mx}, {my})");
    assert_eq!(at(r.x - 1, r.y), None);
    assert_eq!(at(r.x, r.bottom()), None);
}

/// The panel says which numbers are values and which are colours made for
/// showing: chapter 6's image and standard error are radiance; chapter 3's
/// views (depth, normal, …) are display colours.
#[test]
fn display_colours_are_named_as_such() {
    let ch6 = update(rendered(), Msg::ToggleInspect);
    let lines = inspect_lines(&ch6);
    assert!(lines.iter().any(|l| l.starts_with("image: ")), "{lines:?}");
    assert!(
        !lines.iter().any(|l| l.contains("(display colour)")),
        "{lines:?}"
    );
    let ch3 = raystep::chapters::all()[2];
    let app = cornell_app(ch3, 32);
    let job = app.job().unwrap();
    let mut render = ch3.start(job.scene, &Settings::default()).unwrap();
    while !render.pass().complete {}
    let state = RenderState::capture(&*render, job.generation, Duration::ZERO, true);
    let app = update(app, Msg::Progress(Progress::State(Box::new(state))));
    let app = update(app, Msg::ToggleInspect);
    let lines = inspect_lines(&app);
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("depth (display colour): ")),
        "{lines:?}"
    );
}
