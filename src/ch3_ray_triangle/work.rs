//! How much work a BVH traversal did, counted on the thread that did it:
//! slab tests ([`Aabb::enter`](super::readable_bvh::Aabb::enter)) and
//! watertight triangle tests
//! ([`intersect_watertight`](super::triangle::intersect_watertight)).
//!
//! A traversal that prunes visits a few boxes and tests a few triangles
//! per ray; one that does not tests nearly all of them, and gives the same
//! answers. Only the counts tell them apart, so the grader of exercise 3.4
//! reads them (and `tests/ch3` shows what the reference costs). The
//! renderer's traversals ([`super::wide_bvh`], [`super::bvh::Bvh`]) use
//! neither function, so counting costs them nothing; the readable ones pay
//! a thread-local add per call.

use std::cell::Cell;

/// Calls counted since the last [`Work::take`] on this thread.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Work {
    /// Slab tests: calls of `Aabb::enter`.
    pub box_tests: u64,
    /// Triangle tests: calls of `intersect_watertight`.
    pub triangle_tests: u64,
    /// How often the `t_max` of a triangle test differed from the one
    /// before: each change is a traversal shrinking its interval to a
    /// closer hit. Front to back finds the closest hit early and shrinks
    /// rarely; back to front shrinks at every nearer triangle.
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
            last_t_max: f32::NAN,
        })
    };
}

impl Work {
    /// The counts since the last call on this thread, which start again
    /// from zero.
    pub fn take() -> Work {
        WORK.with(|w| {
            w.replace(Work {
                last_t_max: f32::NAN,
                ..Work::default()
            })
        })
    }
}

/// Counts one slab test.
#[inline]
pub(crate) fn box_test() {
    WORK.with(|w| {
        let mut work = w.get();
        work.box_tests += 1;
        w.set(work);
    });
}

/// Counts one triangle test against the interval ending at `t_max`.
#[inline]
pub(crate) fn triangle_test(t_max: f32) {
    WORK.with(|w| {
        let mut work = w.get();
        work.triangle_tests += 1;
        if work.triangle_tests > 1 && t_max != work.last_t_max {
            work.shrinks += 1;
        }
        work.last_t_max = t_max;
        w.set(work);
    });
}
