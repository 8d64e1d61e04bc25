//! Log-log plots drawn into a film with [`crate::core::draw`], for the
//! error-against-time studies of chapters 5 and 6: one coloured polyline
//! with dots per series, grid lines at every power of ten, an optional
//! guide of a given slope. No text: the book's captions name the colours.

use glam::{Vec2, Vec3};

use crate::core::draw::{dot, line};
use crate::core::film::Film;

/// One series of a plot: its colour and its (x, y) points, both positive
/// (they are plotted as log10).
#[derive(Clone, Debug)]
pub struct Polyline {
    /// Colour of the line and the dots.
    pub colour: Vec3,
    /// The points in order, joined by straight lines.
    pub points: Vec<(f64, f64)>,
}

/// How a plot looks.
#[derive(Clone, Copy, Debug)]
pub struct LogLogStyle {
    /// Colour of the empty film.
    pub background: Vec3,
    /// Pixels between the film's edge and the outermost decade.
    pub margin: f64,
    /// Colour of the decade lines.
    pub grid: Vec3,
    /// A guide line (slope in decades per decade, colour) from the first
    /// point to the right edge.
    pub guide: Option<(f64, Vec3)>,
    /// Invert the finished film. The draw helpers keep the brighter of old
    /// and new, so a light plot is drawn light-on-dark and inverted: give
    /// the complements of the colours that should show.
    pub invert: bool,
}

/// Draws `series` on log-log axes spanning whole decades around every
/// point.
// ANCHOR: log_log
pub fn log_log(series: &[Polyline], style: &LogLogStyle, width: u32, height: u32) -> Film {
    let mut film = Film::new(width, height);
    film.pixels.fill(style.background);
    let logs: Vec<(Vec3, Vec<(f64, f64)>)> = series
        .iter()
        .map(|s| {
            let pts = s.points.iter().map(|&(x, y)| (x.log10(), y.log10()));
            (s.colour, pts.collect())
        })
        .collect();
    let all = || logs.iter().flat_map(|(_, pts)| pts.iter().copied());
    let Some(first) = all().next() else {
        return finish(film, style.invert);
    };
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in all() {
        (x0, x1) = (x0.min(x), x1.max(x));
        (y0, y1) = (y0.min(y), y1.max(y));
    }
    let (x0, x1, y0, y1) = (x0.floor(), x1.ceil(), y0.floor(), y1.ceil());
    let m = style.margin;
    let (w, h) = (width as f64 - 2.0 * m, height as f64 - 2.0 * m);
    let to_px = |x: f64, y: f64| {
        let fx = (x - x0) / (x1 - x0).max(1e-9);
        let fy = (y - y0) / (y1 - y0).max(1e-9);
        Vec2::new((m + fx * w) as f32, (height as f64 - m - fy * h) as f32)
    };
    let g = style.grid;
    for k in x0 as i64..=x1 as i64 {
        line(&mut film, to_px(k as f64, y0), to_px(k as f64, y1), g, g);
    }
    for k in y0 as i64..=y1 as i64 {
        line(&mut film, to_px(x0, k as f64), to_px(x1, k as f64), g, g);
    }
    if let Some((slope, c)) = style.guide {
        let (gx, gy) = first;
        let end = to_px(x1, gy + slope * (x1 - gx));
        line(&mut film, to_px(gx, gy), end, c, c);
    }
    for (c, pts) in &logs {
        let px: Vec<Vec2> = pts.iter().map(|&(x, y)| to_px(x, y)).collect();
        for pair in px.windows(2) {
            line(&mut film, pair[0], pair[1], *c, *c);
        }
        for p in &px {
            dot(&mut film, *p, 2.5, *c);
        }
    }
    finish(film, style.invert)
}
// ANCHOR_END: log_log

fn finish(mut film: Film, invert: bool) -> Film {
    if invert {
        for p in &mut film.pixels {
            *p = (Vec3::ONE - *p).max(Vec3::ZERO);
        }
    }
    film
}

#[cfg(test)]
mod tests {
    use super::*;

    const STYLE: LogLogStyle = LogLogStyle {
        background: Vec3::ZERO,
        margin: 10.0,
        grid: Vec3::splat(0.2),
        guide: None,
        invert: false,
    };

    fn red(points: Vec<(f64, f64)>) -> Polyline {
        Polyline {
            colour: Vec3::X,
            points,
        }
    }

    #[test]
    fn decades_span_the_film_inside_the_margin() {
        // x from 1 to 100, y from 0.01 to 1: the corners of the axes.
        let f = log_log(&[red(vec![(1.0, 1.0), (100.0, 0.01)])], &STYLE, 101, 61);
        // The first point sits at the top-left corner (10, 10), the last at
        // the bottom-right (91, 51): red there, nothing red in the corner.
        assert!(f.get(10, 10).x > 0.9 && f.get(90, 50).x > 0.9);
        assert_eq!(f.get(0, 0), Vec3::ZERO);
        // The middle decade line x = 10 is grey, away from the series.
        assert!((f.get(50, 15).y - 0.2).abs() < 0.01, "{:?}", f.get(50, 15));
    }

    #[test]
    fn an_empty_plot_is_background_and_inversion_applies() {
        let style = LogLogStyle {
            invert: true,
            ..STYLE
        };
        let f = log_log(&[red(vec![])], &style, 8, 8);
        assert!(f.pixels.iter().all(|p| *p == Vec3::ONE));
    }

    #[test]
    fn the_guide_starts_at_the_first_point() {
        let style = LogLogStyle {
            guide: Some((-1.0, Vec3::Z)),
            ..STYLE
        };
        // The series runs along the top and right edges of a one-decade
        // square; the guide of slope -1 is its diagonal, through the
        // centre of pixel (29, 29).
        let pts = vec![(1.0, 10.0), (10.0, 10.0), (10.0, 1.0)];
        let f = log_log(&[red(pts)], &style, 60, 60);
        assert!(f.get(29, 29).z > 0.8, "{:?}", f.get(29, 29));
        assert_eq!(f.get(29, 29).x, 0.0);
        assert_eq!(f.get(20, 40), Vec3::ZERO);
    }
}
