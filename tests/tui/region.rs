//! Region statistics on the real chapter 6: a box chosen with `b` at two
//! cursor spots or with a mouse drag; the inspect panel gives its mean
//! with the standard error of that mean, the reference's mean, the
//! relative MSE, the z of the difference and a histogram; the box is
//! outlined on the picture.

use ratatui::backend::TestBackend;
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::Terminal;

use raystep::tui::app::{App, Msg};
use raystep::tui::inspect::inspect_lines;
use raystep::tui::update::update;
use raystep::tui::view::view;

use super::inspect::rendered;

fn boxed() -> App {
    let app = update(rendered(), Msg::ToggleInspect);
    assert_eq!(app.inspect, Some((32, 32)));
    let app = update(app, Msg::MarkRegion);
    assert_eq!((app.region_anchor, app.region), (Some((32, 32)), None));
    assert!(inspect_lines(&app)
        .iter()
        .any(|l| l.contains("corner at (32, 32)")));
    let app = update(app, Msg::CursorMove(-7, 7));
    update(app, Msg::MarkRegion)
}

#[test]
fn b_at_two_corners_gives_the_regions_statistics() {
    let app = boxed();
    assert_eq!(app.region, Some((25, 32, 32, 39)));
    let lines = inspect_lines(&app);
    assert!(
        lines.contains(&"region 8x8 at (25, 32):".to_string()),
        "{lines:?}"
    );
    // The mean is the region's mean over pixels and channels.
    let film = app.main_film().unwrap();
    let mut sum = 0.0f64;
    for y in 32..=39 {
        for x in 25..=32 {
            sum += f64::from(film.get(x, y).element_sum()) / 3.0;
        }
    }
    let mean = raystep::tui::view::short_number(sum / 64.0);
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with(&format!("mean {mean} ± "))),
        "{mean}: {lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("ref ") && l.contains(" · rel MSE ")),
        "{lines:?}"
    );
    let z_line = lines
        .iter()
        .find(|l| l.starts_with("z "))
        .expect("a z line");
    assert!(z_line.ends_with(": within noise"), "{z_line}");
    let z: f64 = z_line
        .strip_prefix("z ")
        .and_then(|l| l.split(':').next())
        .expect("a z line")
        .parse()
        .unwrap();
    assert!(
        z.abs() < 5.0,
        "a correct render's region is within noise: z {z}"
    );
    assert!(
        lines.iter().any(|l| l.starts_with("histogram ")),
        "{lines:?}"
    );
    // b again clears it.
    let cleared = update(app, Msg::MarkRegion);
    assert_eq!((cleared.region, cleared.region_anchor), (None, None));
}

#[test]
fn the_box_is_outlined_in_half_blocks_and_in_a_sixel_picture() {
    let mut app = boxed();
    app.color = true;
    let mut t = Terminal::new(TestBackend::new(100, 30)).unwrap();
    t.draw(|f| view(&app, f)).unwrap();
    let yellow_borders = t
        .backend()
        .buffer()
        .content()
        .iter()
        .filter(|c| c.fg == Color::Yellow && "┌┐└┘─│".contains(c.symbol()))
        .count();
    assert!(yellow_borders >= 4, "{yellow_borders} outline cells");
    let mut g = app;
    g.graphics = raystep::tui::graphics::Graphics::Sixel;
    g.font = Some((8, 16));
    let r = raystep::tui::shown::request(&g, Rect::new(0, 0, 100, 30)).unwrap();
    let yellow = r.image.pixels().filter(|p| p.0 == [255, 255, 0]).count();
    // The cursor's cross is yellow too: the outline adds a box's worth.
    assert!(yellow > 40, "{yellow} yellow pixels");
}

#[test]
fn a_drag_spans_a_box_and_a_click_clears_it() {
    let app = rendered();
    let (w, h) = (100u16, 30u16);
    let screen = Rect::new(0, 0, w, h);
    // Two cells inside the picture.
    let cells: Vec<(u16, u16)> = (0..w)
        .flat_map(|c| (0..h).map(move |r| (c, r)))
        .filter(|&(c, r)| raystep::tui::screen::pixel_at(&app, screen, c, r).is_some())
        .collect();
    let (a, b) = (cells[0], cells[cells.len() - 1]);
    let pa = raystep::tui::screen::pixel_at(&app, screen, a.0, a.1).unwrap();
    let pb = raystep::tui::screen::pixel_at(&app, screen, b.0, b.1).unwrap();
    let click = |app, (column, row): (u16, u16)| {
        update(
            app,
            Msg::Click {
                column,
                row,
                width: w,
                height: h,
            },
        )
    };
    let app = click(app, a);
    assert_eq!(app.inspect, Some(pa));
    // The click opened the pixel panel, which moved the picture: the drag
    // still ends on the pixel that was under `b` when the button went
    // down, not the one there now.
    let moved = raystep::tui::screen::pixel_at(&app, screen, b.0, b.1);
    assert_ne!(moved, Some(pb), "the panel moved the picture");
    let app = update(
        app,
        Msg::Drag {
            column: b.0,
            row: b.1,
            width: w,
            height: h,
        },
    );
    assert_eq!(
        app.region,
        Some((
            pa.0.min(pb.0),
            pa.1.min(pb.1),
            pa.0.max(pb.0),
            pa.1.max(pb.1)
        ))
    );
    let app = click(app, b);
    assert_eq!(app.region, None);
    // `b` with no cursor says how.
    let plain = update(rendered(), Msg::MarkRegion);
    assert!(plain.message.contains("b marks"), "{}", plain.message);
}

#[test]
fn a_region_of_a_render_too_bright_reads_biased() {
    let app = rendered();
    let mut state = app.snapshot.clone().unwrap();
    // The wall at the left, a large box: 30% too bright is many standard
    // errors of its mean.
    state.views[0].pixels.iter_mut().for_each(|p| *p *= 1.3);
    let app = update(
        app,
        Msg::Progress(raystep::tui::worker::Progress::State(Box::new(state))),
    );
    let mut app = update(app, Msg::ToggleInspect);
    app.region = Some((4, 8, 20, 56));
    let lines = inspect_lines(&app);
    let z_line = lines
        .iter()
        .find(|l| l.starts_with("z "))
        .expect("a z line");
    assert!(z_line.ends_with(": biased"), "{lines:?}");
}
