//! `--stats`: how many bytes the UI writes to the terminal, per second,
//! while idle and while a render streams passes. A [`Counting`] writer
//! sits under the terminal backend (the painter's pictures go through it
//! too); [`Rates`] sorts each whole second by whether a pass arrived in it.

use std::io::{self, Write};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// How many bytes went through a [`Counting`] writer (shared with it).
#[derive(Clone, Debug, Default)]
pub struct Count(Arc<AtomicU64>);

impl Count {
    /// The bytes so far.
    pub fn get(&self) -> u64 {
        self.0.load(Ordering::Relaxed)
    }
}

/// A writer that counts the bytes written through it.
#[derive(Debug)]
pub struct Counting<W> {
    /// Where the bytes go.
    pub inner: W,
    count: Count,
}

impl<W> Counting<W> {
    /// Counts what goes to `inner`.
    pub fn new(inner: W) -> Counting<W> {
        Counting {
            inner,
            count: Count::default(),
        }
    }

    /// A handle on the count.
    pub fn count(&self) -> Count {
        self.count.clone()
    }
}

impl<W: Write> Write for Counting<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let n = self.inner.write(buf)?;
        self.count.0.fetch_add(n as u64, Ordering::Relaxed);
        Ok(n)
    }
    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush()
    }
}

/// The terminal the UI draws on: stdout, its bytes counted.
pub type Term = ratatui::Terminal<ratatui::backend::CrosstermBackend<Counting<io::Stdout>>>;

/// Bytes per second, idle and rendering.
#[derive(Clone, Debug)]
pub struct Rates {
    count: Count,
    start: Instant,
    second: Instant,
    bytes_then: u64,
    busy: bool,
    /// Bytes and whole seconds while idle.
    pub idle: (u64, u32),
    /// Bytes and whole seconds with passes arriving.
    pub rendering: (u64, u32),
}

impl Rates {
    /// Starts counting at `now` what goes through `count`.
    pub fn new(now: Instant, count: Count) -> Rates {
        Rates {
            start: now,
            second: now,
            bytes_then: count.get(),
            count,
            busy: false,
            idle: (0, 0),
            rendering: (0, 0),
        }
    }

    /// A pass arrived in this second.
    pub fn busy(&mut self) {
        self.busy = true;
    }

    /// Closes the second when a whole one has passed by `now`.
    pub fn tick(&mut self, now: Instant) {
        let bytes = self.count.get();
        if now.duration_since(self.second) < Duration::from_secs(1) {
            return;
        }
        let spent = bytes - self.bytes_then;
        let slot = if self.busy {
            &mut self.rendering
        } else {
            &mut self.idle
        };
        slot.0 += spent;
        slot.1 += 1;
        (self.second, self.bytes_then, self.busy) = (now, bytes, false);
    }

    /// One line per kind of second, and the total.
    pub fn report(&self) -> String {
        let bytes = self.count.get();
        let rate = |(b, s): (u64, u32)| match s {
            0 => "no whole second".to_string(),
            s => format!("{:.0} bytes/s over {s} s", b as f64 / s as f64),
        };
        format!(
            "bytes written to the terminal: idle {}; rendering {}; {bytes} bytes in {:.1} s in all",
            rate(self.idle),
            rate(self.rendering),
            self.start.elapsed().as_secs_f64()
        )
    }
}
