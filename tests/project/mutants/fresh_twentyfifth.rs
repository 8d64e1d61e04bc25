//! The twenty-fifth fresh set (2026-11-30), four testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: symmetry that hides a mistake (Q, 79 wrong), large
//! counts and long runs (R, 55), signs, sides and orientation (S, 56),
//! and the rarely taken branch (T, 85); 98 right alternatives, all of
//! which pass. With the grader as it stood before (130cbf5), 8 of the 275
//! wrong ones passed under seed 51 or 52. The two that now fail under
//! seeds 51 to 55 are here. Of the other six, five decide survival by
//! u ≥ 1 − q, which the earlier sets count as right, and one is right in
//! f32 after all: cosine_hemisphere's sqrt(1 − x² − y²) without a floor
//! at 0, since √u.x stays below 1 for every u.x below 1 and x² + y² then
//! never rounds past 1 (none of 800,000 tries at the eight largest u.x).

use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch1, ch2};

use super::fails_every;
use super::knobs::{self, LookKnobs, RasterKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [52, 251, 257, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn a_short_up_a_long_row_and_a_long_column_fail() {
    fails(
        "look_at: x = X where |up × z| < 10⁻³, which a short up reaches at any angle",
        || {
            ch1::check_look_at(|e, t, u| {
                knobs::look_at(
                    LookKnobs {
                        side_floor: Some(1e-3),
                        ..Default::default()
                    },
                    e,
                    t,
                    u,
                )
            })
        },
    );
    fails(
        "rasterize_triangle: edge functions stepped along each row from its first sample",
        || {
            ch2::check_rasterize_triangle(|v, c, w, h, depth, image| {
                let k = RasterKnobs {
                    stepped: true,
                    ..Default::default()
                };
                knobs::rasterize(k, v, c, (w, h), depth, image)
            })
        },
    );
    // Written for the review of this set, before the check had columns:
    // it passed the long rows.
    fails(
        "rasterize_triangle: edge functions carried down from row to row",
        || {
            ch2::check_rasterize_triangle(|v, c, w, h, depth, image| {
                let k = RasterKnobs {
                    carried_down: true,
                    ..Default::default()
                };
                knobs::rasterize(k, v, c, (w, h), depth, image)
            })
        },
    );
}
