//! The picture through a graphics protocol: kitty transmits once per
//! change and reuses and deletes ids, sixel resends only what changed,
//! an unchanged redraw writes nothing, overlays hide the picture and it
//! comes back when they close; the picture fills and centres in its box
//! at 80x24, 100x30 and 160x48.

use std::time::{Duration, Instant};

use ratatui::backend::{CrosstermBackend, TestBackend};
use ratatui::layout::Rect;
use ratatui::{Terminal, TerminalOptions, Viewport};
use raystep::tui::app::{App, Msg};
use raystep::tui::graphics::Graphics;
use raystep::tui::painter::{base64, draw_frame, Painter};
use raystep::tui::placement::place;
use raystep::tui::shown::{request, Request};
use raystep::tui::stats::Counting;
use raystep::tui::update::update;

use super::inspect::rendered;

fn req(cells: Rect, shade: u8) -> Request {
    Request::new(
        cells,
        image::RgbImage::from_pixel(40, 30, image::Rgb([shade, 0, 0])),
    )
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn base64_matches_the_standard_alphabet() {
    assert_eq!(base64(b""), "");
    assert_eq!(base64(b"f"), "Zg==");
    assert_eq!(base64(b"fo"), "Zm8=");
    assert_eq!(base64(b"foobar"), "Zm9vYmFy");
    assert_eq!(base64(&[255, 254, 253]), "//79");
}

#[test]
fn kitty_transmits_once_places_by_id_and_deletes_what_is_replaced() {
    let mut p = Painter::new(Graphics::Kitty, 7);
    p.interval = Duration::ZERO;
    let t = Instant::now();
    let at = Rect::new(10, 2, 5, 2);
    let mut out = Vec::new();
    p.paint(&mut out, Some(&req(at, 10)), t).unwrap();
    let first = text(&out);
    assert!(first.starts_with("\x1b[3;11H"), "placed at its cells");
    assert!(
        first.contains("\x1b_Ga=T,f=100,i=7,p=1,C=1,q=2"),
        "{first:.80}"
    );
    assert!(!first.contains("a=d"), "nothing to delete yet");
    assert!(!first.contains("U=1"), "no Unicode placeholders");
    // The same pixels again: nothing at all.
    let mut again = Vec::new();
    for _ in 0..10 {
        p.paint(&mut again, Some(&req(at, 10)), t).unwrap();
    }
    assert_eq!(again.len(), 0, "an unchanged redraw writes no byte");
    // The same pixels elsewhere: placed again by id, not sent.
    let moved = Rect::new(12, 3, 5, 2);
    let mut out = Vec::new();
    p.paint(&mut out, Some(&req(moved, 10)), t).unwrap();
    assert_eq!(text(&out), "\x1b[4;13H\x1b_Ga=p,i=7,p=1,C=1,q=2\x1b\\");
    // New pixels: a new id, and the old image deleted with its data.
    let mut out = Vec::new();
    p.paint(&mut out, Some(&req(moved, 20)), t).unwrap();
    let new = text(&out);
    assert!(new.contains("a=T,f=100,i=8,"), "{new:.80}");
    assert!(new.ends_with("\x1b_Ga=d,d=I,i=7,q=2\x1b\\"), "{new:.80}");
    // Under an overlay: the placement goes, the image stays; back after.
    let mut out = Vec::new();
    p.paint(&mut out, None, t).unwrap();
    assert_eq!(text(&out), "\x1b_Ga=d,d=i,i=8,q=2\x1b\\");
    let mut out = Vec::new();
    p.paint(&mut out, None, t).unwrap();
    assert!(out.is_empty(), "hidden once");
    p.paint(&mut out, Some(&req(moved, 20)), t).unwrap();
    assert_eq!(text(&out), "\x1b[4;13H\x1b_Ga=p,i=8,p=1,C=1,q=2\x1b\\");
    assert!(!p.needs_clear(None), "kitty deletes, it never clears");
}

#[test]
fn a_big_kitty_picture_goes_in_chunks_of_4096() {
    let mut p = Painter::new(Graphics::Kitty, 1);
    // Noise does not compress: many chunks.
    let noise = image::RgbImage::from_fn(64, 64, |x, y| {
        let v = (x * 7919 + y * 104_729) ^ (x * y);
        image::Rgb([v as u8, (v >> 8) as u8, (v >> 3) as u8])
    });
    let mut out = Vec::new();
    let r = Request::new(Rect::new(0, 0, 8, 4), noise);
    p.paint(&mut out, Some(&r), Instant::now()).unwrap();
    let s = text(&out);
    let pieces: Vec<&str> = s.split("\x1b_G").skip(1).collect();
    assert!(pieces.len() > 2, "{}", pieces.len());
    assert!(pieces[0].contains("m=1;"));
    assert!(pieces.last().unwrap().starts_with("m=0;"));
    for piece in &pieces {
        let payload = piece.split(';').nth(1).unwrap().trim_end_matches("\x1b\\");
        assert!(payload.len() <= 4096);
    }
}

#[test]
fn sixel_resends_only_changes_and_clears_when_the_picture_moves() {
    let mut p = Painter::new(Graphics::Sixel, 1);
    let t = Instant::now();
    let at = Rect::new(4, 1, 5, 2);
    let mut out = Vec::new();
    p.paint(&mut out, Some(&req(at, 10)), t).unwrap();
    let s = text(&out);
    assert!(s.starts_with("\x1b[2;5H\x1bP"), "{:?}", &s[..12]);
    let mut again = Vec::new();
    p.paint(&mut again, Some(&req(at, 10)), t).unwrap();
    assert!(again.is_empty(), "an unchanged redraw writes no byte");
    assert!(!p.needs_clear(Some(&req(at, 99))), "same place: drawn over");
    assert!(p.needs_clear(Some(&req(Rect::new(5, 1, 5, 2), 10))));
    assert!(p.needs_clear(None), "a popup or a note: clear first");
    // While passes stream in, new pixels wait for the interval; the last
    // ones are sent when it has passed.
    let mut out = Vec::new();
    p.paint(&mut out, Some(&req(at, 11)), t + Duration::from_millis(50))
        .unwrap();
    assert!(out.is_empty() && p.pending());
    p.paint(&mut out, Some(&req(at, 11)), t + p.interval)
        .unwrap();
    assert!(!out.is_empty() && !p.pending());
}

#[test]
fn the_picture_fills_its_box_by_a_whole_factor_and_is_centred() {
    let area = Rect::new(10, 5, 60, 20);
    // 64x64 in 10x20 cells: room 600x(400→396), zoom 6: 384x384.
    let p = place(area, 64, 64, (10, 20));
    assert_eq!((p.width, p.height), (384, 384));
    assert_eq!((p.cells.width, p.cells.height), (39, 20));
    assert_eq!(p.cells.x, 10 + (60 - 39) / 2);
    // Too big: shrunk to fit, the aspect kept, whole sixel bands.
    let big = place(area, 1280, 960, (10, 20));
    assert!(big.width <= 600 && big.height <= 396, "{big:?}");
    assert!((big.width as f64 / big.height as f64 - 4.0 / 3.0).abs() < 0.01);
    assert_eq!(big.cells.y, 5 + (20 - big.cells.height) / 2);
}

/// A writer whose bytes the test reads afterwards.
#[derive(Clone, Default)]
struct Shared(std::sync::Arc<std::sync::Mutex<Vec<u8>>>);

impl std::io::Write for Shared {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.lock().unwrap().extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

fn graphics_app(graphics: Graphics) -> App {
    let mut app = rendered();
    app.color = true;
    app.graphics = graphics;
    app.font = Some((8, 16));
    app
}

#[test]
fn an_unchanged_redraw_writes_almost_nothing_and_an_overlay_hides_the_picture() {
    for graphics in [Graphics::Kitty, Graphics::Sixel] {
        let app = graphics_app(graphics);
        let seen = Shared::default();
        let out = Counting::new(seen.clone());
        let count = out.count();
        let options = TerminalOptions {
            viewport: Viewport::Fixed(Rect::new(0, 0, 100, 30)),
        };
        let mut t = Terminal::with_options(CrosstermBackend::new(out), options).unwrap();
        let mut p = Painter::new(graphics, 1);
        draw_frame(&mut t, &app, &mut p).unwrap();
        let first = count.get();
        assert!(first > 2000, "{graphics:?}: the picture, {first} bytes");
        draw_frame(&mut t, &app, &mut p).unwrap();
        let second = count.get() - first;
        assert!(second < 100, "{graphics:?}: {second} bytes for no change");
        // The help over the picture, then closed: the picture comes back.
        let help = update(app, Msg::ToggleHelp);
        draw_frame(&mut t, &help, &mut p).unwrap();
        let before = count.get();
        let closed = update(help, Msg::ToggleHelp);
        draw_frame(&mut t, &closed, &mut p).unwrap();
        let back = count.get() - before;
        let all = text(&seen.0.lock().unwrap());
        let tail = &all[all.len() - back as usize..];
        match graphics {
            Graphics::Kitty => {
                assert!(tail.contains("\x1b_Ga=p,i=1,"), "placed again");
                assert!(!tail.contains("a=T"), "not sent again");
            }
            _ => assert!(tail.contains("\x1bP"), "sent again"),
        }
    }
}

#[test]
fn in_graphics_mode_the_pictures_cells_are_left_blank_centred_at_every_size() {
    for (w, h) in [(80u16, 24u16), (100, 30), (160, 48)] {
        let app = update(graphics_app(Graphics::Sixel), Msg::Resize(w, h));
        let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
        t.draw(|f| raystep::tui::view::view(&app, f)).unwrap();
        let buffer = t.backend().buffer().clone();
        let screen = Rect::new(0, 0, w, h);
        let r = request(&app, screen).expect("a picture to send");
        let title: String = (0..w).map(|x| buffer[(x, 0)].symbol()).collect();
        assert!(w < 160 || title.contains("sixel"), "{w}x{h}: {title}");
        let inner = ratatui::widgets::Block::bordered()
            .inner(raystep::tui::screen::areas(&app, screen).preview);
        // Centred, and filling the box along one side.
        let left = r.cells.x - inner.x;
        let right = inner.right() - r.cells.right();
        let top = r.cells.y - inner.y;
        let bottom = inner.bottom() - r.cells.bottom();
        assert!(
            left.abs_diff(right) <= 1 && top.abs_diff(bottom) <= 1,
            "{w}x{h}"
        );
        assert!(
            left + right <= 2 || top + bottom <= 3,
            "{w}x{h}: {r:?} in {inner:?}",
            r = r.cells
        );
        assert!(r.image.width() >= 64, "never smaller than the film here");
        for y in r.cells.top()..r.cells.bottom() {
            for x in r.cells.left()..r.cells.right() {
                assert_eq!(buffer[(x, y)].symbol(), " ", "{w}x{h} ({x}, {y})");
            }
        }
        // Under the help the picture is half blocks (none is sent).
        let help = update(app, Msg::ToggleHelp);
        assert!(request(&help, screen).is_none());
        t.draw(|f| raystep::tui::view::view(&help, f)).unwrap();
        let cells: String = t
            .backend()
            .buffer()
            .content()
            .iter()
            .map(|c| c.symbol())
            .collect();
        // (At 80x24 and 100x30 the help hides all of it.)
        assert!(w < 160 || cells.contains('▀'), "{w}x{h}");
    }
}

/// A line-buffered terminal (stdout) shows only what was flushed.
#[derive(Default)]
struct Buffered {
    held: Vec<u8>,
    shown: Vec<u8>,
}

impl std::io::Write for Buffered {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.held.extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.shown.append(&mut self.held);
        Ok(())
    }
}

#[test]
fn every_change_reaches_the_terminal_at_once() {
    // Hiding kitty's picture under the help was held in stdout's buffer
    // until the next frame: the picture stayed over the help.
    let mut p = Painter::new(Graphics::Kitty, 3);
    p.interval = Duration::ZERO;
    let mut out = Buffered::default();
    let at = Rect::new(1, 1, 4, 2);
    let t = Instant::now();
    for next in [Some(req(at, 1)), None, Some(req(at, 1)), Some(req(at, 2))] {
        p.paint(&mut out, next.as_ref(), t).unwrap();
        assert!(out.held.is_empty(), "flushed");
    }
    let shown = text(&out.shown);
    for command in [
        "a=T,f=100,i=3,",
        "a=d,d=i,i=3,",
        "a=p,i=3,",
        "a=T,f=100,i=4,",
        "a=d,d=I,i=3,",
    ] {
        assert!(shown.contains(command), "{command}");
    }
}

#[test]
fn stats_sort_each_second_by_whether_passes_arrived() {
    use raystep::tui::stats::Rates;
    use std::io::Write;
    let mut out = Counting::new(std::io::sink());
    let t = Instant::now();
    let mut rates = Rates::new(t, out.count());
    let s = Duration::from_secs(1);
    out.write_all(&[0; 500]).unwrap();
    rates.busy();
    rates.tick(t + s / 2); // not a whole second yet
    rates.tick(t + s);
    out.write_all(&[0; 30]).unwrap();
    rates.tick(t + 2 * s);
    rates.tick(t + 3 * s);
    assert_eq!(rates.rendering, (500, 1));
    assert_eq!(rates.idle, (30, 2));
    let report = rates.report();
    assert!(report.contains("idle 15 bytes/s over 2 s"), "{report}");
    assert!(
        report.contains("rendering 500 bytes/s over 1 s"),
        "{report}"
    );
}
