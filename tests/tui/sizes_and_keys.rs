//! Issue #28's "every size works" and "safe keys", drawn into a
//! TestBackend at 80x24, 100x30 and 160x48: the pixel panel and the path
//! table get room and scroll, the status line keeps chapter, samples and
//! RMSE, small terminals get a notice, titles name what is shown, Esc
//! never quits, saves never overwrite, messages clear, colours read on
//! light and dark backgrounds, refused scenes are marked, and the last
//! chapter, scene and view are remembered.

use std::sync::Arc;
use std::time::Duration;

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::backend::TestBackend;
use ratatui::style::Color;
use ratatui::Terminal;

use super::inspect::{inspected, rendered as ch6_rendered};
use super::layout_and_keys::{app as fake_app, draw, rendered, scenes, send, FAKE, FAKE_PLAIN};
use crate::common;
use raystep::core::stage::Settings;
use raystep::tui::app::{App, Msg, MESSAGE_TTL};
use raystep::tui::keys::msg_for_key;
use raystep::tui::last::{self, Last};
use raystep::tui::scenes::{scene_list, SceneEntry};
use raystep::tui::update::{save, update};
use raystep::tui::view::view;
use raystep::tui::worker::{Progress, Target};

const SIZES: [(u16, u16); 3] = [(80, 24), (100, 30), (160, 48)];

fn sized(app: App, (w, h): (u16, u16)) -> App {
    update(app, Msg::Resize(w, h))
}

fn esc() -> KeyEvent {
    KeyEvent::new(KeyCode::Esc, KeyModifiers::NONE)
}

/// Chapter 6, inspecting the middle pixel, with a story long enough that
/// no panel holds all of it.
fn inspecting(size: (u16, u16)) -> App {
    let app = sized(update(ch6_rendered(), Msg::ToggleInspect), size);
    let story: Vec<String> = (0..60).map(|i| format!("story line {i}")).collect();
    update(app, Msg::Story(32, 32, story))
}

#[test]
fn the_pixel_panel_has_room_and_scrolls_at_every_size() {
    for size in SIZES {
        let app = inspecting(size);
        let screen = draw(&app, size.0, size.1);
        // The values are on screen, not cut away: the first lines, and
        // where the view is with the keys that scroll it.
        assert!(screen.contains("pixel (32, 32)"), "{size:?}\n{screen}");
        assert!(screen.contains("image: "), "{size:?}\n{screen}");
        assert!(screen.contains("± std error: "), "{size:?}\n{screen}");
        assert!(screen.contains("u d scroll"), "{size:?}\n{screen}");
        assert!(!screen.contains("story line 59"), "{size:?}\n{screen}");
        // Scrolled to the end (keys; far past it stops at the end): the
        // reference and the difference come into view.
        let end = send(app, &[Msg::Scroll(1000)]);
        let screen = draw(&end, size.0, size.1);
        assert!(screen.contains("story line 59"), "{size:?}\n{screen}");
        assert!(screen.contains("difference: "), "{size:?}\n{screen}");
        assert!(!screen.contains("pixel (32, 32)"), "{size:?}\n{screen}");
        // One step back up shows the line before the first shown.
        let up = update(end, Msg::Scroll(-1));
        let at = up.panel_scroll;
        assert!(at > 0);
        let back = update(up, Msg::Scroll(-1000));
        assert_eq!(back.panel_scroll, 0, "{size:?}");
        // The mouse wheel over the panel scrolls it; over the picture it
        // does not.
        let panel = raystep::tui::screen::areas(&back, back.screen)
            .panel
            .unwrap();
        let preview = raystep::tui::screen::areas(&back, back.screen).preview;
        let wheel = |column, row| Msg::Wheel {
            column,
            row,
            lines: 3,
        };
        let on_panel = update(back, wheel(panel.x + 2, panel.y + 2));
        assert_eq!(on_panel.panel_scroll, 3, "{size:?}");
        let on_picture = update(on_panel, wheel(preview.x + 5, preview.y + 5));
        assert_eq!(on_picture.panel_scroll, 3, "{size:?}");
    }
}

