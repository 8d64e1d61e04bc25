//! The twenty-second fresh set (2026-11-30), with the two wrong ones the
//! twenty-first left passing: a box's area taken as the square of its
//! extents' sum less their squares (0 for a needle), and direct_light's
//! geometry term from unnormalised vectors over d⁴ (which leaves f32's
//! range at scales of 10¹⁰ and 10⁻¹⁰).

use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch3, ch5};

use super::fails_every;
use super::knobs::{self, DirectKnobs, Knobs, Measure, SahKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [221, 222, 227, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn gaps_of_the_twenty_first_set_fail() {
    fails("sah's area as (dx + dy + dz)² − Σ d²", || {
        ch3::check_sah(|boxes, centroids| {
            let k = SahKnobs::with(|k| k.measure = Measure::SquareIdentity);
            knobs::sah_sweep(k, boxes, centroids)
        })
    });
    fails("direct_light's unnormalised cosines over d⁴", || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
            let k = DirectKnobs::with(|k| k.over_d4 = true);
            knobs::direct(k, (p, n, rho), (y, nl, a, le), v)
        })
    });
}
