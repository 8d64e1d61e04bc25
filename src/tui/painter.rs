//! Sends the preview's picture through a graphics protocol, after the
//! frame's cells, and only what changed.
//!
//! - **Kitty**: a picture is transmitted once (PNG, `a=T`) with an id of
//!   its own and placed directly at the cursor, the method every kitty
//!   since 0.20 understands (Debian 12's 0.26 included; Unicode
//!   placeholders need 0.28). A redraw with the same pixels sends
//!   nothing; the same pixels somewhere else are placed again by id
//!   (`a=p`, a few bytes); new pixels get a new id and the old image is
//!   deleted (`a=d,d=I`). Under an overlay the placement is removed and
//!   the image kept, so closing the overlay costs a placement. Every
//!   command asks for no reply (`q=2`): a reply would arrive as keys.
//! - **Sixel** and **iTerm2**: the terminal keeps no image, so new pixels
//!   or a new place are sent whole; an unchanged redraw sends nothing.
//!   When the picture moves, shrinks or goes, the screen must be cleared
//!   first ([`Painter::needs_clear`]): blank cells that stay blank are
//!   never rewritten, and the old picture would stay under them.
//!
//! While a render streams passes, new pixels are sent at most every
//! [`Painter::interval`]; the last ones are always sent ([`Painter::pending`]).

use std::io::{self, Write};
use std::time::{Duration, Instant};

use ratatui::layout::Rect;

use super::graphics::Graphics;
use super::shown::Request;

/// What is on the screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Shown {
    /// Kitty's image id (0 for the other protocols).
    id: u32,
    /// The pixels' key.
    key: u64,
    /// Where.
    cells: Rect,
    /// Whether it is placed (kitty keeps an unplaced image).
    placed: bool,
}

/// The protocol's state between frames.
#[derive(Debug)]
pub struct Painter {
    graphics: Graphics,
    next_id: u32,
    shown: Option<Shown>,
    sent_at: Option<Instant>,
    pending: bool,
    /// The shortest time between two pictures of new pixels.
    pub interval: Duration,
}

/// Kitty's escape: APC `G`, the keys, an optional payload, ST.
fn kitty(out: &mut dyn Write, keys: &str, payload: &str) -> io::Result<()> {
    write!(out, "\x1b_G{keys}")?;
    if !payload.is_empty() {
        write!(out, ";{payload}")?;
    }
    write!(out, "\x1b\\")
}

/// Moves the cursor to the top-left cell of `r`.
fn goto(out: &mut dyn Write, r: Rect) -> io::Result<()> {
    write!(out, "\x1b[{};{}H", r.y + 1, r.x + 1)
}

/// Standard base64 with padding (the base64-simd crate).
pub fn base64(bytes: &[u8]) -> String {
    base64_simd::STANDARD.encode_to_string(bytes)
}

/// `image` as PNG. Adaptive filters: a row repeated by the zoom filters
/// to zeros ("up"), so an enlarged picture costs about what the film does.
fn png(image: &image::RgbImage) -> io::Result<Vec<u8>> {
    use image::codecs::png::{CompressionType, FilterType, PngEncoder};
    let mut bytes = Vec::new();
    let encoder =
        PngEncoder::new_with_quality(&mut bytes, CompressionType::Default, FilterType::Adaptive);
    image
        .write_with_encoder(encoder)
        .map_err(io::Error::other)?;
    Ok(bytes)
}

impl Painter {
    /// A painter for `graphics`; kitty ids start from `first_id`.
    pub fn new(graphics: Graphics, first_id: u32) -> Painter {
        Painter {
            graphics,
            next_id: first_id.max(1),
            shown: None,
            sent_at: None,
            pending: false,
            interval: Duration::from_millis(200),
        }
    }

    /// A painter whose kitty ids start from a number of this process's
    /// own (another program in the same kitty window uses others).
    pub fn for_process(graphics: Graphics) -> Painter {
        Painter::new(
            graphics,
            std::process::id().wrapping_mul(2_654_435_761) >> 8,
        )
    }

    /// Whether new pixels are waiting for [`Painter::interval`] to pass
    /// (the loop draws again then).
    pub fn pending(&self) -> bool {
        self.pending
    }

    /// Whether the screen must be cleared before drawing `next`: a sixel
    /// or iTerm2 picture on screen that `next` does not cover exactly.
    pub fn needs_clear(&self, next: Option<&Request>) -> bool {
        let Some(s) = self.shown else { return false };
        self.graphics != Graphics::Kitty && next.is_none_or(|r| r.cells != s.cells)
    }

