//! "How much faster is MIS than BSDF sampling here?": every estimator's
//! error-against-time curve of the current chapter and scene is kept, so
//! that stepping through the estimators (`e`) draws them on one chart, each
//! with its efficiency 1/(MSE·t) at its newest point: the higher, the less
//! time the estimator needs for a given error.

use ratatui::style::Color;

use super::app::App;
use super::worker::RenderState;

/// One estimator's curve, for the chart and its legend.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// The estimator's name.
    pub name: String,
    /// (seconds, RMSE) per pass, oldest first.
    pub series: Vec<(f64, f64)>,
    /// Whether this is the render running now.
    pub current: bool,
    /// Its colour on the chart.
    pub colour: Color,
}

/// Colours for the estimators, by their index: named colours that read
/// on light and dark backgrounds alike (not grey, white, black, yellow or
/// cyan). The −1/2 guide is drawn in the terminal's own colour.
const PALETTE: [Color; 8] = [
    Color::Red,
    Color::Green,
    Color::Blue,
    Color::Magenta,
    Color::LightRed,
    Color::LightGreen,
    Color::LightBlue,
    Color::LightMagenta,
];

impl Curve {
    /// 1/(MSE·t) at the newest point, in 1/s (`None` before the first
    /// positive point).
    pub fn efficiency(&self) -> Option<f64> {
        let &(t, e) = self.series.last()?;
        (t > 0.0 && e > 0.0).then(|| 1.0 / (e * e * t))
    }
}

impl App {
    /// The key of the render running now: chapter, scene and estimator.
    fn curve_key(&self) -> Option<(usize, String, usize)> {
        let scene = self.current_scene()?.name.clone();
        Some((self.chapter, scene, self.variant))
    }

    /// Takes a render's state after a pass, and keeps its error series
    /// under its estimator, to be drawn beside the others.
    pub fn new_state(&mut self, state: RenderState) {
        self.snapshot = Some(state);
        self.keep_curve();
        self.keep_equal_time();
    }

    /// Keeps the running render's error series under its estimator.
    fn keep_curve(&mut self) {
        let Some(key) = self.curve_key() else { return };
        if let Some(s) = self.snapshot.as_ref().filter(|s| s.error_series.len() >= 2) {
            self.curves.insert(key, s.error_series.clone());
        }
    }

    /// Every kept curve of this chapter and scene, the running one last,
    /// each in its estimator's colour.
    pub fn curves(&self) -> Vec<Curve> {
        let Some((chapter, scene, variant)) = self.curve_key() else {
            return Vec::new();
        };
        let variants = self
            .current_chapter()
            .map(|c| c.info().variants)
            .unwrap_or(&[]);
        let name = |v: usize| {
            variants
                .get(v)
                .map_or("render".to_string(), |x| x.name.to_string())
        };
        let mut out: Vec<Curve> = self
            .curves
            .iter()
            .filter(|((c, s, v), _)| *c == chapter && *s == scene && *v != variant)
            .map(|((_, _, v), series)| Curve {
                name: name(*v),
                series: series.clone(),
                current: false,
                colour: PALETTE[v % PALETTE.len()],
            })
            .collect();
        if let Some(s) = self
            .snapshot
            .as_ref()
            .filter(|s| !s.error_series.is_empty())
        {
            out.push(Curve {
                name: name(variant),
                series: s.error_series.clone(),
                current: true,
                colour: PALETTE[variant % PALETTE.len()],
            });
        }
        out
    }
}
