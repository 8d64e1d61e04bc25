//! How a check runs when the student's code lives in another process.
//!
//! A check is one function of raystep's (`check_look_at(f)`) that calls
//! the student's function `f` many times and judges what comes back. The
//! grader runs it twice, with the same inputs:
//!
//! 1. In the student's process ([`Mode::Record`]), where `f` is the
//!    student's code. Every call of `f` is written down: what it was asked
//!    (its arguments, as bytes), what the grader's building blocks saw it
//!    do (each call of a callback it was handed, the work counters of the
//!    tree it walked), and what it answered, or the panic it raised. That
//!    transcript is all the process sends back. Whatever verdict the check
//!    reaches there is thrown away.
//! 2. In the grader's own process ([`Mode::Replay`]), where `f` is never
//!    run: each call reads the next entry of the transcript, checks that it
//!    was asked the same thing, runs the callbacks the student's code
//!    called (the grader's own, with the arguments recorded) and returns the
//!    recorded answer. The verdict is this run's.
//!
//! Both runs go through one thread, in order (see [`sequential`]), so the
//! n-th call of one is the n-th call of the other. In raystep's own tests
//! ([`Mode::Direct`], the default) `f` is just called.

use std::cell::RefCell;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::sync::Mutex;

use crate::wire::{to_bytes, Wire};

/// How the calls of a student's function go on this thread.
#[derive(Debug, Default)]
pub enum Mode {
    /// Call the function (raystep's tests, the reference solutions).
    #[default]
    Direct,
    /// Call it and write down each call (the student's process).
    Record(Vec<u8>),
    /// Answer from a transcript (the grader's process).
    Replay {
        /// The transcript.
        data: Vec<u8>,
        /// How far it has been read.
        pos: usize,
    },
}

thread_local! {
    static MODE: RefCell<Mode> = const { RefCell::new(Mode::Direct) };
    /// Inside [`uncounted`]: callbacks are not written down.
    static UNCOUNTED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `f`, a part of a check whose callbacks are pure functions it
/// counts nothing of (a scene's distance function for a picture): their
/// calls are neither written down nor replayed, only the answers of the
/// student's functions are. Both processes run the same check, so both
/// leave out the same calls.
pub fn uncounted<T>(f: impl FnOnce() -> T) -> T {
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            UNCOUNTED.with(|u| u.set(self.0));
        }
    }
    let _restore = Restore(UNCOUNTED.with(|u| u.replace(true)));
    f()
}

/// Where the last panic in this process happened (`file:line:column`),
/// kept by the student's process's panic hook for the transcript.
pub static LAST_PANIC_AT: Mutex<Option<String>> = Mutex::new(None);

// The entries of a transcript, one byte each before their values.
const START: u8 = b'S';
const CALLBACK: u8 = b'C';
const RETURNED: u8 = b'R';
const PANICKED: u8 = b'P';
/// The last entry: the check ran to its end in the student's process.
const END: u8 = b'E';

/// Runs `f` with this thread recording (the student's process): returns
/// the transcript of its calls, ended by its end mark whether `f` returned or
/// panicked (a panic of the student's code is in the transcript).
pub fn record(f: impl FnOnce()) -> Vec<u8> {
    MODE.with(|m| *m.borrow_mut() = Mode::Record(Vec::new()));
    let _ = catch_unwind(AssertUnwindSafe(f));
    let mode = MODE.with(|m| std::mem::take(&mut *m.borrow_mut()));
    let mut transcript = match mode {
        Mode::Record(t) => t,
        _ => Vec::new(),
    };
    transcript.push(END);
    transcript
}

/// Runs `f` with this thread answering from `transcript` (the grader's
/// process): returns what `f` returned and whether the replay read the
/// transcript to its end. A panic of `f` goes on (the mode reset first).
pub fn replay<T>(transcript: Vec<u8>, f: impl FnOnce() -> T) -> (T, bool) {
    MODE.with(|m| {
        *m.borrow_mut() = Mode::Replay {
            data: transcript,
            pos: 0,
        }
    });
    let result = catch_unwind(AssertUnwindSafe(f));
    let complete = replay_complete();
    MODE.with(|m| *m.borrow_mut() = Mode::Direct);
    match result {
        Ok(v) => (v, complete),
        Err(payload) => resume_unwind(payload),
    }
}

/// Runs `f` on a pool of one thread, so that every parallel loop of a
/// check calls the student's function in one order, the same in both
/// processes. `f` runs on that thread (set its mode there).
pub fn sequential<T: Send>(f: impl FnOnce() -> T + Send) -> Result<T, String> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .map_err(|e| format!("cannot start the grading thread: {e}"))?;
    Ok(pool.install(f))
}

