//! Keys → messages: one pure function, and the key table that the help
//! overlay and the book show.

use crossterm::event::{
    KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};

use super::app::{App, Msg};

/// Every key, as (keys, what it does), in the order the help shows them:
/// how to quit and close first, so a short terminal that cuts the list
/// still shows them.
pub const KEYS: &[(&str, &str)] = &[
    ("q  Ctrl-C", "quit (Ctrl-Z suspends, `fg` brings it back)"),
    (
        "Esc",
        "close what is open: help, path, inspect, grade, student",
    ),
    ("?", "show / hide this help"),
    ("↑ ↓  k j", "move in the focused list (chapters or scenes)"),
    ("Tab", "switch focus between chapters and scenes"),
    ("1 … 6", "jump to that chapter"),
    ("v  V", "next / previous view (image, depth, normals, …)"),
    (
        "+  -  0  a",
        "exposure one stop up / down / to 0; a: automatic on / off",
    ),
    ("]  [", "one bounce more / less (chapters with bounces)"),
    ("m", "toggle \"exactly k\" / \"up to k\" bounces"),
    (
        "r",
        "render → reference → difference → relative → z (noise?)",
    ),
    (
        "f  p",
        "flip render ↔ reference (A/B); p: pin this render as it",
    ),
    ("|", "split: pinned render | running one, at equal time"),
    (
        "g",
        "grader's newest failed image: student / reference / diff",
    ),
    (
        "x",
        "student mode: your capstone, live (r: yours / ref / diff)",
    ),
    (
        "e  E",
        "next / previous estimator or sampler: the lecture's ladder",
    ),
    ("Space", "pause / resume rendering (chapters that converge)"),
    (
        ">  <",
        "double / halve the target (samples, and the noise reached)",
    ),
    (
        "i  b",
        "inspect a pixel; b at two corners, or a drag: a region",
    ),
    (
        "h j k l",
        "inspecting: move the cursor (arrows, Shift: 8, or click)",
    ),
    (
        "t",
        "inspecting ch6: trace one path from the pixel (again: next)",
    ),
    (
        "u d PgUp PgDn",
        "scroll the pixel panel or the path table (also the wheel)",
    ),
    (
        "s",
        "save the view as PNG and EXR in out/ (never overwrites)",
    ),
    (
        "w",
        "warp test: ch5's sampling routines against their pdf (χ²)",
    ),
    ("z  Z", "zoom in / out, around the inspect cursor (it pans)"),
];

