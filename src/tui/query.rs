//! Asking the terminal what it can show, once, before the UI reads keys.
//!
//! One write sends kitty's graphics query, XTVERSION (the terminal's name
//! and version), the primary device attributes (sixel is attribute 4), the
//! cell size in pixels (`CSI 16 t`) and last a device status report, which
//! every terminal answers: its answer ends the wait. The answers are read
//! from `/dev/tty` with `poll` and a deadline ([`TIMEOUT`]), in this
//! thread, so a terminal that answers nothing costs [`TIMEOUT`] once and
//! leaves no reader behind to steal keys from the UI. (ratatui-image's
//! `Picker::from_query_stdio` reads in a thread that, on a silent terminal,
//! stays blocked on stdin after its timeout.) [`parse`] reads the answers;
//! it is pure, and tested on real terminals' answers.

use std::time::{Duration, Instant};

/// What the terminal answered to the query.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Answer {
    /// It answered kitty's graphics query with OK.
    pub kitty: bool,
    /// Its primary device attributes list 4 (sixel graphics).
    pub sixel: bool,
    /// Its cell size in pixels (width, height), from `CSI 16 t`.
    pub font: Option<(u16, u16)>,
    /// Its name and version (XTVERSION), such as `kitty(0.26.5)`.
    pub version: Option<String>,
}

/// The longest start-up waits for the terminal's answers.
pub const TIMEOUT: Duration = Duration::from_millis(1000);

/// The query: kitty graphics, XTVERSION, DA1, cell size, status report.
pub const QUERY: &str = "\x1b_Gi=31,s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\\x1b[>0q\x1b[c\x1b[16t\x1b[5n";

/// The terminal's answers to [`QUERY`] in `bytes`, and whether they are
/// complete (the status report came back).
pub fn parse(bytes: &[u8]) -> (Answer, bool) {
    let mut answer = Answer::default();
    let mut done = false;
    let text = String::from_utf8_lossy(bytes);
    for seq in text.split('\x1b').filter(|s| !s.is_empty()) {
        if let Some(rest) = seq.strip_prefix("_G") {
            // "_Gi=31;OK" (the ST's backslash follows as its own piece).
            answer.kitty |= rest.starts_with("i=31;OK");
        } else if let Some(rest) = seq.strip_prefix("P>|") {
            answer.version = Some(rest.trim_end_matches('\\').to_string());
        } else if let Some(rest) = seq.strip_prefix("[?").and_then(|s| s.strip_suffix('c')) {
            answer.sixel |= rest.split(';').any(|a| a == "4");
        } else if let Some(rest) = seq.strip_prefix("[6;").and_then(|s| s.strip_suffix('t')) {
            let n: Vec<u16> = rest.split(';').filter_map(|v| v.parse().ok()).collect();
            if let [h, w] = n[..] {
                answer.font = (w > 0 && h > 0).then_some((w, h));
            }
        } else if seq == "[0n" {
            done = true;
        }
    }
    (answer, done)
}

/// Asks the terminal (`/dev/tty`, in raw mode while asking) and reads its
/// answers until the status report or [`TIMEOUT`]; `None` when nothing
/// came back.
#[cfg(unix)]
pub fn ask() -> Option<Answer> {
    use std::io::{Read, Write};

    use nix::poll::{poll, PollFd, PollFlags, PollTimeout};

    let mut tty = std::fs::File::options()
        .read(true)
        .write(true)
        .open("/dev/tty")
        .ok()?;
    let was_raw = crossterm::terminal::is_raw_mode_enabled().unwrap_or(false);
    crossterm::terminal::enable_raw_mode().ok()?;
    let mut bytes = Vec::new();
    let asked = tty.write_all(QUERY.as_bytes()).and_then(|_| tty.flush());
    let start = Instant::now();
    while asked.is_ok() && !parse(&bytes).1 {
        let left = TIMEOUT.saturating_sub(start.elapsed());
        if left.is_zero() {
            break;
        }
        let ms = PollTimeout::try_from(left.as_millis().max(1) as i32).unwrap_or(PollTimeout::ZERO);
        let mut fds = [PollFd::new(
            std::os::fd::AsFd::as_fd(&tty),
            PollFlags::POLLIN,
        )];
        match poll(&mut fds, ms) {
            Ok(n) if n > 0 => {
                let mut buf = [0u8; 256];
                match tty.read(&mut buf) {
                    Ok(0) | Err(_) => break,
                    Ok(k) => bytes.extend_from_slice(&buf[..k]),
                }
            }
            Ok(_) => break,
            Err(nix::errno::Errno::EINTR) => {}
            Err(_) => break,
        }
    }
    if !was_raw {
        let _ = crossterm::terminal::disable_raw_mode();
    }
    (!bytes.is_empty()).then(|| parse(&bytes).0)
}

/// Not asked off unix.
#[cfg(not(unix))]
pub fn ask() -> Option<Answer> {
    None
}
