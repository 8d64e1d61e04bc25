//! Chapter 6's mutants: plausible wrong path loops that the capstone's
//! check must fail, each naming its symptom, and correct alternatives
//! that must pass; and the common mistakes of the smaller exercises.

use std::f32::consts::FRAC_1_PI;

use glam::{Vec2, Vec3};
use raystep::grading::exercise::{Check, Symptom};
use raystep::grading::exercises::ch6;
use raystep::grading::exercises::paths::{self, check_path_radiance, PathScene};

/// What a mutant of the path loop gets wrong (`None`: nothing).
#[derive(Clone, Copy, PartialEq)]
enum Bug {
    None,
    /// Loops until a bounce escapes: never ends in a closed room.
    NoRoulette,
    /// Roulette, but the survivor is not divided by q.
    NoCompensation,
    /// A fixed depth of 8 bounces and no roulette.
    FixedDepth,
    /// Roulette and also a hard cap of 12 bounces.
    RouletteAndCap,
    /// The emission of the first surface is left out.
    NoFirstEmission,
    /// Emission added at every surface as well as the light samples.
    EmissionTwice,
    /// β *= f cos θ (the cosine pdf never divided).
    NoPdf,
    /// β *= f / pdf (the cos θ left out).
    NoCos,
    /// The next ray leaves along −wi.
    Backwards,
    /// No shadow ray for the light sample.
    NoShadowRay,
    /// Casts the shadow ray but ignores its answer (light leaks through
    /// the Cornell box's boxes; the furnace has nothing to block).
    ShadowIgnored,
    /// The shadow ray stopped at 99 % of the light's distance (an
    /// occluder close to the light is missed).
    ShadowShort,
    /// The light sample at each surface after the first drawn from the
    /// two numbers of the bounce that reached it.
    LightFromBounceNumbers,
    /// The light sample without its cos θ at the hit.
    LightWithoutCos,
    /// No light sample at all (and no emission on bounces: only Le).
    NoLightSample,
    /// The right loop, but 2% too bright (a stray factor 1.02).
    TwoPercentBright,
    /// The right loop, but 2% too dark.
    TwoPercentDark,
}

/// The loop as the book teaches it, with one bug switched in. Roulette
/// after the first bounce, q = min(0.95, max β).
fn path(
    scene: &PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
    bug: Bug,
) -> Vec3 {
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    let mut l = if bug == Bug::NoFirstEmission {
        Vec3::ZERO
    } else {
        hit.emitted
    };
    let mut beta = Vec3::ONE;
    let mut depth = 0;
    let mut bounce_numbers = None;
    loop {
        let f = hit.albedo * FRAC_1_PI;
        if bug != Bug::NoLightSample {
            let u = match (bug, bounce_numbers) {
                (Bug::LightFromBounceNumbers, Some(u)) => u,
                _ => Vec2::new(rng(), rng()),
            };
            if let Some(ls) = scene.sample_light(&hit, u) {
                let cos = hit.n.dot(ls.wi);
                let visible = match bug {
                    Bug::NoShadowRay => true,
                    Bug::ShadowIgnored => {
                        let _asked = scene.unoccluded(&hit, ls.wi, ls.dist);
                        true
                    }
                    Bug::ShadowShort => scene.unoccluded(&hit, ls.wi, 0.99 * ls.dist),
                    _ => scene.unoccluded(&hit, ls.wi, ls.dist),
                };
                if cos > 0.0 && visible {
                    let c = if bug == Bug::LightWithoutCos {
                        1.0
                    } else {
                        cos
                    };
                    l += beta * f * ls.li * c / ls.pdf;
                }
            }
        }
        let u = Vec2::new(rng(), rng());
        bounce_numbers = Some(u);
        let (wi, pdf) = scene.sample_cosine(&hit, u);
        if pdf <= 0.0 {
            break;
        }
        let cos = hit.n.dot(wi);
        beta *= match bug {
            Bug::NoPdf => f * cos,
            Bug::NoCos => f / pdf,
            _ => f * cos / pdf,
        };
        depth += 1;
        match bug {
            Bug::NoRoulette => {}
            Bug::FixedDepth if depth >= 8 => break,
            Bug::FixedDepth => {}
            _ => {
                if bug == Bug::RouletteAndCap && depth >= 12 {
                    break;
                }
                let q = beta.max_element().min(0.95);
                if rng() >= q {
                    break;
                }
                if bug != Bug::NoCompensation {
                    beta /= q;
                }
            }
        }
        let w = if bug == Bug::Backwards { -wi } else { wi };
        let Some(next) = scene.next_hit(&hit, w) else {
            break;
        };
        hit = next;
        if bug == Bug::EmissionTwice {
            l += beta * hit.emitted;
        }
    }
    match bug {
        Bug::TwoPercentBright => l * 1.02,
        Bug::TwoPercentDark => l * 0.98,
        _ => l,
    }
}

