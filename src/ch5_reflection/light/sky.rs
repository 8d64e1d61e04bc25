//! A sky-gradient environment: radiance grows linearly with the height y
//! of the direction (world +y is up), from `horizon` at y = 0 to `zenith`
//! at y = 1; every direction below the horizon sees `ground`.
//!
//! Sampling it as a light follows its brightness (the mean of the three
//! channels): first the upper or lower hemisphere by their power, then, in
//! the upper one, the height y from the linear density h + (z − h) y by
//! inverting its quadratic CDF, and the azimuth uniformly. The pdf does not
//! depend on the surface, so a sample may fall below it and is then lost.

use std::f32::consts::PI;

use glam::{Vec2, Vec3};

/// The sky's three colours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sky {
    /// Radiance straight up.
    pub zenith: Vec3,
    /// Radiance along the horizon.
    pub horizon: Vec3,
    /// Radiance from below.
    pub ground: Vec3,
}

fn mean(v: Vec3) -> f32 {
    (v.x + v.y + v.z) / 3.0
}

impl Sky {
    /// Radiance arriving from the unit direction `w`.
    // ANCHOR: sky_radiance
    pub fn radiance(&self, w: Vec3) -> Vec3 {
        if w.y >= 0.0 {
            self.horizon + (self.zenith - self.horizon) * w.y.min(1.0)
        } else {
            self.ground
        }
    }
    // ANCHOR_END: sky_radiance

    /// Irradiance on a surface facing straight up: ∫ L cos θ dω =
    /// π·horizon + (2π/3)·(zenith − horizon).
    pub fn irradiance_up(&self) -> Vec3 {
        PI * self.horizon + (2.0 * PI / 3.0) * (self.zenith - self.horizon)
    }

    /// Probability of sampling the upper hemisphere: its share of the power
    /// π(h + z) against the ground's 2π g.
    fn upper_probability(&self) -> f32 {
        let up = PI * (mean(self.horizon) + mean(self.zenith));
        let down = 2.0 * PI * mean(self.ground);
        if up + down > 0.0 {
            up / (up + down)
        } else {
            0.0
        }
    }

    /// Whether the sky has any light at all.
    pub fn is_dark(&self) -> bool {
        self.zenith.max_element() <= 0.0
            && self.horizon.max_element() <= 0.0
            && self.ground.max_element() <= 0.0
    }

    /// A direction drawn by brightness (see the module doc).
    pub fn sample(&self, u: Vec2) -> Vec3 {
        let p_up = self.upper_probability();
        let phi = 2.0 * PI * u.y;
        let y = if u.x < p_up {
            // Reuse u.x: rescaled, it is uniform in [0, 1) again.
            let v = (u.x / p_up).min(1.0);
            // The answer depends only on the ratio of h to z: scaled to
            // the larger, the squares below cannot overflow (a sky of 1e20
            // squared is past f32's 3.4e38).
            let (h, z) = (mean(self.horizon), mean(self.zenith));
            let s = h.max(z);
            let (h, z) = if s > 0.0 { (h / s, z / s) } else { (h, z) };
            // Solve (z − h)/2 y² + h y = v (h + z)/2 in the stable form
            // y = v (h + z) / (h + √(h² + v (z² − h²))).
            let den = h + (h * h + v * (z * z - h * h)).max(0.0).sqrt();
            if den > 0.0 {
                (v * (h + z) / den).clamp(0.0, 1.0)
            } else {
                v
            }
        } else {
            let v = ((u.x - p_up) / (1.0 - p_up)).clamp(0.0, 1.0);
            -v
        };
        let r = (1.0 - y * y).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), y, r * phi.sin())
    }

    /// The solid-angle pdf of [`Sky::sample`].
    pub fn pdf(&self, w: Vec3) -> f32 {
        let p_up = self.upper_probability();
        if w.y >= 0.0 {
            let (h, z) = (mean(self.horizon), mean(self.zenith));
            if h + z <= 0.0 {
                return 0.0;
            }
            p_up * (h + (z - h) * w.y.min(1.0)).max(0.0) / (PI * (h + z))
        } else {
            (1.0 - p_up) / (2.0 * PI)
        }
    }
}