/// The message for a key press, if the key means anything.
pub fn msg_for_key(app: &App, key: KeyEvent) -> Option<Msg> {
    if key.kind == KeyEventKind::Release {
        return None;
    }
    if key.modifiers.contains(KeyModifiers::CONTROL) {
        return matches!(key.code, KeyCode::Char('c')).then_some(Msg::Quit);
    }
    if app.warp.is_some() {
        return match key.code {
            KeyCode::Esc | KeyCode::Char('w') => Some(Msg::ToggleWarp),
            KeyCode::Right | KeyCode::Char('l') | KeyCode::Tab => Some(Msg::WarpStep(1)),
            KeyCode::Left | KeyCode::Char('h') | KeyCode::BackTab => Some(Msg::WarpStep(-1)),
            KeyCode::Char('n') => Some(Msg::WarpReseed),
            KeyCode::Char('q') => Some(Msg::Quit),
            _ => None,
        };
    }
    if app.inspect.is_some() {
        let shift = key.modifiers.contains(KeyModifiers::SHIFT);
        let (step, code) = match key.code {
            // Shift with a letter arrives as the capital letter.
            KeyCode::Char(c) if c.is_ascii_uppercase() => {
                (8, KeyCode::Char(c.to_ascii_lowercase()))
            }
            code if shift => (8, code),
            code => (1, code),
        };
        let moved = match code {
            KeyCode::Left | KeyCode::Char('h') => Some((-step, 0)),
            KeyCode::Right | KeyCode::Char('l') => Some((step, 0)),
            KeyCode::Up | KeyCode::Char('k') => Some((0, -step)),
            KeyCode::Down | KeyCode::Char('j') => Some((0, step)),
            _ => None,
        };
        if let Some((dx, dy)) = moved {
            return Some(Msg::CursorMove(dx, dy));
        }
        if key.code == KeyCode::Char('t') {
            return Some(Msg::TracePath);
        }
    }
    Some(match key.code {
        KeyCode::Char('q') => Msg::Quit,
        KeyCode::Char('i') => Msg::ToggleInspect,
        KeyCode::Esc => Msg::Close,
        KeyCode::Char('u') => Msg::Scroll(-5),
        KeyCode::Char('d') => Msg::Scroll(5),
        KeyCode::PageUp => Msg::Scroll(-10),
        KeyCode::PageDown => Msg::Scroll(10),
        KeyCode::Up | KeyCode::Char('k') => Msg::Up,
        KeyCode::Down | KeyCode::Char('j') => Msg::Down,
        KeyCode::Tab | KeyCode::BackTab => Msg::SwitchFocus,
        KeyCode::Char(c @ '1'..='9') => Msg::ChapterNumber(c as u32 - '0' as u32),
        KeyCode::Char('v') => Msg::NextView,
        KeyCode::Char('V') => Msg::PrevView,
        KeyCode::Char('+') | KeyCode::Char('=') => Msg::ExposureUp,
        KeyCode::Char('-') => Msg::ExposureDown,
        KeyCode::Char('0') => Msg::ExposureReset,
        KeyCode::Char('a') => Msg::ToggleAutoExposure,
        KeyCode::Char('b') => Msg::MarkRegion,
        KeyCode::Char('p') => Msg::TogglePin,
        KeyCode::Char('|') => Msg::ToggleSplit,
        KeyCode::Char(']') => Msg::BounceUp,
        KeyCode::Char('[') => Msg::BounceDown,
        KeyCode::Char('m') => Msg::ToggleBounceMode,
        KeyCode::Char('r') => Msg::CycleCompare,
        KeyCode::Char('f') => Msg::Flip,
        KeyCode::Char('e') => Msg::NextVariant,
        KeyCode::Char('E') => Msg::PrevVariant,
        KeyCode::Char(' ') => Msg::TogglePause,
        KeyCode::Char('>') | KeyCode::Char('.') => Msg::TargetUp,
        KeyCode::Char('<') | KeyCode::Char(',') => Msg::TargetDown,
        KeyCode::Char('g') => Msg::ToggleGrading,
        KeyCode::Char('x') => Msg::ToggleStudent,
        KeyCode::Char('s') => Msg::Save,
        KeyCode::Char('w') => Msg::ToggleWarp,
        KeyCode::Char('z') => Msg::Zoom(1),
        KeyCode::Char('Z') => Msg::Zoom(-1),
        KeyCode::Char('?') => Msg::ToggleHelp,
        _ => return None,
    })
}

/// The message for a mouse event on a terminal of `size` (columns, rows):
/// a left click, the wheel (3 lines a notch; up is negative) or a move.
pub fn msg_for_mouse(m: MouseEvent, (width, height): (u16, u16)) -> Option<Msg> {
    let (column, row) = (m.column, m.row);
    Some(match m.kind {
        MouseEventKind::Down(MouseButton::Left) => Msg::Click {
            column,
            row,
            width,
            height,
        },
        MouseEventKind::ScrollUp => Msg::Wheel {
            column,
            row,
            lines: -3,
        },
        MouseEventKind::ScrollDown => Msg::Wheel {
            column,
            row,
            lines: 3,
        },
        MouseEventKind::Moved => Msg::Hover { column, row },
        MouseEventKind::Drag(MouseButton::Left) => Msg::Drag {
            column,
            row,
            width,
            height,
        },
        _ => return None,
    })
}

/// How far the help overlay can scroll on a terminal `height` rows tall:
/// until its last key shows above the "more keys" row.
pub fn help_scroll_max(height: u16) -> usize {
    let rows = (KEYS.len() + 2).min(height as usize).saturating_sub(2);
    if rows >= KEYS.len() {
        0
    } else {
        KEYS.len() - rows.saturating_sub(1)
    }
}

impl App {
    /// While the help overlay is open, the arrows, `j` `k`, `u` `d` and the
    /// page keys scroll it (within what the screen hides); `true` when
    /// `msg` was one of them.
    pub fn scroll_help(&mut self, msg: &Msg) -> bool {
        let step: i64 = match msg {
            Msg::Up => -1,
            Msg::Down => 1,
            Msg::Scroll(n) => i64::from(*n),
            _ => return false,
        };
        let max = help_scroll_max(self.screen.height) as i64;
        self.help_scroll = (self.help_scroll as i64 + step).clamp(0, max) as usize;
        true
    }
}
