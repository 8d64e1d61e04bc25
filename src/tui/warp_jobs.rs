//! The warp view's work off the UI thread: each built-in routine's draws,
//! and the student's routine built and run, one build at a time (a newer
//! request, or closing the view, cancels the one running). The event loop
//! calls [`WarpJobs::step`] once a turn and feeds the answers to `update`.

use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::Arc;

use super::msg::Msg;
use super::warp::{builtin_test, student_draws, WarpView};
use crate::core::warp_test::{Drawn, WarpTest};

/// What is running, and where its answers come back.
pub struct WarpJobs {
    builtin: (Sender<BuiltinAnswer>, Receiver<BuiltinAnswer>),
    builtin_sent: Option<(usize, u64)>,
    student: (Sender<StudentAnswer>, Receiver<StudentAnswer>),
    student_sent: Option<u64>,
    cancel: Option<Arc<AtomicBool>>,
}

/// A built-in routine's test: routine, seed, test.
type BuiltinAnswer = (usize, u64, WarpTest);

/// The student's draws for a seed, or why there are none.
type StudentAnswer = (u64, Result<Drawn, String>);

impl Default for WarpJobs {
    fn default() -> Self {
        WarpJobs {
            builtin: channel(),
            builtin_sent: None,
            student: channel(),
            student_sent: None,
            cancel: None,
        }
    }
}

impl WarpJobs {
    /// Starts what `view` waits for (outputs under `out`), and returns the
    /// answers that have come, as messages.
    pub fn step(&mut self, view: Option<&WarpView>, out: &Path) -> Vec<Msg> {
        let wanted = view.and_then(|w| w.student_requested);
        if wanted != self.student_sent {
            if let Some(old) = self.cancel.take() {
                old.store(true, Ordering::SeqCst);
            }
            self.student_sent = wanted;
            if let Some(seed) = wanted {
                let cancel = Arc::new(AtomicBool::new(false));
                self.cancel = Some(cancel.clone());
                let (tx, out) = (self.student.0.clone(), out.to_path_buf());
                std::thread::spawn(move || {
                    let _ = tx.send((seed, student_draws(&out, seed, &cancel)));
                });
            }
        }
        let builtin = view.and_then(|w| w.pending.map(|s| (w.index, s)));
        if let Some((index, seed)) = builtin.filter(|b| Some(*b) != self.builtin_sent) {
            self.builtin_sent = builtin;
            let tx = self.builtin.0.clone();
            std::thread::spawn(move || {
                if let Some(t) = builtin_test(index, seed) {
                    let _ = tx.send((index, seed, t));
                }
            });
        }
        let mut msgs = Vec::new();
        while let Ok((index, seed, test)) = self.builtin.1.try_recv() {
            self.builtin_sent = self.builtin_sent.filter(|b| *b != (index, seed));
            msgs.push(Msg::WarpBuiltin(index, seed, Box::new(test)));
        }
        while let Ok((seed, drawn)) = self.student.1.try_recv() {
            // A cancelled build's late answer must not restart the newer one.
            if self.student_sent == Some(seed) {
                self.student_sent = None;
                self.cancel = None;
            }
            msgs.push(Msg::WarpStudent(seed, drawn));
        }
        msgs
    }
}
