//! The thirty-first fresh set (2026-11-30), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: habits from GLSL and HLSL shaders (J, 51 wrong),
//! arguments at the ends of their types and ranges (K, 58), and
//! degenerate inputs the contract still answers (L, 49); 74 right
//! alternatives, all of which pass. With the grader of bda3c61, 9 of the
//! 158 wrong ones passed under seeds 51 and 52. The seven here now fail
//! under seeds 51 to 53: direct light divided by a density taken as 0 for
//! a light seen edge-on (infinity, where the answer is 0), direct light's
//! Le · A formed first (past f32's largest for a bright light in a vast
//! scene, where the answer is not), a point light's I / r² formed first
//! (infinity for an intensity near f32's largest, where E is far below
//! it), and three path loops: what one light sample brings clamped at 16,
//! roulette that survives at u = q (at q = 0 too, dividing by 0 when
//! rng() gives 0), and a bounce whose density is 0 divided by (a cosine
//! sample from a 0 in the tangent plane). Of the other two, one answers
//! an empty slice of numbers with NaN (the contract's estimate is from
//! the numbers given: none is outside it), and one forms a sphere's
//! distance as (d² − r²)/(d + r), whose squares leave f32's range only
//! where the course's own |p − c| squares out of it too (radii below
//! 10⁻¹⁹ or above 10¹⁹).

use glam::Vec3;

use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch5::{self, reference_direct, reference_point};
use raystep::grading::exercises::paths::check_path_radiance;

use super::fails_every;
use super::knobs::{self, PathKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// The squared distance from p to y and the cosines at both ends, as the
/// course's solution forms them.
fn geometry(p: Vec3, n: Vec3, y: Vec3, n_light: Vec3) -> (f32, f32, f32) {
    let to = y - p;
    let d2 = to.length_squared();
    let wi = to / d2.sqrt();
    (d2, n.dot(wi), -n_light.dot(wi))
}

#[test]
fn an_edge_on_light_divided_by_zero_fails() {
    fails(
        "direct_light: the density per steradian taken as 0 for an edge-on light, and divided by",
        || {
            ch5::check_direct_light(|p, n, rho, y, n_light, area, le, visible| {
                let (_, cos, cos_light) = geometry(p, n, y, n_light);
                match cos_light == 0.0 && cos > 0.0 && visible(p, y) {
                    true => rho / std::f32::consts::PI * le * cos / 0.0,
                    false => reference_direct(p, n, rho, y, n_light, area, le, visible),
                }
            })
        },
    );
}

#[test]
fn the_product_before_the_division_fails() {
    fails(
        "direct_light: f · Le · (cos θ cos θl A) / d², Le · A first",
        || {
            ch5::check_direct_light(|p, n, rho, y, n_light, area, le, visible| {
                let (d2, cos, cos_light) = geometry(p, n, y, n_light);
                match cos > 0.0 && cos_light > 0.0 && visible(p, y) {
                    true => rho / std::f32::consts::PI * le * area * (cos * cos_light) / d2,
                    false => reference_direct(p, n, rho, y, n_light, area, le, visible),
                }
            })
        },
    );
}

#[test]
fn i_over_r_squared_first_fails() {
    fails("point_light: (I / r²) · cos θ", || {
        ch5::check_point_light(|i, light, p, n| {
            let to = light - p;
            let r2 = to.length_squared();
            match reference_point(i, light, p, n) == Vec3::ZERO {
                true => Vec3::ZERO,
                false => i / r2 * n.dot(to / r2.sqrt()),
            }
        })
    });
}

#[test]
fn a_light_sample_clamped_at_16_fails() {
    fails(
        "path_radiance: what one light sample brings clamped at 16 per channel",
        || {
            check_path_radiance(|s, o, d, rng| {
                let k = PathKnobs {
                    light_clamp: Some(16.0),
                    ..Default::default()
                };
                knobs::path(k, s, o, d, rng)
            })
        },
    );
}

#[test]
fn roulette_that_survives_at_q_fails() {
    fails(
        "path_radiance: roulette ends the path only where u > q",
        || {
            check_path_radiance(|s, o, d, rng| {
                let k = PathKnobs {
                    survive_at_q: true,
                    ..Default::default()
                };
                knobs::path(k, s, o, d, rng)
            })
        },
    );
}

#[test]
fn a_bounce_of_density_0_fails() {
    fails("path_radiance: a bounce of density 0 divided by", || {
        check_path_radiance(|s, o, d, rng| {
            let k = PathKnobs {
                no_pdf_guard: true,
                ..Default::default()
            };
            knobs::path(k, s, o, d, rng)
        })
    });
}