#[test]
fn the_path_table_has_room_and_scrolls_at_every_size() {
    for size in SIZES {
        let app = sized(
            update(
                update(ch6_rendered(), Msg::ToggleInspect),
                Msg::CursorMove(0, 18),
            ),
            size,
        );
        let table = inspected(&app, (32, 50), 0);
        let app = update(app, Msg::TracePath);
        let app = update(app, Msg::Traced(Ok(Box::new(table))));
        let screen = draw(&app, size.0, size.1);
        assert!(
            screen.contains("path: sample 0 of pixel (32, 50)"),
            "{size:?}\n{screen}"
        );
        assert!(screen.contains("#1 "), "{size:?}\n{screen}");
        assert!(screen.contains("Esc: close"), "{size:?}\n{screen}");
        let a = raystep::tui::screen::areas(&app, app.screen);
        let t = a.table.unwrap();
        // Beside the picture when the screen is wide, over it when not:
        // never narrower than 50 cells.
        assert!(t.width >= 50, "{size:?}: {t:?}");
        assert_eq!(a.preview.width == 0, size.0 < 140, "{size:?}");
        // The whole table can be reached: scrolled to the end, its last
        // line is on screen.
        let end = update(app, Msg::Scroll(1000));
        let screen = draw(&end, size.0, size.1);
        assert!(screen.contains("sum of the + terms"), "{size:?}\n{screen}");
        // Esc closes the table first, then inspect mode; never quits.
        let closed = update(end, Msg::Close);
        assert!(closed.trace.is_none() && closed.inspect.is_some());
        let closed = update(closed, Msg::Close);
        assert!(closed.inspect.is_none() && !closed.quit);
    }
}

#[test]
fn the_status_line_keeps_chapter_spp_and_rmse_first() {
    let mut app = ch6_rendered();
    let snap = app.snapshot.as_mut().unwrap();
    snap.target = Some(Target::DEFAULT);
    snap.samples = 284;
    snap.rmse = Some(0.0059);
    let rmse = raystep::tui::view::short_number(0.0059);
    for (w, h) in SIZES {
        let screen = draw(&app, w, h);
        let status = screen
            .lines()
            .find(|l| l.starts_with("ch6 "))
            .unwrap_or_else(|| panic!("no status line at {w}x{h}\n{screen}"));
        assert!(
            status.starts_with(&format!(
                "ch6 global-illumination │ spp 284/{} │ rmse {rmse}",
                Target::DEFAULT.spp
            )),
            "{w}x{h}: {status}"
        );
        assert!(status.chars().count() <= w as usize);
    }
    // At 160 columns everything fits; at 80 the tail is dropped.
    let wide = draw(&app, 160, 48);
    assert!(wide.contains("│ 64x64 │"), "{wide}");
    let narrow = raystep::tui::view::status_line_fit(&app, 60).to_string();
    assert!(!narrow.contains("64x64"), "{narrow}");
}

#[test]
fn below_the_minimum_size_a_notice_says_how_big() {
    let (mw, mh) = raystep::tui::screen::MIN_SIZE;
    let app = rendered(fake_app());
    for (w, h) in [(mw - 1, 24), (80, mh - 1), (20, 5)] {
        let screen = draw(&app, w, h);
        let flat = screen.replace('\n', " ");
        assert!(
            flat.contains(&format!("at least {mw}x{mh}")),
            "{w}x{h}\n{screen}"
        );
        assert!(!screen.contains("chapters"), "{w}x{h}\n{screen}");
        // A click or the wheel on a notice does nothing.
        let screen_rect = ratatui::layout::Rect::new(0, 0, w, h);
        assert_eq!(raystep::tui::view::pixel_at(&app, screen_rect, 2, 2), None);
    }
    // 1x1 draws without panicking; at the minimum the UI is there.
    let _ = draw(&app, 1, 1);
    for (w, h) in SIZES.into_iter().chain([(mw, mh)]) {
        let screen = draw(&app, w, h);
        assert!(!screen.contains("at least"), "{w}x{h}\n{screen}");
        assert!(screen.contains("chapters"), "{w}x{h}\n{screen}");
    }
}

/// The preview's title: its first line.
fn title(app: &App, w: u16, h: u16) -> String {
    draw(app, w, h).lines().next().unwrap().to_string()
}

