//! The one plot module of the book: error against run time on log-log
//! axes, drawn with the `plotters` crate. Every chapter that plots goes
//! through [`LogLogPlot`]: labelled axes with units, ticks at every power of
//! ten, a legend, and a look per series (colour, marker, solid or dashed)
//! so lines stay apart in print and for colour-blind readers.
//!
//! Text is rendered from the DejaVu Sans font shipped in `assets/fonts/`
//! (Bitstream Vera licence, beside it), so a fresh machine needs no system
//! fonts.

use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{register_font, FontStyle};
use plotters_backend::{BackendCoord, DrawingErrorKind};

use crate::core::error::{Error, Result};
use crate::core::film::{write_atomically, Film};
use crate::core::report::ErrorTime;

/// DejaVu Sans, Bitstream Vera licence (`assets/fonts/DejaVu-LICENSE.txt`).
static FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
/// Pixels right of the axes kept for the legend.
const LEGEND_WIDTH: i32 = 170;
/// The family name plotters looks the font up by.
const FAMILY: &str = "sans-serif";

/// Registers the font once; an error if the bytes are not a font.
fn font() -> Result<()> {
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

    fn rgb(&self) -> RGBColor {
        let (r, g, b) = PALETTE[self.colour % PALETTE.len()];
        RGBColor(r, g, b)
    }
}

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
        write_rgb_png(&pixels, width, height, path)
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

impl LogLogPlot {
    /// The error-against-time plot of the series of `et` whose names start
    /// with `prefix` (the prefix is left out of the legend), each looked up
    /// in `look`; with the −1/2 guide when `et` shows slopes.
    pub fn error_time(
        et: &ErrorTime,
        prefix: &str,
        title: &str,
        look: impl Fn(&str) -> Look,
    ) -> LogLogPlot {
        let series = et
            .series()
            .into_iter()
            .filter(|s| s.starts_with(prefix))
            .map(|s| Series {
                label: s[prefix.len()..].trim_matches([' ', ':', '/']).to_string(),
                look: look(&s),
                points: et
                    .rows
                    .iter()
                    .filter(|r| r.series == s)
                    .map(|r| (r.seconds, r.error))
                    .collect(),
            })
            .collect();
        LogLogPlot {
            title: title.into(),
            x_label: "run time (s)".into(),
            y_label: et.error_name.clone(),
            series,
            guide: et.show_slopes.then(|| Guide {
                slope: -0.5,
                label: "slope −1/2".into(),
            }),
        }
    }
}

/// Images side by side on white, 2 pixels apart, each with its caption
/// centred under it: the book's strips (bounces, samples per pixel).
/// Returns 8-bit RGB pixels, width and height.
pub fn captioned_strip(images: &[(&Film, &str)]) -> Result<(Vec<u8>, u32, u32)> {
    font()?;
    let gap = 2;
    let band = 22;
    let image_h = images.iter().map(|(f, _)| f.height).max().unwrap_or(1);
    let width = images.iter().map(|(f, _)| f.width).sum::<u32>()
        + gap * images.len().saturating_sub(1) as u32;
    let (width, height) = (width.max(1), image_h + band);
    let mut pixels = vec![255u8; (width * height * 3) as usize];
    let mut x0 = 0;
    for (film, _) in images {
        let rgb = film.to_srgb8();
        for y in 0..film.height {
            let src = (y * film.width * 3) as usize;
            let dst = ((y * width + x0) * 3) as usize;
            let n = (film.width * 3) as usize;
            pixels[dst..dst + n].copy_from_slice(&rgb[src..src + n]);
        }
        x0 += film.width + gap;
    }
    {
        let root = BitMapBackend::with_buffer(&mut pixels, (width, height)).into_drawing_area();
        let style = TextStyle::from((FAMILY, 14).into_font())
            .color(&BLACK)
            .pos(Pos::new(HPos::Center, VPos::Center));
        let mut x0 = 0i32;
        for (film, caption) in images {
            let at = (x0 + film.width as i32 / 2, image_h as i32 + band as i32 / 2);
            root.draw_text(caption, &style, at)
                .map_err(|e| Error::Usage(format!("drawing a caption: {e}")))?;
            x0 += (film.width + gap) as i32;
        }
        root.present()
            .map_err(|e| Error::Usage(format!("drawing a caption: {e}")))?;
    }
    Ok((pixels, width, height))
}

/// [`captioned_strip`] written as a PNG, atomically.
pub fn write_captioned_strip(images: &[(&Film, &str)], path: &Path) -> Result<()> {
    let (pixels, width, height) = captioned_strip(images)?;
    write_rgb_png(&pixels, width, height, path)
}

fn write_rgb_png(pixels: &[u8], width: u32, height: u32, path: &Path) -> Result<()> {
    write_atomically(path, |tmp| {
        image::save_buffer_with_format(
            tmp,
            pixels,
            width,
            height,
            image::ColorType::Rgb8,
            image::ImageFormat::Png,
        )
        .map_err(|e| e.to_string())
    })
}

fn loggable((x, y): (f64, f64)) -> bool {
    x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite()
}

