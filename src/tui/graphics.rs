//! Which picture the preview uses: the kitty, iTerm2 or sixel graphics
//! protocol where the terminal speaks one, the half-block preview
//! ([`super::picture`]) everywhere else.
//!
//! `--graphics auto` (the default) asks the terminal ([`super::query`]):
//! whether it answers kitty's graphics query, whether its device
//! attributes list sixel, and its cell size in pixels. That happens once,
//! before the UI reads keys, and waits at most [`super::query::TIMEOUT`].
//! The environment ([`detect`]) is the fallback for a terminal that does
//! not answer, and it names the iTerm2 terminals (iTerm2, WezTerm), which
//! answer the query in ways that do not say so — ratatui-image's own table
//! maps WezTerm to iTerm2 too. Inside tmux or screen the preview is half
//! blocks and nothing is asked: a multiplexer passes pictures through
//! unreliably. `--graphics kitty|sixel|iterm2` forces a protocol; one that
//! cannot work (no cell size in pixels, or inside a multiplexer) falls back
//! to half blocks with a note saying why ([`choose`]).

use std::str::FromStr;

pub use super::query::Answer;

/// How the preview is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Graphics {
    /// Two pixels per cell, coloured half blocks (works everywhere).
    HalfBlocks,
    /// The kitty graphics protocol (kitty, Ghostty), placed directly.
    Kitty,
    /// iTerm2's inline images (iTerm2, WezTerm).
    Iterm2,
    /// Sixel (xterm -ti vt340, foot, mlterm).
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

    /// The name `--graphics` takes.
    pub fn flag(self) -> &'static str {
        match self {
            Graphics::HalfBlocks => "halfblocks",
            Graphics::Kitty => "kitty",
            Graphics::Iterm2 => "iterm2",
            Graphics::Sixel => "sixel",
        }
    }
}

/// What `--graphics` asks for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Choice {
    /// Ask the terminal, then look at the environment.
    #[default]
    Auto,
    /// This protocol (or half blocks, with a note, where it cannot work).
    Force(Graphics),
}

impl FromStr for Choice {
    type Err = String;
    fn from_str(s: &str) -> Result<Choice, String> {
        Ok(match s {
            "auto" => Choice::Auto,
            "kitty" => Choice::Force(Graphics::Kitty),
            "sixel" => Choice::Force(Graphics::Sixel),
            "iterm2" => Choice::Force(Graphics::Iterm2),
            "halfblocks" => Choice::Force(Graphics::HalfBlocks),
            _ => return Err("one of auto, kitty, sixel, iterm2, halfblocks".into()),
        })
    }
}

/// The protocol chosen, the cell size it places pictures with, and why a
/// forced choice was not followed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Chosen {
    /// How the preview is drawn.
    pub graphics: Graphics,
    /// Cell size in pixels; `None` with half blocks.
    pub font: Option<(u16, u16)>,
    /// Why the forced protocol is not used (shown on the message line).
    pub note: Option<String>,
}

/// Whether the UI runs inside tmux or screen.
pub fn multiplexer(var: &dyn Fn(&str) -> Option<String>) -> bool {
    let set = |k: &str| var(k).is_some_and(|v| !v.is_empty());
    let term = var("TERM").unwrap_or_default();
    set("TMUX") || set("STY") || term.starts_with("tmux") || term.starts_with("screen")
}

/// The iTerm2 terminals, from the environment (as ratatui-image's table).
fn iterm2_env(var: &dyn Fn(&str) -> Option<String>) -> bool {
    let program = var("TERM_PROGRAM").unwrap_or_default();
    program.contains("iTerm")
        || program.contains("WezTerm")
        || var("LC_TERMINAL").is_some_and(|v| v.contains("iTerm"))
}

