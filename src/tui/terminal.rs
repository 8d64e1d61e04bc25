//! The terminal as the UI holds it: taken (raw mode, alternate screen,
//! mouse, bracketed paste), given back on every way out (return, `?`,
//! panic of the UI thread), and through signals ([`super::signals`]):
//! restored before an exit, given back before a stop and taken again
//! after it.

use std::sync::OnceLock;
use std::thread::ThreadId;

use crossterm::event::{
    DisableBracketedPaste, DisableMouseCapture, EnableBracketedPaste, EnableMouseCapture,
};
use crossterm::execute;
use crossterm::terminal::{
    disable_raw_mode, enable_raw_mode, EnterAlternateScreen, LeaveAlternateScreen,
};

use super::{painter, signals, stats};

/// The thread that owns the terminal; panics elsewhere leave it alone.
static UI_THREAD: OnceLock<ThreadId> = OnceLock::new();

/// Puts the terminal back: raw mode, mouse reports and bracketed paste
/// off, main screen, cursor shown. Harmless when the terminal is already
/// restored.
pub fn restore_terminal() {
    let _ = disable_raw_mode();
    let _ = execute!(
        std::io::stdout(),
        DisableBracketedPaste,
        DisableMouseCapture,
        LeaveAlternateScreen,
        crossterm::cursor::Show
    );
}

/// Takes the terminal for the UI: raw mode, the alternate screen, mouse
/// reports, bracketed paste (a paste arrives as one event, never as keys),
/// cursor hidden.
pub(super) fn take_terminal() -> std::io::Result<()> {
    enable_raw_mode()?;
    execute!(
        std::io::stdout(),
        EnterAlternateScreen,
        EnableMouseCapture,
        EnableBracketedPaste,
        crossterm::cursor::Hide
    )
}

/// Installs a panic hook that restores the terminal before printing a
/// panic of the UI thread. Panics of other threads (a stage panicking in
/// the render worker, or in rayon under it) are not printed over the UI:
/// the worker catches them and the UI shows the message.
pub(super) fn install_panic_hook() {
    let _ = UI_THREAD.set(std::thread::current().id());
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if Some(&std::thread::current().id()) == UI_THREAD.get() {
            restore_terminal();
            previous(info);
        }
    }));
}

/// Restores the terminal when dropped, so an early `?` return restores too.
pub(super) struct Restore;

impl Drop for Restore {
    fn drop(&mut self) {
        restore_terminal();
    }
}

/// Answers a signal between two frames: gives the terminal back and exits,
/// or gives it back and stops until continued, or takes it again after a
/// stop (and repaints everything, the screen's content being lost).
pub(super) fn answer_signal(
    signal: signals::Signal,
    terminal: &mut stats::Term,
    painter: &mut painter::Painter,
) -> std::io::Result<()> {
    match signal {
        signals::Signal::Exit(code) => {
            restore_terminal();
            crate::core::film::remove_temporaries_and_exit(code)
        }
        signals::Signal::Suspend => {
            restore_terminal();
            signals::stop_here();
            resume(terminal, painter)
        }
        signals::Signal::Continued => resume(terminal, painter),
    }
}

/// Takes the terminal back after a stop and clears what the next frame
/// must redraw.
fn resume(terminal: &mut stats::Term, painter: &mut painter::Painter) -> std::io::Result<()> {
    take_terminal()?;
    terminal.clear()?;
    painter.invalidate(terminal.backend_mut())
}
