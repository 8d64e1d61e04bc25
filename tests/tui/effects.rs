//! What `update` asks the event loop to do ([`Effect`]): a render started
//! once per generation, a target or pause passed on to the running render,
//! a trace per `t`, a story per pixel and render, a save only of something
//! shown, student mode's watcher on its chapter. The loop keeps no copy of
//! the state: these effects are all it acts on.

use crate::common;
use crate::tui::layout_and_keys::{app, rendered, scenes, FAKE_PLAIN};

use raystep::tui::app::{App, Msg};
use raystep::tui::effect::Effect;
use raystep::tui::update::update;
use raystep::tui::worker::Progress;

/// `msg` applied to `app` with an empty outbox: the next state and the
/// effects of `msg` alone.
fn effects_of(mut app: App, msg: Msg) -> (App, Vec<Effect>) {
    app.effects.clear();
    let mut app = update(app, msg);
    let effects = std::mem::take(&mut app.effects);
    (app, effects)
}

#[test]
fn launch_asks_for_the_first_render() {
    use raystep::tui::{launch_app, Launch};
    let launch = Launch {
        scenes_dir: "no-such-folder".into(),
        chapter: Some(3),
        ..Launch::default()
    };
    let app = launch_app(&launch, false);
    assert!(
        matches!(&app.effects[..], [Effect::Start(job)]
            if job.generation == app.generation && job.chapter.info().number == 3),
        "{:?}",
        app.effects
    );
}

/// A new scene or chapter is a new generation: exactly one render starts,
/// the new selection's; a selection that cannot render starts none.
#[test]
fn a_new_scene_or_chapter_starts_one_render_of_its_generation() {
    let (app, _) = effects_of(app(), Msg::SwitchFocus);
    let (app, asked) = effects_of(app, Msg::Down);
    let [Effect::Start(job)] = &asked[..] else {
        panic!("one start: {asked:?}")
    };
    assert_eq!(job.generation, app.generation);
    assert_eq!(job.scene.name, "no-go");
    // The broken scene cannot render: a new generation, and no render.
    let generation = app.generation;
    let (app, asked) = effects_of(app, Msg::Down);
    assert!(app.generation > generation, "{}", app.generation);
    assert!(asked.is_empty(), "{asked:?}");
    // Down again at the end of the list: nothing changes, nothing starts.
    let generation = app.generation;
    let (app, asked) = effects_of(app, Msg::Down);
    assert_eq!(app.generation, generation);
    assert!(asked.is_empty(), "{asked:?}");

    let (app, asked) = effects_of(self::app(), Msg::ChapterNumber(2));
    assert!(
        matches!(&asked[..], [Effect::Start(job)]
            if job.generation == app.generation && job.chapter.info().number == 2),
        "{asked:?}"
    );
    let (_, asked) = effects_of(app, Msg::ChapterNumber(2));
    assert!(asked.is_empty(), "the same chapter again: {asked:?}");
}

/// `>` and `<` move the running render's target: the same generation goes
/// on, and no render starts.
#[test]
fn a_new_target_goes_to_the_running_render() {
    let app = crate::tui::inspect::rendered();
    let (generation, before) = (app.generation, app.target);
    let (app, asked) = effects_of(app, Msg::TargetUp);
    assert_ne!(app.target, before);
    assert!(
        matches!(asked[..], [Effect::Retarget { generation: g, target }]
            if g == generation && target == app.target),
        "{asked:?}"
    );
    let (app, asked) = effects_of(app, Msg::TargetDown);
    assert!(
        matches!(asked[..], [Effect::Retarget { target, .. }] if target == app.target),
        "{asked:?}"
    );
    assert_eq!(app.generation, generation);
    // A chapter that renders once has no target to move.
    let (_, asked) = effects_of(rendered(self::app()), Msg::TargetUp);
    assert!(asked.is_empty(), "{asked:?}");
}

#[test]
fn space_pauses_and_resumes_the_running_render() {
    // A finished render has nothing to pause.
    let (mut app, asked) = effects_of(crate::tui::inspect::rendered(), Msg::TogglePause);
    assert!(asked.is_empty(), "{asked:?}");
    assert!(app.message.starts_with("finished"), "{}", app.message);
    app.snapshot.as_mut().unwrap().done = false;
    let g = app.generation;
    let (app, asked) = effects_of(app, Msg::TogglePause);
    assert!(
        matches!(asked[..], [Effect::Pause { generation, paused: true }] if generation == g),
        "{asked:?}"
    );
    let (app, asked) = effects_of(app, Msg::TogglePause);
    assert!(
        matches!(asked[..], [Effect::Pause { paused: false, .. }]),
        "{asked:?}"
    );
    // Paused, then another estimator: its render starts, running (a new
    // render is never paused, so no pause is passed on).
    let (app, _) = effects_of(app, Msg::TogglePause);
    let (app, asked) = effects_of(app, Msg::NextVariant);
    assert!(!app.paused);
    assert!(
        matches!(&asked[..], [Effect::Start(job)] if job.generation == app.generation),
        "{asked:?}"
    );
}