#[test]
fn titles_name_render_reference_difference_the_layer_and_the_estimator() {
    let app = rendered(fake_app());
    for (w, h) in SIZES {
        let t = title(&app, w, h);
        assert!(t.contains("render · estimator brdf"), "{w}x{h}: {t}");
        // Up to 0 bounces, then the reference (which has every bounce:
        // the title says so rather than claim the layer).
        let up0 = update(rendered(fake_app()), Msg::BounceUp);
        let t = title(&up0, w, h);
        assert!(t.contains("render, up to 0 bounces"), "{w}x{h}: {t}");
        let reference = update(up0, Msg::CycleCompare);
        let t = title(&reference, w, h);
        assert!(t.contains("reference, all bounces"), "{w}x{h}: {t}");
        assert!(!t.contains("up to 0"), "{w}x{h}: {t}");
        let difference = update(reference, Msg::CycleCompare);
        let t = title(&difference, w, h);
        assert!(
            t.contains("difference: render (up to 0 bounces) - reference"),
            "{w}x{h}: {t}"
        );
        let relative = update(difference, Msg::CycleCompare);
        let t = title(&relative, w, h);
        // The title is cut from the end to fit: the kind of picture first.
        assert!(
            t.contains("relative difference: (render (up to 0 bounces) - r"),
            "{w}x{h}: {t}"
        );
        let exactly = send(
            relative,
            &[
                Msg::CycleCompare,
                Msg::BounceUp,
                Msg::BounceUp,
                Msg::ToggleBounceMode,
            ],
        );
        let t = title(&exactly, w, h);
        assert!(t.contains("render, exactly 2 bounces"), "{w}x{h}: {t}");
        // Another estimator: its name.
        let mis = rendered(update(exactly, Msg::NextVariant));
        let t = title(&mis, w, h);
        assert!(t.contains("estimator mis"), "{w}x{h}: {t}");
    }
}

#[test]
fn esc_closes_what_is_open_and_never_quits() {
    let app = rendered(fake_app());
    // Nothing open: Esc says how to quit, and does not.
    let msg = msg_for_key(&app, esc()).unwrap();
    assert!(matches!(msg, Msg::Close));
    let app = update(app, msg);
    assert!(!app.quit);
    assert!(app.message.contains("q quits"), "{}", app.message);
    // Help, inspect, both: one Esc each, innermost first.
    let app = send(app, &[Msg::ToggleInspect, Msg::ToggleHelp]);
    assert!(app.help && app.inspect.is_some());
    let msg = msg_for_key(&app, esc()).unwrap();
    let app = update(app, msg);
    assert!(!app.help && app.inspect.is_some());
    let msg = msg_for_key(&app, esc()).unwrap();
    let app = update(app, msg);
    assert!(app.inspect.is_none());
    let app = send(app, &[Msg::Close, Msg::Close, Msg::Close]);
    assert!(!app.quit);
    // The grader's images: Esc goes back to the render.
    let dir = common::temp_dir("tui-esc-grade");
    let images = raystep::grading::FailureImages {
        stem: "ch1-pinhole".into(),
        student: raystep::core::film::Film::new(8, 4),
        reference: raystep::core::film::Film::new(8, 4),
    };
    let mut app = update(app, Msg::GradeLoaded(Ok(Some(images))));
    app.out_dir = dir.to_path_buf();
    assert!(app.grading.is_some());
    let app = update(app, Msg::Close);
    assert!(app.grading.is_none() && !app.quit);
    // q still quits.
    let q = msg_for_key(&app, KeyEvent::new(KeyCode::Char('q'), KeyModifiers::NONE));
    assert!(update(app, q.unwrap()).quit);
}

