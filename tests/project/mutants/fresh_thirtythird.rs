//! The thirty-third fresh set (2026-12-01), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: branches, roots and ranges of inverse functions (P, 41
//! wrong), snapping and rounding for robustness (Q, 68), and code written
//! from the book's prose and figures rather than its listings (R, 68); 61
//! right alternatives, all of which pass. With the grader of 5315600, 2
//! of the 177 wrong ones passed under seeds 51 and 52. The one here now
//! fails under seeds 51 to 53: trace_scene's normal taken as -dir where
//! the gradient is shorter than 10⁻³, not only where it is zero. The
//! other snaps cos θ above 0.9999 to 1 in refraction, which moves t by
//! at most 1.1·10⁻⁵ (from inside an index of 2.5; t is normalised after
//! the snap) and F by less: within the contract's 10⁻⁴.

use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch4;

use super::fails_every;
use super::knobs::{self, SceneKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1201];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// The solution of trace_scene, with -dir where the gradient is shorter
/// than `below`.
macro_rules! gives_up_below {
    ($below:expr) => {
        fails(
            concat!(
                "trace_scene: -dir where the gradient is shorter than ",
                stringify!($below)
            ),
            || {
                ch4::check_trace_scene(|sdf, o, d, m| {
                    let k = SceneKnobs {
                        fallback_below: Some($below),
                        ..Default::default()
                    };
                    knobs::trace_scene(k, sdf, o, d, m)
                })
            },
        )
    };
}

#[test]
fn a_normal_that_gives_up_on_a_short_gradient_fails() {
    gives_up_below!(1e-3);
    gives_up_below!(1e-7);
    gives_up_below!(1e-12);
}
