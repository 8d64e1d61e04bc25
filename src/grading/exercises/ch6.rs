//! Chapter 6's exercises and how the first three are graded
//! (statistically: the checks draw random numbers and compare means
//! against known integrals with z-scores, so a biased solution fails and a
//! correct one passes with overwhelming probability; the numbers are
//! seeded, so a grade is repeatable). The capstone's check is in
//! `paths/`, refraction's and the bounce layers' in files of their own.

use std::cell::Cell;

use super::bounce_layers as layers;
use super::draws::{fold_drawn, worst_drawn, Draws};
use super::refraction;
use super::worst_of;
use crate::cases;
use crate::core::sampling::random;
use crate::exercise::{Check, Exercise, Symptom};

type IntegralFn = fn(&dyn Fn(f64) -> f64, f64, f64, &[f64]) -> f64;
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

/// Exercise 6.1's answer: x = a + u (b − a) is uniform on [a, b], with
/// density 1/(b − a), so f(x)/p(x) = (b − a) f(x).
// ANCHOR: mc_integral
fn reference_integral(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    let sum: f64 = u.iter().map(|u| f(a + u * (b - a))).sum();
    (b - a) * sum / u.len().max(1) as f64
}
// ANCHOR_END: mc_integral

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

/// Seeded uniform numbers.
fn uniforms(seed: u64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            // 48 random bits from two draws, so values are never exactly 1.
            let hi = random(seed, i as u64, 0, 0) as f64;
            let lo = random(seed, i as u64, 0, 1) as f64;
            (hi + lo / (1u64 << 24) as f64).min(1.0 - 1e-15)
        })
        .collect()
}

