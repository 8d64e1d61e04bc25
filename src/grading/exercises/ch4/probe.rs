//! A distance function that counts its evaluations, for the checks of
//! chapter 4's step budget.

use std::cell::Cell;

use glam::Vec3;

/// A distance function that counts its evaluations.
pub struct Probe {
    /// The function.
    pub f: fn(Vec3) -> f32,
    /// Evaluations so far.
    pub calls: Cell<u32>,
}

impl Probe {
    /// A probe of `f`, no evaluations yet.
    pub fn new(f: fn(Vec3) -> f32) -> Probe {
        Probe {
            f,
            calls: Cell::new(0),
        }
    }

    /// `f(p)`, counted.
    pub fn eval(&self, p: Vec3) -> f32 {
        self.calls.set(self.calls.get() + 1);
        (self.f)(p)
    }
}
