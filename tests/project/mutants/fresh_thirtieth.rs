//! The thirtieth fresh set (2026-11-30), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: copy-paste slips in code repeated for three axes,
//! channels or corners (G, 49 wrong), the hints followed to the letter
//! with a qualifier missed (H, 57), and Rust idioms with a catch: `zip`,
//! inclusive ranges, `min_by` on ties, `fold` from `f32::MAX` (I, 56); 77
//! right alternatives, all of which pass. With the grader of 7817fe5, 5
//! of the 162 wrong ones passed under seeds 51 and 52. The one here now
//! fails under seeds 51 to 53: a sphere trace whose budget's last
//! evaluation is tested for the distance before the hit (a loop that
//! tests its last evaluation after it), so that a last step landing on a
//! surface beyond max_distance is a miss. Of the other four, three are
//! right as earlier sets rule (roulette decided in f32, a disk lifted
//! without max(0), Fresnel's indices unswapped, which leaves F as it is),
//! and one is within the contract's rounding: a sphere's distance as
//! (d² − r²)/(d + r), whose rounding, about f32's ε times d, is that of
//! |p − c| itself, far inside the 10⁻⁵ of the radius and the distance.

use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch4;

use super::fails_every;
use super::knobs::{self, MarchKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn the_last_evaluation_tested_for_distance_first_fails() {
    fails(
        "sphere_trace: the budget's last evaluation tested for the distance before the hit",
        || {
            ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
                let k = MarchKnobs {
                    last_distance_first: true,
                    ..Default::default()
                };
                knobs::sphere_trace(k, sdf, (o, d), eps, steps, max)
            })
        },
    );
}
