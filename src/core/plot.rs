//! The one plot module of the book: error against run time on log-log
//! axes, drawn with the `plotters` crate. Every chapter that plots goes
//! through [`LogLogPlot`]: labelled axes with units, ticks at every power of
//! ten, a legend, and a look per series (colour, marker, solid or dashed)
//! so lines stay apart in print and for colour-blind readers.
//!
//! Text is rendered from the DejaVu Sans font shipped in `assets/fonts/`
//! (Bitstream Vera licence, beside it), so a fresh machine needs no system
//! fonts; the font, palette and markers are in [`crate::core::style`].

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::core::error::{Error, Result};
use crate::core::film::write_rgb8_png;
pub use crate::core::strip::{captioned_strip, write_captioned_strip};
use crate::core::style::{font, Mark, FAMILY};
pub use crate::core::style::{Look, Marker, PALETTE};

/// Pixels right of the axes kept for the legend.
const LEGEND_WIDTH: i32 = 170;
/// One line of a plot.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The legend entry.
    pub label: String,
    /// (x, y) points in order; points with a non-positive or non-finite
    /// coordinate have no logarithm and are left out.
    pub points: Vec<(f64, f64)>,
    /// Colour, marker and dash.
    pub look: Look,
}

/// A reference line of a given slope (in decades per decade), e.g. the
/// −1/2 every Monte Carlo estimator follows against time.
#[derive(Clone, Debug, PartialEq)]
pub struct Guide {
    /// Decades of y per decade of x.
    pub slope: f64,
    /// The legend entry.
    pub label: String,
}

/// A log-log plot.
#[derive(Clone, Debug, PartialEq)]
pub struct LogLogPlot {
    /// Above the plot.
    pub title: String,
    /// Under the x axis, with its unit, e.g. "run time (s)".
    pub x_label: String,
    /// Beside the y axis, e.g. "RMSE (radiance)".
    pub y_label: String,
    /// The lines.
    pub series: Vec<Series>,
    /// A dashed grey line through the highest first point, or none.
    pub guide: Option<Guide>,
}

// ANCHOR: log_log
impl LogLogPlot {
    /// The plot as 8-bit RGB pixels, row by row.
    pub fn draw(&self, width: u32, height: u32) -> Result<Vec<u8>> {
        font()?;
        let mut pixels = vec![255u8; (width * height * 3) as usize];
        {
            let root = BitMapBackend::with_buffer(&mut pixels, (width, height)).into_drawing_area();
            self.draw_on(&root)
                .map_err(|e| Error::Usage(format!("drawing a plot: {e}")))?;
            root.present()
                .map_err(|e| Error::Usage(format!("drawing a plot: {e}")))?;
        }
        Ok(pixels)
    }

    /// Writes the plot as a PNG, atomically.
    pub fn write_png(&self, path: &Path, width: u32, height: u32) -> Result<()> {
        let pixels = self.draw(width, height)?;
        write_rgb8_png(&pixels, width, height, path)
    }

    fn draw_on<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        let lines: Vec<(&Series, Vec<(f64, f64)>)> = self
            .series
            .iter()
            .map(|s| {
                (
                    s,
                    s.points.iter().copied().filter(|p| loggable(*p)).collect(),
                )
            })
            .collect();
        let (xs, ys) = decades(lines.iter().flat_map(|(_, p)| p.iter().copied()));
        // The legend gets a panel of its own right of the axes, so it never
        // hides a line.
        let (plot_area, legend_area) =
            root.split_horizontally(root.dim_in_pixel().0 as i32 - LEGEND_WIDTH);
        let mut chart = ChartBuilder::on(&plot_area)
            .caption(&self.title, (FAMILY, 17))
            .margin(12)
            .margin_right(20)
            .x_label_area_size(44)
            .y_label_area_size(64)
            .build_cartesian_2d(xs.clone().log_scale(), ys.clone().log_scale())?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style((FAMILY, 13))
            .axis_desc_style((FAMILY, 14))
            .x_label_formatter(&|v| labelled_tick(*v, &xs))
            .y_label_formatter(&|v| labelled_tick(*v, &ys))
            .light_line_style(RGBColor(235, 235, 235))
            .bold_line_style(RGBColor(200, 200, 200))
            .draw()?;
        let grey = RGBColor(120, 120, 120);
        let mut legend: Vec<(&str, Mark<(i32, i32)>)> = Vec::new();
        if let Some(g) = &self.guide {
            if let Some(seg) = guide_segment(g.slope, &lines, chart.x_range(), chart.y_range()) {
                chart.draw_series(DashedLineSeries::new(seg, 6, 5, grey.stroke_width(1)))?;
                let mark = Mark {
                    at: (0, 0),
                    colour: grey,
                    marker: None,
                    legend_line: Some(true),
                };
                legend.push((&g.label, mark));
            }
        }
        for (s, pts) in &lines {
            let line = s.look.rgb().stroke_width(2);
            if s.look.dashed {
                chart.draw_series(DashedLineSeries::new(pts.iter().copied(), 8, 5, line))?;
            } else {
                chart.draw_series(LineSeries::new(pts.iter().copied(), line))?;
            }
            chart.draw_series(pts.iter().map(|p| Mark::point(*p, s.look)))?;
            let mark = Mark {
                legend_line: Some(s.look.dashed),
                ..Mark::point((0, 0), s.look)
            };
            legend.push((&s.label, mark));
        }
        let text = TextStyle::from((FAMILY, 13).into_font())
            .color(&BLACK)
            .pos(Pos::new(HPos::Left, VPos::Center));
        for (i, (label, mut mark)) in legend.into_iter().enumerate() {
            let y = 48 + 20 * i as i32;
            mark.at = (4, y);
            legend_area.draw(&mark)?;
            legend_area.draw_text(label, &text, (34, y))?;
        }
        Ok(())
    }
}
// ANCHOR_END: log_log