    /// The screen was cleared: what was on it is gone (kitty's image is
    /// sent again, the old one deleted).
    pub fn invalidate(&mut self, out: &mut dyn Write) -> io::Result<()> {
        if let Some(s) = self.shown.take() {
            if self.graphics == Graphics::Kitty {
                kitty(out, &format!("a=d,d=I,i={},q=2", s.id), "")?;
            }
        }
        Ok(())
    }

    /// Brings the screen to `next` (none: no picture), writing to `out`,
    /// and flushes it (stdout holds what it is given until a newline).
    pub fn paint(
        &mut self,
        out: &mut dyn Write,
        next: Option<&Request>,
        now: Instant,
    ) -> io::Result<()> {
        self.change(out, next, now)?;
        out.flush()
    }

    fn change(
        &mut self,
        out: &mut dyn Write,
        next: Option<&Request>,
        now: Instant,
    ) -> io::Result<()> {
        self.pending = false;
        let Some(r) = next else {
            if let Some(s) = &mut self.shown {
                if self.graphics == Graphics::Kitty && s.placed {
                    kitty(out, &format!("a=d,d=i,i={},q=2", s.id), "")?;
                    s.placed = false;
                } else if self.graphics != Graphics::Kitty {
                    self.shown = None;
                }
            }
            return Ok(());
        };
        if let Some(s) = &mut self.shown {
            if s.key == r.key {
                if self.graphics == Graphics::Kitty && (!s.placed || s.cells != r.cells) {
                    goto(out, r.cells)?;
                    kitty(out, &format!("a=p,i={},p=1,C=1,q=2", s.id), "")?;
                    (s.placed, s.cells) = (true, r.cells);
                    return Ok(());
                }
                if s.cells == r.cells {
                    return Ok(());
                }
            } else if s.cells == r.cells
                && (s.placed || self.graphics != Graphics::Kitty)
                && self
                    .sent_at
                    .is_some_and(|t| now.duration_since(t) < self.interval)
            {
                // New pixels too soon after the last: later.
                self.pending = true;
                return Ok(());
            }
        }
        let id = match self.graphics {
            Graphics::Kitty => {
                let id = self.next_id;
                self.next_id = self.next_id.checked_add(1).unwrap_or(1);
                id
            }
            _ => 0,
        };
        goto(out, r.cells)?;
        match self.graphics {
            Graphics::Kitty => {
                let data = base64(&png(&r.image)?);
                let chunks: Vec<&[u8]> = data.as_bytes().chunks(4096).collect();
                for (i, chunk) in chunks.iter().enumerate() {
                    let more = u8::from(i + 1 < chunks.len());
                    let keys = if i == 0 {
                        format!("a=T,f=100,i={id},p=1,C=1,q=2,m={more}")
                    } else {
                        format!("m={more}")
                    };
                    kitty(out, &keys, std::str::from_utf8(chunk).unwrap_or(""))?;
                }
                if let Some(old) = self.shown {
                    kitty(out, &format!("a=d,d=I,i={},q=2", old.id), "")?;
                }
            }
            Graphics::Sixel => {
                out.write_all(super::sixel::encode(&r.image).as_bytes())?;
            }
            Graphics::Iterm2 => {
                let data = png(&r.image)?;
                write!(
                    out,
                    "\x1b]1337;File=inline=1;size={};width={}px;height={}px;preserveAspectRatio=1:{}\x07",
                    data.len(),
                    r.image.width(),
                    r.image.height(),
                    base64(&data)
                )?;
            }
            Graphics::HalfBlocks => return Ok(()),
        }
        self.shown = Some(Shown {
            id,
            key: r.key,
            cells: r.cells,
            placed: true,
        });
        self.sent_at = Some(now);
        Ok(())
    }
}

/// Draws a frame of `app` on `terminal`, then brings its picture up to
/// date: the screen cleared first when the old picture would stay.
pub fn draw_frame<W: Write>(
    terminal: &mut ratatui::Terminal<ratatui::backend::CrosstermBackend<W>>,
    app: &super::app::App,
    painter: &mut Painter,
) -> io::Result<()> {
    let screen = terminal.get_frame().area();
    let next = super::shown::request(app, screen);
    if painter.needs_clear(next.as_ref()) {
        terminal.clear()?;
        painter.invalidate(terminal.backend_mut())?;
    }
    terminal.draw(|f| super::view::view(app, f))?;
    painter.paint(terminal.backend_mut(), next.as_ref(), Instant::now())
}
