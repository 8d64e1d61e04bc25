//! The controls box's numbers that answer a question: the noise view's
//! scale, the difference's metrics (tev's: error, absolute, squared,
//! relative absolute and relative squared, each as a mean), the z view's
//! verdict, and the estimators' efficiencies.

use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};

use super::app::{App, Compare};
use super::gauge::short_number;
use crate::core::difference::metrics;

/// A style with this foreground colour, or plain without colour.
pub fn fg(app: &App, c: Color) -> Style {
    if app.color {
        Style::default().fg(c)
    } else {
        Style::default()
    }
}

/// The noise view's scale: the standard error that shows white.
pub fn noise_scale(app: &App) -> Vec<Line<'static>> {
    if app.view_name() != "stderr" {
        return Vec::new();
    }
    let white = 2f64.powi(-app.display_exposure());
    vec![Line::from(format!(
        "white: std error {}",
        short_number(white)
    ))]
}

/// The non-finite view's legend: how many contributions were caught
/// (NaN or infinite, left out of the image) and in how many pixels.
pub fn caught_lines(app: &App) -> Vec<Line<'static>> {
    let counts = app.snapshot.as_ref().and_then(|s| s.views.get(app.view));
    let Some(counts) = counts.filter(|_| app.shows_caught()) else {
        return Vec::new();
    };
    let total: f64 = counts.pixels.iter().map(|c| f64::from(c.x)).sum();
    let pixels = counts.pixels.iter().filter(|c| c.x > 0.0).count();
    if pixels == 0 {
        return vec![Line::styled(
            "non-finite: none caught",
            fg(app, Color::Green),
        )];
    }
    vec![
        Line::styled(format!("non-finite: {total} caught"), fg(app, Color::Red)),
        Line::styled(format!("in {pixels} px: green"), fg(app, Color::Green)),
    ]
}

/// Under a difference, tev's five metrics of the render against the
/// reference, as means over pixels and channels; under the z view, its
/// verdict in words, green or red.
pub fn compare_lines(app: &App) -> Vec<Line<'static>> {
    match app.compare {
        Compare::Difference | Compare::Relative => {
            let Some((render, reference)) = app.compared_pair() else {
                return Vec::new();
            };
            let m = metrics(&render, reference);
            let n = short_number;
            vec![
                Line::from(format!("mean error {}", n(m.error))),
                Line::from(format!("abs {} · sq {}", n(m.absolute), n(m.squared))),
                Line::from(format!(
                    "rel abs {} · rel sq {}",
                    n(m.relative_absolute),
                    n(m.relative_squared)
                )),
            ]
        }
        Compare::Z => match app.verdict() {
            Some(v) => {
                let colour = if v.within_noise() {
                    Color::Green
                } else {
                    Color::Red
                };
                let [first, second] = v.lines();
                vec![Line::styled(first, fg(app, colour)), Line::from(second)]
            }
            None => Vec::new(),
        },
        _ => Vec::new(),
    }
}

/// Each estimator's efficiency 1/(MSE·s), once there are two to compare,
/// beside a bullet of its curve's colour: the chart's legend.
pub fn efficiency_lines(app: &App) -> Vec<Line<'static>> {
    let curves: Vec<_> = app
        .curves()
        .into_iter()
        .filter_map(|c| Some((c.efficiency()?, c)))
        .collect();
    if curves.len() < 2 {
        return Vec::new();
    }
    let best = curves.iter().map(|(e, _)| *e).fold(0.0, f64::max);
    let mut lines = vec![Line::from("efficiency 1/(MSE·s):")];
    for (e, c) in &curves {
        let mark = if *e == best { " best" } else { "" };
        lines.push(Line::from(vec![
            Span::styled("● ", fg(app, c.colour)),
            Span::raw(format!("{} {}{mark}", c.name, short_number(*e))),
        ]));
    }
    lines
}
