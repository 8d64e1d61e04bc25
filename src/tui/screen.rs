//! Where things go on the screen: the layout [`view`](super::view::view)
//! draws into, and the inverse question a mouse click asks (which pixel of
//! the picture is under this cell?).

use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::widgets::Block;

use super::app::App;
use super::state::PictureMap;

/// Width of the left column, in cells.
pub fn sidebar_width(total: u16) -> u16 {
    (total / 3).clamp(16, 34).min(total)
}

/// Width of the left column while inspecting: the pixel panel fills it,
/// so it gets a little more of the screen.
pub fn panel_width(total: u16) -> u16 {
    (total * 2 / 5).clamp(16, 44).min(total)
}

/// The smallest terminal the UI draws into (columns, rows); below it a
/// notice says how big the terminal must be.
pub const MIN_SIZE: (u16, u16) = (60, 16);

/// A path table narrower than this covers the picture instead of sitting
/// beside it.
pub const TABLE_BESIDE_MIN: u16 = 96;

/// Where everything goes on a screen of `area`.
pub struct Areas {
    /// The left column.
    pub side: Rect,
    /// The preview's box (empty while the path table covers it).
    pub preview: Rect,
    /// The traced path's table, beside the preview or over it, when there
    /// is one.
    pub table: Option<Rect>,
    /// The inspect panel (the whole left column while inspecting).
    pub panel: Option<Rect>,
    /// Status line, gauge and message line.
    pub lines: [Rect; 3],
    /// Whether the screen is below [`MIN_SIZE`] (then only a notice is
    /// drawn, and every other area is empty).
    pub too_small: bool,
}

/// The layout of a screen of `area`: the same for drawing, for mapping a
/// mouse click to a pixel and for scrolling.
///
/// While inspecting, the pixel panel takes the whole left column (the
/// chapter and scene lists fold away: the arrow keys move the cursor then,
/// and the status line and title still name chapter and scene). The path
/// table sits beside the picture on wide screens and over it on narrow
/// ones (Esc closes it).
pub fn areas(app: &App, area: Rect) -> Areas {
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        let empty = Rect::new(area.x, area.y, 0, 0);
        return Areas {
            side: empty,
            preview: empty,
            table: None,
            panel: None,
            lines: [empty; 3],
            too_small: true,
        };
    }
    let [main, status, gauge, message] = Layout::vertical([
        Constraint::Min(3),
        Constraint::Length(1),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(area);
    let inspecting = app.inspect.is_some();
    // A path table over the picture gets the room the wider panel would
    // take.
    let covered = app.trace.is_some()
        && area.width.saturating_sub(panel_width(area.width)) < TABLE_BESIDE_MIN;
    let width = if inspecting && !covered {
        panel_width(area.width)
    } else {
        sidebar_width(area.width)
    };
    let [side, right] =
        Layout::horizontal([Constraint::Length(width), Constraint::Min(1)]).areas(main);
    let (preview, table) = match &app.trace {
        Some(_) if right.width >= TABLE_BESIDE_MIN => {
            let w = right.width / 2;
            let [p, t] =
                Layout::horizontal([Constraint::Min(1), Constraint::Length(w)]).areas(right);
            (p, Some(t))
        }
        Some(_) => (Rect::new(right.x, right.y, 0, 0), Some(right)),
        None => (right, None),
    };
    Areas {
        side,
        preview,
        table,
        panel: inspecting.then_some(side),
        lines: [status, gauge, message],
        too_small: false,
    }
}

impl PictureMap {
    /// The picture as `app` shows it on a screen of `area`, if it shows one.
    pub fn of(app: &App, area: Rect) -> Option<PictureMap> {
        let film = app.snapshot.as_ref()?.views.first()?;
        let window = super::zoom::Window::of(app, film.width, film.height);
        let preview = areas(app, area).preview;
        if preview.width < 3 || preview.height < 3 {
            return None;
        }
        let inner = Block::bordered().inner(preview);
        let cells = super::placement::picture_cells(app, inner, window.width, window.height);
        Some(PictureMap { cells, window })
    }

    /// The pixel shown at cell (`column`, `row`), if the cell shows the
    /// picture.
    pub fn pixel(&self, column: u16, row: u16) -> Option<(u32, u32)> {
        let (r, w, h) = (self.cells, self.window.width, self.window.height);
        let inside = |c: u16, start: u16, len: u16| c >= start && c < start + len;
        if !inside(column, r.x, r.width) || !inside(row, r.y, r.height) {
            return None;
        }
        let x = super::inspect::cell_to_pixel(column - r.x, r.width, w);
        let y = super::inspect::cell_to_pixel(row - r.y, r.height, h);
        Some(self.window.to_image((x, y)))
    }
}

/// The pixel of the picture shown at terminal cell (`column`, `row`) of a
/// screen of `area`, if the cell shows the picture.
pub fn pixel_at(app: &App, area: Rect, column: u16, row: u16) -> Option<(u32, u32)> {
    PictureMap::of(app, area)?.pixel(column, row)
}

impl App {
    /// A click on cell (`column`, `row`) of a `screen`: the inspect cursor
    /// goes to the pixel under it (a new pixel forgets the traced path),
    /// and a drag from there may start; a region chosen before is cleared.
    pub fn click_at(&mut self, screen: Rect, column: u16, row: u16) {
        self.pressed = PictureMap::of(self, screen);
        if let Some(p) = self.pressed.and_then(|m| m.pixel(column, row)) {
            if self.inspect != Some(p) {
                self.trace = None;
                self.traces = 0;
            }
            self.inspect = Some(p);
            self.region = None;
        }
    }

    /// A drag of the mouse to cell (`column`, `row`) of a `screen`: the box
    /// from where the button went down (the inspect cursor) to there, both
    /// corners placed by where the picture was when the button went down.
    pub fn drag_to(&mut self, screen: Rect, column: u16, row: u16) {
        let map = self.pressed.or_else(|| PictureMap::of(self, screen));
        if let (Some(a), Some(p)) = (self.inspect, map.and_then(|m| m.pixel(column, row))) {
            self.region = Some(super::region::spanned(a, p));
        }
    }
}
