//! `|`: two estimators at equal wall-clock time, with the real chapter 6.
//! A render pinned after a second is split down the middle with the next
//! estimator's render as it was after the same second: the newest state
//! that had rendered no longer, not the latest.

use std::time::Duration;

use raystep::core::stage::Settings;
use raystep::tui::app::{App, Msg};
use raystep::tui::labels::preview_title_parts;
use raystep::tui::update::update;
use raystep::tui::view::control_lines;
use raystep::tui::worker::{Progress, RenderState};

use super::inspect::rendered;

/// The states of the job `app` asks for, one per pass, said to come
/// `step` apart.
fn states(app: &App, passes: u32, step: Duration) -> Vec<RenderState> {
    let ch6 = raystep::chapters::all()[5];
    let job = app.job().unwrap();
    let settings = Settings {
        spp: 64,
        variant: Some(job.variant),
        ..Settings::default()
    };
    let mut render = ch6.start(job.scene, &settings).unwrap();
    (1..=passes)
        .map(|k| {
            render.pass();
            RenderState::capture(&*render, job.generation, step * k, false)
        })
        .collect()
}

fn feed(app: App, state: &RenderState) -> App {
    update(app, Msg::Progress(Progress::State(Box::new(state.clone()))))
}

#[test]
fn the_split_shows_the_pinned_render_beside_the_next_at_equal_time() {
    let app = update(rendered(), Msg::ToggleSplit);
    assert!(
        app.message.starts_with("p pins a render first"),
        "{}",
        app.message
    );
    assert!(!app.shows_split());
    // Pin a render that ran for a second.
    let mut app = rendered();
    let first = states(&app, 2, Duration::from_millis(500));
    app = feed(app, &first[1]);
    let pinned_image = app.snapshot.as_ref().unwrap().views[0].clone();
    app = update(app, Msg::TogglePin);
    // The next estimator, said to pass at 0.5, 1.0 and 1.5 s.
    app = update(app, Msg::NextVariant);
    let next = states(&app, 3, Duration::from_millis(500));
    for s in &next {
        app = feed(app, s);
    }
    app = update(app, Msg::ToggleSplit);
    assert!(app.shows_split(), "{}", app.message);
    let shown = app.displayed().unwrap();
    let at_one_second = &next[1].views[0];
    assert_ne!(at_one_second.pixels, next[2].views[0].pixels);
    let w = shown.width;
    for (i, p) in shown.pixels.iter().enumerate() {
        let expected = match (i as u32 % w) < w / 2 {
            true => pinned_image.pixels[i],
            false => at_one_second.pixels[i],
        };
        assert_eq!(*p, expected, "pixel {i}");
    }
    let lines: Vec<String> = control_lines(&app).iter().map(|l| l.to_string()).collect();
    let ch6 = raystep::chapters::all()[5];
    let variant = ch6.info().variants[app.variant].name;
    let right = format!("right: {variant}, {} spp", next[1].samples);
    let at = lines.iter().position(|l| *l == right);
    let at = at.unwrap_or_else(|| panic!("{lines:?} lacks {right}"));
    assert!(lines[at + 1].starts_with("  1.0 s, RMSE "), "{lines:?}");
    let left = lines.iter().position(|l| l.starts_with("left: ")).unwrap();
    assert!(lines[left].contains(" spp"), "{lines:?}");
    assert!(lines[left + 1].starts_with("  1.0 s"), "{lines:?}");
    assert_eq!(preview_title_parts(&app)[0], "split at equal time");
    // `|` again, or unpinning, ends the split.
    let app = update(app, Msg::ToggleSplit);
    assert!(!app.shows_split());
    let app = update(app, Msg::ToggleSplit);
    assert!(app.shows_split());
    assert!(!update(app, Msg::TogglePin).shows_split());
}
