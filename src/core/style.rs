//! How the book's figures look: the bundled font (DejaVu Sans, so a fresh
//! machine needs no system fonts), the colour-blind-safe palette, and the
//! markers and line styles that tell a plot's series apart.

use std::sync::OnceLock;

use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::{register_font, FontStyle};
use plotters_backend::{BackendCoord, DrawingErrorKind};

use crate::core::error::{Error, Result};

/// DejaVu Sans, Bitstream Vera licence (`assets/fonts/DejaVu-LICENSE.txt`).
pub(crate) static FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
/// The family name plotters looks the font up by.
pub(crate) const FAMILY: &str = "sans-serif";

/// Registers the font once; an error if the bytes are not a font.
pub(crate) fn font() -> Result<()> {
    static DONE: OnceLock<bool> = OnceLock::new();
    let ok = *DONE.get_or_init(|| register_font(FAMILY, FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err(Error::Usage("the bundled plot font does not parse".into()))
    }
}

/// Okabe–Ito colours, safe for the common colour-vision deficiencies
/// (yellow left out: it vanishes on white).
pub const PALETTE: [(u8, u8, u8); 7] = [
    (0, 114, 178),   // blue
    (213, 94, 0),    // vermillion
    (0, 158, 115),   // bluish green
    (204, 121, 167), // reddish purple
    (230, 159, 0),   // orange
    (86, 180, 233),  // sky blue
    (0, 0, 0),       // black
];

/// The point marker of a series.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Marker {
    /// A filled circle.
    Circle,
    /// A filled triangle.
    Triangle,
    /// An outlined square.
    Square,
    /// A cross.
    Cross,
}

/// How one series looks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Look {
    /// Index into [`PALETTE`] (taken modulo its length).
    pub colour: usize,
    /// The marker at every point.
    pub marker: Marker,
    /// Dashed instead of solid line.
    pub dashed: bool,
}

impl Look {
    /// The `i`-th of a sequence of looks that differ in colour and marker.
    pub fn nth(i: usize) -> Look {
        const MARKERS: [Marker; 4] = [
            Marker::Circle,
            Marker::Triangle,
            Marker::Square,
            Marker::Cross,
        ];
        Look {
            colour: i,
            marker: MARKERS[i % MARKERS.len()],
            dashed: false,
        }
    }

    pub(crate) fn rgb(&self) -> RGBColor {
        let (r, g, b) = PALETTE[self.colour % PALETTE.len()];
        RGBColor(r, g, b)
    }
}

/// A point marker, optionally with a 24-pixel legend line through it
/// (drawn from the anchor rightwards, the marker in its middle).
pub(crate) struct Mark<C> {
    pub(crate) at: C,
    pub(crate) colour: RGBColor,
    pub(crate) marker: Option<Marker>,
    /// `Some(dashed)` for a legend entry.
    pub(crate) legend_line: Option<bool>,
}

impl<C> Mark<C> {
    pub(crate) fn point(at: C, look: Look) -> Mark<C> {
        Mark {
            at,
            colour: look.rgb(),
            marker: Some(look.marker),
            legend_line: None,
        }
    }
}

impl<'b, C> PointCollection<'b, C> for &'b Mark<C> {
    type Point = &'b C;
    type IntoIter = std::iter::Once<&'b C>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<C, DB: DrawingBackend> Drawable<DB> for Mark<C> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut pos: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> std::result::Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((mut x, y)) = pos.next() else {
            return Ok(());
        };
        let thin = self.colour.stroke_width(2);
        if let Some(dashed) = self.legend_line {
            let pieces: &[(i32, i32)] = if dashed {
                &[(0, 7), (11, 17), (21, 24)]
            } else {
                &[(0, 24)]
            };
            for (a, b) in pieces {
                backend.draw_line((x + a, y), (x + b, y), &thin)?;
            }
            x += 12;
        }
        let fill = self.colour.filled();
        match self.marker {
            None => Ok(()),
            Some(Marker::Circle) => backend.draw_circle((x, y), 4, &fill, true),
            Some(Marker::Triangle) => {
                backend.fill_polygon(vec![(x, y - 5), (x - 5, y + 4), (x + 5, y + 4)], &fill)
            }
            Some(Marker::Square) => backend.draw_rect((x - 3, y - 3), (x + 3, y + 3), &thin, false),
            Some(Marker::Cross) => {
                backend.draw_line((x - 4, y - 4), (x + 4, y + 4), &thin)?;
                backend.draw_line((x - 4, y + 4), (x + 4, y - 4), &thin)
            }
        }
    }
}
