//! The answers from the UI's threads, as [`update`](super::update::update)
//! applies them: the render worker's reports (a pass, a failure, a
//! refusal, a traced path, a story), a save's files, the grader's images,
//! the student-mode watcher's reports, a scene file read or edited, the
//! warp view's draws. A report about a render that has been replaced is dropped.

use super::app::{App, Compare, Msg};
use super::student_update::student_event;
use super::worker::{Progress, Purpose};
use crate::core::stage::Inspection;

/// An answer from a thread applied to `app` (`step` sends only those).
pub(super) fn answer(app: &mut App, msg: Msg) {
    match msg {
        Msg::Progress(p) if p.generation() == app.generation => progress(app, p),
        // A pass of a render that has been replaced: dropped.
        Msg::Progress(_) => {}
        Msg::Traced(result) => traced(app, result),
        Msg::Story(x, y, lines) => app.story = Some((x, y, lines)),
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
        Msg::GradeLoaded(result) => grades_loaded(app, result),
        Msg::Student(chapter, event) => student_event(app, chapter, event),
        Msg::SceneRead(index, path, read) => app.scene_read(index, &path, read),
        Msg::SceneEdited(index) => app.scene_edited(index),
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
        _ => {}
    }
}

/// A report of the current render.
fn progress(app: &mut App, p: Progress) {
    match p {
        Progress::State(s) => app.new_state(*s),
        Progress::Failed { message, .. } => app.failure = Some(message),
        // Known from now on: the scene list marks it, and this chapter is
        // not opened on it again while others work.
        Progress::Refused { message, .. } => app.refused(message),
        Progress::Inspected {
            purpose: Purpose::Trace,
            result,
            ..
        } => traced(app, result.map(Box::new)),
        Progress::Inspected {
            purpose: Purpose::Story,
            result,
            ..
        } => {
            if let Ok(i) = result {
                app.story = Some((i.pixel.0, i.pixel.1, i.lines));
            }
        }
    }
}

/// The path `t` asked for, or why there is none: shown if the cursor is
/// still on its pixel.
fn traced(app: &mut App, result: Result<Box<Inspection>, String>) {
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

/// The grader's newest failure images (shown instead of the render), none,
/// or why they could not be read.
fn grades_loaded(app: &mut App, result: Result<Option<crate::grading::FailureImages>, String>) {
    match result {
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
    }
}
