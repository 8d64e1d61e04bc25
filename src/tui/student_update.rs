//! Student mode's part of [`update`](super::update::update): `x` turns it
//! on for the current chapter's capstone (or off), the watcher's reports
//! become its status and images, and it follows the selected chapter.

use super::app::{App, Compare};
use super::student::{StudentEvent, StudentMode};
use crate::grading::live::{capstone, LiveError};

/// `x`: student mode on for the current chapter (when it has a capstone),
/// or off.
pub(super) fn toggle_student(app: &mut App) {
    if app.student.take().is_some() {
        app.compare = Compare::Render;
        app.message = "back to the render".into();
        return;
    }
    start_student(app);
}

/// Student mode for the current chapter, or a message why there is none.
pub(super) fn start_student(app: &mut App) {
    let n = app.current_chapter().map_or(0, |c| c.info().number);
    let Some(ex) = capstone(n) else {
        app.student = None;
        app.message = format!("chapter {n} has no capstone for student mode");
        return;
    };
    app.grading = None;
    app.compare = Compare::Render;
    app.message = format!(
        "student mode: {} from {}, re-rendered when you save (r: student → reference → difference → relative, x: back)",
        ex.id(),
        ex.file
    );
    app.student = Some(StudentMode {
        chapter: n,
        id: ex.id(),
        status: "starting…".into(),
        details: String::new(),
        render: None,
    });
}

/// A report from the watcher of chapter `chapter`; one about another
/// chapter (the student has moved on) is dropped.
pub(super) fn student_event(app: &mut App, chapter: u32, event: StudentEvent) {
    let Some(s) = app.student.as_mut().filter(|s| s.chapter == chapter) else {
        return;
    };
    match event {
        StudentEvent::Building => s.status = "building…".into(),
        StudentEvent::Rendering => s.status = "rendering…".into(),
        StudentEvent::Done(Ok(render)) => {
            s.status = render.status();
            app.message = format!("{}: {}", render.id, render.detail);
            s.render = Some(render);
        }
        StudentEvent::Done(Err(e)) => {
            s.status = e.status();
            s.details = match &e {
                LiveError::DoesNotCompile { message, .. } => {
                    app.message = message.lines().take(2).collect::<Vec<_>>().join(" ");
                    message.lines().take(24).collect::<Vec<_>>().join("\n")
                }
                LiveError::Panicked { message, .. } | LiveError::Build(message) => message.clone(),
                LiveError::NotStarted { file, .. } => {
                    format!("replace the todo!() in {file}: its comments say what to write")
                }
                _ => String::new(),
            };
            s.render = None;
            app.compare = Compare::Render;
        }
    }
}

/// Student mode follows the selected chapter.
pub(super) fn student_follows_chapter(app: &mut App) {
    let n = app.current_chapter().map_or(0, |c| c.info().number);
    if app.student.as_ref().is_some_and(|s| s.chapter != n) {
        start_student(app);
    }
}
