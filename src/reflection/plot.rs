//! A log-log plot of error against time, drawn into a film with
//! [`crate::draw`]: one coloured line per strategy, grid lines at every
//! power of ten. No text: the book's caption names the colours.

use glam::{Vec2, Vec3};

use crate::draw::{dot, line};
use crate::film::Film;

/// The colour of each strategy's line: uniform red, cosine green, light
/// blue, MIS yellow; anything else grey.
pub fn colour(series: &str) -> Vec3 {
    if series.ends_with("uniform") {
        Vec3::new(0.9, 0.15, 0.1)
    } else if series.ends_with("cosine") {
        Vec3::new(0.1, 0.8, 0.2)
    } else if series.ends_with("light") {
        Vec3::new(0.15, 0.35, 1.0)
    } else if series.ends_with("mis") {
        Vec3::new(1.0, 0.85, 0.1)
    } else {
        Vec3::splat(0.6)
    }
}

/// Rows (series, seconds, error) from the study's CSV text; rows with a
/// zero or non-finite time or error are skipped (they have no logarithm).
pub fn rows_from_csv(csv: &str) -> Vec<(String, f64, f64)> {
    csv.lines()
        .skip(1)
        .filter_map(|l| {
            let cells: Vec<&str> = l.split(',').collect();
            let (s, e) = (
                cells.get(2)?.parse::<f64>().ok()?,
                cells.get(4)?.parse::<f64>().ok()?,
            );
            (s > 0.0 && e > 0.0 && s.is_finite() && e.is_finite())
                .then(|| (cells[0].to_string(), s, e))
        })
        .collect()
}

/// Plots the rows whose series starts with `prefix` on log-log axes.
pub fn plot(rows: &[(String, f64, f64)], prefix: &str, width: u32, height: u32) -> Film {
    let mut film = Film::new(width, height);
    for p in &mut film.pixels {
        *p = Vec3::splat(0.02);
    }
    let rows: Vec<_> = rows.iter().filter(|r| r.0.starts_with(prefix)).collect();
    if rows.is_empty() {
        return film;
    }
    let lx = |r: &&(String, f64, f64)| r.1.log10();
    let ly = |r: &&(String, f64, f64)| r.2.log10();
    let (x0, x1) = (
        rows.iter().map(lx).fold(f64::INFINITY, f64::min).floor(),
        rows.iter().map(lx).fold(f64::NEG_INFINITY, f64::max).ceil(),
    );
    let (y0, y1) = (
        rows.iter().map(ly).fold(f64::INFINITY, f64::min).floor(),
        rows.iter().map(ly).fold(f64::NEG_INFINITY, f64::max).ceil(),
    );
    let margin = 16.0;
    let (w, h) = (width as f32 - 2.0 * margin, height as f32 - 2.0 * margin);
    let to_px = |x: f64, y: f64| {
        let fx = ((x - x0) / (x1 - x0).max(1e-9)) as f32;
        let fy = ((y - y0) / (y1 - y0).max(1e-9)) as f32;
        Vec2::new(margin + fx * w, margin + (1.0 - fy) * h)
    };
    let grid = Vec3::splat(0.12);
    for k in x0 as i64..=x1 as i64 {
        line(
            &mut film,
            to_px(k as f64, y0),
            to_px(k as f64, y1),
            grid,
            grid,
        );
    }
    for k in y0 as i64..=y1 as i64 {
        line(
            &mut film,
            to_px(x0, k as f64),
            to_px(x1, k as f64),
            grid,
            grid,
        );
    }
    // A guide of slope −1/2 through the first point, in white.
    let first = rows[0];
    let (gx, gy) = (lx(&first), ly(&first));
    let white = Vec3::splat(0.5);
    line(
        &mut film,
        to_px(gx, gy),
        to_px(x1, gy - 0.5 * (x1 - gx)),
        white,
        white,
    );
    for pair in rows.windows(2) {
        if pair[0].0 == pair[1].0 {
            let c = colour(&pair[0].0);
            line(
                &mut film,
                to_px(lx(&pair[0]), ly(&pair[0])),
                to_px(lx(&pair[1]), ly(&pair[1])),
                c,
                c,
            );
        }
    }
    for r in &rows {
        dot(&mut film, to_px(lx(r), ly(r)), 2.5, colour(&r.0));
    }
    film
}
