//! A warp test, after Nori's `warptest`: does a sampling routine really
//! draw directions with the density its pdf claims? Draw many directions,
//! count how many fall in each cell of a grid over the sphere, compare the
//! counts with what the pdf predicts for each cell, and let Pearson's χ²
//! test give the verdict.
//!
//! The grid is in (cos θ, φ), so every cell has the same solid angle
//! (dω = d(cos θ) dφ). The expected count of a cell is n times the pdf
//! integrated over it (a midpoint rule on a finer grid, [`INTEGRATION_POINTS`]² per cell); cells expecting
//! fewer than [`MIN_EXPECTED`] draws are pooled into one, and draws that
//! returned no direction form a cell of their own, expected from the mass
//! the pdf leaves out. The terminal UI's warp view shows the directions,
//! both histograms and the verdict; chapter 5 supplies the routines
//! ([`crate::ch5_reflection::warp_test`]).

use std::f64::consts::PI;

use glam::{Vec2, Vec3};

use crate::core::sampling::random;

/// Cells in cos θ (from -1 to 1).
pub const COS_CELLS: usize = 16;
/// Cells in φ (from 0 to 2π).
pub const PHI_CELLS: usize = 32;
/// Cells expecting fewer draws than this are pooled (the usual rule for
/// the χ² approximation to hold).
pub const MIN_EXPECTED: f64 = 5.0;
/// The test rejects below this p-value.
pub const SIGNIFICANCE: f64 = 0.01;
/// Midpoint-rule points per cell side when integrating the pdf: a pdf
/// with an edge inside a cell (the area light's square) needs many.
pub const INTEGRATION_POINTS: usize = 48;
/// Draws per test unless told otherwise: about 400 per cell of the upper
/// hemisphere.
pub const DEFAULT_DRAWS: usize = 100_000;

/// A sampling routine the front ends can test by name: plain functions,
/// so a list of them can be a constant.
#[derive(Clone, Copy, Debug)]
pub struct WarpRoutine {
    /// A name for titles.
    pub name: &'static str,
    /// Draws a direction from two uniform numbers (or none).
    pub sample: fn(Vec2) -> Option<Vec3>,
    /// Its claimed density per steradian.
    pub pdf: fn(Vec3) -> f32,
}

impl WarpRoutine {
    /// Runs the test on this routine (see [`run`]).
    pub fn run(&self, draws: usize, seed: u64) -> WarpTest {
        run(
            &Warp {
                name: self.name,
                sample: &self.sample,
                pdf: &self.pdf,
            },
            draws,
            seed,
        )
    }
}

/// A student's sampling routine the warp view can test: the exercise that
/// holds it, a name for the title, and the density its contract names
/// (the student's own draws are made in the grader's sandbox).
#[derive(Clone, Copy, Debug)]
pub struct StudentWarp {
    /// The exercise, `chN/name`.
    pub id: &'static str,
    /// A name for titles.
    pub name: &'static str,
    /// The density the exercise's contract asks for, per steradian.
    pub pdf: fn(Vec3) -> f32,
}

/// A sampling routine to test: draws a direction from two uniform
/// numbers (or none), and says its density per steradian.
pub struct Warp<'a> {
    /// A name for titles.
    pub name: &'a str,
    /// The routine.
    pub sample: &'a dyn Fn(Vec2) -> Option<Vec3>,
    /// Its claimed density per steradian.
    pub pdf: &'a dyn Fn(Vec3) -> f32,
}

/// The outcome of a warp test.
#[derive(Clone, Debug, PartialEq)]
pub struct WarpTest {
    /// The routine's name.
    pub name: String,
    /// Draws made.
    pub draws: usize,
    /// The first few directions drawn, for a scatter plot.
    pub points: Vec<Vec3>,
    /// Draws per cell, `COS_CELLS × PHI_CELLS`, row `c` (cos θ) major.
    pub observed: Vec<f64>,
    /// Expected draws per cell from the pdf.
    pub expected: Vec<f64>,
    /// Draws that returned no direction, and how many the pdf expects.
    pub lost: (f64, f64),
    /// Pearson's χ² statistic.
    pub chi2: f64,
    /// Its degrees of freedom (cells after pooling, minus one).
    pub dof: usize,
    /// The probability of a χ² at least this large if the routine is right.
    pub p_value: f64,
    /// Directions that were not unit length or not finite.
    pub bad: usize,
}

impl WarpTest {
    /// Whether the routine passes (p ≥ [`SIGNIFICANCE`], every direction
    /// a finite unit vector).
    pub fn passes(&self) -> bool {
        self.bad == 0 && self.p_value >= SIGNIFICANCE
    }