macro_rules! mutant {
    ($bug:expr) => {
        check_path_radiance(|s, o, d, r| path(s, o, d, r, $bug))
    };
}

fn fails_with(check: Check, symptom: Symptom) {
    super::fails_naming(check, symptom, &ch6::exercises(), "");
}

#[test]
fn the_book_loop_passes() {
    let check = mutant!(Bug::None);
    assert!(check.passed(), "{}", check.detail);
    assert!(check.images.is_some());
}

#[test]
fn a_loop_without_roulette_never_ends_and_is_named() {
    fails_with(mutant!(Bug::NoRoulette), paths::NO_ROULETTE);
}

#[test]
fn roulette_without_dividing_by_q_is_too_dark() {
    fails_with(mutant!(Bug::NoCompensation), paths::TOO_DARK);
}

#[test]
fn a_fixed_depth_is_a_bias_in_a_closed_room() {
    let check = mutant!(Bug::FixedDepth);
    fails_with(check.clone(), paths::DEPTH_CAP);
    assert!(
        check.detail.contains("at exactly 7 bounces"),
        "{}",
        check.detail
    );
    fails_with(mutant!(Bug::RouletteAndCap), paths::DEPTH_CAP);
}

#[test]
fn missing_or_doubled_emission_is_named() {
    fails_with(mutant!(Bug::NoFirstEmission), paths::NO_FIRST_EMISSION);
    fails_with(mutant!(Bug::EmissionTwice), paths::DOUBLE_EMISSION);
}

#[test]
fn a_missing_pdf_or_cosine_is_a_constant_factor() {
    fails_with(mutant!(Bug::NoPdf), paths::TOO_DARK);
    fails_with(mutant!(Bug::NoCos), paths::TOO_BRIGHT);
    fails_with(mutant!(Bug::LightWithoutCos), paths::LIGHT_SAMPLE_WRONG);
}

#[test]
fn bouncing_below_the_surface_is_named() {
    fails_with(mutant!(Bug::Backwards), paths::BELOW_SURFACE);
}

#[test]
fn light_samples_need_their_shadow_rays_and_surfaces_their_light_samples() {
    fails_with(mutant!(Bug::NoShadowRay), paths::NO_SHADOW_RAY);
    fails_with(mutant!(Bug::NoLightSample), paths::NO_NEE);
}

#[test]
fn light_through_an_occluder_fails_even_when_it_is_close_to_the_light() {
    // A lamp in a closed box: a shadow ray whose answer is ignored, or
    // that stops 1 % short of the lamp, lets its light out.
    fails_with(mutant!(Bug::ShadowIgnored), paths::LIGHT_THROUGH_OCCLUDER);
    fails_with(mutant!(Bug::ShadowShort), paths::LIGHT_THROUGH_OCCLUDER);
}

#[test]
fn a_light_sample_from_the_numbers_of_the_bounce_before_it_fails() {
    fails_with(
        mutant!(Bug::LightFromBounceNumbers),
        paths::LIGHT_FROM_BOUNCE_NUMBERS,
    );
}

#[test]
fn a_two_percent_bias_fails() {
    // The furnace's standard error is about 0.2% of the mean: ±2% is a z
    // of about 10.
    for check in [mutant!(Bug::TwoPercentBright), mutant!(Bug::TwoPercentDark)] {
        eprintln!("{}", check.detail);
        assert!(!check.passed() && check.error > 7.0, "{}", check.detail);
    }
}

