//! [`update`], a pure function from (state, message) to the next state and
//! the [`Effect`]s it asks for, and [`save`]. `update` touches neither the
//! terminal, the clock, the disk nor a thread: the event loop turns keys
//! and answers into messages, and carries out the effects `update` leaves
//! in [`App::effects`].
//!
//! `step` hands each message to the function of its mode: here the lists,
//! the look of the picture, the render's controls, inspect mode, grading
//! and saving, and the warp view; the answers from the threads in
//! [`answers`](super::answers); scrolling, the mouse, Esc and the clock in
//! [`screen_update`](super::screen_update); student mode in
//! [`student_update`](super::student_update).
//!
//! Some effects are asked for by a message itself: `s` saves
//! ([`Effect::Save`]), `g` reads the grader's images
//! ([`Effect::LoadGrades`]), `t` traces a path ([`Effect::Trace`]). The
//! others follow from comparing the state before and after the message
//! (`follow`): a new generation starts its render ([`Effect::Start`],
//! once); within a generation a new target or pause goes to the running
//! render ([`Effect::Retarget`], [`Effect::Pause`]); student mode's
//! chapter gets its watcher ([`Effect::Watch`]); a pixel inspected over a
//! new picture or a newly inspected pixel gets its story asked for
//! ([`Effect::Story`], once per pixel and generation); and the routine the
//! warp view waits for gets drawn ([`Effect::WarpBuiltin`],
//! [`Effect::WarpStudent`], which also cancels the student's build the
//! view no longer wants).

use super::answers::answer;
use super::app::*;
use super::effect::Effect;
pub use super::save::save;
use super::screen_update::screen;
use super::student_update::{student_follows_chapter, toggle_student};
use super::worker::Target;

/// The next state of the UI after `msg`, with what it asks the event loop
/// to do added to [`App::effects`].
pub fn update(mut app: App, msg: Msg) -> App {
    let outward = Outward::of(&app);
    let old_message = app.message.clone();
    // The next action clears a message (it may set its own).
    let action = msg.is_action();
    if action {
        app.message.clear();
    }
    let mut app = step(app, msg);
    // A new message, or the same one said again, starts its time anew.
    if app.message != old_message || (action && !app.message.is_empty()) {
        app.message_age = std::time::Duration::ZERO;
    }
    follow(&mut app, &outward);
    app
}

/// The part of the state the world outside follows (the running render,
/// student mode's watcher, the inspect panel's story, the warp view's
/// draws), compared before and after a message.
struct Outward {
    generation: u64,
    target: Target,
    paused: bool,
    watched: Option<u32>,
    story: Option<((u32, u32), u64)>,
    warp_builtin: Option<(usize, u64)>,
    warp_student: Option<u64>,
}

impl Outward {
    fn of(app: &App) -> Outward {
        Outward {
            generation: app.generation,
            target: app.target,
            paused: app.paused,
            watched: app.student.as_ref().map(|s| s.chapter),
            story: story_wanted(app),
            warp_builtin: app
                .warp
                .as_ref()
                .and_then(|w| w.pending.map(|s| (w.index, s))),
            warp_student: app.warp.as_ref().and_then(|w| w.student_requested),
        }
    }
}

/// The pixel whose story the inspect panel wants, with the render to ask:
/// inspect mode is on over a picture, in a chapter that tells stories
/// (chapter 6 traces paths instead).
fn story_wanted(app: &App) -> Option<((u32, u32), u64)> {
    let pixel = app.inspect?;
    app.snapshot.as_ref()?;
    (!app.traces_paths()).then_some((pixel, app.generation))
}

