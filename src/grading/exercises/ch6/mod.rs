//! Chapter 6's exercises and how the first three are graded
//! (statistically: the checks draw random numbers and compare means
//! against known integrals with z-scores, so a biased solution fails and a
//! correct one passes with overwhelming probability; the numbers are
//! seeded, so a grade is repeatable). The capstone's check is in
//! `paths/`, refraction's and the bounce layers' in files of their own.

mod integral;
mod roulette_tails;

pub use integral::check_mc_integral;
use integral::reference_integral;
use roulette_tails::values_and_small_q;

use super::bounce_layers as layers;
use super::draws::{fold_drawn, worst_drawn, Draws};
use super::refraction;
use super::worst_of;
use crate::cases;
use crate::core::sampling::random;
use crate::exercise::{Check, Exercise, Symptom};
use crate::exercises::stateless;

type RouletteFn = fn(f64, f64, f64) -> f64;
type WeightFn = fn(f64, f64) -> f64;

/// The integral of [`check_mc_integral`] is off by the factor (b − a).
pub const NO_INTERVAL: Symptom = Symptom {
    name: "off by the length of the interval",
};

/// Roulette that keeps the mean of [`check_russian_roulette`] wrong.
pub const ROULETTE_BIASED: Symptom = Symptom {
    name: "roulette changes the mean",
};

/// Roulette that ends the wrong fraction of paths.
pub const ROULETTE_WRONG_FRACTION: Symptom = Symptom {
    name: "the wrong fraction of paths ends",
};

/// The balance heuristic instead of the power heuristic.
pub const BALANCE_HEURISTIC: Symptom = Symptom {
    name: "the balance heuristic, not the power heuristic",
};

/// A weight that overflows or divides 0 by 0.
pub const WEIGHT_NOT_FINITE: Symptom = Symptom {
    name: "huge or zero densities break the weight",
};

/// Chapter 6's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 6,
            name: "mc_integral",
            file: "chapters/ch6-global-illumination/exercises/mc_integral.rs",
            symptoms: &[NO_INTERVAL],
            reference: || check_mc_integral(reference_integral),
        },
        Exercise {
            chapter: 6,
            name: "russian_roulette",
            file: "chapters/ch6-global-illumination/exercises/russian_roulette.rs",
            symptoms: &[ROULETTE_BIASED, ROULETTE_WRONG_FRACTION],
            reference: || check_russian_roulette(reference_roulette),
        },
        Exercise {
            chapter: 6,
            name: "mis_weight",
            file: "chapters/ch6-global-illumination/exercises/mis_weight.rs",
            symptoms: &[BALANCE_HEURISTIC, WEIGHT_NOT_FINITE],
            reference: || check_mis_weight(reference_weight),
        },
        Exercise {
            chapter: 6,
            name: "path_radiance",
            file: "chapters/ch6-global-illumination/exercises/path_radiance.rs",
            symptoms: &super::paths::SYMPTOMS,
            reference: || super::paths::check_path_radiance(super::paths::reference_path),
        },
        Exercise {
            chapter: 6,
            name: "refraction",
            file: "chapters/ch6-global-illumination/exercises/refraction.rs",
            symptoms: &super::refraction::SYMPTOMS,
            reference: || refraction::check_refraction(refraction::reference_refract),
        },
        Exercise {
            chapter: 6,
            name: "bounce_layers",
            file: "chapters/ch6-global-illumination/exercises/bounce_layers.rs",
            symptoms: &super::bounce_layers::SYMPTOMS,
            reference: || layers::check_bounce_layers(layers::reference_layers),
        },
    ]
}

/// [`crate::ch5_reflection::mis::power_heuristic`] in f64.
fn reference_weight(f: f64, g: f64) -> f64 {
    if f.is_infinite() {
        return 1.0;
    }
    if f.is_nan() || f <= 0.0 {
        return 0.0;
    }
    let r = g / f;
    1.0 / (1.0 + r * r)
}

/// Exercise 6.2's answer: survive with probability q, carry value / q.
// ANCHOR: russian_roulette
fn reference_roulette(value: f64, q: f64, u: f64) -> f64 {
    if u < q {
        value / q
    } else {
        0.0
    }
}
// ANCHOR_END: russian_roulette

