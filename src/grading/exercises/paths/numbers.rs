//! What the capstone's paths do with their random numbers, from the
//! scene's tally ([`Tally`]): the numbers a light sample or a bounce is
//! drawn from must be uniform, and whether a path goes on must not depend
//! on the numbers its direction came from.

use super::Tally;

/// Which quarter of [0, 1) `v` falls in (below 0 or NaN: the first; 1 or
/// more: the last).
pub(super) fn quarter(v: f32) -> usize {
    ((v * 4.0) as usize).min(3)
}

/// How many numbers `cells` counted, and their χ² against the same count
/// in every cell.
fn against_even(cells: &[u32]) -> (u32, f64) {
    let all: u32 = cells.iter().sum();
    let e = f64::from(all) / cells.len() as f64;
    (
        all,
        cells.iter().map(|&o| (f64::from(o) - e).powi(2) / e).sum(),
    )
}

/// The numbers a bounce is drawn from must be uniform on [0, 1)²
/// (sample_cosine's density assumes it): each quarter of u.x's and of
/// u.y's range (`quarters`) gets a quarter of them (χ² with 3 degrees of
/// freedom under 30: a false alarm about once in a million runs). What
/// differs, if it does.
pub(super) fn bounce_numbers_not_uniform(quarters: &[[u32; 4]; 2]) -> Option<String> {
    ["u.x", "u.y"].iter().zip(quarters).find_map(|(axis, q)| {
        let (all, chi2) = against_even(q);
        (all >= 1000 && chi2 > 30.0).then(|| {
            format!(
                "closed furnace: the numbers your bounces gave sample_cosine are not uniform on \
                 [0, 1): their {axis} fell {q:?} in the four quarters of [0, 1) (χ² = {chi2:.0}); \
                 each bounce needs fresh uniform numbers (a number already used for a decision, \
                 such as roulette's, is not uniform any more)"
            )
        })
    })
}

/// The numbers a light sample is drawn from must be uniform on [0, 1)²,
/// each independent of the other (the light's density assumes it; in the
/// furnace every light sample brings the same light wherever it lands, so
/// the mean cannot tell): each cell of a 4 × 4 grid gets a sixteenth of
/// them (χ² with 15 degrees of freedom under 70: a false alarm about once
/// in two hundred million runs). What differs, if it does.
pub(super) fn light_numbers_not_uniform(cells: &[u32; 16]) -> Option<String> {
    let (all, chi2) = against_even(cells);
    (all >= 1000 && chi2 > 70.0).then(|| {
        let rows: Vec<[u32; 4]> = cells.chunks(4).map(|r| [r[0], r[1], r[2], r[3]]).collect();
        format!(
            "closed furnace: the numbers your paths gave sample_light are not uniform on [0, 1)²: \
             by quarter of u.x (rows) and of u.y (columns) they fell {rows:?} (χ² = {chi2:.0}); \
             each light sample needs two fresh uniform numbers, independent of each other"
        )
    })
}

/// Whether a path goes on after a bounce must not depend on the numbers
/// its direction came from (roulette decided by one of them keeps only
/// the directions near the normal, say): the share that went on is the
/// same in each quarter of u.x's and of u.y's range (χ² of the 2 × 4
/// table, 3 degrees of freedom, under 30). What differs, if it does.
pub(super) fn went_on_by_numbers(t: &Tally) -> Option<String> {
    for (axis, (all, on)) in ["u.x", "u.y"]
        .iter()
        .zip(t.cosine_quarters.iter().zip(t.cosine_went_on))
    {
        let (n_all, n_on) = (all.iter().sum::<u32>(), on.iter().sum::<u32>());
        let share = f64::from(n_on) / f64::from(n_all.max(1));
        let chi2: f64 = all
            .iter()
            .zip(on)
            .filter(|(a, _)| **a > 0)
            .map(|(&a, o)| {
                let (e_on, e_off) = (f64::from(a) * share, f64::from(a) * (1.0 - share));
                let d = f64::from(o) - e_on;
                d * d / e_on.max(1e-9) + d * d / e_off.max(1e-9)
            })
            .sum();
        if n_all >= 1000 && n_on < n_all && chi2 > 30.0 {
            let went: Vec<String> = all
                .iter()
                .zip(on)
                .map(|(&a, o)| format!("{:.0}%", 100.0 * f64::from(o) / f64::from(a.max(1))))
                .collect();
            let detail = format!(
                "closed furnace: whether a path went on after a bounce depends on the numbers \
                 its direction was drawn from: with {axis} in each quarter of [0, 1), {} of the \
                 paths went on (χ² = {chi2:.0}); roulette needs a number of its own (one that \
                 also chose the direction keeps only some directions: biased)",
                went.join(", ")
            );
            return Some(detail);
        }
    }
    None
}