#[test]
fn saves_never_overwrite_and_name_the_estimator_and_spp() {
    let dir = common::temp_dir("tui-save-twice");
    let mut app = rendered(fake_app());
    app.out_dir = dir.clone();
    let first = save(&app).unwrap();
    let second = save(&app).unwrap();
    let third = save(&app).unwrap();
    let names: Vec<String> = [&first[0], &second[0], &third[0]]
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        names,
        [
            "tui-ch6-cornell-box-image-brdf.png",
            "tui-ch6-cornell-box-image-brdf-2.png",
            "tui-ch6-cornell-box-image-brdf-3.png"
        ]
    );
    assert!(second[1].ends_with("tui-ch6-cornell-box-image-brdf-2.exr"));
    // The other estimator saves under its own name.
    let mut mis = rendered(update(app, Msg::NextVariant));
    mis.out_dir = dir.clone();
    let files = save(&mis).unwrap();
    assert!(files[0].ends_with("tui-ch6-cornell-box-image-mis.png"));
    // A progressive render's samples are in the name.
    let mut ch6 = ch6_rendered();
    ch6.snapshot.as_mut().unwrap().samples = 2;
    ch6.out_dir = dir.to_path_buf();
    assert_eq!(ch6.save_stem(), "tui-ch6-cornell-box-image-mis-sobol-2spp");
}

#[test]
fn messages_clear_after_a_while_or_on_the_next_key_and_hints_remain() {
    let app = update(rendered(fake_app()), Msg::TogglePause);
    assert!(!app.message.is_empty());
    // Time passes: the message stays a while, then clears.
    let app = update(app, Msg::Tick(MESSAGE_TTL / 2));
    assert!(!app.message.is_empty());
    let app = update(app, Msg::Tick(MESSAGE_TTL / 2 + Duration::from_millis(1)));
    assert!(app.message.is_empty());
    // A worker's report does not clear a message; the next key does.
    let app = update(app, Msg::Close);
    assert!(!app.message.is_empty());
    let app = update(app, Msg::Saved(Err("disk full".into())));
    assert!(app.message.contains("disk full"));
    // The same message said again starts its time anew.
    let three_quarters = MESSAGE_TTL * 3 / 4;
    let app = update(app, Msg::Close);
    let app = update(app, Msg::Tick(three_quarters));
    let again = update(app, Msg::Close);
    assert!(again.message.contains("q quits"));
    let again = update(again, Msg::Tick(three_quarters));
    assert!(!again.message.is_empty(), "said again: not stale yet");
    let app = update(again, Msg::Tick(MESSAGE_TTL / 2));
    let app = update(app, Msg::NextView);
    assert!(app.message.is_empty(), "{}", app.message);
    // With no message, the line shows the keys of the mode, at every
    // size: the hints never go stale with the message.
    for (w, h) in SIZES {
        let screen = draw(&app, w, h);
        let last = screen.lines().last().unwrap();
        assert!(
            last.contains("i inspect") && last.contains("q quit"),
            "{last}"
        );
        let inspecting = update(rendered(fake_app()), Msg::ToggleInspect);
        let screen = draw(&inspecting, w, h);
        let last = screen.lines().last().unwrap();
        assert!(last.contains("Esc close"), "{last}");
    }
}

#[test]
fn the_ui_reads_on_light_and_dark_backgrounds() {
    // Colours that vanish on one of the two backgrounds, as a foreground
    // on the terminal's own background.
    let unreadable = [
        Color::Gray,
        Color::DarkGray,
        Color::White,
        Color::Black,
        Color::Yellow,
        Color::LightYellow,
        Color::Cyan,
        Color::LightCyan,
    ];
    let mut base = rendered(fake_app());
    base.color = true;
    let states = [
        base,
        update(rendered(fake_app()), Msg::TogglePause),
        update(rendered(fake_app()), Msg::ToggleHelp),
        update(rendered(fake_app()), Msg::ToggleInspect),
        send(rendered(fake_app()), &[Msg::SwitchFocus, Msg::Down]),
    ];
    for mut app in states {
        app.color = true;
        for (w, h) in SIZES {
            let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
            t.draw(|f| view(&app, f)).unwrap();
            for cell in t.backend().buffer().content() {
                if cell.bg == Color::Reset && cell.symbol().trim() != "" {
                    assert!(
                        !unreadable.contains(&cell.fg),
                        "{:?} on the default background at {w}x{h}: {:?}",
                        cell.fg,
                        cell.symbol()
                    );
                }
            }
        }
    }
}

