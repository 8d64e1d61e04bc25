//! Differences of two images as false colour on a fixed scale: what the
//! terminal UI's difference views and the grader's failure images show.

use glam::Vec3;

use crate::core::film::Film;

impl Film {
    /// The signed difference `self − reference` as false colour on the
    /// fixed scale `scale`: red where `self` is brighter, blue where it is
    /// darker (by the channel that differs most), full at ±`scale`, black
    /// where they match, magenta where `self` is not a number or infinite.
    pub fn signed_difference(&self, reference: &Film, scale: f32) -> Film {
        self.signed_by(reference, scale, |d, _| d)
    }

    /// The signed relative difference (`self − reference`) / reference, as
    /// [`Film::signed_difference`] shows it, full at ±`scale` (e.g. 0.5 for
    /// ±50%); where the reference is darker than 1% of its mean, the
    /// difference is divided by that 1% instead.
    pub fn signed_relative(&self, reference: &Film, scale: f32) -> Film {
        let mean = reference
            .pixels
            .iter()
            .map(|p| p.element_sum() as f64)
            .sum::<f64>()
            / (3.0 * reference.pixels.len().max(1) as f64);
        let floor = (0.01 * mean as f32).max(f32::MIN_POSITIVE);
        self.signed_by(reference, scale, |d, r| d / r.abs().max(Vec3::splat(floor)))
    }

    fn signed_by(&self, reference: &Film, scale: f32, f: impl Fn(Vec3, Vec3) -> Vec3) -> Film {
        let mut out = Film::new(self.width, self.height);
        for ((o, a), b) in out
            .pixels
            .iter_mut()
            .zip(&self.pixels)
            .zip(&reference.pixels)
        {
            let diff = f(*a - *b, *b);
            if !diff.is_finite() {
                *o = Vec3::new(1.0, 0.0, 1.0);
                continue;
            }
            let abs = diff.abs();
            let most = if abs.x >= abs.y && abs.x >= abs.z {
                diff.x
            } else if abs.y >= abs.z {
                diff.y
            } else {
                diff.z
            };
            *o = signed_colour(most / scale);
        }
        out
    }
}

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
