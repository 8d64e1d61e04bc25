//! Exercise 6.2's checks at small q, where evenly spaced u over [0, 1)
//! see no survivor at all.

use super::super::draws::Draws;
use super::RouletteFn;

/// `count` drawn (value, q): a value of either sign from 10⁻³ to 10³, and
/// q between 10^from and 10^to, evenly in its exponent (in f64: the
/// decades reach far below what f32 holds).
pub(super) fn values_and_small_q(
    draws: &mut Draws,
    count: usize,
    (from, to): (f64, f64),
) -> Vec<(f64, f64)> {
    (0..count)
        .map(|_| {
            draws.next_case();
            let value = (draws.sign() * draws.decades(-3.0, 3.0)) as f64;
            (value, 10f64.powf(from + (to - from) * draws.unit() as f64))
        })
        .collect()
}

/// For q from 10⁻⁷ to 10⁻⁴ (six drawn), the share of survivors where the
/// stub says they lie (within 2q of 0 or of 1): 20,000 evenly spaced u in
/// each of those two windows, the survivors' measure to 2q / 20,000. What
/// is wrong with it, if anything. (u ≥ 1 − q decided in f32 is off by up
/// to 3 % there.)
pub(super) fn share_near_the_ends(f: RouletteFn) -> Option<String> {
    let shares = values_and_small_q(&mut Draws::new(262), 6, (-7.0, -4.0));
    shares.into_iter().find_map(|(v, q): (f64, f64)| {
        let m = 20_000;
        let step = 2.0 * q / m as f64;
        let survivors = |from: f64| {
            (0..m)
                .filter(|&i| f(v, q, from + (i as f64 + 0.5) * step) != 0.0)
                .count()
        };
        let share = (survivors(0.0) + survivors(1.0 - 2.0 * q)) as f64 * step;
        ((share - q).abs() > 2e-3 * q + 2.0 * step).then(|| {
            format!(
                "value {v}, q {q:e}: the survivors within 2q of 0 and of 1 make up {share:e} \
                 of [0, 1), not q (within 0.2 %)"
            )
        })
    })
}
