//! Full-resolution pictures where the terminal can show them: the kitty,
//! iTerm2 and sixel graphics protocols through ratatui-image, and the
//! half-block preview ([`super::picture`]) everywhere else.
//!
//! The protocol is chosen from the environment alone ([`detect`]), never
//! by querying the terminal: a query waits for an answer (start-up would
//! wait too, and forever on a terminal that does not answer), and its
//! answer arrives on stdin, where crossterm reads keys. Inside tmux or
//! screen the preview is always half blocks: a multiplexer passes graphics
//! through unreliably. Over ssh `TERM` still names the terminal, so kitty is
//! found there too. `--halfblocks` forces the fallback.

use ratatui_image::picker::{Picker, ProtocolType};

/// How the preview is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Graphics {
    /// Two pixels per cell, coloured half blocks (works everywhere).
    HalfBlocks,
    /// The kitty graphics protocol (kitty, WezTerm, Ghostty).
    Kitty,
    /// iTerm2's inline images.
    Iterm2,
    /// Sixel (foot, mlterm).
    Sixel,
}

impl Graphics {
    /// Name for the preview's title.
    pub fn name(self) -> &'static str {
        match self {
            Graphics::HalfBlocks => "half blocks",
            Graphics::Kitty => "kitty graphics",
            Graphics::Iterm2 => "iTerm2 images",
            Graphics::Sixel => "sixel",
        }
    }
}

/// The protocol the environment says the terminal speaks. `var` looks an
/// environment variable up; `font` is the size of a cell in pixels when
/// the terminal reports its size in pixels (without it no picture can be
/// placed, so half blocks).
pub fn detect(var: &dyn Fn(&str) -> Option<String>, font: Option<(u16, u16)>) -> Graphics {
    let set = |k: &str| var(k).is_some_and(|v| !v.is_empty());
    let is = |k: &str, v: &str| var(k).is_some_and(|x| x == v);
    if set("TMUX") || set("STY") || font.is_none() {
        return Graphics::HalfBlocks;
    }
    let term = var("TERM").unwrap_or_default();
    if term == "xterm-kitty"
        || set("KITTY_WINDOW_ID")
        || is("TERM_PROGRAM", "WezTerm")
        || is("TERM_PROGRAM", "ghostty")
    {
        Graphics::Kitty
    } else if is("TERM_PROGRAM", "iTerm.app") || is("LC_TERMINAL", "iTerm2") {
        Graphics::Iterm2
    } else if term.starts_with("foot") || term.starts_with("mlterm") {
        Graphics::Sixel
    } else {
        Graphics::HalfBlocks
    }
}

/// The cell size in pixels, from the terminal's reported window size
/// (an ioctl, no query); `None` when it reports no pixels.
pub fn font_size() -> Option<(u16, u16)> {
    let w = crossterm::terminal::window_size().ok()?;
    (w.width > 0 && w.height > 0 && w.columns > 0 && w.rows > 0)
        .then(|| (w.width / w.columns, w.height / w.rows))
        .filter(|(x, y)| *x > 0 && *y > 0)
}

/// A picker for `graphics` with cells of `font` pixels; `None` for half
/// blocks (the UI's own preview draws those).
pub fn picker(graphics: Graphics, font: (u16, u16)) -> Option<Picker> {
    let protocol = match graphics {
        Graphics::HalfBlocks => return None,
        Graphics::Kitty => ProtocolType::Kitty,
        Graphics::Iterm2 => ProtocolType::Iterm2,
        Graphics::Sixel => ProtocolType::Sixel,
    };
    let mut p = Picker::from_fontsize(font);
    p.set_protocol_type(protocol);
    Some(p)
}
