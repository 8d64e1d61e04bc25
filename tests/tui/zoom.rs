//! Zoom and pan: the window the preview shows, the cursor and clicks in
//! it, the keys, and the cursor drawn into a graphics protocol's pixels.

use ratatui::backend::TestBackend;
use ratatui::Terminal;
use raystep::core::film::Film;
use raystep::tui::app::{App, Msg};
use raystep::tui::screen::pixel_at;
use raystep::tui::update::update;
use raystep::tui::view::view;
use raystep::tui::zoom::{graphics_pixels, zoomed, Window, MAX_ZOOM};

use super::inspect::rendered;

fn draw(app: &App, w: u16, h: u16) -> ratatui::buffer::Buffer {
    let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
    terminal.draw(|f| view(app, f)).unwrap();
    terminal.backend().buffer().clone()
}

#[test]
fn the_window_follows_the_cursor_and_stays_inside_the_image() {
    let mut app = rendered();
    let (w, h) = (64, 64);
    assert!(
        Window::of(&app, w, h).is_whole(w, h),
        "zoom 1: the whole image"
    );
    app.zoom = 4;
    let centre = Window::of(&app, w, h);
    assert_eq!(
        (centre.x0, centre.y0, centre.width, centre.height),
        (24, 24, 16, 16)
    );
    app.inspect = Some((2, 60));
    let corner = Window::of(&app, w, h);
    assert_eq!((corner.x0, corner.y0), (0, 48), "clamped to the image");
    assert_eq!(corner.to_window((2, 60)), Some((2, 12)));
    assert_eq!(corner.to_window((20, 60)), None);
    assert_eq!(corner.to_image((2, 12)), (2, 60));
    let zooms: Vec<u32> = std::iter::successors(Some(1), |z| Some(zoomed(*z, 1)))
        .take(8)
        .collect();
    assert_eq!(zooms, [1, 2, 4, 8, 16, 32, 32, 32]);
    assert_eq!(zoomed(MAX_ZOOM, -1), 16);
    assert_eq!(zoomed(1, -1), 1);
}

#[test]
fn z_zooms_in_around_the_cursor_and_a_click_lands_on_the_pixel_shown() {
    let app = update(rendered(), Msg::ToggleInspect);
    let app = update(update(app, Msg::Zoom(1)), Msg::Zoom(1));
    assert_eq!(app.zoom, 4);
    for (w, h) in [(80u16, 24u16), (100, 30), (160, 48)] {
        let buffer = draw(&app, w, h);
        let text: String = (0..h)
            .map(|y| (0..w).map(|x| buffer[(x, y)].symbol()).collect::<String>() + "\n")
            .collect();
        assert!(text.contains("zoom 4x"), "{w}x{h}:\n{text}");
        // The cursor is drawn, and clicking its cell gives its pixel back.
        let (cx, cy) = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .find(|&(x, y)| {
                let cell = &buffer[(x, y)];
                cell.symbol() == "+" && cell.bg == ratatui::style::Color::Yellow
            })
            .expect("the cursor is drawn");
        let screen = ratatui::layout::Rect::new(0, 0, w, h);
        assert_eq!(pixel_at(&app, screen, cx, cy), app.inspect, "{w}x{h}");
    }
    // Moving the cursor pans: the window stays around it.
    let moved = update(app, Msg::CursorMove(20, 0));
    let window = Window::of(&moved, 64, 64);
    assert!(window.to_window(moved.inspect.unwrap()).is_some());
    assert_eq!(update(moved, Msg::Zoom(-1)).zoom, 2);
}

#[test]
fn a_graphics_protocol_gets_the_cursor_in_its_pixels() {
    let mut film = Film::new(32, 32);
    film.pixels
        .iter_mut()
        .for_each(|p| *p = glam::Vec3::splat(0.5));
    let plain = graphics_pixels(&film, None);
    let marked = graphics_pixels(&film, Some((10, 20)));
    let at = |b: &[u8], x: usize, y: usize| b[3 * (y * 32 + x)..3 * (y * 32 + x) + 3].to_vec();
    assert_eq!(
        at(&marked, 10, 20),
        at(&plain, 10, 20),
        "the pixel itself stays visible"
    );
    assert_eq!(at(&marked, 12, 20), vec![255, 255, 0]);
    assert_eq!(at(&marked, 10, 18), vec![255, 255, 0]);
    assert_eq!(at(&marked, 14, 24), at(&plain, 14, 24), "only the cross");
    // At the edge the cross is cut, not wrapped.
    let edge = graphics_pixels(&film, Some((0, 0)));
    assert_eq!(at(&edge, 31, 0), at(&plain, 31, 0));
}

#[test]
fn the_mouse_reads_the_pixel_under_it_and_its_wheel_zooms_the_picture() {
    let app = rendered();
    let screen = app.screen;
    let buffer = draw(&app, screen.width, screen.height);
    let preview = raystep::tui::screen::areas(&app, screen).preview;
    let (cx, cy) = (
        preview.x + preview.width / 2,
        preview.y + preview.height / 2,
    );
    let app = update(
        app,
        Msg::Hover {
            column: cx,
            row: cy,
        },
    );
    let p = app.hover.expect("the middle of the picture is a pixel");
    assert_eq!(pixel_at(&app, screen, cx, cy), Some(p));
    let line = raystep::tui::view::key_hints(&app);
    let v = app.displayed_ref().unwrap().get(p.0, p.1);
    assert!(
        line.starts_with(&format!("pixel ({}, {}): ", p.0, p.1)),
        "{line}"
    );
    assert!(line.contains(&raystep::core::format::rgb(v)), "{line}");
    drop(buffer);
    // Off the picture: no readout, the keys again.
    let app = update(app, Msg::Hover { column: 0, row: 0 });
    assert_eq!(app.hover, None);
    assert!(!raystep::tui::view::key_hints(&app).starts_with("pixel"));
    // The wheel over the picture zooms, up in, down out.
    let app = update(
        app,
        Msg::Wheel {
            column: cx,
            row: cy,
            lines: -3,
        },
    );
    assert_eq!(app.zoom, 2);
    let app = update(
        app,
        Msg::Wheel {
            column: cx,
            row: cy,
            lines: 3,
        },
    );
    assert_eq!(app.zoom, 1);
}

#[test]
fn mouse_events_map_to_click_wheel_and_hover() {
    use crossterm::event::{KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
    use raystep::tui::keys::msg_for_mouse;
    let at = |kind| MouseEvent {
        kind,
        column: 7,
        row: 3,
        modifiers: KeyModifiers::NONE,
    };
    let m = |kind| msg_for_mouse(at(kind), (80, 24)).map(|m| format!("{m:?}"));
    assert_eq!(
        m(MouseEventKind::Down(MouseButton::Left)).as_deref(),
        Some("Click { column: 7, row: 3, width: 80, height: 24 }")
    );
    assert_eq!(
        m(MouseEventKind::ScrollUp).as_deref(),
        Some("Wheel { column: 7, row: 3, lines: -3 }")
    );
    assert_eq!(
        m(MouseEventKind::Moved).as_deref(),
        Some("Hover { column: 7, row: 3 }")
    );
    assert_eq!(m(MouseEventKind::Down(MouseButton::Right)), None);
}