#[test]
fn mesh_chapters_refuse_a_scene_without_meshes_and_say_why() {
    let sdf = Arc::new(common::shipped_scene("sdf-shapes", 32, 24));
    let n = sdf.sdfs.len();
    for chapter in raystep::chapters::all() {
        let number = chapter.info().number;
        let result = chapter.start(sdf.clone(), &Settings::default());
        if number == 4 {
            assert!(result.is_ok(), "chapter 4 draws SDFs");
            continue;
        }
        let why = result.err().expect("refused").to_string();
        let expected = if number >= 5 {
            // Chapters 5 and 6 draw SDFs too: what they lack is light.
            format!(
                "chapter {number} needs light; sdf-shapes has no lights and no emitting \
                 material (add a [[lights]] entry, or an emission to a material)"
            )
        } else {
            format!(
                "chapter {number} draws triangle meshes; sdf-shapes has none \
                 (it has {n} SDF objects: chapter 4 draws them)"
            )
        };
        assert_eq!(why, expected);
    }
    // Chapter 4 on a scene without SDFs renders its meshes (through
    // chapter 3's BVH): it does not refuse.
    let ch4 = raystep::chapters::all()[3];
    let cornell = Arc::new(
        raystep::scene::Scene::builtin()
            .with_resolution(16, 12)
            .unwrap(),
    );
    let mut render = ch4.start(cornell, &Settings::default()).unwrap();
    while !render.pass().complete {}
    let shaded = &render.snapshot().views[0];
    assert!(shaded.pixels.iter().any(|p| p.max_element() > 0.0));
}

/// The scene list of the shipped folder, the real chapters.
fn real_app() -> App {
    App::new(
        raystep::chapters::all(),
        scene_list(&common::root().join("scenes")),
        false,
    )
}

fn find(app: &App, stem: &str) -> usize {
    app.scenes.iter().position(|e| e.stem() == stem).unwrap()
}

#[test]
fn a_refused_scene_is_marked_in_the_list_and_chapters_avoid_it() {
    let mut app = real_app();
    assert_eq!(app.current_chapter().unwrap().info().number, 1);
    let sdf = find(&app, "sdf-shapes");
    app = send(app, &[Msg::SwitchFocus]);
    while app.scene != sdf {
        app = update(app, Msg::Down);
    }
    app.read_scene_now();
    // The worker reports what chapter 1 said when it started.
    let job = app.job().expect("not known yet: it is tried");
    let why = job
        .chapter
        .start(job.scene.clone(), &job.settings)
        .err()
        .unwrap()
        .to_string();
    let app = update(
        app,
        Msg::Progress(Progress::Refused {
            generation: job.generation,
            message: why.clone(),
        }),
    );
    assert_eq!(app.scene_problem(sdf), Some(why.clone()));
    assert!(app.job().is_none(), "a known refusal is not started again");
    let (_, gauge) = raystep::tui::view::gauge_state(&app);
    assert_eq!(gauge, "not rendered: the preview says why");
    for (w, h) in SIZES {
        let screen = draw(&app, w, h);
        assert!(screen.contains("✗ sdf-shapes"), "{w}x{h}\n{screen}");
        assert!(
            screen.contains("chapter 1 draws"),
            "{w}x{h}: the reason\n{screen}"
        );
    }
    // Chapter 4 renders it: no mark there.
    let app = update(app, Msg::ChapterNumber(4));
    assert_eq!(app.scene, sdf);
    assert_eq!(app.scene_problem(sdf), None);
    assert!(!draw(&app, 100, 30).contains("✗ sdf-shapes"));
    // Back to chapter 1: it does not open on the scene it refused.
    let app = update(app, Msg::ChapterNumber(1));
    assert_ne!(app.scene, sdf);
    assert!(app.problem().is_none() && app.job().is_some());
    // (The list shows every scene only where it has the rows.)
    assert!(draw(&app, 160, 48).contains("✗ sdf-shapes"));
}

