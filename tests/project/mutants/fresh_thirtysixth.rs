//! The thirty-sixth fresh set (2026-12-01), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: the order of the inputs (Y, 51 wrong), single-token
//! edits of the course's solutions (Z, 71), and two special cases at
//! once (A, 51); 83 right alternatives, all of which pass. With the
//! grader of a394a06, 4 of the 173 wrong ones passed under seeds 51 to
//! 53. The one here now fails under seeds 51 to 55. The other three are
//! right: two Fresnel terms with the indices in a fixed order (swapping
//! η_i and η_t swaps r_s and r_p, whose mean is the same), and a disk
//! lifted without max(0), right in f32 (x² + y² never rounds past 1 for
//! u in [0, 1), as the thirty-second set's note checked).

use glam::Vec3;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch5;

use super::fails_every;

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1204];

/// Same side when the two z agree on "above", with ωo off the plane:
/// right but where ωo is below and ωi lies exactly in the plane, which
/// gets ρ/π.
fn lambert_above_equals_above(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    let same_side = (wo.z > 0.0) == (wi.z > 0.0);
    match same_side && wo.z != 0.0 {
        true => rho / std::f32::consts::PI,
        false => Vec3::ZERO,
    }
}

#[test]
fn a_brdf_that_lights_the_plane_from_below_fails() {
    let check = || -> Check { ch5::check_lambert_brdf(lambert_above_equals_above) };
    fails_every(
        &SEEDS,
        "lambert_brdf: ωi in the plane seen from below",
        None,
        check,
    );
}
