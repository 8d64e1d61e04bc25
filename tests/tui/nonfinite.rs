//! "Where are the NaNs?": chapter 6's non-finite view, with the real
//! renderer on a Cornell box whose lamp is made infinite in code (a scene
//! file cannot ask for that). The view marks in green the pixels whose
//! samples were caught as NaN or infinite, on a dim copy of the image;
//! its legend counts them, the mouse and the pixel panel give a pixel's
//! count, and a finite render says that nothing was caught.

use glam::Vec3;
use ratatui::backend::TestBackend;
use ratatui::Terminal;

use raystep::ch6_global_illumination::accumulate::downsample;
use raystep::core::difference::NONFINITE;
use raystep::core::film::Film;
use raystep::scene::Scene;
use raystep::tui::app::{App, Msg};
use raystep::tui::inspect::inspect_lines;
use raystep::tui::labels::hover_text;
use raystep::tui::update::{save, update};
use raystep::tui::view::{control_lines, view};
use raystep::tui::worker::Progress;

use super::inspect::{app_on, render_state};

/// Chapter 6 after 2 spp of the 32x32 Cornell box with its lamp at `le`,
/// showing the non-finite view.
fn non_finite_view(le: f32) -> App {
    let mut scene = Scene::builtin().with_resolution(32, 32).unwrap();
    for m in &mut scene.materials {
        if m.emission.max_element() > 0.0 {
            m.emission = Vec3::splat(le);
        }
    }
    let app = app_on(raystep::chapters::all()[5], scene);
    let state = render_state(&app, 2);
    let mut app = update(app, Msg::Progress(Progress::State(Box::new(state))));
    while app.view_name() != "non-finite" {
        app = update(app, Msg::NextView);
        assert!(app.view != 0, "chapter 6 has a non-finite view");
    }
    app
}

fn counts(app: &App) -> Vec<f32> {
    let snap = app.snapshot.as_ref().unwrap();
    snap.views[app.view].pixels.iter().map(|p| p.x).collect()
}

#[test]
fn the_pixels_that_caught_a_sample_are_green_and_counted() {
    let app = non_finite_view(f32::INFINITY);
    assert!(app.shows_caught());
    let counts = counts(&app);
    let total: f32 = counts.iter().sum();
    let marked = counts.iter().filter(|&&c| c > 0.0).count();
    assert!(marked > 0 && marked < counts.len(), "{marked} marked");
    let lines: Vec<String> = control_lines(&app).iter().map(|l| l.to_string()).collect();
    for legend in [
        format!("non-finite: {total} caught"),
        format!("in {marked} px: green"),
    ] {
        assert!(lines.contains(&legend), "{lines:?} lacks {legend}");
    }
    // Full size: green exactly where a pixel caught one, grey elsewhere.
    let painted = app.paint(&app.displayed().unwrap());
    for (c, p) in counts.iter().zip(&painted.pixels) {
        if *c > 0.0 {
            assert_eq!(*p, NONFINITE);
        } else {
            assert!(p.x == p.y && p.y == p.z && p.x <= 1.0 / 3.0, "{p}");
        }
    }
    // Averaged to half size, as a small terminal shows it: a cell is
    // green when any of its four pixels caught one.
    let half = app.paint_pooled(&downsample(&app.displayed().unwrap(), 2), 4.0);
    for y in 0..16 {
        for x in 0..16 {
            let any = (0..4).any(|k| counts[((2 * y + k / 2) * 32 + 2 * x + k % 2) as usize] > 0.0);
            assert_eq!(half.get(x, y) == NONFINITE, any, "cell ({x}, {y})");
        }
    }
    // The mouse and the pixel panel give a pixel's count.
    let i = counts.iter().position(|&c| c > 0.0).unwrap() as u32;
    let (x, y) = (i % 32, i / 32);
    let n = counts[i as usize];
    let app = App {
        hover: Some((x, y)),
        inspect: Some((x, y)),
        ..app
    };
    let hover = hover_text(&app).unwrap();
    assert!(
        hover.contains(&format!("{n} samples NaN or infinite")),
        "{hover}"
    );
    let panel = inspect_lines(&app);
    assert!(
        panel.contains(&format!("non-finite: {n} caught (left out)")),
        "{panel:?}"
    );
    let mut t = Terminal::new(TestBackend::new(100, 30)).unwrap();
    t.draw(|f| view(&app, f)).unwrap();
    // `s` saves the counts themselves as EXR, the marks as PNG.
    let dir = std::env::temp_dir().join(format!("raystep-nonfinite-{}", std::process::id()));
    let app = App {
        out_dir: dir.clone(),
        ..app
    };
    let files = save(&app).unwrap();
    let exr = files
        .iter()
        .find(|f| f.extension().is_some_and(|e| e == "exr"));
    let saved = Film::read_exr(exr.unwrap()).unwrap();
    let saved: Vec<f32> = saved.pixels.iter().map(|p| p.x).collect();
    assert_eq!(saved, counts);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_finite_render_says_nothing_was_caught() {
    let app = non_finite_view(10.0);
    assert!(counts(&app).iter().all(|&c| c == 0.0));
    let lines: Vec<String> = control_lines(&app).iter().map(|l| l.to_string()).collect();
    assert!(
        lines.contains(&"non-finite: none caught".to_string()),
        "{lines:?}"
    );
    let painted = app.paint(&app.displayed().unwrap());
    assert!(painted.pixels.iter().all(|p| *p != NONFINITE));
}
