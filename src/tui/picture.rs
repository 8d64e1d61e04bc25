//! The preview widget: a film drawn by hand into terminal cells.
//!
//! With colour, each cell holds two pixels: the upper half block `▀` in the
//! top pixel's colour over a background of the bottom pixel's colour, as
//! 24-bit RGB (sRGB-encoded with [`encode_srgb`], like the PNG). Without
//! colour (`NO_COLOR`), each cell is one character of an ASCII brightness
//! ramp for the mean of its two pixels. The film is box-filtered to the
//! cells with [`downsample`], keeping its aspect ratio, and centred.

use glam::Vec3;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::widgets::Widget;

use crate::core::film::{encode_srgb, Film};
use crate::core::preview::downsample;

/// The ASCII ramp from dark to bright (the same as the headless preview).
const RAMP: &[u8] = b" .:-=+*#%@";

/// A film as a widget.
pub struct Picture<'a> {
    /// What to draw (already exposed).
    pub film: &'a Film,
    /// 24-bit half blocks, or the ASCII ramp.
    pub color: bool,
}

/// The cell rectangle, inside `area`, that shows a `width` x `height` film
/// at the largest size with the film's aspect ratio (a cell is one pixel
/// wide and two pixels tall). Centred; at least one cell.
pub fn fit(area: Rect, width: u32, height: u32) -> Rect {
    if area.width == 0 || area.height == 0 || width == 0 || height == 0 {
        return Rect::new(area.x, area.y, 0, 0);
    }
    let (aw, ah) = (area.width as f64, area.height as f64 * 2.0);
    let scale = (aw / width as f64).min(ah / height as f64);
    let cols = ((width as f64 * scale).round() as u16).clamp(1, area.width);
    let rows = (((height as f64 * scale) / 2.0).round() as u16).clamp(1, area.height);
    Rect::new(
        area.x + (area.width - cols) / 2,
        area.y + (area.height - rows) / 2,
        cols,
        rows,
    )
}

fn rgb(p: Vec3) -> Color {
    let [r, g, b] = p.to_array().map(encode_srgb);
    Color::Rgb(r, g, b)
}

impl Widget for Picture<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let r = fit(area, self.film.width, self.film.height);
        if r.width == 0 {
            return;
        }
        let small = downsample(self.film, r.width as u32, r.height as u32 * 2);
        for row in 0..r.height {
            for col in 0..r.width {
                let top = small.get(col as u32, row as u32 * 2);
                let bottom = small.get(col as u32, row as u32 * 2 + 1);
                let Some(cell) = buf.cell_mut((r.x + col, r.y + row)) else {
                    continue;
                };
                if self.color {
                    cell.set_symbol("▀").set_fg(rgb(top)).set_bg(rgb(bottom));
                } else {
                    let luma = ((top + bottom) * 0.5).dot(crate::core::preview::LUMA);
                    let level = encode_srgb(luma) as usize * RAMP.len() / 256;
                    cell.set_char(RAMP[level] as char);
                }
            }
        }
    }
}
