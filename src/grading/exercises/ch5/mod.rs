//! Chapter 5's exercises and how each is graded (the capstone's check is
//! in `direct.rs`, exercise 5.6's in `solid.rs`, 5.7's in `spot.rs`).

mod area_pdf;
mod direct;
mod drawn;
mod ends;
mod grid;
mod point;
mod references;
mod solid;
mod spot;
mod symptoms;
pub use area_pdf::check_area_pdf;
pub use direct::*;
pub use point::check_point_light;
pub use references::*;
pub use solid::check_solid_angle;
pub use spot::{check_spot, falloff_integral};
pub use symptoms::*;

use std::f32::consts::FRAC_1_PI;

use glam::{Vec2, Vec3};

use super::draws::{fold_drawn, worst_drawn, Draws};
use super::worst_of;
use crate::cases::{self, unit, v3, V3};
use crate::core::sampling::random;
use crate::exercise::{Check, Exercise, Symptom};
use crate::exercises::{stateless, AbsMax};

type BrdfFn = fn(Vec3, Vec3, Vec3) -> Vec3;
type CosineFn = fn(Vec2) -> (Vec3, f32);
pub(super) type AreaPdfFn = fn(f32, Vec3, Vec3, Vec3) -> f32;

/// Chapter 5's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 5,
            name: "lambert_brdf",
            file: "chapters/ch5-reflection/exercises/lambert_brdf.rs",
            symptoms: &[LAMBERT_PI, LAMBERT_ONE_SIDED],
            reference: || check_lambert_brdf(reference_lambert),
        },
        Exercise {
            chapter: 5,
            name: "cosine_hemisphere",
            file: "chapters/ch5-reflection/exercises/cosine_hemisphere.rs",
            symptoms: &[NOT_ON_HEMISPHERE, COSINE_PDF, NOT_COSINE, COSINE_GAP],
            reference: || check_cosine_hemisphere(reference_cosine),
        },
        Exercise {
            chapter: 5,
            name: "point_light",
            file: "chapters/ch5-reflection/exercises/point_light.rs",
            symptoms: &[INVERSE_SQUARE, POINT_BEHIND],
            reference: || check_point_light(reference_point),
        },
        Exercise {
            chapter: 5,
            name: "area_pdf",
            file: "chapters/ch5-reflection/exercises/area_pdf.rs",
            symptoms: &[PDF_JACOBIAN, PDF_SIGN],
            reference: || check_area_pdf(reference_area_pdf),
        },
        Exercise {
            chapter: 5,
            name: "solid_angle",
            file: "chapters/ch5-reflection/exercises/solid_angle.rs",
            symptoms: &[
                SOLID_SIGNED,
                SOLID_FAR_LIMIT,
                SOLID_ABOVE_PI,
                SOLID_PRECISION,
            ],
            reference: || check_solid_angle(reference_solid_angle),
        },
        Exercise {
            chapter: 5,
            name: "spot",
            file: "chapters/ch5-reflection/exercises/spot.rs",
            symptoms: &[SPOT_BAND, SPOT_FACTOR, SPOT_NARROW],
            reference: || check_spot(reference_spot),
        },
        Exercise {
            chapter: 5,
            name: "direct_light",
            file: "chapters/ch5-reflection/exercises/direct_light.rs",
            symptoms: &SYMPTOMS,
            reference: || check_direct_light(reference_direct),
        },
    ]
}

fn rel(got: Vec3, want: Vec3) -> f64 {
    ((got - want).abs_max() / want.abs_max().max(1e-6)) as f64
}

/// A hand case's error: relative to what was expected, or the size of
/// what came back where nothing was.
fn off(got: Vec3, want: Vec3) -> f64 {
    if want == Vec3::ZERO {
        got.abs_max() as f64
    } else {
        rel(got, want)
    }
}

/// A hand-worked case of the Lambertian BRDF (`src/grading/cases.toml`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct LambertCase {
    rho: V3,
    wo: V3,
    wi: V3,
    same_side: bool,
}

/// ρ/π on the same side, 0 across, for hand-picked directions.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_lambert_brdf(f: BrdfFn) -> Check {
    stateless::unless_changed(lambert_brdf_values(f), || {
        stateless::probes::lambert_brdf(f, reference_lambert)
    })
}

