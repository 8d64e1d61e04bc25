//! The difference views average signed values first and colour them
//! after, through the real drawing path: converged noise shows black, not
//! an even purple wash; a NaN shows in a colour no finite difference
//! takes; the readout and the saved EXR carry the signed numbers.

use crate::common;
use crate::tui::layout_and_keys::{scenes, FAKE};
use glam::Vec3;
use ratatui::backend::TestBackend;
use ratatui::style::Color;
use ratatui::Terminal;

use raystep::core::film::Film;
use raystep::grading::FailureImages;
use raystep::tui::app::{App, Compare, Msg};
use raystep::tui::update::{save, update};
use raystep::tui::view::view;

/// The grader's pair: a reference of 0.5 grey, and a student image that is
/// the reference plus noise of ±`noise` in a checkerboard (zero on
/// average over any two neighbours), with pixel (0, 0) set to `first`.
fn noisy_pair(noise: f32, first: Option<Vec3>) -> FailureImages {
    let (w, h) = (64, 32);
    let mut reference = Film::new(w, h);
    reference
        .pixels
        .iter_mut()
        .for_each(|p| *p = Vec3::splat(0.5));
    let mut student = reference.clone();
    for y in 0..h {
        for x in 0..w {
            let s = if (x + y) % 2 == 0 { noise } else { -noise };
            *student.get_mut(x, y) += Vec3::splat(s);
        }
    }
    if let Some(v) = first {
        *student.get_mut(0, 0) = v;
    }
    FailureImages {
        stem: "ch5-noise".into(),
        student,
        reference,
    }
}

fn with_pair(pair: FailureImages) -> App {
    let mut app = App::new(vec![&FAKE], scenes(), true);
    app.grading = Some(pair);
    app = update(app, Msg::CycleCompare); // reference
    update(app, Msg::CycleCompare) // difference
}

/// The colours of the half-block preview cells, drawn at 40x16 (the
/// 64x32 film shrinks into fewer cells, so each cell averages pixels).
fn preview_cells(app: &App) -> Vec<(Color, Color)> {
    let mut terminal = Terminal::new(TestBackend::new(60, 20)).unwrap();
    terminal.draw(|f| view(app, f)).unwrap();
    terminal
        .backend()
        .buffer()
        .content()
        .iter()
        .filter(|c| c.symbol() == "▀")
        .map(|c| (c.fg, c.bg))
        .collect()
}

#[test]
fn converged_noise_averages_to_black_not_purple() {
    // ±0.2 on a scale of 0.25: each pixel alone is strongly red or blue.
    let app = with_pair(noisy_pair(0.2, None));
    assert_eq!(app.compare, Compare::Difference);
    let cells = preview_cells(&app);
    assert!(cells.len() > 50, "only {} preview cells", cells.len());
    let channel = |c: Color| match c {
        Color::Rgb(r, g, b) => [r, g, b],
        other => panic!("{other:?}"),
    };
    for (fg, bg) in &cells {
        for c in [fg, bg] {
            let [r, _, b] = channel(*c);
            // Colouring first, then averaging, gave (188, 0, 188) here
            // (half red, half blue, in sRGB). Averaged first, a cell is
            // black, or faintly red or blue where it holds one more pixel
            // of one sign than of the other: never both.
            assert!(
                r < 100 && b < 100 && r.min(b) == 0,
                "a cell of averaged noise is {c:?}"
            );
        }
    }
    // Each pixel on its own is still the signed number, strongly red.
    let film = app.displayed().unwrap();
    assert!((film.pixels[0] - Vec3::splat(0.2)).abs().max_element() < 1e-6);
    let red = app.paint(&film).pixels[0];
    assert!(red.x > 0.79 && red.y == 0.0 && red.z == 0.0, "{red}");
}

#[test]
fn a_nan_shows_green_in_any_cell_that_holds_it() {
    let app = with_pair(noisy_pair(0.0, Some(Vec3::new(f32::NAN, 0.5, 0.5))));
    let cells = preview_cells(&app);
    let green = cells
        .iter()
        .flat_map(|(fg, bg)| [*fg, *bg])
        .filter(|c| *c == Color::Rgb(0, 255, 0))
        .count();
    assert_eq!(green, 1, "the one cell holding the NaN is green, no other");
    // No finite difference is ever green.
    let mut film = Film::new(3, 1);
    film.pixels = vec![
        Vec3::splat(1e30),
        Vec3::splat(-1e30),
        Vec3::new(0.1, -0.2, 0.0),
    ];
    for p in film.colour_signed(0.25).pixels {
        assert_eq!(p.y, 0.0, "{p}");
    }
}

