//! "How much faster is MIS than BSDF sampling here?": stepping through
//! chapter 6's estimators keeps each one's error-against-time curve on the
//! chart, in its own colour and named in the legend, with each one's
//! efficiency 1/(MSE·t) in the controls box. The real chapter 6, two
//! estimators.

use std::time::Duration;

use ratatui::backend::TestBackend;
use ratatui::Terminal;

use raystep::core::stage::Settings;
use raystep::tui::app::{App, Msg};
use raystep::tui::update::update;
use raystep::tui::view::{control_lines, view};
use raystep::tui::worker::{Progress, RenderState};

use super::inspect::rendered;

/// The current job rendered to completion with the real chapter 6 (8 spp
/// at 64x64), fed to the UI.
pub(crate) fn render_current(app: App) -> App {
    let job = app.job().unwrap();
    let settings = Settings {
        spp: 8,
        variant: Some(job.variant),
        ..Settings::default()
    };
    let ch6 = app.current_chapter().unwrap();
    let mut render = ch6.start(job.scene, &settings).unwrap();
    while !render.pass().complete {}
    let state = RenderState::capture(&*render, job.generation, Duration::ZERO, true);
    update(app, Msg::Progress(Progress::State(Box::new(state))))
}

#[test]
fn each_estimators_curve_is_kept_and_its_efficiency_shown() {
    let first = render_current(rendered());
    let name = |app: &App| {
        let info = app.current_chapter().unwrap().info();
        info.variants[app.variant].name.to_string()
    };
    let a = name(&first);
    assert_eq!(first.curves().len(), 1, "one estimator so far");
    // The next estimator: a new render, the first one's curve kept.
    let second = render_current(update(first, Msg::NextVariant));
    let b = name(&second);
    assert_ne!(a, b);
    let curves = second.curves();
    assert_eq!(curves.len(), 2, "{curves:?}");
    assert_eq!(
        (curves[0].name.as_str(), curves[0].current),
        (a.as_str(), false)
    );
    assert_eq!(
        (curves[1].name.as_str(), curves[1].current),
        (b.as_str(), true)
    );
    assert_ne!(curves[0].colour, curves[1].colour);
    for c in &curves {
        let &(t, e) = c.series.last().unwrap();
        assert_eq!(c.efficiency(), Some(1.0 / (e * e * t)));
    }
    let lines: Vec<String> = control_lines(&second)
        .iter()
        .map(|l| l.to_string())
        .collect();
    assert!(
        lines.contains(&"efficiency 1/(MSE·s):".to_string()),
        "{lines:?}"
    );
    for n in [&a, &b] {
        assert!(
            lines.iter().any(|l| l.starts_with(&format!("● {n} "))),
            "{n}: {lines:?}"
        );
    }
    assert_eq!(
        lines.iter().filter(|l| l.ends_with(" best")).count(),
        1,
        "{lines:?}"
    );
    // The controls' bullets are the chart's legend: each curve's colour.
    let mut second = second;
    second.color = true;
    let controls = control_lines(&second);
    for c in &curves {
        let line = controls
            .iter()
            .find(|l| l.to_string().starts_with(&format!("● {} ", c.name)))
            .unwrap();
        assert_eq!(line.spans[0].style.fg, Some(c.colour), "{}", c.name);
    }
    // The chart draws both curves, in their colours, and says what the
    // uncoloured guide is.
    let mut t = Terminal::new(TestBackend::new(140, 48)).unwrap();
    t.draw(|f| view(&second, f)).unwrap();
    let buffer = t.backend().buffer();
    let text: String = buffer.content().iter().map(|c| c.symbol()).collect();
    assert!(text.contains("error vs time; plain line −1/2"), "{text}");
    for c in &curves {
        assert!(
            buffer.content().iter().any(|cell| cell.fg == c.colour
                && cell
                    .symbol()
                    .chars()
                    .all(|ch| ('\u{2800}'..='\u{28ff}').contains(&ch))),
            "no braille cell in {}'s colour",
            c.name
        );
    }
}

#[test]
fn a_long_scene_list_leaves_the_chart_room_on_a_tall_terminal() {
    let mut app = render_current(rendered());
    for i in 0..20 {
        let mut entry = app.scenes[0].clone();
        entry.name = format!("scene-{i}");
        app.scenes.push(entry);
    }
    let mut t = Terminal::new(TestBackend::new(120, 40)).unwrap();
    t.draw(|f| view(&app, f)).unwrap();
    let text: String = t
        .backend()
        .buffer()
        .content()
        .iter()
        .map(|c| c.symbol())
        .collect();
    assert!(text.contains("error vs time"), "the chart is shown");
    assert!(text.contains("scene-0"), "and the scene list, scrolled");
}
