//! [`update`](super::update::update)'s part for the screen and the clock:
//! scrolling the inspect panel and the path table (keys and the mouse
//! wheel), the pixel under the mouse, a new terminal size, Esc, and an old
//! message clearing.

use ratatui::layout::Rect;

use super::app::{App, Compare, Msg, MESSAGE_TTL};
use super::inspect::{inspect_lines, overflow};
use super::screen::{areas, pixel_at};

/// A message about the screen or the clock applied to `app` (`step` sends
/// only those).
pub(super) fn screen(app: &mut App, msg: Msg) {
    match msg {
        Msg::Close => close(app),
        Msg::Scroll(lines) => scroll(app, lines),
        Msg::Wheel { column, row, lines } => {
            let a = areas(app, app.screen);
            let inside = |r: Rect| {
                column >= r.x && column < r.x + r.width && row >= r.y && row < r.y + r.height
            };
            if a.table.is_some_and(inside) {
                app.table_scroll = scrolled(app.table_scroll, lines, table_room(app));
            } else if a.panel.is_some_and(inside) {
                app.panel_scroll = scrolled(app.panel_scroll, lines, panel_room(app));
            } else if inside(a.preview) {
                // Over the picture the wheel zooms: up is in.
                app.zoom = super::zoom::zoomed(app.zoom, -lines.signum());
            }
        }
        Msg::Hover { column, row } => app.hover = pixel_at(app, app.screen, column, row),
        Msg::Resize(width, height) => {
            app.screen = Rect::new(0, 0, width, height);
            // The same scroll may now be past the end.
            app.panel_scroll = app.panel_scroll.min(panel_room(app));
            app.table_scroll = app.table_scroll.min(table_room(app));
        }
        Msg::Tick(elapsed) if !app.message.is_empty() => {
            app.message_age += elapsed;
            if app.message_age >= MESSAGE_TTL {
                app.message.clear();
            }
        }
        _ => {}
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
    let a = areas(app, app.screen);
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
    let a = areas(app, app.screen);
    a.panel.map_or(0, |r| overflow(&inspect_lines(app), r))
}

/// How far the path table can scroll at the current screen size.
fn table_room(app: &App) -> u16 {
    let a = areas(app, app.screen);
    match (a.table, &app.trace) {
        (Some(r), Some(t)) => overflow(&t.lines, r),
        _ => 0,
    }
}
