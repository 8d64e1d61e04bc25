//! A χ² goodness-of-fit test of a direction sampler against its pdf, on a
//! grid over the sphere in (cos θ, φ): equal-area cells (dω = d(cos θ) dφ).
//! Expected counts come from integrating the pdf over each cell by a
//! midpoint rule; cells expecting fewer than 5 samples are pooled.

use std::f64::consts::PI;

use glam::Vec3;

/// Cells in cos θ and in φ.
pub const COS_CELLS: usize = 32;
/// Cells in φ.
pub const PHI_CELLS: usize = 32;

fn cell_of(w: Vec3) -> usize {
    let c = ((w.z as f64 + 1.0) * 0.5 * COS_CELLS as f64).floor() as usize;
    let phi = (w.y as f64).atan2(w.x as f64).rem_euclid(2.0 * PI);
    let p = (phi / (2.0 * PI) * PHI_CELLS as f64).floor() as usize;
    c.min(COS_CELLS - 1) * PHI_CELLS + p.min(PHI_CELLS - 1)
}

/// ∫ pdf over each cell (midpoint rule, `sub`² points per cell).
pub fn expected_mass(pdf: &dyn Fn(Vec3) -> f32, sub: usize) -> Vec<f64> {
    let mut mass = vec![0.0; COS_CELLS * PHI_CELLS];
    let (dc, dp) = (2.0 / COS_CELLS as f64, 2.0 * PI / PHI_CELLS as f64);
    for (k, m) in mass.iter_mut().enumerate() {
        let (ci, pi) = (k / PHI_CELLS, k % PHI_CELLS);
        let mut sum = 0.0;
        for a in 0..sub {
            for b in 0..sub {
                let z = -1.0 + dc * (ci as f64 + (a as f64 + 0.5) / sub as f64);
                let phi = dp * (pi as f64 + (b as f64 + 0.5) / sub as f64);
                let r = (1.0 - z * z).max(0.0).sqrt();
                let w = Vec3::new((r * phi.cos()) as f32, (r * phi.sin()) as f32, z as f32);
                sum += pdf(w) as f64;
            }
        }
        *m = sum * dc * dp / (sub * sub) as f64;
    }
    mass
}

/// The χ² statistic and its degrees of freedom for `samples` (directions
/// the sampler returned out of `n` draws) against `mass` (per-cell
/// probability; the lost mass, draws that returned nothing, is its own
/// cell).
pub fn chi2(samples: &[Vec3], n: usize, mass: &[f64]) -> (f64, usize) {
    let mut observed = vec![0.0f64; mass.len() + 1];
    for w in samples {
        observed[cell_of(*w)] += 1.0;
    }
    observed[mass.len()] = (n - samples.len()) as f64;
    let lost = (1.0 - mass.iter().sum::<f64>()).max(0.0);
    let expected: Vec<f64> = mass
        .iter()
        .chain(std::iter::once(&lost))
        .map(|m| m * n as f64)
        .collect();
    // Pool small cells.
    let (mut stat, mut dof) = (0.0, 0usize);
    let (mut pool_o, mut pool_e) = (0.0, 0.0);
    for (o, e) in observed.iter().zip(&expected) {
        if *e < 5.0 {
            pool_o += o;
            pool_e += e;
        } else {
            stat += (o - e) * (o - e) / e;
            dof += 1;
        }
    }
    if pool_e > 0.0 {
        stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e.max(1.0);
        dof += 1;
    }
    (stat, dof.saturating_sub(1))
}

/// The upper-tail p-value of χ² with `dof` degrees of freedom, by the
/// Wilson–Hilferty normal approximation (good for dof ≳ 10).
pub fn p_value(stat: f64, dof: usize) -> f64 {
    let k = dof.max(1) as f64;
    let z = ((stat / k).cbrt() - (1.0 - 2.0 / (9.0 * k))) / (2.0 / (9.0 * k)).sqrt();
    0.5 * erfc(z / std::f64::consts::SQRT_2)
}

/// The complementary error function (Numerical Recipes' erfcc, |error| <
/// 1.2e-7).
pub fn erfc(x: f64) -> f64 {
    // The exponent's polynomial in t, highest power first (Horner's rule;
    // written as a loop because the nested form makes rustfmt crawl).
    const C: [f64; 10] = [
        0.17087277,
        -0.82215223,
        1.48851587,
        -1.13520398,
        0.27886807,
        -0.18628806,
        0.09678418,
        0.37409196,
        1.00002368,
        -1.26551223,
    ];
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = C.iter().fold(0.0, |acc, c| acc * t + c);
    let r = t * (-z * z + poly).exp();
    if x >= 0.0 {
        r
    } else {
        2.0 - r
    }
}
