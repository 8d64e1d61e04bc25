//! "Noise or wrong?" on screen, with the real chapter 6: the z view is in
//! the compare cycle where the render and its stored reference both know
//! their noise, and its verdict reads "within noise" for a correct render
//! and names the bias of a wrong one.

use ratatui::backend::TestBackend;
use ratatui::Terminal;

use raystep::tui::app::{App, Compare, Msg};
use raystep::tui::update::update;
use raystep::tui::view::{control_lines, view};
use raystep::tui::worker::Progress;

use super::inspect::{app_on, render_state, rendered};

/// Chapter 6 on the built-in Cornell box at `size`², estimator `variant`,
/// rendered to `spp` samples per pixel by the real stage.
fn rendered_with(size: u32, variant: &str, spp: u32) -> App {
    let scene = raystep::scene::Scene::builtin()
        .with_resolution(size, size)
        .unwrap();
    let ch6 = raystep::chapters::all()[5];
    let mut app = app_on(ch6, scene);
    while ch6.info().variants[app.variant].name != variant {
        app = update(app, Msg::NextVariant);
    }
    let state = render_state(&app, spp);
    update(app, Msg::Progress(Progress::State(Box::new(state))))
}

fn to_z(app: App) -> App {
    let app = (0..4).fold(app, |a, _| update(a, Msg::CycleCompare));
    assert_eq!(app.compare, Compare::Z);
    app
}

fn controls(app: &App) -> Vec<String> {
    control_lines(app).iter().map(|l| l.to_string()).collect()
}

#[test]
fn a_correct_render_is_within_noise() {
    let app = rendered();
    assert!(
        app.z_available(),
        "chapter 6's Cornell box knows its noise and the reference's"
    );
    let app = to_z(app);
    let v = app.verdict().expect("a verdict");
    assert!(v.within_noise(), "{v:?}");
    let lines = controls(&app);
    assert!(
        lines.contains(&"verdict: within noise".to_string()),
        "{lines:?}"
    );
    assert!(lines.iter().any(|l| l.contains("−5σ blue")), "{lines:?}");
    // The view holds z, and the whole UI draws it.
    // At 2 samples per pixel a pixel's own standard error is a rough
    // guess, so single pixels stray; few stray past the limit.
    let z = app.displayed().unwrap();
    let far = z
        .pixels
        .iter()
        .filter(|p| p.abs().max_element() > 5.0)
        .count();
    assert!(
        far * 20 < z.pixels.len(),
        "{far} of {} pixels past |z| 5",
        z.pixels.len()
    );
    let mut t = Terminal::new(TestBackend::new(100, 30)).unwrap();
    t.draw(|f| view(&app, f)).unwrap();
    // The cycle goes on to the render.
    assert_eq!(update(app, Msg::CycleCompare).compare, Compare::Render);
}

#[test]
fn a_render_thirty_percent_too_bright_is_called_biased() {
    let app = rendered();
    let mut state = app.snapshot.clone().unwrap();
    // At 2 samples per pixel a block's standard error is about 10% of its
    // mean: a bias of 30% is z ≈ 10 in the worst block.
    state.views[0].pixels.iter_mut().for_each(|p| *p *= 1.3);
    let app = to_z(update(app, Msg::Progress(Progress::State(Box::new(state)))));
    let v = app.verdict().unwrap();
    assert!(!v.within_noise(), "{v:?}");
    let lines = controls(&app);
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("verdict: biased, ") && l.ends_with("% brighter")),
        "{lines:?}"
    );
}

#[test]
fn without_the_references_noise_there_is_no_z_view() {
    let app = rendered();
    let mut state = app.snapshot.clone().unwrap();
    state.reference_stderr = None;
    let app = update(app, Msg::Progress(Progress::State(Box::new(state))));
    assert!(!app.z_available());
    let app = (0..4).fold(app, |a, _| update(a, Msg::CycleCompare));
    assert_eq!(
        app.compare,
        Compare::Render,
        "relative goes back to the render"
    );
    assert!(app.verdict().is_none());
}

#[test]
fn the_noise_view_is_auto_exposed_and_a_key_steps_from_there() {
    // Chapter 6's second view, the standard error, is dark: automatic
    // exposure brings its mean to 0.18.
    let app = update(rendered(), Msg::NextView);
    assert_eq!(app.view_name(), "stderr");
    assert!(app.auto_exposure_on());
    let stops = app.display_exposure();
    let mean = {
        let f = app.displayed().unwrap();
        f.pixels
            .iter()
            .map(|p| f64::from(p.element_sum()) / 3.0)
            .sum::<f64>()
            / f.pixels.len() as f64
    };
    assert_eq!(stops, ((0.18 / mean).log2().round() as i32).clamp(-10, 10));
    assert!(stops >= 2, "the noise view is dark: {stops} stops");
    let lines = controls(&app);
    assert!(
        lines.contains(&format!("exposure {stops:+} stops (auto)")),
        "{lines:?}"
    );
    // Its scale: at +k stops a standard error of 2^-k shows white.
    let white = raystep::tui::view::short_number(2f64.powi(-stops));
    assert!(
        lines.contains(&format!("white: std error {white}")),
        "{lines:?}"
    );
    // `+` steps from the automatic exposure and turns it off; `a` turns it
    // back on.
    let up = update(app, Msg::ExposureUp);
    assert!(!up.auto_exposure_on());
    assert_eq!(up.display_exposure(), stops + 1);
    let auto = update(up, Msg::ToggleAutoExposure);
    assert!(auto.auto_exposure_on() && auto.display_exposure() == stops);
    // A choice made with `a` holds for every picture; the main image is
    // not auto-exposed unless asked.
    let main = update(auto, Msg::PrevView);
    assert_eq!(main.view, 0);
    assert!(main.auto_exposure_on(), "the choice made with a holds");
    assert!(!rendered().auto_exposure_on());
    let plain = update(rendered(), Msg::ToggleAutoExposure);
    assert!(plain.auto_exposure_on(), "a turns it on for any picture");
    let off = update(rendered(), Msg::ExposureReset);
    assert!(!off.auto_exposure_on() && off.display_exposure() == 0);
}

#[test]
fn uniform_sampling_at_twice_the_references_size_is_not_called_biased() {
    // Uniform sampling finds the lamp rarely, so a block's light rests on
    // a few samples. Compared pixel by pixel with the 64² reference
    // enlarged to 128², this render was called "biased, 46% darker,
    // |z| 23.0" at 128 spp; at the reference's own resolution, and with
    // the effective samples counted, it is noise.
    let app = to_z(rendered_with(128, "uniform-independent", 128));
    let v = app.verdict().expect("a verdict");
    let [first, _] = v.lines();
    assert!(!first.starts_with("verdict: biased"), "{v:?}");
    // The same render made 30% brighter is a bias, and is called one.
    let mut state = app.snapshot.clone().unwrap();
    state.views[0].pixels.iter_mut().for_each(|p| *p *= 1.3);
    let app = update(app, Msg::Progress(Progress::State(Box::new(state))));
    let v = app.verdict().unwrap();
    assert!(v.lines()[0].starts_with("verdict: biased, "), "{v:?}");
}