    /// One line: χ², degrees of freedom, p and the verdict.
    pub fn verdict(&self) -> String {
        let bad = if self.bad > 0 {
            format!(", {} directions not unit length", self.bad)
        } else {
            String::new()
        };
        format!(
            "χ² = {:.1} with {} degrees of freedom, p = {:.3}{bad}: {}",
            self.chi2,
            self.dof,
            self.p_value,
            if self.passes() {
                "accepted"
            } else {
                "rejected"
            }
        )
    }
}

/// The cell of unit direction `w`.
pub fn cell_of(w: Vec3) -> usize {
    let c = ((w.z as f64 + 1.0) * 0.5 * COS_CELLS as f64).floor() as usize;
    let phi = (w.y as f64).atan2(w.x as f64).rem_euclid(2.0 * PI);
    let p = (phi / (2.0 * PI) * PHI_CELLS as f64).floor() as usize;
    c.min(COS_CELLS - 1) * PHI_CELLS + p.min(PHI_CELLS - 1)
}

/// The pdf integrated over every cell (midpoint rule, `sub`² points each).
pub fn cell_mass(pdf: &dyn Fn(Vec3) -> f32, sub: usize) -> Vec<f64> {
    let (dc, dp) = (2.0 / COS_CELLS as f64, 2.0 * PI / PHI_CELLS as f64);
    (0..COS_CELLS * PHI_CELLS)
        .map(|k| {
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
            sum * dc * dp / (sub * sub) as f64
        })
        .collect()
}

/// Runs the test: `draws` directions from `warp`, with numbers from
/// (`seed`, draw index, dimension).
pub fn run(warp: &Warp, draws: usize, seed: u64) -> WarpTest {
    draw(warp.sample, draws, seed).test(warp.name, warp.pdf)
}

/// What a routine drew: the counts per cell, the draws that returned no
/// direction or a bad one, and the first few directions. The half of a
/// warp test that runs the routine (in the grader's sandbox, for a
/// student's); [`Drawn::test`] is the other half.
#[derive(Clone, Debug, PartialEq)]
pub struct Drawn {
    /// Draws made.
    pub draws: usize,
    /// Draws per cell.
    pub observed: Vec<f64>,
    /// Draws that returned no direction.
    pub lost: f64,
    /// Directions that were not unit length or not finite.
    pub bad: usize,
    /// The first few directions, for a scatter plot.
    pub points: Vec<Vec3>,
}

/// Draws `draws` directions from `sample`, with numbers from (`seed`,
/// draw index, dimension), and counts them per cell.
pub fn draw(sample: &dyn Fn(Vec2) -> Option<Vec3>, draws: usize, seed: u64) -> Drawn {
    let mut observed = vec![0.0; COS_CELLS * PHI_CELLS];
    let (mut lost, mut bad) = (0.0, 0);
    let mut points = Vec::new();
    for i in 0..draws as u64 {
        let u = Vec2::new(random(seed, 0, i, 0), random(seed, 0, i, 1));
        match sample(u) {
            Some(w) if w.is_finite() && (w.length() - 1.0).abs() < 1e-3 => {
                observed[cell_of(w)] += 1.0;
                if points.len() < MAX_POINTS {
                    points.push(w);
                }
            }
            Some(_) => bad += 1,
            None => lost += 1.0,
        }
    }
    Drawn {
        draws,
        observed,
        lost,
        bad,
        points,
    }
}

/// Directions kept for the scatter plot.
pub const MAX_POINTS: usize = 4000;

impl Drawn {
    /// The test of these draws against `pdf`.
    pub fn test(self, name: &str, pdf: &dyn Fn(Vec3) -> f32) -> WarpTest {
        let n = self.draws as f64;
        let expected: Vec<f64> = cell_mass(pdf, INTEGRATION_POINTS)
            .iter()
            .map(|m| m * n)
            .collect();
        let lost_expected = (n - expected.iter().sum::<f64>()).max(0.0);
        let (chi2, dof) = pearson(&self.observed, &expected, (self.lost, lost_expected));
        WarpTest {
            name: name.to_string(),
            draws: self.draws,
            points: self.points,
            observed: self.observed,
            expected,
            lost: (self.lost, lost_expected),
            chi2,
            dof,
            p_value: chi2_survival(chi2, dof),
            bad: self.bad,
        }
    }

    /// As text, one `key value…` line each, for a child process to print.
    pub fn to_text(&self) -> String {
        let counts: Vec<String> = self.observed.iter().map(|c| c.to_string()).collect();
        let points: Vec<String> = self
            .points
            .iter()
            .map(|p| format!("{},{},{}", p.x, p.y, p.z))
            .collect();
        format!(
            "draws {}\nlost {}\nbad {}\nobserved {}\npoints {}\n",
            self.draws,
            self.lost,
            self.bad,
            counts.join(" "),
            points.join(" ")
        )
    }

