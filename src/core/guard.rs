//! An exercise may use the building blocks its stub imports, not raystep's
//! own solution of that exercise. The exercises crate calls each student
//! function through [`student`]; each reference solution starts with
//! [`reference()`], which refuses to run inside a student's call. The check
//! then fails, naming the exercise whose solution was called.
//!
//! Cost outside grading: one relaxed atomic load per call of a reference
//! function (only `grade-student` ever sets `ARMED`).

use std::cell::Cell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

/// Set once a student's function has been called in this process.
static ARMED: AtomicBool = AtomicBool::new(false);

/// The first reference solution a student's code called, if any.
static CALLED: Mutex<Option<&'static str>> = Mutex::new(None);

thread_local! {
    /// Whether this thread is inside a student's function now.
    static INSIDE: Cell<bool> = const { Cell::new(false) };
}

/// Calls a student's function `f`, marking this thread as running student
/// code until it returns (or unwinds).
pub fn student<R>(f: impl FnOnce() -> R) -> R {
    ARMED.store(true, Ordering::Relaxed);
    inside(true, f)
}

/// Calls the grader's own code `f` from inside a student's function: the
/// building blocks a student's code is handed (chapter 6's scene, a check's
/// distance function) may use raystep's solutions, which are not the
/// student's calls.
pub fn grader<R>(f: impl FnOnce() -> R) -> R {
    inside(false, f)
}

/// Runs `f` with this thread marked as inside a student's function or
/// not, restoring the mark when `f` returns (or unwinds).
fn inside<R>(student: bool, f: impl FnOnce() -> R) -> R {
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            INSIDE.with(|i| i.set(self.0));
        }
    }
    let _restore = Restore(INSIDE.with(|i| i.replace(student)));
    f()
}

/// Marks the start of raystep's reference solution of exercise `id`
/// (`chN/name`): inside a student's function it records the call and
/// panics, so that the check fails and says why.
#[inline]
pub fn reference(id: &'static str) {
    if ARMED.load(Ordering::Relaxed) && INSIDE.with(|i| i.get()) {
        let mut called = CALLED.lock().unwrap_or_else(|e| e.into_inner());
        called.get_or_insert(id);
        drop(called);
        panic!("{}", message(id));
    }
}

/// The message for a student's code that called the reference of `id`.
pub fn message(id: &str) -> String {
    format!(
        "your code calls raystep's own solution of {id}: write it with the building \
         blocks the stub imports instead"
    )
}

/// The reference solution a student's code called in this process, if
/// any (even when the student's code caught the panic).
pub fn reference_called() -> Option<&'static str> {
    *CALLED.lock().unwrap_or_else(|e| e.into_inner())
}
