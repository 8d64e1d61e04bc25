//! Multiple importance sampling (Veach and Guibas 1995): when two
//! strategies can produce the same sample, weight each by how likely it
//! was to come from that strategy, so the weights sum to one and each
//! strategy counts where it is good.

/// The balance heuristic w_f = f / (f + g) for one sample from strategy
/// f (pdf `f`) combined with strategy g (pdf `g`), one sample each.
pub fn balance_heuristic(f: f32, g: f32) -> f32 {
    let sum = f + g;
    if sum > 0.0 && sum.is_finite() {
        f / sum
    } else if f.is_infinite() {
        1.0
    } else {
        0.0
    }
}

/// The power heuristic with β = 2: w_f = f² / (f² + g²). It trusts the
/// strategy with the larger pdf more than the balance heuristic does, which
/// usually lowers variance further. Safe for huge pdfs (no f² overflow).
// ANCHOR: power_heuristic
pub fn power_heuristic(f: f32, g: f32) -> f32 {
    if f.is_infinite() {
        return 1.0;
    }
    if f.is_nan() || f <= 0.0 {
        return 0.0;
    }
    // f² / (f² + g²) = 1 / (1 + (g/f)²), which cannot overflow.
    let r = g / f;
    1.0 / (1.0 + r * r)
}
// ANCHOR_END: power_heuristic