/// The threads a check's own work may run on (its reference pictures),
/// apart from the one thread where the student's functions are called:
/// what runs there calls none of them, so the order of the calls stays
/// the same in both processes. The student's process starts it
/// ([`start_grader_pool`]) before its sandbox forbids new threads.
static GRADER_POOL: std::sync::OnceLock<Option<rayon::ThreadPool>> = std::sync::OnceLock::new();

/// Starts the pool of [`on_grader_pool`] (a thread per core).
pub fn start_grader_pool() {
    GRADER_POOL.get_or_init(|| {
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        rayon::ThreadPoolBuilder::new()
            .num_threads(cores)
            .build()
            .ok()
    });
}

/// Runs `f`, the grader's own work inside a check that calls no student
/// function (a reference picture), on the grader's pool of threads.
pub fn on_grader_pool<T: Send>(f: impl FnOnce() -> T + Send) -> T {
    start_grader_pool();
    match GRADER_POOL.get().and_then(Option::as_ref) {
        Some(pool) => pool.install(f),
        None => f(),
    }
}

/// Whether this thread records.
fn recording() -> bool {
    MODE.with(|m| matches!(*m.borrow(), Mode::Record(_)))
}

/// Lets `write` append to the transcript being recorded.
fn append(write: impl FnOnce(&mut Vec<u8>)) {
    MODE.with(|m| {
        if let Mode::Record(out) = &mut *m.borrow_mut() {
            write(out);
        }
    });
}

/// Appends `value`'s bytes behind their length (what `Vec<u8>::get`
/// reads back), without a buffer of their own.
fn put_framed(out: &mut Vec<u8>, value: &impl Wire) {
    let at = out.len();
    out.extend_from_slice(&[0; 8]);
    value.put(out);
    let n = (out.len() - at - 8) as u64;
    out[at..at + 8].copy_from_slice(&n.to_le_bytes());
}

/// What the grader's replay found wrong with a transcript: the student's
/// process answered something else than it was asked, or stopped early.
pub(crate) fn mismatch(what: &str) -> ! {
    std::panic::panic_any(format!(
        "the grader could not replay your code's answers ({what}); \
         nothing your code printed or did outside its answers counts"
    ))
}

fn next_byte(data: &[u8], pos: &mut usize) -> Option<u8> {
    let b = *data.get(*pos)?;
    *pos += 1;
    Some(b)
}

/// The next framed value's bytes (its length, 8 bytes, then the bytes).
fn next_slice<'a>(data: &'a [u8], pos: &mut usize) -> Option<&'a [u8]> {
    let len = data.get(*pos..*pos + 8)?;
    let n = usize::try_from(u64::from_le_bytes(len.try_into().ok()?)).ok()?;
    let bytes = data.get(*pos + 8..(*pos + 8).checked_add(n)?)?;
    *pos += 8 + n;
    Some(bytes)
}

fn next_bytes(data: &[u8], pos: &mut usize) -> Option<Vec<u8>> {
    next_slice(data, pos).map(<[u8]>::to_vec)
}

/// What a call carries besides its arguments and answer: the work a
/// building block counted while the student's code ran (in the student's
/// process) and how to account it in the grader's (in replay).
pub struct Side<'a> {
    /// After the call, in the student's process: what was counted.
    pub record: Box<dyn FnOnce() -> Vec<u8> + 'a>,
    /// In replay: account what was counted; `false` when the bytes do not
    /// decode.
    pub replay: Credit<'a>,
}

/// How a replay accounts counted work (see [`Side::replay`]).
pub type Credit<'a> = Box<dyn FnOnce(&[u8]) -> bool + 'a>;

impl Side<'_> {
    /// Nothing besides the answer.
    pub fn none() -> Side<'static> {
        Side {
            record: Box::new(Vec::new),
            replay: Box::new(|b| b.is_empty()),
        }
    }
}

/// The grader's callbacks of one call, for replay: given a callback's slot
/// and its recorded argument, runs the grader's callback and returns its
/// answer's bytes (`None`: no such slot, or the argument does not decode).
pub type Callbacks<'a> = &'a mut dyn FnMut(u8, &[u8]) -> Option<Vec<u8>>;

/// No callbacks.
pub fn no_callbacks(_: u8, _: &[u8]) -> Option<Vec<u8>> {
    None
}

