//! A log-log plot of error against time, drawn with [`crate::core::plot`]: one
//! coloured line per strategy, grid lines at every power of ten. No text:
//! the book's caption names the colours.

use glam::Vec3;

use crate::core::film::Film;
use crate::core::plot::{log_log, LogLogStyle, Polyline};

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

/// Plots the rows whose series starts with `prefix` on log-log axes: one
/// line per run of rows of the same series, a guide of slope −1/2 through
/// the first point, on a near-black film.
pub fn plot(rows: &[(String, f64, f64)], prefix: &str, width: u32, height: u32) -> Film {
    let rows: Vec<_> = rows.iter().filter(|r| r.0.starts_with(prefix)).collect();
    let series: Vec<Polyline> = rows
        .chunk_by(|a, b| a.0 == b.0)
        .map(|run| Polyline {
            colour: colour(&run[0].0),
            points: run.iter().map(|r| (r.1, r.2)).collect(),
        })
        .collect();
    let style = LogLogStyle {
        background: Vec3::splat(0.02),
        margin: 16.0,
        grid: Vec3::splat(0.12),
        guide: Some((-0.5, Vec3::splat(0.5))),
        invert: false,
    };
    log_log(&series, &style, width, height)
}
