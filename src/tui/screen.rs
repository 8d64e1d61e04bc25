//! Where things go on the screen: the layout [`view`](super::view::view)
//! draws into, and the inverse question a mouse click asks (which pixel of
//! the picture is under this cell?).

use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::widgets::Block;

use super::app::App;
use super::picture::fit;

/// Width of the left column, in cells.
pub fn sidebar_width(total: u16) -> u16 {
    (total / 3).clamp(16, 34).min(total)
}

/// Where everything goes on a screen of `area`.
pub struct Areas {
    /// The left column.
    pub side: Rect,
    /// The preview's box.
    pub preview: Rect,
    /// The traced path's table, right of the preview, when there is one.
    pub table: Option<Rect>,
    /// Status line, gauge and message line.
    pub lines: [Rect; 3],
}

/// The layout of a screen of `area`: the same for drawing and for mapping
/// a mouse click to a pixel.
pub fn areas(app: &App, area: Rect) -> Areas {
    let [main, status, gauge, message] = Layout::vertical([
        Constraint::Min(3),
        Constraint::Length(1),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(area);
    let [side, right] = Layout::horizontal([
        Constraint::Length(sidebar_width(area.width)),
        Constraint::Min(1),
    ])
    .areas(main);
    let (preview, table) = if app.trace.is_some() && right.width >= 40 {
        let w = (right.width / 2).max(36).min(right.width - 4);
        let [p, t] = Layout::horizontal([Constraint::Min(1), Constraint::Length(w)]).areas(right);
        (p, Some(t))
    } else {
        (right, None)
    };
    Areas {
        side,
        preview,
        table,
        lines: [status, gauge, message],
    }
}

/// The pixel of the picture shown at terminal cell (`column`, `row`) of a
/// screen of `area`, if the cell shows the picture.
pub fn pixel_at(app: &App, area: Rect, column: u16, row: u16) -> Option<(u32, u32)> {
    let film = app.snapshot.as_ref()?.views.first()?;
    let (w, h) = (film.width, film.height);
    let inner = Block::bordered().inner(areas(app, area).preview);
    let r = match (&app.picker, app.color) {
        (Some(p), true) => super::inspect::graphics_rect(inner, w, h, p.font_size()),
        _ => fit(inner, w, h),
    };
    let inside = |c: u16, start: u16, len: u16| c >= start && c < start + len;
    if !inside(column, r.x, r.width) || !inside(row, r.y, r.height) {
        return None;
    }
    let x = super::inspect::cell_to_pixel(column - r.x, r.width, w);
    let y = super::inspect::cell_to_pixel(row - r.y, r.height, h);
    Some((x, y))
}
