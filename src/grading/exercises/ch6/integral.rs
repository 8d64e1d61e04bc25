//! Exercise 6.1, a Monte Carlo integral: five integrals with known
//! values (unbiased, with a plain estimator's spread), a constant that
//! integrates exactly, drawn intervals where f is counted and located and
//! every number's value weighs the same, and evenly spaced numbers whose
//! points must spread evenly over [a, b].

use std::cell::Cell;

use super::super::draws::{fold_drawn, worst_drawn, Draws};
use super::super::worst_of;
use super::{z_of, NO_INTERVAL};
use crate::core::sampling::random;
use crate::exercise::Check;

/// Exercise 6.1's signature.
pub(super) type IntegralFn = fn(&dyn Fn(f64) -> f64, f64, f64, &[f64]) -> f64;

/// Exercise 6.1's answer: x = a + u (b − a) is uniform on [a, b], with
/// density 1/(b − a), so f(x)/p(x) = (b − a) f(x).
// ANCHOR: mc_integral
pub(super) fn reference_integral(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    let sum: f64 = u.iter().map(|u| f(a + u * (b - a))).sum();
    (b - a) * sum / u.len().max(1) as f64
}
// ANCHOR_END: mc_integral

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

/// The estimator on five integrals with known values: 64 independent
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
    let spike = |x: f64| {
        if (0.3..0.301).contains(&x) {
            1000.0
        } else {
            0.0
        }
    };
    // (f, a, b, value, σ of one sample of (b - a) f(x))
    type Case<'a> = (&'a dyn Fn(f64) -> f64, f64, f64, f64, f64, &'a str);
    let cases: [Case; 5] = [
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
        // A narrow spike: most estimates see it once or not at all, and
        // their mean is still the integral.
        (
            &spike,
            0.0,
            1.0,
            1.0,
            999f64.sqrt(),
            "∫₀¹ 1000·[0.3 ≤ x < 0.301] dx = 1",
        ),
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
    // From any numbers: 0 is one of them.
    let constant = f(&|_| 2.5, -1.0, 3.0, &[0.1, 0.7]);
    let at_zero = f(&|_| 2.5, -1.0, 3.0, &[0.0, 0.0]);
    // And from 70,000 numbers (more than a u16 counts).
    // (Each one evaluated: a buffer sized by an earlier, shorter call
    // would still average 2.5 exactly.)
    let many: Vec<f64> = (0..70_000).map(|i| (i as f64 + 0.5) / 70_000.0).collect();
    let many_calls = Cell::new(0usize);
    let from_many = f(
        &|_| {
            many_calls.set(many_calls.get() + 1);
            2.5
        },
        -1.0,
        3.0,
        &many,
    );
    // (Written so that a NaN fails.)
    let ten = |x: f64| (x - 10.0).abs() <= 1e-9;
    let (mut error, mut detail) = if !ten(constant) {
        (1.0, format!("∫₋₁³ 2.5 dx = 10, got {constant}"))
    } else if !ten(at_zero) {
        (
            1.0,
            format!("∫₋₁³ 2.5 dx = 10 from the numbers [0, 0], got {at_zero}"),
        )
    } else if !ten(from_many) {
        (
            1.0,
            format!("∫₋₁³ 2.5 dx = 10 from 70,000 numbers, got {from_many}"),
        )
    } else if many_calls.get() != many.len() {
        (
            1.0,
            format!(
                "∫₋₁³ 2.5 dx from 70,000 numbers evaluated f {} times: one evaluation per number",
                many_calls.get()
            ),
        )
    } else {
        (error, detail)
    };
    // Drawn intervals (anywhere, any width from 10⁻³ to 10³, either
    // order) and a drawn constant from 10⁻⁸ to 10⁸ (a fifth, from a
    // stream of their own, 10³⁸ to 10³⁰⁰ or 10⁻²⁹⁰ to 10⁻³⁸: any f64, in
    // f32's range or not), from drawn numbers: exact up to rounding, with
    // f evaluated once per number, inside the interval.
    let mut draws = Draws::new(61);
    let mut narrow = Draws::new(261);
    let mut vast = Draws::new(361);
    let mut values = Draws::new(461);
    let drawn = worst_drawn((0..draws.count(20, 60)).map(|k| {
        draws.next_case();
        narrow.next_case();
        vast.next_case();
        let a = (draws.sign() * draws.decades(-3.0, 3.0)) as f64;
        let width = (draws.sign() * draws.decades(-3.0, 3.0)) as f64;
        // The first and a tenth of the others from 10⁻¹² to 10⁻⁹ wide (a
        // stream of their own): narrow is not empty.
        let width = match narrow.unit() < 0.1 || k == 0 {
            true => width.signum() * narrow.decades(-12.0, -9.0) as f64,
            false => width,
        };
        let c = (draws.sign() * draws.decades(-8.0, 8.0)) as f64;
        let c = vast
            .far_exponent(0.2, (-290.0, -38.0), (38.0, 300.0))
            .map_or(c, |u| c.signum() * 10f64.powf(u as f64));
        let mut u: Vec<f64> = (0..draws.count(1, 16))
            .map(|_| draws.unit() as f64)
            .collect();
        // A third of them with a number given twice: evaluated twice.
        if draws.unit() < 1.0 / 3.0 {
            u.push(u[draws.count(0, u.len() - 1)]);
        }
        // A tenth with a number exactly 0, which is one of them.
        if draws.unit() < 0.1 {
            u[0] = 0.0;
        }
        let b = a + width;
        // Each asked twice in a row: the same interval and numbers, another
        // integrand (c, then -2c): each its own answer.
        // Then an integrand whose values (1 to 2, drawn) f hands out in
        // the order it is called: every number's value counts, each once
        // and with the same weight.
        values.next_case();
        let v: Vec<f64> = u.iter().map(|_| values.range(1.0, 2.0) as f64).collect();
        let constants = [c, -2.0 * c].map(|c| {
            drawn_once(
                f,
                (a, b, &u),
                |_| c,
                c * (b - a),
                &format!("the constant {c:e}"),
            )
        });
        let mean = (b - a) * v.iter().sum::<f64>() / v.len() as f64;
        let asked = format!(
            "an f returning {v:?} in the order it is called, from the numbers {u:?} ((b − a) times \
             their mean: each number's value counts once, with weight 1/N)"
        );
        let weighed = drawn_once(
            f,
            (a, b, &u),
            |k| v.get(k).copied().unwrap_or(1.0),
            mean,
            &asked,
        );
        worst_drawn(constants.into_iter().chain([weighed]))
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    // Uniform there when the number is: 4,096 evenly spaced numbers (at a
    // drawn offset from the grid's cells), each alone in its call (a
    // point may depend on the number's place in `u` too, as long as it is
    // uniform), give evaluation points spread evenly over a drawn [a, b]
    // (sorted, each within 2/4,096 of the width of its place on the even
    // grid), and all different (points snapped to a grid of their own are
    // not uniform).
    let drawn = (
        (draws.sign() * draws.decades(-3.0, 3.0)) as f64,
        draws.decades(-3.0, 3.0) as f64,
    );
    let m = 4096;
    // Not half way: u and 1 - u never meet on the grid.
    let phase = draws.range(0.05, 0.45) as f64 + 0.5 * draws.count(0, 1) as f64;
    let evenly: Vec<f64> = (0..m).map(|i| (i as f64 + phase) / m as f64).collect();
    // Then again on a narrow interval far from 0 (10³ to 10⁵ out, 10⁻³ to
    // 10⁻¹ wide, from a stream of its own), where a point worked out in
    // f32 lands on f32's own coarse grid.
    let mut afar = Draws::new(161);
    let far = (
        (afar.sign() * afar.decades(3.0, 5.0)) as f64,
        afar.decades(-3.0, -1.0) as f64,
    );
    for (a, width) in [drawn, far] {
        let points = std::cell::RefCell::new(Vec::with_capacity(m));
        for u in &evenly {
            f(
                &|x| {
                    points.borrow_mut().push(x);
                    1.0
                },
                a,
                a + width,
                std::slice::from_ref(u),
            );
        }
        let mut points = points.into_inner();
        points.sort_by(f64::total_cmp);
        let off = match points.len() == m {
            true => points
                .iter()
                .zip(&evenly)
                .map(|(x, u)| (x - (a + width * u)).abs() / width)
                .fold(
                    0.0,
                    |w: f64, d| if d.is_nan() { f64::INFINITY } else { w.max(d) },
                ),
            false => f64::INFINITY,
        };
        let repeated = points.windows(2).filter(|w| w[0] == w[1]).count();
        if off > 2.0 / m as f64 && error <= 1e-3 {
            (error, detail) = (
                1.0,
                format!(
                    "4,096 evenly spaced numbers, one per call, on [{a}, {}] put f's points up to {off:.4} of the \
                     width from an even spread: the points must be uniform on [a, b] when the numbers are",
                    a + width
                ),
            );
        } else if repeated > 0 && error <= 1e-3 {
            (error, detail) = (
                1.0,
                format!(
                    "4,096 different numbers, one per call, on [{a}, {}] put f's points at only {} different places: \
                     points snapped to a grid are not uniform on [a, b]",
                    a + width,
                    m - repeated
                ),
            );
        }
    }
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

/// The integral from a to b, from the numbers `u`, of an integrand that
/// returns `value(k)` at its k-th call, whatever the point (`of` says
/// which, `want` is the answer): its error (10³ times the relative error;
/// infinite where f is not evaluated once per number, inside [a, b]) and
/// what was asked.
fn drawn_once(
    f: IntegralFn,
    (a, b, u): (f64, f64, &[f64]),
    value: impl Fn(usize) -> f64,
    want: f64,
    of: &str,
) -> (f64, String) {
    // One evaluation per number, each in [a, b] (to rounding).
    let (calls, outside) = (Cell::new(0usize), Cell::new(None));
    let (lo, hi) = (a.min(b), a.max(b));
    let slack = 1e-12 * (lo.abs() + hi.abs());
    let g = |x: f64| {
        calls.set(calls.get() + 1);
        if !(lo - slack..=hi + slack).contains(&x) {
            outside.set(Some(x));
        }
        value(calls.get() - 1)
    };
    let got = f(&g, a, b, u);
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
        // In scientific notation: the constants go up to 10³⁰⁰ (every
        // digit, still exact, and short).
        format!("∫ from {a} to {b} of {of} = {want:e}, got {got:e}"),
    )
}