/// The effects that follow from what a message changed (`before`: the
/// state before it).
fn follow(app: &mut App, before: &Outward) {
    let now = Outward::of(app);
    let generation = app.generation;
    if now.generation != before.generation {
        // The job carries the target, and a new render runs unpaused.
        let job = app.job();
        app.effects.extend(job.map(Effect::Start));
    } else {
        if now.target != before.target {
            let target = app.target;
            app.effects.push(Effect::Retarget { generation, target });
        }
        if now.paused != before.paused {
            let paused = app.paused;
            app.effects.push(Effect::Pause { generation, paused });
        }
    }
    if now.watched != before.watched {
        app.effects.push(Effect::Watch(now.watched));
    }
    if let Some((index, seed)) = now.warp_builtin.filter(|w| Some(*w) != before.warp_builtin) {
        app.effects.push(Effect::WarpBuiltin { index, seed });
    }
    if now.warp_student != before.warp_student {
        app.effects.push(Effect::WarpStudent(now.warp_student));
    }
    // Asked when the pixel or the render changes, unless the panel holds
    // that pixel's story already (inspect mode off and on again).
    let held = |pixel: (u32, u32)| app.story.as_ref().map(|(x, y, _)| (*x, *y)) == Some(pixel);
    if let Some((pixel, generation)) = now.story.filter(|s| Some(*s) != before.story) {
        if !held(pixel) {
            app.effects.push(Effect::Story { generation, pixel });
        }
    }
}

/// `msg` applied to `app`: the help overlay takes the keys while it is
/// open; every other message goes to the function of its mode.
fn step(mut app: App, msg: Msg) -> App {
    // Any key but `?` and `q` closes the help overlay first (and does
    // nothing else); the arrows, j k, u d and the page keys scroll it. What
    // the user did not do (an answer from a thread, the clock) goes on.
    if app.help && app.scroll_help(&msg) {
        return app;
    }
    if app.help && msg.is_action() && !matches!(msg, Msg::ToggleHelp | Msg::Quit) {
        app.help = false;
        return app;
    }
    match msg {
        Msg::Up | Msg::Down | Msg::SwitchFocus | Msg::ChapterNumber(_) => navigate(&mut app, msg),
        Msg::NextView
        | Msg::PrevView
        | Msg::ExposureUp
        | Msg::ExposureDown
        | Msg::ExposureReset
        | Msg::ToggleAutoExposure
        | Msg::BounceUp
        | Msg::BounceDown
        | Msg::ToggleBounceMode
        | Msg::CycleCompare
        | Msg::Flip
        | Msg::Zoom(_) => look(&mut app, msg),
        Msg::NextVariant
        | Msg::PrevVariant
        | Msg::TogglePause
        | Msg::TargetUp
        | Msg::TargetDown => render_control(&mut app, msg),
        Msg::ToggleInspect
        | Msg::CursorMove(..)
        | Msg::TracePath
        | Msg::Click { .. }
        | Msg::Drag { .. }
        | Msg::MarkRegion
        | Msg::TogglePin
        | Msg::ToggleSplit => inspect(&mut app, msg),
        Msg::ToggleGrading | Msg::ToggleStudent | Msg::Save => grade_or_save(&mut app, msg),
        Msg::ToggleWarp | Msg::WarpStep(_) | Msg::WarpReseed => warp(&mut app, msg),
        Msg::Progress(_)
        | Msg::Traced(_)
        | Msg::Story(..)
        | Msg::Saved(_)
        | Msg::GradeLoaded(_)
        | Msg::Student(..)
        | Msg::SceneRead(..)
        | Msg::SceneEdited(_)
        | Msg::WarpBuiltin(..)
        | Msg::WarpStudent(..) => answer(&mut app, msg),
        Msg::Scroll(_)
        | Msg::Wheel { .. }
        | Msg::Hover { .. }
        | Msg::Resize(..)
        | Msg::Tick(_)
        | Msg::Close => screen(&mut app, msg),
        Msg::ToggleHelp => app.help = !app.help,
        Msg::Pasted => app.message = "paste ignored: the UI takes keys one at a time".into(),
        Msg::Quit => app.quit = true,
    }
    student_follows_chapter(&mut app);
    app
}