/// One call of a student's function: `run` calls it. `args` are its
/// arguments as the grader compares them; `side` carries counted work;
/// `callbacks` replays the callbacks it called.
pub fn call<R: Wire>(
    args: &impl Wire,
    side: Side<'_>,
    callbacks: Callbacks<'_>,
    run: impl FnOnce() -> R,
) -> R {
    let mode = MODE.with(|m| match &*m.borrow() {
        Mode::Direct => 0,
        Mode::Record(_) => 1,
        Mode::Replay { .. } => 2,
    });
    match mode {
        0 => run(),
        1 => record_call(args, side, run),
        _ => replay_call(args, side, callbacks),
    }
}

fn record_call<R: Wire>(args: &impl Wire, side: Side<'_>, run: impl FnOnce() -> R) -> R {
    append(|out| {
        out.push(START);
        put_framed(out, args);
    });
    *LAST_PANIC_AT.lock().unwrap_or_else(|e| e.into_inner()) = None;
    match catch_unwind(AssertUnwindSafe(run)) {
        Ok(r) => {
            let counted = (side.record)();
            append(|out| {
                out.push(RETURNED);
                put_framed(out, &r);
                counted.put(out);
            });
            r
        }
        Err(payload) => {
            let message = crate::panic_text(&*payload);
            let at = LAST_PANIC_AT
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .take()
                .unwrap_or_default();
            append(|out| {
                out.push(PANICKED);
                message.put(out);
                at.put(out);
            });
            resume_unwind(payload)
        }
    }
}

/// One callback made by the student's code: `f` is the grader's callback,
/// `arg` its argument. Recorded in the student's process.
pub fn callback<A: Wire, R: Wire>(slot: u8, arg: A, f: impl FnOnce(&A) -> R) -> R {
    if !recording() || UNCOUNTED.with(|u| u.get()) {
        return f(&arg);
    }
    let r = f(&arg);
    append(|out| {
        out.push(CALLBACK);
        out.push(slot);
        put_framed(out, &arg);
        put_framed(out, &r);
    });
    r
}

/// Takes the next entry of the transcript being replayed.
fn take_entry<T>(f: impl FnOnce(&[u8], &mut usize) -> Option<T>) -> Option<T> {
    MODE.with(|m| match &mut *m.borrow_mut() {
        Mode::Replay { data, pos } => {
            let mut at = *pos;
            let v = f(data, &mut at)?;
            *pos = at;
            Some(v)
        }
        _ => None,
    })
}

enum Entry {
    Callback(u8, Vec<u8>, Vec<u8>),
    Returned(Vec<u8>, Vec<u8>),
    Panicked(String, String),
}

fn replay_call<R: Wire>(args: &impl Wire, side: Side<'_>, callbacks: Callbacks<'_>) -> R {
    let want = to_bytes(args);
    let asked = take_entry(|d, p| {
        (next_byte(d, p)? == START)
            .then_some(())
            .and_then(|_| next_slice(d, p))
            .map(|a| a == want.as_slice())
    });
    match asked {
        None => mismatch("your code's process stopped before this call"),
        Some(false) => mismatch("a call was asked something else"),
        Some(true) => {}
    }
    loop {
        let entry = take_entry(|d, p| match next_byte(d, p)? {
            CALLBACK => Some(Entry::Callback(
                next_byte(d, p)?,
                next_bytes(d, p)?,
                next_bytes(d, p)?,
            )),
            RETURNED => Some(Entry::Returned(next_bytes(d, p)?, next_bytes(d, p)?)),
            PANICKED => {
                let m = String::from_utf8(next_bytes(d, p)?).ok()?;
                let at = String::from_utf8(next_bytes(d, p)?).ok()?;
                Some(Entry::Panicked(m, at))
            }
            _ => None,
        });
        match entry {
            None => mismatch("the transcript ends inside a call"),
            Some(Entry::Callback(slot, arg, answer)) => match callbacks(slot, &arg) {
                Some(a) if a == answer => {}
                _ => mismatch("a callback answered something else"),
            },
            Some(Entry::Returned(r, counted)) => {
                if !(side.replay)(&counted) {
                    mismatch("the counted work does not decode");
                }
                return match crate::wire::from_bytes::<R>(&r) {
                    Some(v) => v,
                    None => mismatch("an answer does not decode"),
                };
            }
            Some(Entry::Panicked(message, at)) => {
                if !at.is_empty() {
                    crate::note_panic_at(at);
                }
                std::panic::panic_any(message)
            }
        }
    }
}

/// Whether the replay read the whole transcript up to its end mark (a
/// check that stops calling early in one process but not the other is a
/// mismatch too).
fn replay_complete() -> bool {
    MODE.with(|m| match &*m.borrow() {
        Mode::Replay { data, pos } => data.get(*pos) == Some(&END) && *pos + 1 == data.len(),
        _ => false,
    })
}