/// z = |mean - expected| / (s / √n) over repeated estimates.
pub(super) fn z_of(estimates: &[f64], expected: f64) -> f64 {
    let n = estimates.len() as f64;
    let mean = estimates.iter().sum::<f64>() / n;
    let var = estimates.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / (n - 1.0);
    let z = (mean - expected).abs() / (var / n).sqrt().max(1e-12);
    if z.is_nan() {
        f64::INFINITY
    } else {
        z
    }
}

/// Roulette keeps the mean (stratified numbers: the mean is exact) and
/// actually ends paths: the fraction of zeros is 1 - q.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_russian_roulette(f: RouletteFn) -> Check {
    stateless::unless_changed(russian_roulette_values(f), || {
        stateless::probes::russian_roulette(f)
    })
}

/// [`check_russian_roulette`]'s checks of the values.
fn russian_roulette_values(f: RouletteFn) -> Check {
    let n = 10_000;
    let mut symptom = None;
    // The hand cases, then drawn ones: values over six decades (and of
    // either sign, one tiny), survival probabilities from 10⁻⁴ to 1.
    let mut draws = Draws::new(62);
    // Small values too: a path's throughput of 10⁻⁵ or 10⁻²⁰ plays the
    // same game (small is not zero, and it is not a reason to skip it).
    let mut cases: Vec<(f64, f64, usize)> = [
        (3.0, 0.1),
        (0.7, 0.5),
        (2.0, 0.9),
        (5.0, 1.0),
        (-2.0, 0.5),
        (1e-5, 0.5),
        (-3e-20, 0.25),
        // Small q close together: each its own 1/q.
        (3.0, 0.0041),
        (-2.0, 0.0046),
        (0.5, 0.0013),
    ]
    .map(|(v, q)| (v, q, n))
    .to_vec();
    for k in 0..draws.count(4, 8) {
        draws.next_case();
        // The fourth a value from 10⁻³⁰ to 10⁻⁶: small is not zero.
        let value = match k {
            3 => draws.sign() * draws.decades(-30.0, -6.0),
            _ => draws.sign() * draws.decades(-3.0, 3.0),
        } as f64;
        // The first from 10⁻⁴ to 3·10⁻⁴, the second from 3·10⁻⁴ to 0.05,
        // where paths rarely survive; the third from 0.991 to 0.998, where
        // they rarely die. A whole number of the 10,000 evenly spaced u
        // survive: the mean is then exact.
        let q = match k {
            0 => draws.decades(-4.0, -3.5),
            1 => draws.decades(-3.5, -1.3),
            2 => draws.range(0.991, 0.998),
            _ if draws.unit() < 0.2 => 1.0,
            _ => draws.decades(-2.0, 0.0),
        };
        let q = (q as f64 * 1e4).round().max(1.0) / 1e4;
        cases.push((value, q, n));
    }
    // And three small q between the ten-thousandths, on a million evenly
    // spaced u (a whole number of them survive): survival decided to the
    // nearest ten-thousandth is off by up to 15 % there.
    cases.extend([
        (3.0, 0.00155, 1_000_000),
        (-1.5, 0.03625, 1_000_000),
        (0.25, 0.00047, 1_000_000),
    ]);
    let (error, detail) = worst_of(cases.into_iter().map(|(value, q, n): (f64, f64, usize)| {
        let outs: Vec<f64> = (0..n)
            .map(|i| f(value, q, (i as f64 + 0.5) / n as f64))
            .collect();
        let mean = outs.iter().sum::<f64>() / n as f64;
        let killed = outs.iter().filter(|o| **o == 0.0).count() as f64 / n as f64;
        let (bias, fraction) = (
            (mean - value).abs() / value.abs(),
            (killed - (1.0 - q)).abs(),
        );
        if fraction > 2e-3 {
            symptom = Some(ROULETTE_WRONG_FRACTION);
        } else if bias > 2e-3 && symptom.is_none() {
            symptom = Some(ROULETTE_BIASED);
        }
        let err = super::worse(bias, fraction);
        (
            err,
            format!(
                "value {value}, q {q}: mean {mean:.4} (want {value}), {:.1}% ended (want {:.1}%)",
                100.0 * killed,
                100.0 * (1.0 - q)
            ),
        )
    }));
    // Decided by u: the same (value, q, u) asked again, in the other
    // order, gets the same answer (a path's fate is a function of its
    // number, not of the calls before it).
    let probes: Vec<(f64, f64, f64)> = (0..64)
        .map(|_| {
            draws.next_case();
            let value = (draws.sign() * draws.decades(-3.0, 3.0)) as f64;
            (value, draws.range(0.1, 0.9) as f64, draws.unit() as f64)
        })
        .collect();
    let first: Vec<f64> = probes.iter().map(|&(v, q, u)| f(v, q, u)).collect();
    let again: Vec<f64> = probes.iter().rev().map(|&(v, q, u)| f(v, q, u)).collect();
    let changed = probes
        .iter()
        .zip(&first)
        .zip(again.iter().rev())
        .find(|((_, a), b)| a.to_bits() != b.to_bits());
    if let Some(((&(v, q, u), a), b)) = changed {
        return Check {
            error: 1.0,
            tolerance: 2e-3,
            detail: format!(
                "value {v}, q {q}, u {u}: returned {a}, and {b} when asked again: the \
                 outcome must be decided by u alone"
            ),
            images: None,
            symptom: None,
        };
    }
    // q = 1 means it always survives, u = 0 (a number like any other)
    // included (asked once the rest agrees, so that a mistake there keeps
    // its name).
    let always = [(3.0, 1.0), (-2.0, 1.0)].into_iter().find_map(|(v, q)| {
        let got = f(v, q, 0.0);
        let close = (got - v).abs() <= 1e-12 * v.abs();
        (!close).then(|| {
            format!(
                "value {v}, q {q}, u 0: returned {got}, expected {v} (q = 1: it always survives)"
            )
        })
    });
    // A survivor carries value / q however small q is (10⁻⁸, 10⁻⁴⁰,
    // 10⁻²⁰⁰, and eight drawn from 10⁻³⁰⁰ to 10⁻³⁰, most of them below
    // what f32 holds, so that a q rounded to f32 shares its 1/q with
    // others): asked at u = 0, q / 2, 1 − q / 2 and the largest u below
    // 1, whatever comes back that is not 0 must be value / q. (Which u
    // survive is the solution's choice; no u in f64 lies in the top 10⁻⁴⁰.)
    // And q where 1 − q rounds in f64 (value / (1 − (1 − q)) is off by
    // up to 10 % there): 1.5·10⁻¹⁵, 6·10⁻¹⁶, twelve drawn from 10⁻¹⁶ to
    // 10⁻¹² (half of them off by more than 0.2 %) and four to 10⁻⁴.
    let mut tiny = vec![(3.0, 1e-8), (-0.5, 1e-40), (2.0, 1e-200)];
    tiny.extend(values_and_small_q(&mut draws, 8, (-30.0, -300.0)));
    tiny.extend([(1.5, 1.5e-15), (-0.7, 6e-16)]);
    let mut rounded = Draws::new(162);
    tiny.extend(values_and_small_q(&mut rounded, 12, (-16.0, -12.0)));
    tiny.extend(values_and_small_q(&mut rounded, 4, (-12.0, -4.0)));
    let carried = tiny.into_iter().find_map(|(v, q): (f64, f64)| {
        let top = 1.0f64.next_down();
        let us = [0.0, q / 2.0, (1.0 - q / 2.0).min(top), top];
        us.into_iter().find_map(|u| {
            let got = f(v, q, u);
            let right = got == 0.0 || ((got - v / q) / (v / q)).abs() <= 2e-3;
            (!right).then(|| {
                format!(
                    "value {v:e}, q {q:e}, u {u}: returned {got:e}, expected {:e} if the path \
                     survives (value / q), or 0",
                    v / q
                )
            })
        })
    });
    // And a small q is not zero: down to 10⁻¹⁵ some u survives, and the
    // usual choices (u below q, or u at or above 1 − q) have a survivor at
    // u = 0, q / 2 or 1 − q / 2 (the stub says the grader looks there).
    // Below 10⁻¹⁵, where 1 − q rounds to 1, none need.
    let mut small = vec![(1.5, 1e-5), (-2.0, 1e-9), (0.5, 1e-14)];
    small.extend(values_and_small_q(&mut draws, 6, (-15.0, -4.0)));
    let dead = small.into_iter().find_map(|(v, q): (f64, f64)| {
        let us = [0.0, q / 2.0, 1.0 - q / 2.0];
        us.iter().all(|&u| f(v, q, u) == 0.0).then(|| {
            format!(
                "value {v}, q {q:e}: no path survived at u = 0, q / 2 or 1 − q / 2; a path \
                 with q = {q:e} must survive with that probability (small is not zero)"
            )
        })
    });
    let share = roulette_tails::share_near_the_ends(f);
    let first = always.or(carried).or(dead).or(share);
    if let Some(detail) = first.filter(|_| error <= 2e-3) {
        return Check {
            error: 1.0,
            tolerance: 2e-3,
            detail,
            images: None,
            symptom: None,
        };
    }
    Check {
        error,
        tolerance: 2e-3,
        detail,
        images: None,
        symptom: if error > 2e-3 { symptom } else { None },
    }
}