/// The chapter and scene lists: up, down, the other list, a chapter by
/// its number.
fn navigate(app: &mut App, msg: Msg) {
    match msg {
        Msg::Up => match app.focus {
            Focus::Chapters => app.select_chapter(app.chapter.saturating_sub(1)),
            Focus::Scenes => app.select_scene(app.scene.saturating_sub(1)),
        },
        Msg::Down => match app.focus {
            Focus::Chapters => app.select_chapter(app.chapter + 1),
            Focus::Scenes => app.select_scene(app.scene + 1),
        },
        Msg::SwitchFocus => {
            app.focus = match app.focus {
                Focus::Chapters => Focus::Scenes,
                Focus::Scenes => Focus::Chapters,
            }
        }
        Msg::ChapterNumber(n) => {
            if let Some(i) = app.chapters.iter().position(|c| c.info().number == n) {
                app.select_chapter(i);
            }
        }
        _ => {}
    }
}

/// How the picture is shown: the view, exposure, the bounce layers, the
/// comparison and the zoom. Nothing renders anew.
fn look(app: &mut App, msg: Msg) {
    let bounces = app.shows_bounces();
    match msg {
        Msg::NextView | Msg::PrevView => {
            let n = app
                .current_chapter()
                .map_or(1, |c| c.info().views.len().max(1));
            app.view = match msg {
                Msg::NextView => (app.view + 1) % n,
                _ => (app.view + n - 1) % n,
            };
        }
        Msg::ExposureUp => app.step_exposure(Some(1)),
        Msg::ExposureDown => app.step_exposure(Some(-1)),
        Msg::ExposureReset => app.step_exposure(None),
        Msg::ToggleAutoExposure => app.auto_exposure = Some(!app.auto_exposure_on()),
        Msg::BounceUp if bounces => {
            app.bounce = match app.bounce {
                None => Some(0),
                Some(k) if k >= MAX_BOUNCE => None,
                Some(k) => Some(k + 1),
            }
        }
        Msg::BounceDown if bounces => {
            app.bounce = match app.bounce {
                None => Some(MAX_BOUNCE),
                Some(0) => None,
                Some(k) => Some(k - 1),
            }
        }
        Msg::ToggleBounceMode if bounces => {
            app.bounce_mode = match app.bounce_mode {
                BounceMode::Exactly => BounceMode::UpTo,
                BounceMode::UpTo => BounceMode::Exactly,
            }
        }
        Msg::CycleCompare | Msg::Flip if app.shows_compare() => {
            app.compare = match msg {
                Msg::Flip => app.compare.flipped(),
                _ => app.compare.next(app.z_available()),
            };
        }
        Msg::Zoom(step) => app.zoom = super::zoom::zoomed(app.zoom, step),
        _ => {}
    }
}

/// The render itself: the estimator (a new render), pause, the target.
fn render_control(app: &mut App, msg: Msg) {
    match msg {
        Msg::NextVariant | Msg::PrevVariant => {
            let n = app.current_chapter().map_or(0, |c| c.info().variants.len());
            if n > 1 {
                app.variant = match msg {
                    Msg::NextVariant => (app.variant + 1) % n,
                    _ => (app.variant + n - 1) % n,
                };
                app.restart();
                app.message = app.variant_label().unwrap_or_default();
            }
        }
        Msg::TogglePause => {
            if !app.progressive() {
                app.message = "this chapter renders once: nothing to pause".into();
            } else if app.snapshot.is_none() {
                app.message = "nothing to pause yet".into();
            } else if app.snapshot.as_ref().is_some_and(|s| s.done) {
                app.message = "finished: > raises the target".into();
            } else {
                app.paused = !app.paused;
                app.message = if app.paused {
                    "paused (space resumes)"
                } else {
                    "resumed"
                }
                .into();
            }
        }
        Msg::TargetUp | Msg::TargetDown if app.progressive() => {
            app.target = match msg {
                Msg::TargetUp => app.target.doubled(),
                _ => app.target.halved(),
            };
            app.message = format!("target: {}", target_text(&app.target));
        }
        _ => {}
    }
}