#[test]
fn chapter_4_opens_on_an_sdf_scene_when_the_list_has_one() {
    let app = real_app();
    assert_eq!(app.current_scene().unwrap().stem(), "cornell-box");
    let mut app = update(app, Msg::ChapterNumber(4));
    assert_eq!(app.current_scene().unwrap().stem(), "sdf-shapes");
    app.read_scene_now();
    assert!(!app
        .current_scene()
        .unwrap()
        .scene
        .as_ref()
        .unwrap()
        .sdfs
        .is_empty());
    // Only the first time: back in chapter 4 after choosing the Cornell
    // box in chapter 3, it stays on the Cornell box.
    let mut app = send(app, &[Msg::ChapterNumber(3), Msg::SwitchFocus]);
    while app.scene != 0 {
        app = update(app, Msg::Up);
    }
    let app = update(app, Msg::ChapterNumber(4));
    assert_eq!(app.current_scene().unwrap().stem(), "cornell-box");
    // A list without it: chapter 4 stays on the scene it was given.
    let app = App::new(raystep::chapters::all(), vec![SceneEntry::builtin()], false);
    let app = update(app, Msg::ChapterNumber(4));
    assert_eq!(app.scene, 0);
    // The fakes have no scene of their own: switching keeps the scene.
    let app = App::new(vec![&FAKE_PLAIN, &FAKE], scenes(), false);
    let app = update(app, Msg::ChapterNumber(6));
    assert_eq!(app.scene, 0);
}

#[test]
fn the_last_chapter_scene_and_view_are_remembered() {
    // Where the file goes: the override, else XDG, else HOME.
    let env = |pairs: &'static [(&'static str, &'static str)]| {
        move |k: &str| {
            pairs
                .iter()
                .find(|(key, _)| *key == k)
                .map(|(_, v)| v.to_string())
        }
    };
    let p = |pairs| last::path(&env(pairs));
    assert_eq!(
        p(&[("HOME", "/h")]),
        Some("/h/.config/raystep/last.toml".into())
    );
    assert_eq!(
        p(&[("HOME", "/h"), ("XDG_CONFIG_HOME", "/x")]),
        Some("/x/raystep/last.toml".into())
    );
    assert_eq!(
        p(&[("HOME", "/h"), (last::CONFIG_DIR_ENV, "/t")]),
        Some("/t/last.toml".into())
    );
    assert_eq!(p(&[]), None);

    let dir = common::temp_dir("tui-last");
    let file = dir.join("config").join("last.toml");
    assert_eq!(last::load(&file), Ok(None), "no file yet");
    // What a run showed: chapter 3, the tetrahedron, the normals view.
    let root = common::root();
    let launch = raystep::tui::Launch {
        scenes_dir: root.join("scenes"),
        remember: Some(file.clone()),
        ..Default::default()
    };
    let mut app = raystep::tui::launch_app(&launch, false);
    app = update(app, Msg::ChapterNumber(3));
    let tet = find(&app, "tetrahedron");
    app = update(app, Msg::SwitchFocus);
    while app.scene != tet {
        app = update(app, Msg::Down);
    }
    app = update(app, Msg::NextView);
    let shown = last::of(&app).unwrap();
    last::store(&file, &shown).unwrap();
    let loaded = last::load(&file).unwrap().unwrap();
    assert_eq!(loaded, shown);
    assert_eq!(loaded.chapter, 3);
    // The next run opens there.
    let next = raystep::tui::launch_app_with(&launch, false, Some(&loaded));
    assert_eq!(next.current_chapter().unwrap().info().number, 3);
    assert_eq!(next.current_scene().unwrap().stem(), "tetrahedron");
    assert_eq!(next.view_name(), shown.view);
    assert_ne!(next.view, 0);
    // The flags win over it.
    let flagged = raystep::tui::Launch {
        chapter: Some(2),
        ..launch.clone()
    };
    let next = raystep::tui::launch_app_with(&flagged, false, Some(&loaded));
    assert_eq!(next.current_chapter().unwrap().info().number, 2);
    assert_eq!(next.view, 0);
    // A broken file is an error to warn about, not a crash; a remembered
    // scene that is gone is ignored.
    std::fs::write(&file, "chapter = \"six\"\n").unwrap();
    let err = last::load(&file).unwrap_err();
    assert!(err.contains("last.toml"), "{err}");
    let gone = Last {
        chapter: 2,
        scene: "/no/such/scene.toml".into(),
        view: "no-such-view".into(),
    };
    let next = raystep::tui::launch_app_with(&launch, false, Some(&gone));
    assert_eq!(next.current_chapter().unwrap().info().number, 2);
    assert_eq!(next.scene, 0);
    assert_eq!(next.view, 0);
}

