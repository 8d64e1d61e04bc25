//! What the preview box shows ([`content`]: a film, or a note), and how a
//! film is drawn: with half blocks into the cells, or, with a graphics
//! protocol, as a picture placed over cells the view leaves blank
//! ([`request`] says what the [`super::painter`] sends after the frame).
//!
//! A picture fills its box: enlarged by a whole factor where that fills
//! most of it (every pixel a sharp square), scaled to fill otherwise, and
//! centred
//! ([`place`]). Its cells reach to whole sixel bands (six pixels) below
//! it, so a terminal that paints the last band whole stays inside them. While the help or the warp
//! test covers the screen ([`covered`]), the picture is drawn with half
//! blocks instead, under the overlay: nothing of it can show through, and
//! when the overlay closes the picture is sent again.

use std::borrow::Cow;
use std::hash::{Hash, Hasher};

use image::RgbImage;
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::widgets::Block;
use ratatui::Frame;

use super::app::App;
use super::picture::Picture;
use super::placement::{covered, graphics_font, picture_cells, place};
use super::zoom::{graphics_pixels, Window};
use crate::core::film::Film;
use crate::core::preview::downsample;

/// What the preview box holds.
pub enum Content<'a> {
    /// A picture.
    Film(Cow<'a, Film>),
    /// A line of text in this colour (why there is no picture yet).
    Note(String, Color),
}

/// What the preview shows for `app`.
pub fn content(app: &App) -> Content<'_> {
    let note = |text: String, color| Content::Note(text, color);
    if app.grading.is_some() || app.student_render().is_some() {
        // The grader's images need no render: shown whatever the selection.
        return match app.displayed_ref() {
            Some(film) => Content::Film(film),
            None => note(String::new(), Color::Reset),
        };
    }
    if let Some(s) = &app.student {
        let color = match s.status.as_str() {
            "starting…" | "building…" | "rendering…" => Color::Reset,
            _ => Color::Red,
        };
        note(format!("{}\n\n{}", s.status, s.details), color)
    } else if let Some(why) = app.problem() {
        let scene = app.current_scene().map(|s| s.source.as_str()).unwrap_or("");
        note(format!("cannot render {scene}:\n{why}"), Color::Red)
    } else if let Some(e) = &app.failure {
        note(format!("render failed: {e}"), Color::Red)
    } else if let Some(film) = app.displayed_ref() {
        Content::Film(film)
    } else if let Some((_, path)) = app.scene_to_read() {
        let path = crate::core::text::escape(&path.display().to_string()).into_owned();
        note(format!("reading {path}…"), Color::Reset)
    } else {
        note("rendering…".into(), Color::Reset)
    }
}

/// A picture for the painter: where, what, and a key that changes when
/// the pixels do.
#[derive(Clone, Debug)]
pub struct Request {
    /// The cells it covers.
    pub cells: Rect,
    /// The pixels, already scaled to their size on screen.
    pub image: RgbImage,
    /// A hash of the pixels and their size.
    pub key: u64,
}

impl Request {
    /// A request for `image` at `cells`.
    pub fn new(cells: Rect, image: RgbImage) -> Request {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        (image.width(), image.height()).hash(&mut h);
        image.as_raw().hash(&mut h);
        Request {
            cells,
            key: h.finish(),
            image,
        }
    }
}

/// The box inside the preview's border on a screen of `screen` cells.
fn preview_inner(app: &App, screen: Rect) -> Option<Rect> {
    let a = super::screen::areas(app, screen);
    (!a.too_small && a.preview.width >= 3 && a.preview.height >= 3)
        .then(|| Block::bordered().inner(a.preview))
}

/// The picture a graphics protocol shows of `app` on a screen of
/// `screen` cells; `None` with half blocks, under an overlay, or when the
/// box holds a note.
pub fn request(app: &App, screen: Rect) -> Option<Request> {
    let font = graphics_font(app).filter(|_| !covered(app))?;
    let inner = preview_inner(app, screen)?;
    let Content::Film(full) = content(app) else {
        return None;
    };
    let window = Window::of(app, full.width, full.height);
    let mut film = window.crop(&full);
    let mut cursor = app.inspect.and_then(|p| window.to_window(p));
    let p = place(inner, film.width, film.height, font);
    if app.shows_signed() && (p.width < film.width || p.height < film.height) {
        // A signed difference is averaged to its size on screen before it
        // is coloured: noise then averages out instead of turning purple.
        let (w, h) = (
            p.width.min(film.width).max(1),
            p.height.min(film.height).max(1),
        );
        cursor = cursor.map(|(x, y)| (x * w / film.width, y * h / film.height));
        film = downsample(&film, w, h);
    }
    let pooled = (full.width * full.height) as f32 / (film.width * film.height) as f32;
    let painted = app.paint_pooled(&film, pooled.max(1.0));
    let raw = RgbImage::from_raw(film.width, film.height, graphics_pixels(&painted, cursor))?;
    let filter = if p.width >= film.width {
        image::imageops::FilterType::Nearest
    } else {
        image::imageops::FilterType::Triangle
    };
    let mut image = image::imageops::resize(&raw, p.width, p.height, filter);
    if let Some(region) = super::region::in_window(app, &window) {
        super::region::outline(&mut image, region, window.width, window.height);
    }
    Some(Request::new(p.cells, image))
}

/// Draws `full` with the exposure into `area`. With a graphics protocol
/// (and no overlay) the picture's cells are left blank for the painter;
/// otherwise half blocks, box-filtered to the cells first and exposed (or,
/// for a signed difference, coloured) after, so a redraw touches the
/// full-size film once.
pub fn draw_film(app: &App, frame: &mut Frame, full: &Film, area: Rect) {
    let window = Window::of(app, full.width, full.height);
    let cropped;
    let film = if window.is_whole(full.width, full.height) {
        full
    } else {
        cropped = window.crop(full);
        &cropped
    };
    let cursor = app.inspect.and_then(|p| window.to_window(p));
    let r = picture_cells(app, area, film.width, film.height);
    if graphics_font(app).is_some() && !covered(app) {
        // The painter places the picture here after the frame.
        frame.render_widget(ratatui::widgets::Clear, r);
        return;
    }
    if r.width == 0 {
        return;
    }
    // Averaged to the cells first, coloured or exposed after.
    let small = downsample(film, r.width as u32, r.height as u32 * 2);
    let pooled = (film.width * film.height) as f32 / (small.width * small.height) as f32;
    let small = app.paint_pooled(&small, pooled.max(1.0));
    frame.render_widget(
        Picture {
            film: &small,
            color: app.color,
        },
        r,
    );
    if let Some(region) = super::region::in_window(app, &window) {
        super::region::draw_region(frame, r, region, film.width, film.height);
    }
    if let Some(p) = cursor {
        super::inspect::draw_cursor(frame, r, p, film.width, film.height);
    }
}