    /// Reads [`Drawn::to_text`]'s text back; `None` when it is not that
    /// (wrong cell count, a number that does not parse, a count that does
    /// not add up).
    pub fn from_text(text: &str) -> Option<Drawn> {
        let field = |key: &str| {
            text.lines()
                .find_map(|l| l.strip_prefix(key)?.strip_prefix(' ').or(Some("")))
        };
        let draws: usize = field("draws")?.trim().parse().ok()?;
        let lost: f64 = field("lost")?.trim().parse().ok()?;
        let bad: usize = field("bad")?.trim().parse().ok()?;
        let observed: Vec<f64> = field("observed")?
            .split_whitespace()
            .map(|c| c.parse().ok())
            .collect::<Option<_>>()?;
        let points: Vec<Vec3> = field("points")?
            .split_whitespace()
            .map(|p| {
                let v: Vec<f32> = p
                    .split(',')
                    .map(|c| c.parse().ok())
                    .collect::<Option<_>>()?;
                (v.len() == 3).then(|| Vec3::new(v[0], v[1], v[2]))
            })
            .collect::<Option<_>>()?;
        let total = observed.iter().sum::<f64>() + lost + bad as f64;
        let ok = observed.len() == COS_CELLS * PHI_CELLS
            && observed.iter().all(|c| c.is_finite() && *c >= 0.0)
            && total == draws as f64
            && points.len() <= MAX_POINTS;
        ok.then_some(Drawn {
            draws,
            observed,
            lost,
            bad,
            points,
        })
    }
}

/// Pearson's statistic Σ (O − E)² / E over the cells and the "no
/// direction" cell, cells expecting fewer than [`MIN_EXPECTED`] pooled
/// into one; with its degrees of freedom (cells used − 1).
pub fn pearson(observed: &[f64], expected: &[f64], lost: (f64, f64)) -> (f64, usize) {
    let (mut stat, mut cells) = (0.0, 0usize);
    let (mut pool_o, mut pool_e) = (0.0, 0.0);
    let all = observed
        .iter()
        .zip(expected)
        .map(|(o, e)| (*o, *e))
        .chain(std::iter::once(lost));
    for (o, e) in all {
        if e < MIN_EXPECTED {
            pool_o += o;
            pool_e += e;
        } else {
            stat += (o - e) * (o - e) / e;
            cells += 1;
        }
    }
    if pool_e >= MIN_EXPECTED {
        stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        cells += 1;
    } else if pool_o > 0.0 {
        // Draws where the pdf says there should be (almost) none: as
        // wrong as it gets, whatever the pooled expectation.
        stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e.max(1.0);
        cells += 1;
    }
    (stat, cells.saturating_sub(1).max(1))
}

/// P(X ≥ x) for X χ²-distributed with `dof` degrees of freedom: the
/// regularised upper incomplete gamma function Q(dof/2, x/2), by its series
/// below a + 1 and its continued fraction above (Numerical Recipes §6.2).
pub fn chi2_survival(x: f64, dof: usize) -> f64 {
    let (a, x) = (dof as f64 / 2.0, x / 2.0);
    if !x.is_finite() {
        // An infinite statistic (or NaN from a broken routine): reject.
        return 0.0;
    }
    if x <= 0.0 {
        return 1.0;
    }
    let ln_prefix = a * x.ln() - x - ln_gamma(a);
    if x < a + 1.0 {
        // P(a, x) = e^-x x^a / Γ(a+1) Σ x^n / ((a+1)…(a+n)).
        let (mut term, mut sum, mut ap) = (1.0 / a, 1.0 / a, a);
        for _ in 0..1000 {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if term.abs() < sum.abs() * 1e-15 {
                break;
            }
        }
        (1.0 - sum * ln_prefix.exp()).clamp(0.0, 1.0)
    } else {
        // Lentz's method for the continued fraction of Q(a, x).
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..1000 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-15 {
                break;
            }
        }
        (ln_prefix.exp() * h).clamp(0.0, 1.0)
    }
}

/// ln Γ(a) for a > 0 (Lanczos, g = 7, nine terms: about 15 digits).
pub fn ln_gamma(a: f64) -> f64 {
    const G: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if a < 0.5 {
        // Reflection: Γ(a) Γ(1 − a) = π / sin(πa).
        return (PI / (PI * a).sin()).ln() - ln_gamma(1.0 - a);
    }
    let a = a - 1.0;
    let mut x = G[0];
    for (i, g) in G.iter().enumerate().skip(1) {
        x += g / (a + i as f64);
    }
    let t = a + 7.5;
    0.5 * (2.0 * PI).ln() + (a + 0.5) * t.ln() - t + x.ln()
}