/// A correct alternative: the same estimator written recursively, with
/// roulette from the first bounce at q = min(0.9, max β), the light sample
/// taken after the bounce direction, and its own order of random numbers.
fn recursive(scene: &PathScene, origin: Vec3, dir: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    fn from(scene: &PathScene, hit: &paths::Hit, rng: &mut dyn FnMut() -> f32) -> Vec3 {
        let f = hit.albedo / std::f32::consts::PI;
        let (wi, pdf) = scene.sample_cosine(hit, Vec2::new(rng(), rng()));
        let mut l = Vec3::ZERO;
        if let Some(ls) = scene.sample_light(hit, Vec2::new(rng(), rng())) {
            let cos = ls.wi.dot(hit.n).max(0.0);
            if cos > 0.0 && scene.unoccluded(hit, ls.wi, ls.dist) {
                l += f * ls.li * (cos / ls.pdf);
            }
        }
        if pdf <= 0.0 {
            return l;
        }
        let beta = f * (wi.dot(hit.n) / pdf);
        let q = beta.max_element().min(0.9);
        if rng() < q {
            if let Some(next) = scene.next_hit(hit, wi) {
                l += beta / q * from(scene, &next, rng);
            }
        }
        l
    }
    match scene.first_hit(origin, dir) {
        Some(hit) => hit.emitted + from(scene, &hit, rng),
        None => Vec3::ZERO,
    }
}

/// A correct alternative: roulette at every surface but the first,
/// before its light sample (a survivor of probability q carries 1/q of
/// everything after), q the mean of β's channels (at most 1), in f64.
fn roulette_first(
    scene: &PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    let mut l = hit.emitted.as_dvec3();
    let mut beta = glam::DVec3::ONE;
    let mut first = true;
    loop {
        if !first {
            let q = (beta.element_sum() / 3.0).min(1.0);
            if (rng() as f64) >= q {
                break;
            }
            beta /= q;
        }
        first = false;
        let f = hit.albedo.as_dvec3() / std::f64::consts::PI;
        if let Some(ls) = scene.sample_light(&hit, Vec2::new(rng(), rng())) {
            let cos = hit.n.dot(ls.wi) as f64;
            if cos > 0.0 && scene.unoccluded(&hit, ls.wi, ls.dist) {
                l += beta * f * ls.li.as_dvec3() * cos / ls.pdf as f64;
            }
        }
        let (wi, pdf) = scene.sample_cosine(&hit, Vec2::new(rng(), rng()));
        if pdf <= 0.0 {
            break;
        }
        beta *= f * hit.n.dot(wi) as f64 / pdf as f64;
        match scene.next_hit(&hit, wi) {
            Some(next) => hit = next,
            None => break,
        }
    }
    l.as_vec3()
}

#[test]
fn correct_alternatives_pass() {
    let check = check_path_radiance(recursive);
    assert!(check.passed(), "recursive: {}", check.detail);
    let check = check_path_radiance(roulette_first);
    assert!(check.passed(), "roulette first: {}", check.detail);
}

#[test]
fn the_check_names_every_symptom_it_can_return() {
    let ex = ch6::exercises();
    let capstone = ex.iter().find(|e| e.name == "path_radiance").unwrap();
    for s in paths::SYMPTOMS {
        assert!(capstone.symptoms.contains(&s), "{}", s.name);
    }
}

// The smaller exercises' common mistakes.

#[test]
fn an_integral_without_the_interval_is_named() {
    let check = ch6::check_mc_integral(|f, a, b, u| {
        u.iter().map(|u| f(a + u * (b - a))).sum::<f64>() / u.len() as f64
    });
    fails_with(check, ch6::NO_INTERVAL);
}

#[test]
fn roulette_mistakes_are_named() {
    fails_with(
        ch6::check_russian_roulette(|v, q, u| if u < q { v } else { 0.0 }),
        ch6::ROULETTE_BIASED,
    );
    // Survives when u > q: the wrong fraction ends.
    fails_with(
        ch6::check_russian_roulette(|v, q, u| if u > q { v / q } else { 0.0 }),
        ch6::ROULETTE_WRONG_FRACTION,
    );
}

#[test]
fn mis_weight_mistakes_are_named() {
    fails_with(
        ch6::check_mis_weight(|f, g| if f + g > 0.0 { f / (f + g) } else { 0.0 }),
        ch6::BALANCE_HEURISTIC,
    );
    fails_with(
        ch6::check_mis_weight(|f, g| f * f / (f * f + g * g)),
        ch6::WEIGHT_NOT_FINITE,
    );
}
