//! Exercise 5.2's grid of u: the cosine map's directions over a 256 × 256
//! grid of cell centres, where a right map's spread is known closely (a
//! grid integrates smooth functions of u far better than as many random
//! numbers do).

use glam::Vec2;

use super::symptoms::NOT_COSINE;
use super::CosineFn;
use crate::exercise::Check;

/// The density over the whole hemisphere, not only its moments: under
/// cos θ / π both z² and the azimuth / 2π are uniform on [0, 1], so the
/// directions of a 256 × 256 grid of u (each cell's centre) must put them
/// within 0.02 of an even spread (the largest gap between the share below
/// t and t). A right map is within 0.008 (the concentric map's grid; the
/// polar one 0.002); a radius a few percent off, or an angle bent, is
/// not.
pub(super) fn grid_spread(f: CosineFn) -> Option<Check> {
    let n = 256;
    let (mut z2, mut azimuth) = (Vec::with_capacity(n * n), Vec::with_capacity(n * n));
    for i in 0..n {
        for j in 0..n {
            let u = Vec2::new((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32);
            let w = f(u).0.as_dvec3();
            z2.push(w.z * w.z);
            azimuth.push((w.y.atan2(w.x) / std::f64::consts::TAU).rem_euclid(1.0));
        }
    }
    let gap = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        let m = v.len() as f64;
        v.iter().enumerate().fold(0.0f64, |g, (k, &x)| {
            let below = (k as f64 / m - x).abs().max(((k + 1) as f64 / m - x).abs());
            if below.is_nan() {
                f64::INFINITY
            } else {
                g.max(below)
            }
        })
    };
    // The spread first, which names the bigger mistakes; then the moments.
    let moments = grid_moments(&z2, &azimuth);
    let (gz, ga) = (gap(z2), gap(azimuth));
    let detail = match gz > 0.02 || ga > 0.02 {
        true => format!(
            "a 256 × 256 grid of u: z² is up to {gz:.3} and the azimuth up to {ga:.3} from an \
             even spread on [0, 1] (under cos θ / π both are uniform; at most 0.02)"
        ),
        false => moments?,
    };
    Some(Check {
        error: 1e9,
        tolerance: 5.0,
        detail,
        images: None,
        symptom: Some(NOT_COSINE),
    })
}

/// The grid's averages that a uniform z² and azimuth fix: cos kφ and
/// sin kφ (k = 1 to 8) average 0, z² averages 1/2 and z⁴ 1/3. A right
/// map is within 10⁻⁴ of each on this grid (the polar map to 10⁻¹⁵, the
/// concentric one to 6·10⁻⁵); an angle that wraps around a little more or
/// less than once (φ = 360·u.y in radians) is 10⁻² off. `None` when
/// every average is within 10⁻³.
fn grid_moments(z2: &[f64], azimuth: &[f64]) -> Option<String> {
    let m = z2.len() as f64;
    let mean = |v: &mut dyn Iterator<Item = f64>| v.sum::<f64>() / m;
    let mut worst = (0.0f64, String::new());
    let mut consider = |what: String, got: f64, want: f64| {
        let off = (got - want).abs();
        if off.is_nan() || off > worst.0 {
            worst = (
                if off.is_nan() { f64::INFINITY } else { off },
                format!("{what} = {got:.5}, expected {want:.5}"),
            );
        }
    };
    for k in 1..=8 {
        let w = |a: f64| k as f64 * std::f64::consts::TAU * a;
        consider(
            format!("mean cos {k}φ"),
            mean(&mut azimuth.iter().map(|&a| w(a).cos())),
            0.0,
        );
        consider(
            format!("mean sin {k}φ"),
            mean(&mut azimuth.iter().map(|&a| w(a).sin())),
            0.0,
        );
    }
    consider("mean z²".into(), mean(&mut z2.iter().copied()), 0.5);
    consider(
        "mean z⁴".into(),
        mean(&mut z2.iter().map(|&q| q * q)),
        1.0 / 3.0,
    );
    (worst.0 > 1e-3).then(|| {
        format!(
            "a 256 × 256 grid of u: {} (under cos θ / π the azimuth φ and z² are uniform, and \
             on this grid a right map is within 10⁻⁴ of each such average; at most 10⁻³)",
            worst.1
        )
    })
}
