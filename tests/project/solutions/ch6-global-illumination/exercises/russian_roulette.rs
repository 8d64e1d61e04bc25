//! Exercise 6.2, solved: survivors carry value / q.

/// The contribution after the roulette.
pub fn russian_roulette(value: f64, q: f64, u: f64) -> f64 {
    if u < q {
        value / q
    } else {
        0.0
    }
}
