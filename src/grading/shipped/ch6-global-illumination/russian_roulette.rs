//! Exercise 6.2: Russian roulette that stays unbiased.
//!
//! A path with contribution `value` survives with probability `q`
//! (0 < q ≤ 1), decided by the uniform number `u` in [0, 1). A path that
//! dies contributes 0. Make the expected result equal `value`, so that
//! ending paths early adds noise but no bias.
//!
//! Grade it with: `cargo run --release --bin grade -- ch6`

/// The contribution after the roulette.
pub fn russian_roulette(value: f64, q: f64, u: f64) -> f64 {
    // TODO: when does the path survive?
    // TODO: what must a survivor carry so that the mean is `value`?
    todo!()
}