#[test]
fn t_traces_one_path_per_press_in_chapter_6s_inspect_mode() {
    let (app, asked) = effects_of(crate::tui::inspect::rendered(), Msg::TracePath);
    assert!(asked.is_empty(), "not inspecting: {asked:?}");
    assert!(app.message.contains("inspect mode"), "{}", app.message);
    let (app, asked) = effects_of(app, Msg::ToggleInspect);
    assert!(
        asked.is_empty(),
        "chapter 6 traces paths, it tells no story: {asked:?}"
    );
    let g = app.generation;
    let (app, asked) = effects_of(app, Msg::TracePath);
    assert!(
        matches!(asked[..], [Effect::Trace { generation, pixel: (32, 32), sample: 0 }]
            if generation == g),
        "{asked:?}"
    );
    // Again: the next sample (the render has 2 per pixel).
    let (_, asked) = effects_of(app, Msg::TracePath);
    assert!(
        matches!(asked[..], [Effect::Trace { sample: 1, .. }]),
        "{asked:?}"
    );
}

/// Chapters 3 to 5 tell the inspected pixel's story: asked of the render
/// once per pixel and generation, not again for each pass.
#[test]
fn the_story_is_asked_once_per_pixel_and_render() {
    let app = rendered(App::new(vec![&FAKE_PLAIN], scenes(), false));
    let pass = Msg::Progress(Progress::State(Box::new(app.snapshot.clone().unwrap())));
    let g = app.generation;
    let (app, asked) = effects_of(app, Msg::ToggleInspect);
    let (x, y) = app.inspect.unwrap();
    assert!(
        matches!(asked[..], [Effect::Story { generation, pixel }]
            if generation == g && pixel == (x, y)),
        "{asked:?}"
    );
    // The same pass again: the same pixel of the same render.
    let (app, asked) = effects_of(app, pass.clone());
    assert!(asked.is_empty(), "{asked:?}");
    // Another pixel, and back before its story came: each asked.
    let (app, asked) = effects_of(app, Msg::CursorMove(1, 0));
    assert!(
        matches!(asked[..], [Effect::Story { pixel, .. }] if pixel == (x + 1, y)),
        "{asked:?}"
    );
    let (app, asked) = effects_of(app, Msg::CursorMove(-1, 0));
    assert!(
        matches!(asked[..], [Effect::Story { pixel, .. }] if pixel == (x, y)),
        "{asked:?}"
    );
    // Its story came: inspect mode off and on again asks nothing.
    let (app, _) = effects_of(app, Msg::Story(x, y, vec!["a story".into()]));
    let (app, asked) = effects_of(app, Msg::ToggleInspect);
    assert!(asked.is_empty(), "{asked:?}");
    let (app, asked) = effects_of(app, Msg::ToggleInspect);
    assert_eq!(app.inspect, Some((x, y)));
    assert!(asked.is_empty(), "{asked:?}");
}

/// `s` asks for a save only when something is shown; the event loop's
/// threads carry it out and answer with the files, as they read the
/// grader's images for `g`.
#[test]
fn s_saves_only_what_is_shown_and_the_loop_carries_it_out() {
    let (app, asked) = effects_of(app(), Msg::Save);
    assert!(asked.is_empty(), "{asked:?}");
    assert_eq!(app.message, "nothing to save yet");
    let dir = common::temp_dir("tui-effect-save");
    let mut app = rendered(app);
    app.out_dir = dir.clone();
    app.effects.clear();
    let mut threads = raystep::tui::threads::Threads::spawn();
    let app = threads.handle(app, Msg::Save);
    assert!(app.effects.is_empty(), "{:?}", app.effects);
    assert!(app.message.starts_with("saved "), "{}", app.message);
    let written = std::fs::read_dir(&dir).unwrap().count();
    assert_eq!(written, 2, "a PNG and an EXR");
    let app = threads.handle(app, Msg::ToggleGrading);
    assert!(app.message.contains("--bin grade"), "{}", app.message);
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn student_mode_keeps_a_watcher_on_its_chapter() {
    let (app, asked) = effects_of(app(), Msg::ToggleStudent);
    assert!(matches!(asked[..], [Effect::Watch(Some(6))]), "{asked:?}");
    // Another chapter: its render starts, and student mode (with its
    // watcher) follows it.
    let (app, asked) = effects_of(app, Msg::ChapterNumber(2));
    assert!(
        matches!(asked[..], [Effect::Start(_), Effect::Watch(Some(2))]),
        "{asked:?}"
    );
    let (_, asked) = effects_of(app, Msg::ToggleStudent);
    assert!(matches!(asked[..], [Effect::Watch(None)]), "{asked:?}");
}
