//! The progress gauge under the status line: how far a render is, and for
//! a progressive one which stop is nearer and why it stopped.

use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::widgets::Gauge;
use ratatui::Frame;

use super::app::App;
use super::worker::Finish;
use crate::core::format::format_number;

/// Three significant digits: 0.012345 → "0.0123".
pub fn short_number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format_number(x);
    }
    let digits = (2 - x.abs().log10().floor() as i32).clamp(0, 8) as usize;
    format!("{x:.digits$}")
}

/// How far the render is, 0 to 1, and the gauge's label. A progressive
/// render is as far as the nearer of its two stops: the budget (samples
/// done / budget) and the noise level ((level / noise)², as noise falls
/// with 1/√spp).
pub fn gauge_state(app: &App) -> (f64, String) {
    let Some(snap) = &app.snapshot else {
        let label = if app.problem().is_some() {
            "not rendered: the preview says why"
        } else if app.failure.is_some() {
            "failed"
        } else {
            "0/1 passes"
        };
        return (0.0, label.into());
    };
    if let Some(t) = &snap.target {
        let budget = snap.samples as f64 / t.spp.max(1) as f64;
        let clean = match (snap.relative_noise(), t.noise) {
            (Some(n), Some(level)) if n > 0.0 => (level / n).powi(2),
            _ => 0.0,
        };
        let ratio = if snap.done { 1.0 } else { budget.max(clean) };
        let state = match (app.paused && !snap.done, snap.finish) {
            (true, _) => "paused",
            (_, Some(Finish::Clean)) => "clean",
            (_, Some(Finish::Budget)) => "budget spent",
            (_, Some(Finish::Complete)) => "done",
            (_, None) => "rendering",
        };
        let noise = match (snap.relative_noise(), t.noise) {
            (Some(n), Some(level)) => format!(
                " · noise {:.1}% of the mean, target {:.1}%",
                100.0 * n,
                100.0 * level
            ),
            (Some(n), None) => format!(" · noise {:.1}% of the mean", 100.0 * n),
            _ => String::new(),
        };
        return (
            ratio.clamp(0.0, 1.0),
            format!("{}/{} spp{noise} · {state}", snap.samples, t.spp),
        );
    }
    let (done, planned) = snap.progress;
    let ratio = if planned == 0 {
        0.0
    } else {
        (done as f64 / planned as f64).clamp(0.0, 1.0)
    };
    (ratio, format!("{done}/{planned} passes"))
}

pub(super) fn draw_gauge(app: &App, frame: &mut Frame, area: Rect) {
    let (ratio, label) = gauge_state(app);
    let gauge = Gauge::default()
        .ratio(ratio)
        .label(label)
        .gauge_style(if app.color {
            Style::default().fg(Color::Green)
        } else {
            Style::default()
        });
    frame.render_widget(gauge, area);
}