/// Whole decades around every point (one decade when there are none).
fn decades(pts: impl Iterator<Item = (f64, f64)>) -> (std::ops::Range<f64>, std::ops::Range<f64>) {
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
fn guide_segment(
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
fn labelled_tick(v: f64, range: &std::ops::Range<f64>) -> String {
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

/// A point marker, optionally with a 24-pixel legend line through it
/// (drawn from the anchor rightwards, the marker in its middle).
struct Mark<C> {
    at: C,
    colour: RGBColor,
    marker: Option<Marker>,
    /// `Some(dashed)` for a legend entry.
    legend_line: Option<bool>,
}

impl<C> Mark<C> {
    fn point(at: C, look: Look) -> Mark<C> {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn plot(series: Vec<Series>) -> LogLogPlot {
        LogLogPlot {
            title: "test".into(),
            x_label: "run time (s)".into(),
            y_label: "RMSE".into(),
            series,
            guide: Some(Guide {
                slope: -0.5,
                label: "slope −1/2".into(),
            }),
        }
    }

    fn at(px: &[u8], w: u32, x: u32, y: u32) -> (u8, u8, u8) {
        let i = ((y * w + x) * 3) as usize;
        (px[i], px[i + 1], px[i + 2])
    }

    #[test]
    fn ticks_read_as_numbers() {
        assert_eq!(tick(0.001), "0.001");
        assert_eq!(tick(1.0), "1");
        assert_eq!(tick(100.0), "100");
        assert_eq!(tick(1e-5), "1e-5");
        assert_eq!(tick(1e6), "1e6");
    }

    #[test]
    fn only_decades_are_labelled_on_long_axes() {
        let long = 1e-6..1.0;
        let short = 0.01..1.0;
        assert_eq!(labelled_tick(1e-3, &long), "0.001");
        assert_eq!(labelled_tick(2e-3, &long), "");
        assert_eq!(labelled_tick(0.05, &short), "0.05");
        assert_eq!(labelled_tick(0.03, &short), "");
    }

    #[test]
    fn decades_round_outwards() {
        let (x, y) = decades([(2.0, 0.05), (30.0, 0.5)].into_iter());
        assert!((x.start - 1.0).abs() < 2e-3 && x.end == 100.0);
        assert!((y.start - 0.01).abs() < 2e-5 && (y.end - 1.0).abs() < 2e-3);
    }

    #[test]
    fn the_guide_is_clipped_to_the_axes() {
        let s = Series {
            label: "a".into(),
            points: vec![(1.0, 1.0), (100.0, 0.1)],
            look: Look::nth(0),
        };
        let lines = vec![(&s, s.points.clone())];
        let seg = guide_segment(-0.5, &lines, 1.0..100.0, 0.1..1.0).unwrap();
        // From (1, 1) down to (100, 0.1): slope -1/2 over two decades.
        assert!((seg[0].0 - 1.0).abs() < 1e-9 && (seg[0].1 - 1.0).abs() < 1e-9);
        assert!((seg[1].0 - 100.0).abs() < 1e-6 && (seg[1].1 - 0.1).abs() < 1e-9);
    }

    #[test]
    fn a_plot_draws_coloured_lines_and_text_on_white() {
        let series = vec![
            Series {
                label: "uniform".into(),
                points: vec![(0.01, 1.0), (0.1, 0.3), (1.0, 0.1)],
                look: Look::nth(0),
            },
            Series {
                label: "light".into(),
                points: vec![(0.01, 0.1), (0.1, 0.03), (1.0, 0.01), (0.0, 5.0)],
                look: Look {
                    dashed: true,
                    ..Look::nth(1)
                },
            },
        ];
        let (w, h) = (480, 320);
        let px = plot(series).draw(w, h).unwrap();
        assert_eq!(at(&px, w, 0, 0), (255, 255, 255));
        let count = |c: (u8, u8, u8)| {
            (0..h)
                .flat_map(|y| (0..w).map(move |x| (x, y)))
                .filter(|&(x, y)| at(&px, w, x, y) == c)
                .count()
        };
        // Both series' colours show, and dark text (axis labels, ticks,
        // legend) is drawn.
        assert!(count(PALETTE[0]) > 100, "blue {}", count(PALETTE[0]));
        assert!(count(PALETTE[1]) > 50, "vermillion {}", count(PALETTE[1]));
        let dark = px.chunks(3).filter(|p| p.iter().all(|v| *v < 60)).count();
        assert!(dark > 500, "dark pixels {dark}");
    }

    #[test]
    fn a_strip_keeps_its_images_and_captions_them() {
        let mut red = Film::new(40, 30);
        red.pixels.fill(glam::Vec3::X);
        let blue = Film {
            pixels: vec![glam::Vec3::Z; 40 * 30],
            ..Film::new(40, 30)
        };
        let (px, w, h) = captioned_strip(&[(&red, "one"), (&blue, "two")]).unwrap();
        assert_eq!((w, h), (82, 52));
        assert_eq!(at(&px, w, 10, 10), (255, 0, 0));
        assert_eq!(at(&px, w, 60, 10), (0, 0, 255));
        // The gap stays white, and the caption band has dark text.
        assert_eq!(at(&px, w, 40, 10), (255, 255, 255));
        let band = &px[(30 * w * 3) as usize..];
        assert!(band.chunks(3).filter(|p| p[0] < 100).count() > 20);
    }

    #[test]
    fn an_empty_plot_still_draws_its_axes() {
        let px = plot(vec![]).draw(200, 150).unwrap();
        assert!(px.chunks(3).any(|p| p == [0, 0, 0]));
    }
}