/// A hand-worked weight (`src/grading/cases.toml`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct WeightCase {
    pdf_f: f64,
    pdf_g: f64,
    expect: f64,
}

/// The weight against hand values and extremes, the two weights summing
/// to one, and an unbiased two-strategy MIS estimate of ∫₀¹ 3x² dx = 1
/// (uniform sampling, pdf 1, and sampling by 2x, pdf 2x).
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_mis_weight(f: WeightFn) -> Check {
    stateless::unless_changed(mis_weight_values(f), || {
        stateless::probes::mis_weight(f, reference_weight)
    })
}

/// [`check_mis_weight`]'s checks of the values.
fn mis_weight_values(f: WeightFn) -> Check {
    let hand = cases::worst("ch6/mis_weight", |c: &WeightCase| {
        let (a, b, want) = (c.pdf_f, c.pdf_g, c.expect);
        let got = f(a, b);
        (
            (got - want).abs(),
            format!("pdf_f {a:e}, pdf_g {b:e}: got {got}, expected {want}"),
        )
    });
    let (mut error, mut detail) = match hand {
        Ok(w) => w,
        Err(check) => return check,
    };
    // Drawn densities over 400 decades, a tenth of them 0, half of the
    // pairs within three decades of each other, in a number of calls that
    // changes from run to run.
    let mut draws = Draws::new(63);
    let n = draws.count(500, 3000);
    let mut last_f: Option<f64> = None;
    let drawn = worst_drawn((0..n).map(|_| {
        draws.next_case();
        let density = |d: &mut Draws| {
            if d.unit() < 0.1 {
                0.0
            } else {
                10f64.powf(d.range(-200.0, 200.0) as f64)
            }
        };
        let (mut a, mut b) = (density(&mut draws), density(&mut draws));
        // A fifth keep the last pdf_f with a new pdf_g: w depends on both.
        if let Some(last) = last_f.filter(|_| draws.unit() < 0.2) {
            a = last;
        }
        // Half of them with pdf_g within three decades of pdf_f, where w
        // moves most, a tenth within 10⁻⁶ to 10⁻² of it (w near 1/2).
        match draws.count(0, 9) {
            0..=3 => b = a * 10f64.powf(draws.range(-3.0, 3.0) as f64),
            4 => b = a * (1.0 + (draws.sign() * draws.decades(-6.0, -2.0)) as f64),
            _ => {}
        }
        last_f = Some(a);
        let want = if a == 0.0 {
            0.0
        } else {
            1.0 / (1.0 + (b / a).powi(2))
        };
        let got = f(a, b);
        (
            (got - want).abs(),
            format!("pdf_f {a:e}, pdf_g {b:e}: got {got}, expected {want}"),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    // The MIS estimate: one sample from each strategy per estimate.
    let estimates: Vec<f64> = (0..4000u64)
        .map(|i| {
            let integrand = |x: f64| 3.0 * x * x;
            let x1 = random(77, i, 0, 0) as f64; // uniform, pdf 1
            let x2 = (random(77, i, 0, 1) as f64).sqrt(); // pdf 2x
            let e1 = f(1.0, 2.0 * x1) * integrand(x1) / 1.0;
            let e2 = if x2 > 0.0 {
                f(2.0 * x2, 1.0) * integrand(x2) / (2.0 * x2)
            } else {
                0.0
            };
            e1 + e2
        })
        .collect();
    let z = z_of(&estimates, 1.0);
    if z > 5.0 && error < 1.0 {
        error = 1.0;
        detail = format!("the MIS estimate of ∫₀¹ 3x² dx = 1 is biased (z = {z:.1})");
    }
    let symptom = if error <= 1e-6 {
        None
    } else if (f(2.0, 1.0) - 2.0 / 3.0).abs() < 1e-9 {
        Some(BALANCE_HEURISTIC)
    } else if !(f(1e200, 1e199).is_finite() && f(0.0, 0.0).is_finite() && f(0.0, 5.0) == 0.0) {
        Some(WEIGHT_NOT_FINITE)
    } else {
        None
    };
    Check {
        error,
        tolerance: 1e-6,
        detail,
        images: None,
        symptom,
    }
}
