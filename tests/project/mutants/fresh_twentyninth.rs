//! The twenty-ninth fresh set (2026-11-30), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: library semantics (D, 42 wrong: `signum(0.0)`,
//! `f32::EPSILON` as an absolute tolerance, `total_cmp`, `round`'s ties),
//! formulas transcribed from the lecture's slides (E, 55), and the
//! components of vectors and channels of colours (F, 44); 61 right
//! alternatives, all of which pass. With the grader of 0580a58, 5 of the
//! 141 wrong ones passed under seeds 51 and 52, and all five are here:
//! cosines below `f32::EPSILON` taken for 0 by the point light and by
//! direct light (the drawn exact cosines went down to 10⁻⁵ only), a box's
//! area with its terms from the wrong axes (right, up to a factor, on the
//! scenes flat in z the grader drew, and on cubes), sphere tracing that
//! gives up where p − o's largest coordinate passes max_distance (no ray
//! met a surface between max_distance and √3 times it), and a normal of
//! -dir where the gradient's largest component is 0 (no wall faced -x).

use glam::Vec3;

use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch5::{reference_direct, reference_point};
use raystep::grading::exercises::{ch3, ch4, ch5};

use super::fails_every;
use super::knobs::{self, MarchKnobs, Measure, SahKnobs, SceneKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn a_point_light_cut_off_below_epsilon_fails() {
    fails(
        "point_light: nothing where cos θ is below f32::EPSILON",
        || {
            ch5::check_point_light(|i, light, p, n| {
                match n.dot((light - p).normalize()) < f32::EPSILON {
                    true => Vec3::ZERO,
                    false => reference_point(i, light, p, n),
                }
            })
        },
    );
}

#[test]
fn direct_light_cut_off_below_epsilon_fails() {
    fails(
        "direct_light: nothing where cos θ or cos θl is below f32::EPSILON",
        || {
            ch5::check_direct_light(|p, n, rho, y, n_light, area, le, visible| {
                let wi = (y - p).normalize();
                match n.dot(wi) < f32::EPSILON || -n_light.dot(wi) < f32::EPSILON {
                    true => Vec3::ZERO,
                    false => reference_direct(p, n, rho, y, n_light, area, le, visible),
                }
            })
        },
    );
}

#[test]
fn an_area_from_the_wrong_axes_fails() {
    fails("sah: the surface area as 2 d · (dy, dx, dz)", || {
        ch3::check_sah(|b, c| {
            let k = SahKnobs {
                measure: Measure::Swizzled,
                ..Default::default()
            };
            knobs::sah_sweep(k, b, c)
        })
    });
}

#[test]
fn a_limit_on_the_largest_coordinate_fails() {
    fails(
        "sphere_trace: gives up where p − o's largest |coordinate| passes max_distance",
        || {
            ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
                let k = MarchKnobs {
                    travel_by_largest: true,
                    ..Default::default()
                };
                knobs::sphere_trace(k, sdf, (o, d), eps, steps, max)
            })
        },
    );
}

#[test]
fn a_zero_gradient_by_its_largest_component_fails() {
    fails(
        "trace_scene: -dir where the gradient's largest component is 0",
        || {
            ch4::check_trace_scene(|sdf, o, d, m| {
                let k = SceneKnobs {
                    zero_by_max_element: true,
                    ..Default::default()
                };
                knobs::trace_scene(k, sdf, o, d, m)
            })
        },
    );
}
