//! How much work a BVH traversal did, counted on the thread that did it:
//! slab tests and watertight triangle tests, as the counted blocks of
//! exercise 3.4 ([`super::counted`]) make them.
//!
//! A traversal that prunes visits a few boxes and tests a few triangles
//! per ray; one that does not tests nearly all of them, and gives the same
//! answers. Only the counts tell them apart, so the grader of exercise 3.4
//! reads them (and `tests/ch3` shows what the book's traversal costs).
//! The lesson's functions count nothing: only the blocks a traversal is
//! handed do.

use std::cell::Cell;

/// Calls counted on this thread: [`Work::now`] is the count so far, and
/// `Work::now().since(before)` the calls made since `before`. The counts
/// only grow (nothing resets them), so no code can hide work it did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Work {
    /// Slab tests: calls of `Aabb::enter`.
    pub box_tests: u64,
    /// Triangle tests: calls of `intersect_watertight`.
    pub triangle_tests: u64,
    /// How often the `t_max` of a triangle test was below the one before:
    /// each time, a traversal shrank its interval to a closer hit. Front to
    /// back finds the closest hit early and shrinks rarely; back to front
    /// shrinks at every nearer triangle. (The next ray starts at a larger
    /// t_max again, which is not counted.)
    pub shrinks: u64,
    /// The `t_max` of the last triangle test.
    last_t_max: f32,
}

thread_local! {
    static WORK: Cell<Work> = const {
        Cell::new(Work {
            box_tests: 0,
            triangle_tests: 0,
            shrinks: 0,
            last_t_max: f32::INFINITY,
        })
    };
}

impl Work {
    /// Counts as a student's process reported them (the grader's replay).
    pub fn counted(box_tests: u64, triangle_tests: u64, shrinks: u64, last_t_max: f32) -> Work {
        Work {
            box_tests,
            triangle_tests,
            shrinks,
            last_t_max,
        }
    }

    /// The `t_max` of the last triangle test.
    pub fn last_t_max(&self) -> f32 {
        self.last_t_max
    }

    /// The calls counted on this thread so far.
    pub fn now() -> Work {
        WORK.with(|w| w.get())
    }

    /// The calls counted between `before` and `self`.
    pub fn since(self, before: Work) -> Work {
        Work {
            box_tests: self.box_tests - before.box_tests,
            triangle_tests: self.triangle_tests - before.triangle_tests,
            shrinks: self.shrinks - before.shrinks,
            last_t_max: self.last_t_max,
        }
    }
}

/// Adds `done`, work that a student's code did in its own process (the
/// grader's replay of its transcript, `grading::bridge`), to this
/// thread's counts: the counts still only grow.
pub(crate) fn credit(done: Work) {
    WORK.with(|w| {
        let mut work = w.get();
        work.box_tests += done.box_tests;
        work.triangle_tests += done.triangle_tests;
        work.shrinks += done.shrinks;
        work.last_t_max = done.last_t_max;
        w.set(work);
    });
}

/// Counts one slab test.
#[inline]
pub fn box_test() {
    WORK.with(|w| {
        let mut work = w.get();
        work.box_tests += 1;
        w.set(work);
    });
}

/// Counts one triangle test against the interval ending at `t_max`.
#[inline]
pub fn triangle_test(t_max: f32) {
    WORK.with(|w| {
        let mut work = w.get();
        work.triangle_tests += 1;
        if t_max < work.last_t_max {
            work.shrinks += 1;
        }
        work.last_t_max = t_max;
        w.set(work);
    });
}
