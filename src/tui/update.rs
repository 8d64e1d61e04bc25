//! [`update`], a pure function from (state, message) to the next state and
//! the [`Effect`]s it asks for (its student-mode part is in
//! [`student_update`](super::student_update)), and [`save`]. `update`
//! touches neither the terminal, the clock, the disk nor a thread: the
//! event loop turns keys and answers into messages, and carries out the
//! effects `update` leaves in [`App::effects`].
//!
//! Some effects are asked for by a message itself: `s` saves
//! ([`Effect::Save`]), `g` reads the grader's images
//! ([`Effect::LoadGrades`]), `t` traces a path ([`Effect::Trace`]). The
//! others follow from comparing the state before and after the message
//! (`follow`): a new generation starts its render ([`Effect::Start`],
//! once); within a generation a new target or pause goes to the running
//! render ([`Effect::Retarget`], [`Effect::Pause`]); student mode's
//! chapter gets its watcher ([`Effect::Watch`]); and a pixel inspected over
//! a new picture or a newly inspected pixel gets its story asked for
//! ([`Effect::Story`], once per pixel and generation).

use super::app::*;
use super::effect::Effect;
pub use super::save::save;
use super::student_update::{student_event, student_follows_chapter, toggle_student};
use super::worker::{Progress, Purpose, Target};

/// The next state of the UI after `msg`, with what it asks the event loop
/// to do added to [`App::effects`].
pub fn update(mut app: App, msg: Msg) -> App {
    let outward = Outward::of(&app);
    let before = app.message.clone();
    // The next action clears a message (it may set its own).
    let action = msg.is_action();
    if action {
        app.message.clear();
    }
    let mut app = step(app, msg);
    // A new message, or the same one said again, starts its time anew.
    if app.message != before || (action && !app.message.is_empty()) {
        app.message_age = std::time::Duration::ZERO;
    }
    follow(&mut app, &outward);
    app
}

/// The part of the state the world outside follows (the running render,
/// student mode's watcher, the inspect panel's story), compared before
/// and after a message.
struct Outward {
    generation: u64,
    target: Target,
    paused: bool,
    watched: Option<u32>,
    story: Option<((u32, u32), u64)>,
}