/// Inspect mode: the cursor (keys, a click), a path traced with `t`; and
/// a region dragged or marked, a render pinned.
fn inspect(app: &mut App, msg: Msg) {
    let size = app
        .snapshot
        .as_ref()
        .and_then(|s| s.views.first())
        .map(|f| (f.width, f.height));
    match msg {
        Msg::ToggleInspect => {
            app.inspect = match (app.inspect, size) {
                (None, Some((w, h))) => Some((w / 2, h / 2)),
                _ => None,
            };
            app.trace = None;
            app.panel_scroll = 0;
            if app.inspect.is_none() && size.is_none() {
                app.message = "nothing rendered yet: i inspects a pixel of the picture".into();
            }
        }
        Msg::CursorMove(dx, dy) => {
            if let (Some((x, y)), Some((w, h))) = (app.inspect, size) {
                let clamp =
                    |v: u32, d: i32, n: u32| (v as i64 + d as i64).clamp(0, n as i64 - 1) as u32;
                app.inspect = Some((clamp(x, dx, w), clamp(y, dy, h)));
                app.trace = None;
                app.traces = 0;
            }
        }
        Msg::TracePath => match (app.inspect, app.snapshot.as_ref()) {
            (Some(pixel), Some(snap)) if app.traces_paths() => {
                let sample = app.traces % snap.samples.max(1);
                let generation = app.generation;
                app.effects.push(Effect::Trace {
                    generation,
                    pixel,
                    sample,
                });
                app.traces += 1;
            }
            (Some(_), _) if app.traces_paths() => app.message = "nothing rendered yet".into(),
            _ => app.message = "t traces a path in chapter 6's inspect mode (i)".into(),
        },
        Msg::Click {
            column,
            row,
            width,
            height,
        } => app.click_at(ratatui::layout::Rect::new(0, 0, width, height), column, row),
        Msg::Drag {
            column,
            row,
            width,
            height,
        } => app.drag_to(ratatui::layout::Rect::new(0, 0, width, height), column, row),
        Msg::MarkRegion => app.mark_region(),
        Msg::TogglePin => app.toggle_pin(),
        Msg::ToggleSplit => app.toggle_split(),
        _ => {}
    }
}

/// `g` (the grader's images, or back), `x` (student mode, or back) and
/// `s` (save what is shown, when something is).
fn grade_or_save(app: &mut App, msg: Msg) {
    match msg {
        Msg::ToggleGrading => {
            if app.grading.take().is_some() {
                app.compare = Compare::Render;
                app.message = "back to the render".into();
            } else {
                app.effects.push(Effect::LoadGrades);
            }
        }
        Msg::ToggleStudent => toggle_student(app),
        Msg::Save => {
            if app.snapshot.is_some() || app.grading.is_some() || app.student_render().is_some() {
                app.effects.push(Effect::Save);
            } else {
                app.message = "nothing to save yet".into();
            }
        }
        _ => {}
    }
}

/// The warp test view: open or close it, the next routine, new random
/// numbers (the draws themselves run in a thread: [`super::warp_jobs`]).
fn warp(app: &mut App, msg: Msg) {
    match msg {
        Msg::ToggleWarp => {
            app.warp = match app.warp {
                Some(_) => None,
                None => Some(Box::new(super::warp::WarpView::new(0, 1))),
            }
        }
        Msg::WarpStep(step) => {
            if let Some(w) = &app.warp {
                app.warp = Some(Box::new(w.step(step)));
            }
        }
        Msg::WarpReseed => {
            if let Some(w) = &app.warp {
                app.warp = Some(Box::new(w.reseeded()));
            }
        }
        _ => {}
    }
}

/// A target in words: "1024 spp, or noise below 1.0% of the mean".
pub fn target_text(t: &Target) -> String {
    match t.noise {
        Some(n) => format!(
            "{} spp, or noise below {:.2}% of the mean",
            t.spp,
            100.0 * n
        ),
        None => format!("{} spp", t.spp),
    }
}
