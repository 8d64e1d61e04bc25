//! Where the preview's picture goes: with a graphics protocol, a
//! placement that fills its box ([`place`]); with half blocks, [`fit`].
//! The view, the painter and the mouse all ask here, so they agree.

use ratatui::layout::Rect;

use super::app::App;
use super::graphics::Graphics;
use super::picture::fit;

/// The cell size when the preview uses a graphics protocol (colour on,
/// a protocol chosen, a cell size known); `None` for half blocks.
pub fn graphics_font(app: &App) -> Option<(u16, u16)> {
    (app.color && app.graphics != Graphics::HalfBlocks)
        .then_some(app.font)
        .flatten()
}

/// Whether an overlay covers the picture (the help, the warp test).
pub fn covered(app: &App) -> bool {
    app.help || app.warp.is_some()
}

/// Where a picture goes in its box, and its size in pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Placement {
    /// The cells it covers, centred in the box.
    pub cells: Rect,
    /// Its width in pixels.
    pub width: u32,
    /// Its height in pixels.
    pub height: u32,
}

/// `n` rounded up to a multiple of 6.
pub fn pad6(n: u32) -> u32 {
    n.div_ceil(6) * 6
}

/// The placement of a `width` x `height` picture in `area` with cells of
/// `font` pixels, centred: the largest whole zoom that fits when it fills
/// at least four fifths of the room it could (every pixel a sharp
/// square), else scaled to fill (shrunk when even 1x does not fit).
pub fn place(area: Rect, width: u32, height: u32, font: (u16, u16)) -> Placement {
    let (fw, fh) = (font.0.max(1) as u32, font.1.max(1) as u32);
    let (w, h) = (width.max(1), height.max(1));
    let room_w = area.width as u32 * fw;
    // Whole sixel bands only.
    let room_h = area.height as u32 * fh / 6 * 6;
    let s = (room_w as f64 / w as f64).min(room_h as f64 / h as f64);
    // A whole factor unless it would leave a fifth of the room empty.
    let s = if s >= 1.0 && s.floor() >= 0.8 * s {
        s.floor()
    } else {
        s
    };
    let pw = ((w as f64 * s).floor() as u32).clamp(1, room_w.max(1));
    let ph = ((h as f64 * s).floor() as u32).clamp(1, room_h.max(1));
    let cols = (pw.div_ceil(fw) as u16).clamp(1, area.width.max(1));
    let rows = (pad6(ph).div_ceil(fh) as u16).clamp(1, area.height.max(1));
    Placement {
        cells: Rect::new(
            area.x + (area.width.saturating_sub(cols)) / 2,
            area.y + (area.height.saturating_sub(rows)) / 2,
            cols.min(area.width),
            rows.min(area.height),
        ),
        width: pw,
        height: ph,
    }
}

/// The cells the picture of a `w` x `h` window takes in `inner`: the
/// placement with a graphics protocol, [`fit`] with half blocks.
pub fn picture_cells(app: &App, inner: Rect, w: u32, h: u32) -> Rect {
    match graphics_font(app) {
        Some(font) if !covered(app) => place(inner, w, h, font).cells,
        _ => fit(inner, w, h),
    }
}