impl Outward {
    fn of(app: &App) -> Outward {
        Outward {
            generation: app.generation,
            target: app.target,
            paused: app.paused,
            watched: app.student.as_ref().map(|s| s.chapter),
            story: story_wanted(app),
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
    // Asked when the pixel or the render changes, unless the panel holds
    // that pixel's story already (inspect mode off and on again).
    let held = |pixel: (u32, u32)| app.story.as_ref().map(|(x, y, _)| (*x, *y)) == Some(pixel);
    if let Some((pixel, generation)) = now.story.filter(|s| Some(*s) != before.story) {
        if !held(pixel) {
            app.effects.push(Effect::Story { generation, pixel });
        }
    }
}

fn step(mut app: App, msg: Msg) -> App {
    // Any key but `?` closes the help overlay first; the arrows, j k, u d
    // and the page keys scroll it.
    if app.help && app.scroll_help(&msg) {
        return app;
    }
    if app.help
        && !matches!(
            msg,
            Msg::ToggleHelp
                | Msg::Quit
                | Msg::Tick(_)
                | Msg::Resize(..)
                | Msg::Progress(_)
                | Msg::Saved(_)
                | Msg::GradeLoaded(_)
                | Msg::Student(..)
        )
    {
        app.help = false;
        return app;
    }
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
        Msg::BounceUp if app.shows_bounces() => {
            app.bounce = match app.bounce {
                None => Some(0),
                Some(k) if k >= MAX_BOUNCE => None,
                Some(k) => Some(k + 1),
            }
        }
        Msg::BounceDown if app.shows_bounces() => {
            app.bounce = match app.bounce {
                None => Some(MAX_BOUNCE),
                Some(0) => None,
                Some(k) => Some(k - 1),
            }
        }
        Msg::ToggleBounceMode if app.shows_bounces() => {
            app.bounce_mode = match app.bounce_mode {
                BounceMode::Exactly => BounceMode::UpTo,
                BounceMode::UpTo => BounceMode::Exactly,
            }
        }
        Msg::BounceUp | Msg::BounceDown | Msg::ToggleBounceMode => {}
        Msg::CycleCompare | Msg::Flip => {
            if app.shows_compare() {
                let flip = matches!(msg, Msg::Flip);
                app.compare = if flip {
                    app.compare.flipped()
                } else {
                    app.compare.next(app.z_available())
                };
            }
        }
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
        Msg::ToggleInspect => {
            let size = app
                .snapshot
                .as_ref()
                .and_then(|s| s.views.first())
                .map(|f| (f.width, f.height));
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
            let size = app
                .snapshot
                .as_ref()
                .and_then(|s| s.views.first())
                .map(|f| (f.width, f.height));
            if let (Some((x, y)), Some((w, h))) = (app.inspect, size) {
                let clamp =
                    |v: u32, d: i32, n: u32| (v as i64 + d as i64).clamp(0, n as i64 - 1) as u32;
                app.inspect = Some((clamp(x, dx, w), clamp(y, dy, h)));
                app.trace = None;
                app.traces = 0;
            }
        }
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
        Msg::Traced(result) => traced(&mut app, result),
        Msg::Story(x, y, lines) => app.story = Some((x, y, lines)),
        Msg::TargetUp | Msg::TargetDown => {
            if app.progressive() {
                app.target = match msg {
                    Msg::TargetUp => app.target.doubled(),
                    _ => app.target.halved(),
                };
                app.message = format!("target: {}", target_text(&app.target));
            }
        }
        Msg::ToggleGrading => {
            if app.grading.take().is_some() {
                app.compare = Compare::Render;
                app.message = "back to the render".into();
            } else {
                app.effects.push(Effect::LoadGrades);
            }
        }
        Msg::GradeLoaded(result) => match result {
            Ok(Some(images)) => {
                app.student = None;
                app.message = format!(
                        "grading {}: student vs reference (r: student → reference → difference → relative, g: back)",
                        images.stem
                    );
                app.grading = Some(images);
                app.compare = Compare::Render;
            }
            Ok(None) => {
                app.message = format!(
                    "no failed image checks in {}: run `cargo run --release --bin grade` first",
                    app.grade_dir().display()
                )
            }
            Err(e) => app.message = format!("cannot read the grader's images: {e}"),
        },
        Msg::ToggleStudent => toggle_student(&mut app),
        Msg::Student(chapter, event) => student_event(&mut app, chapter, event),
        Msg::Save => {
            if app.snapshot.is_some() || app.grading.is_some() || app.student_render().is_some() {
                app.effects.push(Effect::Save);
            } else {
                app.message = "nothing to save yet".into();
            }
        }
        Msg::Pasted => {
            app.message = "paste ignored: the UI takes keys one at a time".into();
        }
        Msg::Saved(result) => {
            app.message = match result {
                Ok(files) => format!(
                    "saved {}",
                    files
                        .iter()
                        .map(|f| f.display().to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
                Err(e) => format!("save failed: {e}"),
            };
        }
        Msg::ToggleHelp => app.help = !app.help,
        Msg::Zoom(step) => app.zoom = super::zoom::zoomed(app.zoom, step),
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
        Msg::SceneRead(index, path, read) => app.scene_read(index, &path, read),
        Msg::WarpBuiltin(index, seed, test) => {
            if let Some(w) = app.warp.as_mut() {
                w.builtin_done(index, seed, *test);
            }
        }
        Msg::WarpStudent(seed, drawn) => {
            if let Some(w) = app.warp.as_mut() {
                w.student_drawn(seed, drawn);
            }
        }
        Msg::Quit => app.quit = true,
        Msg::Close => close(&mut app),
        Msg::Scroll(lines) => scroll(&mut app, lines),
        Msg::Wheel { column, row, lines } => {
            let a = super::screen::areas(&app, app.screen);
            let inside = |r: ratatui::layout::Rect| {
                column >= r.x && column < r.x + r.width && row >= r.y && row < r.y + r.height
            };
            if a.table.is_some_and(inside) {
                app.table_scroll = scrolled(app.table_scroll, lines, table_room(&app));
            } else if a.panel.is_some_and(inside) {
                app.panel_scroll = scrolled(app.panel_scroll, lines, panel_room(&app));
            } else if inside(a.preview) {
                // Over the picture the wheel zooms: up is in.
                app.zoom = super::zoom::zoomed(app.zoom, -lines.signum());
            }
        }
        Msg::Hover { column, row } => {
            app.hover = super::screen::pixel_at(&app, app.screen, column, row);
        }
        Msg::Resize(width, height) => {
            app.screen = ratatui::layout::Rect::new(0, 0, width, height);
            // The same scroll may now be past the end.
            app.panel_scroll = app.panel_scroll.min(panel_room(&app));
            app.table_scroll = app.table_scroll.min(table_room(&app));
        }
        Msg::Tick(elapsed) => {
            if !app.message.is_empty() {
                app.message_age += elapsed;
                if app.message_age >= MESSAGE_TTL {
                    app.message.clear();
                }
            }
        }
        Msg::Progress(p) if p.generation() == app.generation => match p {
            Progress::State(s) => app.new_state(*s),
            Progress::Failed { message, .. } => app.failure = Some(message),
            // Known from now on: the scene list marks it, and this chapter
            // is not opened on it again while others work.
            Progress::Refused { message, .. } => app.refused(message),
            Progress::Inspected {
                purpose: Purpose::Trace,
                result,
                ..
            } => traced(&mut app, result.map(Box::new)),
            Progress::Inspected {
                purpose: Purpose::Story,
                result,
                ..
            } => {
                if let Ok(i) = result {
                    app.story = Some((i.pixel.0, i.pixel.1, i.lines));
                }
            }
        },
        // A pass of a render that has been replaced: dropped.
        Msg::Progress(_) => {}
    }
    student_follows_chapter(&mut app);
    app
}

/// The path `t` asked for, or why there is none: shown if the cursor is
/// still on its pixel.
fn traced(app: &mut App, result: Result<Box<crate::core::stage::Inspection>, String>) {
    match result {
        Ok(t) if Some(t.pixel) == app.inspect => {
            app.message = format!(
                "traced sample {} of pixel ({}, {}) (t: the next sample)",
                t.sample, t.pixel.0, t.pixel.1
            );
            app.trace = Some(t);
            app.table_scroll = 0;
        }
        Ok(_) => {}
        Err(e) => app.message = format!("cannot trace: {e}"),
    }
}

/// Esc: closes what is open, the innermost first (the help is closed
/// before any message gets here): the path table, inspect mode, the
/// grader's images, student mode. It never quits.
fn close(app: &mut App) {
    if app.trace.is_some() {
        app.trace = None;
        app.table_scroll = 0;
    } else if app.inspect.is_some() {
        app.inspect = None;
        app.panel_scroll = 0;
    } else if app.grading.take().is_some() || app.student.take().is_some() {
        // (The two are never on together.)
        app.compare = Compare::Render;
        app.message = "back to the render".into();
    } else {
        app.message = "nothing to close: q quits".into();
    }
}

/// `u`/`d`, Page Up/Down: scrolls the path table when it is shown, else
/// the inspect panel.
fn scroll(app: &mut App, lines: i32) {
    let a = super::screen::areas(app, app.screen);
    if a.table.is_some() {
        app.table_scroll = scrolled(app.table_scroll, lines, table_room(app));
    } else if a.panel.is_some() {
        app.panel_scroll = scrolled(app.panel_scroll, lines, panel_room(app));
    } else {
        app.message = "nothing to scroll: i opens the pixel panel".into();
    }
}

fn scrolled(at: u16, lines: i32, max: u16) -> u16 {
    (at as i32 + lines).clamp(0, max as i32) as u16
}

/// How far the inspect panel can scroll at the current screen size.
fn panel_room(app: &App) -> u16 {
    let a = super::screen::areas(app, app.screen);
    a.panel.map_or(0, |r| {
        super::inspect::overflow(&super::inspect::inspect_lines(app), r)
    })
}

/// How far the path table can scroll at the current screen size.
fn table_room(app: &App) -> u16 {
    let a = super::screen::areas(app, app.screen);
    match (a.table, &app.trace) {
        (Some(r), Some(t)) => super::inspect::overflow(&t.lines, r),
        _ => 0,
    }
}

/// A target in words: "1024 spp, or noise below 1.0% of the mean".
pub fn target_text(t: &super::worker::Target) -> String {
    match t.noise {
        Some(n) => format!(
            "{} spp, or noise below {:.2}% of the mean",
            t.spp,
            100.0 * n
        ),
        None => format!("{} spp", t.spp),
    }
}