fn loggable((x, y): (f64, f64)) -> bool {
    x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite()
}

/// Whole decades around every point (one decade when there are none).
pub fn decades(
    pts: impl Iterator<Item = (f64, f64)>,
) -> (std::ops::Range<f64>, std::ops::Range<f64>) {
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in pts {
        let (lx, ly) = (x.log10(), y.log10());
        (x0, x1, y0, y1) = (x0.min(lx), x1.max(lx), y0.min(ly), y1.max(ly));
    }
    if x0 > x1 {
        return (1.0..10.0, 1.0..10.0);
    }
    let span = |lo: f64, hi: f64| {
        let (a, b) = (lo.floor(), hi.ceil());
        let b = if b <= a { a + 1.0 } else { b };
        // A hair lower, so rounding in the tick positions keeps the
        // lowest decade's tick.
        10f64.powf(a) * 0.999..10f64.powf(b)
    };
    (span(x0, x1), span(y0, y1))
}

/// The guide through the first point of the line that starts highest,
/// clipped to the axes: two points, or none without data.
pub fn guide_segment(
    slope: f64,
    lines: &[(&Series, Vec<(f64, f64)>)],
    xs: std::ops::Range<f64>,
    ys: std::ops::Range<f64>,
) -> Option<Vec<(f64, f64)>> {
    let (gx, gy) = lines
        .iter()
        .filter_map(|(_, p)| p.first().copied())
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    let (lx, ly) = (gx.log10(), gy.log10());
    let y_at = |x: f64| ly + slope * (x - lx);
    let x_at = |y: f64| lx + (y - ly) / slope;
    let (a, b) = (xs.start.log10(), xs.end.log10());
    let (lo, hi) = (ys.start.log10(), ys.end.log10());
    // Clip the line x in [a, b] to y in [lo, hi].
    let mut x_lo = a;
    let mut x_hi = b;
    if slope != 0.0 {
        let (p, q) = (x_at(lo), x_at(hi));
        x_lo = x_lo.max(p.min(q));
        x_hi = x_hi.min(p.max(q));
    }
    (x_lo < x_hi).then(|| {
        [x_lo, x_hi]
            .iter()
            .map(|x| (10f64.powf(*x), 10f64.powf(y_at(*x))))
            .collect()
    })
}

/// The label of a tick at `v` on an axis spanning `range`: every power of
/// ten, and 2 and 5 times it when the axis spans at most two decades;
/// other ticks get grid lines but no label, so labels never overlap.
pub fn labelled_tick(v: f64, range: &std::ops::Range<f64>) -> String {
    let decades = (range.end / range.start).log10();
    let mantissa = v / 10f64.powf(v.log10().floor());
    let near = |m: f64| (mantissa - m).abs() < 1e-3 * m;
    if near(1.0) || near(10.0) || (decades <= 2.01 && (near(2.0) || near(5.0))) {
        tick(v)
    } else {
        String::new()
    }
}

/// A tick label: 0.001 … 1000 as decimals, anything else as 1e-5.
pub fn tick(v: f64) -> String {
    if (1e-3..1e4).contains(&v) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        let e = v.log10().round() as i32;
        if (v / 10f64.powi(e) - 1.0).abs() < 1e-6 {
            format!("1e{e}")
        } else {
            format!("{v:.0e}")
        }
    }
}
