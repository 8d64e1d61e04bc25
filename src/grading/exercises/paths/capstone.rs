//! The path capstone's check: the run's closed furnace, the furnace's
//! variants, the Cornell box, and last the brighter furnace (see
//! [`check`](super::check) for each clause).

use super::bright::{bright_furnace, dim_furnace, faint_light_furnace};
use super::check::{
    furnace_of_run, judge_furnace_of, trace_furnace, CORNELL_DIFFERS, FURNACE_PATHS,
};
use super::cornell::cornell;
use super::open;
use super::{PathFn, PathScene};
use crate::exercise::Check;

/// The capstone: the closed furnace, then the Cornell box (see the
/// module's doc). The error is the larger z of the two (5 passes).
pub fn check_path_radiance(f: PathFn) -> Check {
    let (albedo, le) = furnace_of_run();
    let scene = PathScene::furnace(albedo, le);
    let furnace = trace_furnace(f, &scene, FURNACE_PATHS, 611 ^ crate::run_seed());
    let (fz, fdetail, fsymptom) = judge_furnace_of(f, &furnace, FURNACE_PATHS, (albedo, le));
    if fz <= 5.0 {
        if let Some((detail, symptom)) = open::contract_failure(f) {
            return Check {
                error: 1e3,
                tolerance: 5.0,
                detail: format!("{fdetail}; but in {detail}"),
                images: None,
                symptom: Some(symptom),
            };
        }
    }
    let box_check = cornell(f);
    // Only once the rest passes (so that a failure keeps the name it had):
    // the brighter furnace, then a dim one, then one with a faint light.
    if fz <= 5.0 && box_check.passed() {
        let furnaces = bright_furnace(f)
            .or_else(|| dim_furnace(f))
            .or_else(|| faint_light_furnace(f));
        if let Some((error, detail, symptom)) = furnaces {
            return Check {
                error,
                tolerance: 5.0,
                detail: format!("{fdetail}; but {detail}"),
                images: box_check.images,
                symptom,
            };
        }
    }
    let error = crate::exercises::worse(fz, box_check.error);
    let (detail, symptom) = if fz > 5.0 {
        (fdetail, fsymptom)
    } else if !box_check.passed() {
        (
            format!("{fdetail}; but in the Cornell box, {}", box_check.detail),
            Some(CORNELL_DIFFERS),
        )
    } else {
        (
            format!("{fdetail}; Cornell box: {}", box_check.detail),
            None,
        )
    };
    Check {
        error,
        tolerance: 5.0,
        detail,
        images: box_check.images,
        symptom,
    }
}
