//! Every chapter that exists, in lecture order. Front ends (the main binary,
//! the terminal UI) list chapters from here and nowhere else.

use crate::core::stage::Chapter;

/// All chapters, in order: each chapter's `stage::DEFAULT`, chapter 6
/// with the fast engine.
pub fn all() -> Vec<&'static dyn Chapter> {
    vec![
        &crate::ch1_projection::stage::DEFAULT,
        &crate::ch2_rasterization::stage::DEFAULT,
        &crate::ch3_ray_triangle::stage::DEFAULT,
        &crate::ch4_implicit_surfaces::stage::DEFAULT,
        &crate::ch5_reflection::stage::DEFAULT,
        &FAST_CH6,
    ]
}

/// [`all`], with chapter 6 traced by the lesson's readable engine when
/// `readable` (`--engine readable`; the images agree to the last bits of
/// a sine, see [the fast engine](crate)).
pub fn with_engine(readable: bool) -> Vec<&'static dyn Chapter> {
    let mut chapters = all();
    if readable {
        chapters[5] = &crate::ch6_global_illumination::stage::DEFAULT;
    }
    chapters
}

/// Chapter 6's defaults traced by the fast engine: the one place the front
/// ends' engine is chosen (the chapter's own default is the lesson's).
const FAST_CH6: crate::ch6_global_illumination::stage::GlobalIllumination =
    crate::ch6_global_illumination::stage::GlobalIllumination {
        engine: crate::FAST,
        ..crate::ch6_global_illumination::stage::DEFAULT
    };

/// The sampling routines the warp view tests (chapter 5's).
pub fn warp_routines() -> &'static [crate::core::warp_test::WarpRoutine] {
    &crate::ch5_reflection::warp_test::ROUTINES
}

/// The student's sampling routine the warp view can test (exercise 5.2).
pub fn student_warp() -> crate::core::warp_test::StudentWarp {
    crate::ch5_reflection::warp_test::STUDENT
}
