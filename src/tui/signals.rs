//! The terminal through signals. TERM, HUP, INT and QUIT restore it (main
//! screen, cursor shown, mouse reports and bracketed paste off, cooked
//! mode) and exit with the usual status, 128 + the signal; TSTP (and
//! Ctrl-Z, a key in raw mode) restores it and stops the process, as vim
//! and less do; CONT takes the terminal back and repaints everything.
//!
//! A thread of its own receives the signals and hands them to the event
//! loop, which owns the terminal: the loop restores it between two frames,
//! never in the middle of one. Should the loop not answer an exit within a
//! second (a frame stuck writing), the thread restores and exits itself.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, Receiver};
use std::sync::Arc;
use std::time::Duration;

/// What a signal asks of the event loop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Signal {
    /// Give the terminal back and stop (TSTP).
    Suspend,
    /// The process was continued (CONT): take the terminal again.
    Continued,
    /// Give the terminal back and exit with this status (TERM, HUP, INT,
    /// QUIT: 128 + the signal).
    Exit(i32),
}

/// The signals the UI answers, while it runs.
pub struct Signals {
    rx: Receiver<Signal>,
    /// Set by the event loop once it handles an exit itself.
    exiting: Arc<AtomicBool>,
    #[cfg(unix)]
    handle: signal_hook::iterator::Handle,
}

impl Signals {
    /// Starts listening; `None` where signals cannot be caught (then the
    /// UI runs without).
    #[cfg(unix)]
    pub fn install(restore: fn()) -> Option<Signals> {
        use signal_hook::consts::{SIGCONT, SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGTSTP};
        let mut signals = signal_hook::iterator::Signals::new([
            SIGTERM, SIGHUP, SIGINT, SIGQUIT, SIGTSTP, SIGCONT,
        ])
        .ok()?;
        let handle = signals.handle();
        let (tx, rx) = channel();
        let exiting = Arc::new(AtomicBool::new(false));
        let handled = exiting.clone();
        std::thread::spawn(move || {
            for signal in signals.forever() {
                let msg = match signal {
                    SIGTSTP => Signal::Suspend,
                    SIGCONT => Signal::Continued,
                    s => Signal::Exit(128 + s),
                };
                if tx.send(msg).is_err() {
                    return;
                }
                if let Signal::Exit(code) = msg {
                    std::thread::sleep(Duration::from_secs(1));
                    if !handled.load(Ordering::SeqCst) {
                        restore();
                        crate::core::film::remove_temporaries_and_exit(code);
                    }
                }
            }
        });
        Some(Signals {
            rx,
            exiting,
            handle,
        })
    }

    /// Without Unix signals there is nothing to listen to.
    #[cfg(not(unix))]
    pub fn install(_restore: fn()) -> Option<Signals> {
        None
    }

    /// The next signal that arrived, if any.
    pub fn try_recv(&self) -> Option<Signal> {
        let signal = self.rx.try_recv().ok()?;
        if matches!(signal, Signal::Exit(_)) {
            self.exiting.store(true, Ordering::SeqCst);
        }
        Some(signal)
    }
}

impl Drop for Signals {
    fn drop(&mut self) {
        #[cfg(unix)]
        self.handle.close();
    }
}

/// Stops this process as TSTP would have, once the terminal is given
/// back; returns when it is continued.
pub fn stop_here() {
    #[cfg(unix)]
    let _ = signal_hook::low_level::emulate_default_handler(signal_hook::consts::SIGTSTP);
}
