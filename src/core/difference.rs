//! Differences of two images as false colour on a fixed scale: what the
//! terminal UI's difference views and the grader's failure images show;
//! and a variance as a standard error.

use glam::Vec3;

use crate::core::film::Film;

impl Film {
    /// The signed difference `self − reference` as false colour on the
    /// fixed scale `scale`: red where `self` is brighter, blue where it is
    /// darker (by the channel that differs most), full at ±`scale`, black
    /// where they match, green ([`NONFINITE`]) where `self` is not a
    /// number or infinite.
    pub fn signed_difference(&self, reference: &Film, scale: f32) -> Film {
        self.difference_values(reference).colour_signed(scale)
    }

    /// The signed relative difference (`self − reference`) / reference, as
    /// [`Film::signed_difference`] shows it, full at ±`scale` (e.g. 0.5 for
    /// ±50%); see [`Film::relative_values`].
    pub fn signed_relative(&self, reference: &Film, scale: f32) -> Film {
        self.relative_values(reference).colour_signed(scale)
    }

    /// The signed difference `self − reference` per channel, as numbers:
    /// what a difference view averages before it colours, and what its
    /// EXR holds. A non-finite pixel of `self` stays non-finite.
    pub fn difference_values(&self, reference: &Film) -> Film {
        self.zip_with(reference, |a, b| a - b)
    }

    /// The signed relative difference (`self − reference`) / reference per
    /// channel; where the reference is darker than 1% of its mean, the
    /// difference is divided by that 1% instead.
    pub fn relative_values(&self, reference: &Film) -> Film {
        let mean = reference
            .pixels
            .iter()
            .map(|p| p.element_sum() as f64)
            .sum::<f64>()
            / (3.0 * reference.pixels.len().max(1) as f64);
        let floor = (0.01 * mean as f32).max(f32::MIN_POSITIVE);
        self.zip_with(reference, |a, b| (a - b) / b.abs().max(Vec3::splat(floor)))
    }

    fn zip_with(&self, reference: &Film, f: impl Fn(Vec3, Vec3) -> Vec3) -> Film {
        Film {
            width: self.width,
            height: self.height,
            pixels: self
                .pixels
                .iter()
                .zip(&reference.pixels)
                .map(|(a, b)| f(*a, *b))
                .collect(),
        }
    }

    /// Signed values (a difference, averaged or not) as false colour on
    /// the scale `scale`: each pixel by the channel that differs most,
    /// [`signed_colour`] of it over `scale`; a non-finite pixel is
    /// [`NONFINITE`], a colour no finite value takes.
    pub fn colour_signed(&self, scale: f32) -> Film {
        let pixels = self
            .pixels
            .iter()
            .map(|d| {
                if !d.is_finite() {
                    return NONFINITE;
                }
                let abs = d.abs();
                let most = if abs.x >= abs.y && abs.x >= abs.z {
                    d.x
                } else if abs.y >= abs.z {
                    d.y
                } else {
                    d.z
                };
                signed_colour(most / scale)
            })
            .collect();
        Film {
            width: self.width,
            height: self.height,
            pixels,
        }
    }
}

/// The colour of a non-finite pixel in a difference: green, which no
/// finite difference takes (those are red, blue or black).
pub const NONFINITE: Vec3 = Vec3::new(0.0, 1.0, 0.0);

/// The colour of a signed difference `s` in units of its scale: red for
/// positive, blue for negative, full at ±1, black at 0.
pub fn signed_colour(s: f32) -> Vec3 {
    let s = s.clamp(-1.0, 1.0);
    if s >= 0.0 {
        Vec3::new(s, 0.0, 0.0)
    } else {
        Vec3::new(0.0, 0.0, -s)
    }
}

impl Film {
    /// The square root of every channel, negatives taken as 0: a variance
    /// as a standard error.
    pub fn sqrt_clamped(mut self) -> Film {
        self.pixels
            .iter_mut()
            .for_each(|p| *p = p.max(Vec3::ZERO).powf(0.5));
        self
    }
}

/// tev's five error metrics of an image against a reference, each a mean
/// over pixels and channels (non-finite values left out): with d the
/// difference and r the reference, d, |d|, d², |d| / (r + ε) and
/// d² / (r² + ε), ε = 0.01.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Metrics {
    /// Mean d: a bias shows here, noise averages out.
    pub error: f64,
    /// Mean |d|.
    pub absolute: f64,
    /// Mean d², the MSE.
    pub squared: f64,
    /// Mean |d| / (r + ε).
    pub relative_absolute: f64,
    /// Mean d² / (r² + ε).
    pub relative_squared: f64,
}

/// [`Metrics`] of `image` against `reference` (the same size).
pub fn metrics(image: &Film, reference: &Film) -> Metrics {
    const EPS: f64 = 0.01;
    let mut m = Metrics::default();
    let mut n = 0.0;
    for (a, b) in image.pixels.iter().zip(&reference.pixels) {
        for c in 0..3 {
            let (a, r) = (f64::from(a[c]), f64::from(b[c]));
            let d = a - r;
            if !d.is_finite() {
                continue;
            }
            m.error += d;
            m.absolute += d.abs();
            m.squared += d * d;
            m.relative_absolute += d.abs() / (r.abs() + EPS);
            m.relative_squared += d * d / (r * r + EPS);
            n += 1.0;
        }
    }
    let n = f64::max(n, 1.0);
    Metrics {
        error: m.error / n,
        absolute: m.absolute / n,
        squared: m.squared / n,
        relative_absolute: m.relative_absolute / n,
        relative_squared: m.relative_squared / n,
    }
}
