//! The warp view's work off the UI thread: each built-in routine's draws,
//! and the student's routine built and run, one build at a time (a newer
//! request, or closing the view, cancels the one running). The event loop
//! starts them when `update` asks ([`Effect::WarpBuiltin`],
//! [`Effect::WarpStudent`]) and feeds the answers back to `update`
//! ([`WarpJobs::answers`]).
//!
//! [`Effect::WarpBuiltin`]: super::effect::Effect::WarpBuiltin
//! [`Effect::WarpStudent`]: super::effect::Effect::WarpStudent

use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::Arc;

use super::msg::Msg;
use super::warp::{builtin_test, student_draws};
use crate::core::warp_test::{Drawn, WarpTest};

/// Where the answers come back, and the cancel flag of the student's
/// build under way.
pub struct WarpJobs {
    builtin: (Sender<BuiltinAnswer>, Receiver<BuiltinAnswer>),
    student: (Sender<StudentAnswer>, Receiver<StudentAnswer>),
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
            student: channel(),
            cancel: None,
        }
    }
}

impl WarpJobs {
    /// Draws built-in routine `index` with `seed` in a thread.
    pub fn draw_builtin(&self, index: usize, seed: u64) {
        let tx = self.builtin.0.clone();
        std::thread::spawn(move || {
            if let Some(t) = builtin_test(index, seed) {
                let _ = tx.send((index, seed, t));
            }
        });
    }

    /// Cancels the student's build under way, and with a seed builds and
    /// runs the student's routine anew (outputs under `out`) in a thread.
    pub fn draw_student(&mut self, seed: Option<u64>, out: &Path) {
        if let Some(old) = self.cancel.take() {
            old.store(true, Ordering::SeqCst);
        }
        if let Some(seed) = seed {
            let cancel = Arc::new(AtomicBool::new(false));
            self.cancel = Some(cancel.clone());
            let (tx, out) = (self.student.0.clone(), out.to_path_buf());
            std::thread::spawn(move || {
                let _ = tx.send((seed, student_draws(&out, seed, &cancel)));
            });
        }
    }

    /// The answers that have come, as messages (the view drops one it no
    /// longer waits for).
    pub fn answers(&self) -> Vec<Msg> {
        let builtin = self.builtin.1.try_iter();
        let student = self.student.1.try_iter();
        builtin
            .map(|(index, seed, test)| Msg::WarpBuiltin(index, seed, Box::new(test)))
            .chain(student.map(|(seed, drawn)| Msg::WarpStudent(seed, drawn)))
            .collect()
    }
}