#[test]
fn the_headless_summary_says_which_chapters_refuse_a_scene() {
    let scene = common::shipped_scene("sdf-shapes", 32, 24);
    let out = common::temp_dir("tui-summary-refused");
    let mut text = Vec::new();
    let clean = raystep::summary::summarise(
        &scene,
        &out,
        1,
        16,
        &mut text,
        &mut raystep::summary::NoProgress,
    )
    .expect("a refusal is a line, not a failure");
    assert!(clean.is_none());
    let text = String::from_utf8(text).unwrap();
    for n in [1, 2, 3] {
        assert!(
            text.contains(&format!("refused: chapter {n} draws triangle meshes")),
            "{text}"
        );
    }
    for n in [5, 6] {
        assert!(
            text.contains(&format!("refused: chapter {n} needs light")),
            "{text}"
        );
    }
    assert!(out.join("ch4-sdf-shapes.png").exists(), "{text}");
    assert!(text.contains("ch6 clean: refused"), "{text}");
}

#[test]
fn the_help_says_when_a_short_terminal_hides_keys() {
    let app = update(rendered(fake_app()), Msg::ToggleHelp);
    let keys = raystep::tui::keys::KEYS.len();
    let tall = draw(&app, 100, 30);
    assert!(!tall.contains("more keys"), "{tall}");
    for (_, what) in raystep::tui::keys::KEYS {
        assert!(tall.contains(what), "{what}\n{tall}");
    }
    let short = draw(&app, 80, 16);
    assert!(
        short.contains(&format!("… {} more keys", keys - 13)),
        "{short}"
    );
}

/// Chapters 5 and 6 render SDFs: an SDF-only scene with a light renders,
/// one without any light or emitter is refused for that reason.
#[test]
fn chapters_5_and_6_render_sdfs_and_refuse_only_a_dark_scene() {
    let mut lit = common::shipped_scene("sdf-lit", 24, 16);
    lit.meshes.clear(); // the area light is a mesh: keep the point light and sky
    assert!(!lit.lights.is_empty() && !lit.sdfs.is_empty());
    let lit = Arc::new(lit);
    for n in [5, 6] {
        let chapter = raystep::chapters::all()[n - 1];
        let mut render = chapter.start(lit.clone(), &Settings::default()).unwrap();
        while !render.pass().complete {}
        let image = &render.snapshot().views[0];
        assert!(image.pixels.iter().any(|p| p.max_element() > 0.0), "ch{n}");
    }
    let mut dark = common::shipped_scene("sdf-lit", 24, 16);
    dark.meshes.clear();
    dark.lights.clear();
    for m in &mut dark.materials {
        m.emission = glam::Vec3::ZERO;
    }
    let dark = Arc::new(dark);
    for n in [5, 6] {
        let chapter = raystep::chapters::all()[n - 1];
        let why = chapter
            .start(dark.clone(), &Settings::default())
            .err()
            .unwrap();
        assert!(why.to_string().contains("needs light"), "{why}");
    }
}

/// What the worker does with the current job's start: a refusal comes
/// back as `Progress::Refused`.
fn start_or_refuse(mut app: App) -> App {
    app.read_scene_now();
    let Some(job) = app.job() else {
        return app;
    };
    match job.chapter.start(job.scene.clone(), &job.settings) {
        Ok(_) => app,
        Err(e) => update(
            app,
            Msg::Progress(Progress::Refused {
                generation: job.generation,
                message: e.to_string(),
            }),
        ),
    }
}