/// The protocol the environment alone says the terminal speaks (the
/// fallback when it does not answer the query). `var` looks an
/// environment variable up; `font` is the cell size in pixels, without
/// which no picture can be placed.
pub fn detect(var: &dyn Fn(&str) -> Option<String>, font: Option<(u16, u16)>) -> Graphics {
    let set = |k: &str| var(k).is_some_and(|v| !v.is_empty());
    let is = |k: &str, v: &str| var(k).is_some_and(|x| x == v);
    if multiplexer(var) || font.is_none() {
        return Graphics::HalfBlocks;
    }
    let term = var("TERM").unwrap_or_default();
    if iterm2_env(var) {
        Graphics::Iterm2
    } else if term == "xterm-kitty" || set("KITTY_WINDOW_ID") || is("TERM_PROGRAM", "ghostty") {
        Graphics::Kitty
    } else if term.starts_with("foot") || term.starts_with("mlterm") {
        Graphics::Sixel
    } else {
        Graphics::HalfBlocks
    }
}

/// Whether [`choose`] would ask the terminal: never inside a multiplexer,
/// never for half blocks; for a forced kitty or sixel always, so that the
/// note on a protocol the terminal does not list is said only where the
/// terminal really did not list it (xterm lists sixel, but its
/// environment does not say so); for a forced iTerm2, which no query
/// reveals, only when the window size gave no cell size.
pub fn should_query(
    choice: Choice,
    var: &dyn Fn(&str) -> Option<String>,
    ioctl_font: Option<(u16, u16)>,
) -> bool {
    !multiplexer(var)
        && match choice {
            Choice::Auto | Choice::Force(Graphics::Kitty | Graphics::Sixel) => true,
            Choice::Force(Graphics::HalfBlocks) => false,
            Choice::Force(Graphics::Iterm2) => ioctl_font.is_none(),
        }
}

/// The protocol for `choice`, from the terminal's `answer` (`None`: not
/// asked, or no answer), the environment and the cell size the window
/// size reports (`ioctl_font`).
pub fn choose(
    choice: Choice,
    var: &dyn Fn(&str) -> Option<String>,
    ioctl_font: Option<(u16, u16)>,
    answer: Option<&Answer>,
) -> Chosen {
    let font = answer.and_then(|a| a.font).or(ioctl_font);
    let half = |note: Option<String>| Chosen {
        graphics: Graphics::HalfBlocks,
        font: None,
        note,
    };
    let graphics = match choice {
        Choice::Force(Graphics::HalfBlocks) => return half(None),
        Choice::Force(g) if multiplexer(var) => {
            return half(Some(format!(
                "--graphics {}: tmux and screen pass no pictures; half blocks",
                g.flag()
            )))
        }
        Choice::Force(g) if font.is_none() => {
            return half(Some(format!(
                "--graphics {}: the terminal reports no cell size in pixels; half blocks",
                g.flag()
            )))
        }
        Choice::Force(g) => {
            // Followed; but where neither the terminal's answer nor its
            // environment says it shows such pictures, a blank preview
            // must not go unexplained.
            let said = answer.is_some_and(|a| {
                (g == Graphics::Kitty && a.kitty) || (g == Graphics::Sixel && a.sixel)
            }) || detect(var, font) == g;
            let note = (!said).then(|| {
                format!(
                    "--graphics {}: this terminal did not say it shows such pictures; if the \
                     preview stays blank, run without --graphics",
                    g.flag()
                )
            });
            return Chosen {
                graphics: g,
                font,
                note,
            };
        }
        Choice::Auto if multiplexer(var) || font.is_none() => return half(None),
        Choice::Auto if iterm2_env(var) => Graphics::Iterm2,
        Choice::Auto => match answer {
            Some(a) if a.kitty => Graphics::Kitty,
            Some(a) if a.sixel => Graphics::Sixel,
            _ => detect(var, font),
        },
    };
    if graphics == Graphics::HalfBlocks {
        return half(None);
    }
    Chosen {
        graphics,
        font,
        note: None,
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

/// The protocol for `choice` in this terminal: asks it (once, before the
/// UI reads keys) when [`should_query`] says so.
pub fn pick(choice: Choice) -> Chosen {
    let var = |k: &str| std::env::var(k).ok();
    let font = font_size();
    let answer = should_query(choice, &var, font)
        .then(super::query::ask)
        .flatten();
    choose(choice, &var, font, answer.as_ref())
}