#[test]
fn the_readout_and_the_saved_exr_hold_the_signed_difference() {
    let dir = common::temp_dir("tui-signed-save");
    let mut app = with_pair(noisy_pair(0.1, Some(Vec3::new(f32::INFINITY, 0.5, 0.5))));
    app.out_dir = dir.clone();
    app.hover = Some((1, 0));
    let text = raystep::tui::labels::hover_text(&app).unwrap();
    assert!(
        text.contains("render − reference") && text.contains("-0.1"),
        "{text}"
    );
    let files = save(&app).unwrap();
    let exr = Film::read_exr(&files[1]).unwrap();
    let near = |a: Vec3, b: Vec3| (a - b).abs().max_element() < 1e-6;
    assert!(
        near(exr.pixels[1], Vec3::splat(-0.1)),
        "the EXR holds the negative difference: {}",
        exr.pixels[1]
    );
    assert!(near(exr.pixels[2], Vec3::splat(0.1)), "{}", exr.pixels[2]);
    assert!(
        exr.pixels.iter().all(|p| p.is_finite()),
        "no Inf reaches the EXR"
    );
    let png = Film::read_png(&files[0]).unwrap();
    assert_eq!(
        png.pixels[0],
        Vec3::new(0.0, 1.0, 0.0),
        "the PNG shows the Inf in green"
    );
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_sixel_picture_of_a_difference_is_averaged_before_it_is_coloured() {
    // 512x256 pixels shrink into a 60x20 screen's preview, a few hundred
    // pixels wide: each picture pixel averages several film pixels.
    let mut pair = noisy_pair(0.2, None);
    let (w, h) = (512, 256);
    pair.reference = Film::new(w, h);
    pair.reference
        .pixels
        .iter_mut()
        .for_each(|p| *p = Vec3::splat(0.5));
    pair.student = pair.reference.clone();
    for y in 0..h {
        for x in 0..w {
            let s = if (x + y) % 2 == 0 { 0.2 } else { -0.2 };
            *pair.student.get_mut(x, y) += Vec3::splat(s);
        }
    }
    let mut app = with_pair(pair);
    app.color = true;
    app.graphics = raystep::tui::graphics::Graphics::Sixel;
    app.font = Some((8, 16));
    let app = update(app, Msg::Resize(60, 20));
    let r = raystep::tui::shown::request(&app, ratatui::layout::Rect::new(0, 0, 60, 20))
        .expect("a picture to send");
    assert!(
        r.image.width() < w,
        "the picture shrinks: {}",
        r.image.width()
    );
    let purple = r
        .image
        .pixels()
        .filter(|p| p.0[0] > 60 && p.0[2] > 60)
        .count();
    assert_eq!(purple, 0, "no picture pixel is a mix of red and blue");
}

#[test]
fn a_difference_shows_tevs_five_metrics_as_means() {
    // render − reference = (0, 0, −0.125) at every pixel of the fake, with
    // the reference (0.5, 0.25, 0.25).
    let app = crate::tui::layout_and_keys::rendered(crate::tui::layout_and_keys::app());
    let app = update(update(app, Msg::CycleCompare), Msg::CycleCompare);
    assert_eq!(app.compare, Compare::Difference);
    let m = raystep::core::difference::metrics(
        &app.compared_pair().unwrap().0,
        app.compared_pair().unwrap().1,
    );
    let near = |a: f64, b: f64| (a - b).abs() < 1e-6;
    assert!(near(m.error, -0.125 / 3.0), "{m:?}");
    assert!(near(m.absolute, 0.125 / 3.0));
    assert!(near(m.squared, 0.125 * 0.125 / 3.0));
    assert!(near(m.relative_absolute, 0.125 / 0.26 / 3.0));
    assert!(near(
        m.relative_squared,
        0.125 * 0.125 / (0.0625 + 0.01) / 3.0
    ));
    let lines: Vec<String> = raystep::tui::view::control_lines(&app)
        .iter()
        .map(|l| l.to_string())
        .collect();
    let n = raystep::tui::view::short_number;
    for want in [
        format!("mean error {}", n(m.error)),
        format!("abs {} · sq {}", n(m.absolute), n(m.squared)),
        format!(
            "rel abs {} · rel sq {}",
            n(m.relative_absolute),
            n(m.relative_squared)
        ),
    ] {
        assert!(lines.contains(&want), "{want}: {lines:?}");
    }
    // A NaN is left out of the means, not spread through them.
    let mut bad = app.compared_pair().unwrap().0.into_owned();
    bad.pixels[0] = Vec3::splat(f32::NAN);
    let m2 = raystep::core::difference::metrics(&bad, app.compared_pair().unwrap().1);
    assert!(m2.squared.is_finite() && near(m2.squared, m.squared));
}