/// z = |mean - expected| / (s / √n) over repeated estimates.
fn z_of(estimates: &[f64], expected: f64) -> f64 {
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

/// The estimator on four integrals with known values: 64 independent
/// estimates of 1024 samples each must average to the value (|z| ≤ 5), and
/// their spread must be the one of an unbiased uniform estimator (within
/// a factor 2 of σ/√N), which catches a wrong (b - a) factor that happens
/// to be right on average nowhere. A constant integrates exactly.
pub fn check_mc_integral(f: IntegralFn) -> Check {
    use std::f64::consts::PI;
    let sin = |x: f64| x.sin();
    let square = |x: f64| x * x;
    let inv = |x: f64| 1.0 / x;
    let step = |x: f64| if x > 0.5 { 1.0 } else { 0.0 };
    // (f, a, b, value, σ of one sample of (b - a) f(x))
    type Case<'a> = (&'a dyn Fn(f64) -> f64, f64, f64, f64, f64, &'a str);
    let cases: [Case; 4] = [
        (
            &sin,
            0.0,
            PI,
            2.0,
            (PI * PI / 2.0 - 4.0).sqrt(),
            "∫₀^π sin x dx = 2",
        ),
        (
            &square,
            0.0,
            1.0,
            1.0 / 3.0,
            (1.0f64 / 5.0 - 1.0 / 9.0).sqrt(),
            "∫₀¹ x² dx = 1/3",
        ),
        (
            &inv,
            1.0,
            3.0,
            3f64.ln(),
            (2.0 * (2.0 / 3.0) - 3f64.ln().powi(2)).sqrt(),
            "∫₁³ dx/x = ln 3",
        ),
        // Zero on half the interval: a sample of 0 counts like any other.
        (&step, 0.0, 1.0, 0.5, 0.5, "∫₀¹ [x > ½] dx = ½"),
    ];
    let n = 1024;
    let (error, detail) = worst_of(cases.iter().enumerate().map(|(k, (g, a, b, value, sigma, name))| {
        let estimates: Vec<f64> = (0..64)
            .map(|r| f(*g, *a, *b, &uniforms(1000 * k as u64 + r, n)))
            .collect();
        let z = z_of(&estimates, *value);
        let mean = estimates.iter().sum::<f64>() / 64.0;
        let sd = (estimates.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / 63.0).sqrt();
        let ratio = sd / (sigma / (n as f64).sqrt());
        // Spread outside [0.5, 2] of the expected counts as failing.
        let spread_err = if (0.5..=2.0).contains(&ratio) { 0.0 } else { 100.0 };
        (
            (z / 5.0).max(spread_err) * 1e-3,
            format!("{name}: mean of 64 estimates {mean:.5} (z = {z:.1}), spread {ratio:.2}× the expected"),
        )
    }));
    let constant = f(&|_| 2.5, -1.0, 3.0, &[0.1, 0.7]);
    let (mut error, mut detail) = if (constant - 10.0).abs() > 1e-9 {
        (1.0, format!("∫₋₁³ 2.5 dx = 10, got {constant}"))
    } else {
        (error, detail)
    };
    // Drawn intervals (anywhere, any width from 10⁻³ to 10³, either
    // order) and a drawn constant from 10⁻⁸ to 10⁸, from drawn numbers: exact up to
    // rounding, with f evaluated once per number, inside the interval.
    let mut draws = Draws::new(61);
    let drawn = worst_drawn((0..draws.count(20, 60)).map(|_| {
        draws.next_case();
        let a = (draws.sign() * draws.decades(-3.0, 3.0)) as f64;
        let width = (draws.sign() * draws.decades(-3.0, 3.0)) as f64;
        let c = (draws.sign() * draws.decades(-8.0, 8.0)) as f64;
        let u: Vec<f64> = (0..draws.count(1, 16))
            .map(|_| draws.unit() as f64)
            .collect();
        let b = a + width;
        // One evaluation per number, each in [a, b] (to rounding).
        let (calls, outside) = (Cell::new(0usize), Cell::new(None));
        let (lo, hi) = (a.min(b), a.max(b));
        let slack = 1e-12 * (lo.abs() + hi.abs());
        let g = |x: f64| {
            calls.set(calls.get() + 1);
            if !(lo - slack..=hi + slack).contains(&x) {
                outside.set(Some(x));
            }
            c
        };
        let got = f(&g, a, b, &u);
        let want = c * (b - a);
        if calls.get() != u.len() {
            return (
                f64::INFINITY,
                format!(
                    "∫ from {a} to {b} from {} numbers evaluated f {} times: one evaluation per number",
                    u.len(),
                    calls.get()
                ),
            );
        }
        if let Some(x) = outside.get() {
            return (
                f64::INFINITY,
                format!("∫ from {a} to {b}: f evaluated at {x}, outside the interval"),
            );
        }
        (
            (got - want).abs() / want.abs() * 1e3,
            format!("∫ from {a} to {b} of the constant {c} = {want}, got {got}"),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    // Off by (b − a): the constant 1 on [0, 2] comes out as 1, not 2.
    let unit = f(&|_| 1.0, 0.0, 2.0, &[0.25, 0.75]);
    Check {
        error,
        tolerance: 1e-3,
        detail,
        images: None,
        symptom: (error > 1e-3 && (unit - 1.0).abs() < 1e-9).then_some(NO_INTERVAL),
    }
}

/// Roulette keeps the mean (stratified numbers: the mean is exact) and
/// actually ends paths: the fraction of zeros is 1 - q.
pub fn check_russian_roulette(f: RouletteFn) -> Check {
    let n = 10_000;
    let mut symptom = None;
    // The hand cases, then drawn ones: values over six decades (and of
    // either sign), survival probabilities from 10⁻⁴ to 1.
    let mut draws = Draws::new(62);
    let mut cases = vec![(3.0, 0.1), (0.7, 0.5), (2.0, 0.9), (5.0, 1.0), (-2.0, 0.5)];
    for k in 0..draws.count(4, 8) {
        draws.next_case();
        let value = (draws.sign() * draws.decades(-3.0, 3.0)) as f64;
        // The first from 10⁻⁴ to 10⁻², the second from 0.01 to 0.05,
        // where paths rarely survive. A whole number of the 10,000 evenly
        // spaced u survive: the mean is then exact.
        let q = match k {
            0 => draws.decades(-4.0, -2.0),
            1 => draws.decades(-2.0, -1.3),
            _ if draws.unit() < 0.2 => 1.0,
            _ => draws.decades(-2.0, 0.0),
        };
        let q = (q as f64 * 1e4).round().max(1.0) / 1e4;
        cases.push((value, q));
    }
    let (error, detail) = worst_of(cases.into_iter().map(|(value, q): (f64, f64)| {
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
        let err = bias.max(fraction);
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
pub fn check_mis_weight(f: WeightFn) -> Check {
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
    // Drawn densities over 400 decades, a tenth of them 0, in a number of
    // calls that changes from run to run.
    let mut draws = Draws::new(63);
    let n = draws.count(500, 3000);
    let drawn = worst_drawn((0..n).map(|_| {
        draws.next_case();
        let density = |d: &mut Draws| {
            if d.unit() < 0.1 {
                0.0
            } else {
                10f64.powf(d.range(-200.0, 200.0) as f64)
            }
        };
        let (a, b) = (density(&mut draws), density(&mut draws));
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
