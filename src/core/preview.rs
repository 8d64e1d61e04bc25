//! A preview of a film in the terminal, for headless runs and reports.
//!
//! With colour, each character cell shows two pixels: the upper half block
//! `▀` painted in the top pixel's colour over a background of the bottom
//! pixel's colour, in 24-bit ANSI colour. Without colour (`NO_COLOR` set, or
//! stdout is not a terminal) each cell is one character of an ASCII ramp.

use std::io::IsTerminal;

use glam::Vec3;

use crate::core::film::{encode_srgb, Film};

/// How to draw the preview.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PreviewStyle {
    /// Half blocks in 24-bit colour.
    Color,
    /// A plain ASCII brightness ramp.
    Ascii,
}

impl PreviewStyle {
    /// Colour on a terminal unless `NO_COLOR` is set; ASCII otherwise.
    pub fn for_stdout() -> PreviewStyle {
        let no_color = std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty());
        if !no_color && std::io::stdout().is_terminal() {
            PreviewStyle::Color
        } else {
            PreviewStyle::Ascii
        }
    }
}

/// The ASCII ramp from dark to bright.
const RAMP: &[u8] = b" .:-=+*#%@";

/// Draws `film` at most `columns` characters wide.
pub fn preview(film: &Film, columns: u32, style: PreviewStyle) -> String {
    let cols = columns.clamp(1, film.width.max(1));
    // Character cells are about twice as tall as wide: a half-block cell
    // holds two square pixels; an ASCII cell one pixel of twice the height.
    let rows_px = match style {
        PreviewStyle::Color => {
            ((film.height as f32 * cols as f32 / film.width as f32).round() as u32).max(2) & !1
        }
        PreviewStyle::Ascii => {
            ((film.height as f32 * cols as f32 / film.width as f32 / 2.0).round() as u32).max(1)
        }
    };
    let small = downsample(film, cols, rows_px);
    let mut out = String::new();
    match style {
        PreviewStyle::Color => {
            for y in (0..rows_px).step_by(2) {
                for x in 0..cols {
                    let [tr, tg, tb] = small.get(x, y).to_array().map(encode_srgb);
                    let [br, bg, bb] = small.get(x, y + 1).to_array().map(encode_srgb);
                    out += &format!("\x1b[38;2;{tr};{tg};{tb}m\x1b[48;2;{br};{bg};{bb}m▀");
                }
                out += "\x1b[0m\n";
            }
        }
        PreviewStyle::Ascii => {
            for y in 0..rows_px {
                for x in 0..cols {
                    let p = small.get(x, y);
                    let luma = p.dot(LUMA);
                    let level = encode_srgb(luma) as usize * RAMP.len() / 256;
                    out.push(RAMP[level] as char);
                }
                out.push('\n');
            }
        }
    }
    out
}

/// The luminance of linear RGB: its dot product with these (Rec. 709).
pub const LUMA: Vec3 = Vec3::new(0.2126, 0.7152, 0.0722);

/// Box-filters `film` down (or up) to `w` x `h`.
pub fn downsample(film: &Film, w: u32, h: u32) -> Film {
    let mut small = Film::new(w, h);
    let (sx, sy) = (film.width as f32 / w as f32, film.height as f32 / h as f32);
    for y in 0..h {
        for x in 0..w {
            let (x0, x1) = (
                (x as f32 * sx) as u32,
                (((x + 1) as f32 * sx).ceil() as u32).min(film.width),
            );
            let (y0, y1) = (
                (y as f32 * sy) as u32,
                (((y + 1) as f32 * sy).ceil() as u32).min(film.height),
            );
            let mut sum = Vec3::ZERO;
            let mut n = 0.0;
            for yy in y0..y1.max(y0 + 1).min(film.height) {
                for xx in x0..x1.max(x0 + 1).min(film.width) {
                    sum += film.get(xx, yy);
                    n += 1.0;
                }
            }
            *small.get_mut(x, y) = if n > 0.0 { sum / n } else { Vec3::ZERO };
        }
    }
    small
}