/// [`check_lambert_brdf`]'s checks of the values.
fn lambert_brdf_values(f: BrdfFn) -> Check {
    let worst = cases::worst("ch5/lambert_brdf", |c: &LambertCase| {
        let (rho, wo, wi) = (v3(c.rho), unit(c.wo), unit(c.wi));
        let want = if c.same_side {
            rho * FRAC_1_PI
        } else {
            Vec3::ZERO
        };
        let got = f(rho, wo, wi);
        (
            off(got, want),
            format!("ρ {rho}, ωo {wo}, ωi {wi}: got {got}, expected {want}"),
        )
    });
    let (mut error, mut detail) = match worst {
        Ok(w) => w,
        Err(check) => return check,
    };
    // Drawn albedos (a channel may be 0 or 1) and directions, grazing ones
    // (|z| down to 10⁻³⁰) among them.
    let mut draws = Draws::new(51);
    let mut black = Draws::new(151);
    let mut mirror = Draws::new(251);
    let mut flat = Draws::new(351);
    let drawn = worst_drawn((0..draws.count(200, 1000)).map(|_| {
        draws.next_case();
        flat.next_case();
        let channel = |d: &mut Draws| match d.count(0, 5) {
            0 => 0.0,
            1 => 1.0,
            _ => d.unit(),
        };
        let rho = Vec3::new(
            channel(&mut draws),
            channel(&mut draws),
            channel(&mut draws),
        );
        // Now and then black: ρ/π is 0, not 0/0 (drawn apart, so that the
        // other draws stay as they were).
        let rho = if black.unit() < 0.05 { Vec3::ZERO } else { rho };
        // One of the two down to 10⁻³⁰, the other to 10⁻⁶ (their product
        // still above f32's smallest number).
        let dir = |d: &mut Draws, lowest: f32| {
            let mut w = d.direction();
            if d.unit() < 0.3 {
                w.z = d.sign() * d.decades(lowest, -1.0);
                w = w.normalize();
            }
            w
        };
        let lowest = match draws.unit() < 0.5 {
            true => [-30.0, -6.0],
            false => [-6.0, -30.0],
        };
        let (wo, wi) = (dir(&mut draws, lowest[0]), dir(&mut draws, lowest[1]));
        // A tenth with one of the two exactly in the surface's plane (z =
        // 0 or -0), the other on either side: nothing (from a stream of
        // its own).
        let onto_plane = |w: Vec3, d: &mut Draws| {
            let along = Vec3::new(w.x, w.y, 0.0).normalize_or(Vec3::X);
            Vec3::new(along.x, along.y, 0.0f32.copysign(d.sign()))
        };
        let (wo, wi) = match (flat.unit() < 0.1, flat.unit() < 0.5) {
            (true, true) => (onto_plane(wo, &mut flat), wi),
            (true, false) => (wo, onto_plane(wi, &mut flat)),
            (false, _) => (wo, wi),
        };
        let judge = |wi: Vec3| {
            let want = if (wo.z > 0.0) == (wi.z > 0.0) && wo.z != 0.0 && wi.z != 0.0 {
                rho * FRAC_1_PI
            } else {
                Vec3::ZERO
            };
            let got = f(rho, wo, wi);
            let err = (got - want).abs_max() as f64 / (FRAC_1_PI as f64);
            (
                err,
                format!("ρ {rho}, ωo {wo}, ωi {wi}: got {got}, expected {want}"),
            )
        };
        // A fifth of them asked again at once with ωi mirrored across the
        // surface: the other side, a hair away (from a stream of its own).
        mirror.next_case();
        let first = judge(wi);
        match mirror.unit() < 0.2 {
            true => worst_drawn([first, judge(Vec3::new(wi.x, wi.y, -wi.z))].into_iter()),
            false => first,
        }
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    Check {
        error,
        tolerance: 1e-5,
        detail,
        images: None,
        symptom: (error > 1e-5).then(|| lambert_symptom(f)).flatten(),
    }
}

/// Statistical: every sample is a unit direction with z ≥ 0 whose pdf is
/// z/π; over 40,000 samples, E(z) = 2/3, E(x) = E(y) = 0, P(z < 1/2)
/// = 1/4 (for cos θ/π, P(cos θ < c) = c²), and the azimuth uniform (its
/// first harmonics average to 0); over 640,000 more, P(z < 0.03) = 0.03²
/// (the directions reach the rim), P(x² + y² < s) = s for a small cap
/// about the pole, and no gap in z² or the azimuth wider than chance
/// leaves (`ends.rs`); and a grid of u spread evenly over
/// the hemisphere (`grid_spread`). The error is the worst
/// deviation in standard errors (5 passes), or a large number when a
/// sample is not even a direction on the hemisphere.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_cosine_hemisphere(f: CosineFn) -> Check {
    stateless::unless_changed(cosine_hemisphere_values(f), || {
        stateless::probes::cosine_hemisphere(f)
    })
}

/// [`check_cosine_hemisphere`]'s checks of the values.
fn cosine_hemisphere_values(f: CosineFn) -> Check {
    let n = 40_000u64;
    // The numbers are new for every grading run.
    let seed = 55 ^ crate::run_seed().wrapping_mul(0x9e37_79b9_7f4a_7c15);
    // First the square's edges (u at 0 or just below 1 on one axis),
    // where every common map puts its most grazing directions, asked twice
    // in opposite orders: the answer must be a function of u alone.
    let top = 1.0 - f32::EPSILON / 2.0;
    let edges: Vec<Vec2> = (0..64)
        .flat_map(|k| {
            let t = (k as f32 + 0.5) / 64.0;
            [
                Vec2::new(0.0, t),
                Vec2::new(top, t),
                Vec2::new(t, 0.0),
                Vec2::new(t, top),
            ]
        })
        // And the eight largest u.x below 1, at drawn u.y: the most
        // grazing directions, where x² + y² may round past 1.
        .chain((0..2048u64).map(|i| {
            let x = 1.0 - (1 + i % 8) as f32 * f32::EPSILON / 2.0;
            Vec2::new(x, random(seed ^ 0x5eed, i, 0, 0))
        }))
        // And the round numbers in every pair: u = (1/2, 1/2) is the
        // centre of the square, where a map to the disk divides 0 by 0.
        .chain({
            let round = [0.0, 0.25, 0.5, 0.75, top];
            round
                .into_iter()
                .flat_map(move |x| round.map(|y| Vec2::new(x, y)))
        })
        .collect();
    let first: Vec<(Vec3, f32)> = edges.iter().map(|&u| f(u)).collect();
    let again: Vec<(Vec3, f32)> = edges.iter().rev().map(|&u| f(u)).collect();
    for ((u, a), b) in edges.iter().zip(&first).zip(again.iter().rev()) {
        if a.0.to_array().map(f32::to_bits) != b.0.to_array().map(f32::to_bits)
            || a.1.to_bits() != b.1.to_bits()
        {
            return Check {
                error: 1e9,
                tolerance: 5.0,
                detail: format!(
                    "u = {u}: {a:?}, and {b:?} when asked again: the direction must be a function of u alone"
                ),
                images: None,
                symptom: None,
            };
        }
    }
    // A sample that is not a unit direction on the hemisphere, or whose
    // pdf is not z/π: what is wrong with it.
    let invalid = |u: Vec2, (w, pdf): (Vec3, f32)| {
        if !((w.length() - 1.0).abs() < 1e-4 && w.z >= -1e-6) {
            return Some(Check {
                error: 1e9,
                tolerance: 5.0,
                detail: format!("u = {u}: {w} is not a unit direction with z ≥ 0"),
                images: None,
                symptom: Some(NOT_ON_HEMISPHERE),
            });
        }
        let want = w.z.max(0.0) * FRAC_1_PI;
        let off = (pdf - want).abs();
        (off.is_nan() || off > 1e-4 * want.max(1e-3)).then(|| Check {
            error: 1e9,
            tolerance: 5.0,
            detail: format!("u = {u}: direction {w} has pdf {pdf}, expected z/π = {want}"),
            images: None,
            symptom: Some(COSINE_PDF),
        })
    };
    if let Some(check) = edges.iter().zip(first).find_map(|(&u, r)| invalid(u, r)) {
        return check;
    }
    // A density has no lumps: 4,096 evenly spaced u.y (and then u.x)
    // give at least 1,200 different directions, not a table's few (a map
    // that folds [0, 1) onto itself two or three times, as r² = |2u − 1|
    // does, is still uniform and gives a half or a third of them). The
    // other number is held at three values and the most counts: one of
    // them may be where a right map has a pole (u.x = 1/2 for the fold).
    for axis in 0..2 {
        let distinct = |other: f32| {
            let mut seen: Vec<[u32; 3]> = (0..4096)
                .map(|k| {
                    let mut u = Vec2::splat(other);
                    u[axis] = (k as f32 + 0.5) / 4096.0;
                    f(u).0.to_array().map(f32::to_bits)
                })
                .collect();
            seen.sort_unstable();
            seen.dedup();
            seen.len()
        };
        let most = [0.3, 0.5, 0.77]
            .map(distinct)
            .into_iter()
            .max()
            .unwrap_or(0);
        if most < 1200 {
            return Check {
                error: 1e9,
                tolerance: 5.0,
                detail: format!(
                    "4,096 evenly spaced u.{} gave only {} different directions (at least 1,200): \
                     a density has no lumps (no angle or radius taken from a table)",
                    ["x", "y"][axis],
                    most
                ),
                images: None,
                symptom: None,
            };
        }
    }
    if let Some(check) = grid::grid_spread(f) {
        return check;
    }
    let (mut sx, mut sy, mut sz, mut low) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let mut ring = [0.0f64; 4];
    for i in 0..n {
        let u = Vec2::new(random(seed, i, 0, 0), random(seed, i, 0, 1));
        let (w, pdf) = f(u);
        if let Some(check) = invalid(u, (w, pdf)) {
            return check;
        }
        sx += w.x as f64;
        sy += w.y as f64;
        sz += w.z as f64;
        low += f64::from(w.z < 0.5);
        // The azimuth's harmonics, cos 2φ, sin 2φ, cos 4φ, sin 4φ (0 on
        // average when φ is uniform, whatever the map).
        let (x, y) = (w.x as f64, w.y as f64);
        let r2 = x * x + y * y;
        if r2 > 0.0 {
            let (c2, s2) = ((x * x - y * y) / r2, 2.0 * x * y / r2);
            ring[0] += c2;
            ring[1] += s2;
            ring[2] += c2 * c2 - s2 * s2;
            ring[3] += 2.0 * c2 * s2;
        }
    }
    let m = n as f64;
    // The rim, the pole and the finest scale, from numbers of their own.
    let ends = ends::ends(|u| f(u).0, seed);
    // Standard deviations under cos θ/π: x and y have variance 1/4, z has
    // 1/2 − 4/9, the indicator 1/4 · 3/4, each harmonic of a uniform
    // azimuth 1/2.
    let stats = [
        ("mean x", sx / m, 0.0, 0.25f64),
        ("mean y", sy / m, 0.0, 0.25),
        ("mean z", sz / m, 2.0 / 3.0, 0.5 - 4.0 / 9.0),
        ("P(z < 1/2)", low / m, 0.25, 0.1875),
        ("mean cos 2φ", ring[0] / m, 0.0, 0.5),
        ("mean sin 2φ", ring[1] / m, 0.0, 0.5),
        ("mean cos 4φ", ring[2] / m, 0.0, 0.5),
        ("mean sin 4φ", ring[3] / m, 0.0, 0.5),
    ];
    let (error, detail) = worst_of(
        stats
            .into_iter()
            .map(|(what, got, want, var)| {
                let z = (got - want).abs() / (var / m).sqrt();
                (
                    z,
                    format!("{what} = {got:.4}, expected {want:.4} ({z:.1} standard errors off)"),
                )
            })
            .chain(ends),
    );
    let gap = detail.starts_with(ends::GAP);
    Check {
        error,
        tolerance: 5.0,
        detail,
        images: None,
        symptom: (error > 5.0).then_some(if gap { COSINE_GAP } else { NOT_COSINE }),
    }
}

/// What a failing Lambertian BRDF got wrong, from two probes.
fn lambert_symptom(f: BrdfFn) -> Option<Symptom> {
    let rho = Vec3::new(0.9, 0.5, 0.1);
    let up = f(rho, Vec3::Z, Vec3::new(0.6, 0.0, 0.8));
    let below = f(rho, -Vec3::Z, Vec3::new(0.0, 0.6, -0.8));
    let want = rho * FRAC_1_PI;
    if rel(up, rho) < 1e-3 || rel(up, want * FRAC_1_PI) < 1e-3 {
        Some(LAMBERT_PI)
    } else if rel(up, want) < 1e-4 && below.abs_max() < 1e-6 {
        Some(LAMBERT_ONE_SIDED)
    } else {
        None
    }
}
