//! Student mode (`x`): the current chapter's capstone rendered with the
//! student's own code, live. A [`Watcher`] thread polls the chapter's
//! exercise files every [`POLL`]; after an edit (and once at the start) it
//! runs [`live_student_with`] (the grader's build of the exercises crate, then
//! the capstone's render in a process of its own, under a time limit) and
//! sends what it found. The UI thread never waits for it. The state it
//! updates ([`StudentMode`]) and the messages ([`StudentEvent`]) are plain
//! data; [`update`](super::update::update) applies them.

use std::panic::AssertUnwindSafe;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use crate::grading::live::{
    exercise_stamp, live_student_with, LiveError, LiveOptions, StudentRender,
};

/// How often the watcher looks at the exercise files.
pub const POLL: Duration = Duration::from_millis(500);

/// What student mode shows.
#[derive(Clone, Debug)]
pub struct StudentMode {
    /// The chapter (lecture number) whose capstone is shown.
    pub chapter: u32,
    /// The capstone, `chN/name`.
    pub id: String,
    /// The status: "building…", "compile error: …", "… not started
    /// (todo!)", "student matches reference", "differs: …".
    pub status: String,
    /// More about an error: the compiler's messages, the panic message.
    pub details: String,
    /// The newest images, when the last build and render gave some.
    pub render: Option<StudentRender>,
}

/// What the watcher reports.
#[derive(Clone, Debug)]
pub enum StudentEvent {
    /// A build and render has started (an edit, or the first time).
    Building,
    /// The build is done; the student's code is rendering.
    Rendering,
    /// It finished: the images, or why there are none.
    Done(Result<StudentRender, LiveError>),
}

/// The thread that watches one chapter's exercise files and renders its
/// capstone after each edit. Dropping it stops it (a build or render
/// under way is cancelled) and waits for that at most [`STOP_WAIT`].
pub struct Watcher {
    /// The chapter watched.
    pub chapter: u32,
    /// What the thread found, in order.
    pub events: Receiver<StudentEvent>,
    stop: Arc<AtomicBool>,
    handle: Option<JoinHandle<()>>,
}

/// How long dropping a [`Watcher`] waits for its thread (and the cargo or
/// render process it stops) to end.
pub const STOP_WAIT: Duration = Duration::from_millis(500);

impl Watcher {
    /// Starts watching chapter `chapter`; images go to `<out_dir>/student`.
    pub fn spawn(chapter: u32, out_dir: PathBuf) -> Watcher {
        let (tx, events) = channel();
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let handle = std::thread::Builder::new()
            .name(format!("student-ch{chapter}"))
            .spawn(move || watch(chapter, &out_dir, &flag, &tx))
            .ok();
        Watcher {
            chapter,
            events,
            stop,
            handle,
        }
    }

    /// Stops the thread without waiting for it (the UI moves on at once;
    /// the thread cancels what it runs and ends by itself).
    pub fn detach(mut self) {
        self.stop.store(true, Ordering::Relaxed);
        self.handle = None;
    }
}

impl Drop for Watcher {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(h) = self.handle.take() {
            let start = Instant::now();
            while !h.is_finished() && start.elapsed() < STOP_WAIT {
                std::thread::sleep(Duration::from_millis(5));
            }
        }
    }
}

fn watch(chapter: u32, out_dir: &std::path::Path, stop: &AtomicBool, tx: &Sender<StudentEvent>) {
    let opts = match LiveOptions::for_out_dir(out_dir) {
        Ok(o) => o,
        Err(e) => {
            let _ = tx.send(StudentEvent::Done(Err(LiveError::Build(e))));
            return;
        }
    };
    let mut seen = None;
    while !stop.load(Ordering::Relaxed) {
        let stamp = exercise_stamp(&opts.exercises, chapter);
        if seen.as_ref() != Some(&stamp) {
            if tx.send(StudentEvent::Building).is_err() {
                return;
            }
            // A bug here must not leave "building…" up for ever.
            let result = std::panic::catch_unwind(AssertUnwindSafe(|| {
                let rendering = || {
                    let _ = tx.send(StudentEvent::Rendering);
                };
                live_student_with(chapter, &opts, Some(stop), &rendering)
            }))
            .unwrap_or_else(|_| Err(LiveError::Build("student mode failed".into())));
            if stop.load(Ordering::Relaxed) || tx.send(StudentEvent::Done(result)).is_err() {
                return;
            }
            // An edit saved during the build shows as a new stamp next time.
            seen = Some(stamp);
        }
        let start = Instant::now();
        while start.elapsed() < POLL && !stop.load(Ordering::Relaxed) {
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}
