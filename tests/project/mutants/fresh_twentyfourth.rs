//! The twenty-fourth fresh set (2026-11-30), four testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: boundaries, ties and off-by-one (M, 66 wrong), the
//! contract read another way (N, 70), shortcuts for speed (O, 68), and
//! sampling and statistics (P, 59); 97 right alternatives, all of which
//! pass. With the grader as it stood before (5ebc727), 7 of the 263
//! wrong ones passed under seed 51 or 52; the three mistakes that now
//! fail under seeds 51 to 53 are here (a march that gives up at exactly
//! max_distance came twice). The other four passes are survival decided
//! by u ≥ 1 − q, which the earlier sets count as right.

use glam::{Vec2, Vec3};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch3, ch4, ch5};

use super::fails_every;
use super::knobs::{self, InsideKnobs, Knobs, MarchKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [241, 242, 247, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn boundaries_and_shortcuts_fail() {
    fails(
        "sphere_trace: gives up at t = max_distance, not only beyond it",
        || {
            ch4::check_sphere_trace(|sdf, o, d, eps, steps, far| {
                let k = MarchKnobs::with(|k| k.stop_at_max = true);
                knobs::sphere_trace(k, sdf, (o, d), eps, steps, far)
            })
        },
    );
    fails(
        "barycentric_inside: u, v down to -1e-5 and u + v up to 1 + 1e-5 taken as inside",
        || {
            ch3::check_barycentric_inside(|p, tri| {
                knobs::inside(InsideKnobs::with(|k| k.slack = 1e-5), p, tri)
            })
        },
    );
    fails(
        "cosine_hemisphere: the first 10⁻³ of u.x sent straight up",
        || {
            ch5::check_cosine_hemisphere(|u: Vec2| {
                if u.x < 1e-3 {
                    return (Vec3::Z, std::f32::consts::FRAC_1_PI);
                }
                let r = u.x.sqrt();
                let phi = std::f32::consts::TAU * u.y;
                let z = (1.0 - u.x).sqrt();
                (
                    Vec3::new(r * phi.cos(), r * phi.sin(), z),
                    z * std::f32::consts::FRAC_1_PI,
                )
            })
        },
    );
}