/// Chapter 4 opens on `sdf-shapes`; chapters 5, 6 and 1, switched to from
/// there, learn only when they start that they refuse it: each then moves
/// to a scene it takes and says so, as the book promises. A scene the user
/// picks in a chapter stays picked, refused or not.
#[test]
fn a_chapter_switched_onto_a_scene_it_refuses_moves_to_one_it_takes() {
    let mut app = start_or_refuse(update(real_app(), Msg::ChapterNumber(4)));
    let sdf = find(&app, "sdf-shapes");
    assert_eq!(app.scene, sdf);
    for n in [5, 6, 1] {
        app = update(app, Msg::ChapterNumber(4));
        app = send(app, &[Msg::SwitchFocus]);
        while app.scene != sdf {
            app = update(app, Msg::Down);
        }
        app = send(app, &[Msg::SwitchFocus]);
        assert_eq!(app.scene, sdf, "chapter 4 on sdf-shapes");
        app = start_or_refuse(update(app, Msg::ChapterNumber(n)));
        assert_eq!(app.current_chapter().unwrap().info().number, n);
        assert_ne!(app.scene, sdf, "chapter {n} stayed on a scene it refuses");
        assert!(
            app.message.contains("opened"),
            "chapter {n}: {}",
            app.message
        );
        assert!(
            app.problem().is_none() && app.job().is_some(),
            "chapter {n}"
        );
    }
    // Picked in chapter 1 itself: the refusal is shown, the pick stays.
    let mut app = send(app, &[Msg::SwitchFocus]);
    while app.scene != sdf {
        app = update(app, Msg::Down);
    }
    let app = start_or_refuse(app);
    assert_eq!(app.scene, sdf);
    assert!(app.problem().is_some());
}

#[test]
fn the_help_scrolls_to_every_key_on_a_short_terminal() {
    let app = update(rendered(fake_app()), Msg::Resize(80, 24));
    let app = update(app, Msg::ToggleHelp);
    let (last_key, last_what) = raystep::tui::keys::KEYS[raystep::tui::keys::KEYS.len() - 1];
    let top = draw(&app, 80, 24);
    assert!(!top.contains(last_what), "{top}");
    assert!(top.contains("↑ ↓ scroll"), "{top}");
    // Down (and u/d, PgDn) scroll it; it stops at the last key.
    let app = (0..40).fold(app, |a, _| update(a, Msg::Down));
    assert!(app.help, "scrolling keeps the help open");
    let bottom = draw(&app, 80, 24);
    assert!(bottom.contains(last_what), "{last_key}: {bottom}");
    assert!(bottom.contains("0 more keys below"), "{bottom}");
    let app = update(app, Msg::Scroll(-5));
    assert!(!draw(&app, 80, 24).contains(last_what));
    // Any other key still closes it.
    let app = update(app, Msg::NextView);
    assert!(!app.help);
}

#[test]
fn chapter_titles_are_never_cut_mid_word() {
    use raystep::tui::labels::fit_title;
    let t = "Implicit surfaces: signed distance functions and sphere tracing";
    assert_eq!(fit_title(t, 80), t);
    assert_eq!(fit_title(t, 26), "Implicit surfaces");
    assert_eq!(
        fit_title("Ray-triangle intersection and a BVH", 26),
        "Ray-triangle intersection…"
    );
    assert_eq!(
        fit_title("Radiometry, lights, BRDFs and the reflection equation", 26),
        "Radiometry, lights, BRDFs…"
    );
    assert_eq!(fit_title("Supercalifragilistic", 6), "Super…");
    // The real list, at every size: each title whole, its part before the
    // colon, or cut after a word with "…".
    let chapters = raystep::chapters::all();
    let app = App::new(
        chapters.to_vec(),
        vec![raystep::tui::scenes::SceneEntry::builtin()],
        false,
    );
    for (w, h) in SIZES {
        let screen = draw(&app, w, h);
        for c in &chapters {
            let info = c.info();
            let full = info.title;
            let head = full.split(':').next().unwrap();
            let row = screen
                .lines()
                .find(|l| l.contains(&format!("{} ", info.number)) && l.contains(&full[..4]))
                .unwrap_or_else(|| panic!("{w}x{h}: no row for chapter {}\n{screen}", info.number));
            let shown = row
                .split('│')
                .nth(1)
                .unwrap()
                .trim_start_matches("> ")
                .trim();
            let title = shown.split_once(' ').unwrap().1;
            assert!(
                title == full
                    || title == head
                    || (title.ends_with('…') && full.starts_with(title.trim_end_matches('…'))),
                "{w}x{h}: chapter {} shows {title:?}",
                info.number
            );
        }
    }
}
