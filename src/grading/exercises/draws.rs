//! Inputs a check draws across an exercise's whole contract, new for every
//! grading run: the run's seed ([`crate::run_seed`]) is not
//! printed, so a solution cannot be fitted to them, and how many are drawn
//! changes too (a function right only for its first N calls meets more
//! than N). Scales from 10⁻³ to 10³, places far from the origin, grazing
//! and degenerate cases: what the hand cases cannot all cover.
//!
//! Every draw is a function of (run seed, check, draw, dimension), so the
//! student's process and the grader's replay draw the same inputs.

use glam::{Vec2, Vec3};

use crate::core::sampling::random;
use crate::run_seed;

/// The drawn inputs of one check.
pub struct Draws {
    seed: u64,
    case: u64,
    dim: u64,
}

impl Draws {
    /// The draws of the check named by `salt` in this run.
    pub fn new(salt: u64) -> Draws {
        let seed = run_seed()
            .wrapping_mul(0x9e37_79b9_7f4a_7c15)
            .rotate_left(17)
            ^ salt.wrapping_mul(0xbf58_476d_1ce4_e5b9);
        Draws {
            seed,
            case: 0,
            dim: 0,
        }
    }

    /// Moves on to the next case (its numbers start afresh).
    pub fn next_case(&mut self) {
        self.case += 1;
        self.dim = 0;
    }

    /// A uniform number in [0, 1).
    pub fn unit(&mut self) -> f32 {
        self.dim += 1;
        random(self.seed, self.case, 0, self.dim)
    }

    /// A uniform number in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit()
    }

    /// A whole number in [lo, hi].
    pub fn count(&mut self, lo: usize, hi: usize) -> usize {
        (lo + (self.unit() * (hi - lo + 1) as f32) as usize).min(hi)
    }

    /// 10^u with u uniform in [lo, hi): a scale spread evenly over its
    /// decades.
    pub fn decades(&mut self, lo: f32, hi: f32) -> f32 {
        10f32.powf(self.range(lo, hi))
    }

    /// With probability `share`, a scale far from 1: 10^u with u uniform
    /// in `small` or in `large`, each half the time; `None` otherwise.
    pub fn far_scale(&mut self, share: f32, small: (f32, f32), large: (f32, f32)) -> Option<f32> {
        self.far_exponent(share, small, large)
            .map(|u| 10f32.powf(u))
    }

    /// [`Draws::far_scale`]'s exponent u, for a scale past f32's range
    /// (10^u taken in f64).
    pub fn far_exponent(
        &mut self,
        share: f32,
        small: (f32, f32),
        large: (f32, f32),
    ) -> Option<f32> {
        match (self.unit() < share, self.sign() < 0.0) {
            (true, true) => Some(self.range(small.0, small.1)),
            (true, false) => Some(self.range(large.0, large.1)),
            (false, _) => None,
        }
    }

    /// ±1.
    pub fn sign(&mut self) -> f32 {
        if self.unit() < 0.5 {
            -1.0
        } else {
            1.0
        }
    }

    /// A point in the cube [-1, 1]³.
    pub fn in_cube(&mut self) -> Vec3 {
        Vec3::new(
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
        )
    }

    /// A point in the square [-1, 1]².
    pub fn in_square(&mut self) -> Vec2 {
        Vec2::new(self.range(-1.0, 1.0), self.range(-1.0, 1.0))
    }

    /// A unit direction, uniform on the sphere.
    pub fn direction(&mut self) -> Vec3 {
        let z = self.range(-1.0, 1.0);
        let phi = std::f32::consts::TAU * self.unit();
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    }

    /// A colour's channels kept (1) or turned off (0), each off with
    /// probability `p`: a pure green light, a surface black in red. Drawn
    /// from a stream of its own, the other draws of a case stay as they
    /// were.
    pub fn channels_off(&mut self, p: f32) -> Vec3 {
        let on = Vec3::new(self.unit(), self.unit(), self.unit()).cmpge(Vec3::splat(p));
        Vec3::select(on, Vec3::ONE, Vec3::ZERO)
    }

    /// Where a drawn object of size `scale` sits: the origin in a quarter
    /// of the cases, else up to `10^decades · scale` away (far enough that
    /// a solution which loses precision there fails, near enough that the
    /// rounding of the coordinates themselves leaves the answer well
    /// defined).
    pub fn place_for(&mut self, scale: f32, decades: f32) -> Vec3 {
        if self.unit() < 0.25 {
            return Vec3::ZERO;
        }
        let d = self.direction();
        d * scale * self.decades(0.0, decades)
    }

    /// A colour whose channels are each in [0.1, 1): nowhere black, so an
    /// answer is relative to a colour of its own size in every channel.
    pub fn colour(&mut self) -> Vec3 {
        Vec3::new(
            self.range(0.1, 1.0),
            self.range(0.1, 1.0),
            self.range(0.1, 1.0),
        )
    }

    /// Two points `dist` apart, the second skimming a plane through the
    /// origin across a drawn axis in which the first lies: (the plane's
    /// unit normal, ± the axis; the first point, up to 10 `dist` from the
    /// origin; the second, 10⁻¹² to 10⁻⁶ of `dist` above the plane). The
    /// cosine between the normal and the way from one to the other is then
    /// one exact coordinate over their distance, however small.
    pub fn skimming(&mut self, dist: f32) -> (Vec3, Vec3, Vec3) {
        let axis = self.count(0, 2);
        let normal = Vec3::AXES[axis] * self.sign();
        let mut from = self.place_for(dist, 1.0);
        from[axis] = 0.0;
        let mut way = self.direction();
        way[axis] = 0.0;
        let mut to = from + way.normalize_or(normal.any_orthonormal_vector()) * dist;
        to[axis] = normal[axis] * dist * self.decades(-12.0, -6.0);
        (normal, from, to)
    }

    /// A triangle's size: from 10⁻³ to 10³, and in a sixth of the cases
    /// at a millimetre and below (where an absolute ε shows).
    pub fn triangle_scale(&mut self) -> f32 {
        if self.unit() < 1.0 / 6.0 {
            self.decades(-3.5, -2.5)
        } else {
            self.decades(-3.0, 3.0)
        }
    }
}

/// The worst of the drawn cases: `cases` gives (error, what) for each,
/// a NaN error counting as infinite; (0, "") when none is above 0.
pub fn worst_drawn(cases: impl Iterator<Item = (f64, String)>) -> (f64, String) {
    let mut worst = (0.0f64, String::new());
    for (e, what) in cases {
        let e = if e.is_nan() { f64::INFINITY } else { e };
        if e > worst.0 {
            worst = (e, what);
        }
    }
    worst
}

/// Folds a drawn worst case into a check's (error, detail): the larger
/// error wins, and the drawn case's detail says it was drawn.
pub fn fold_drawn(error: &mut f64, detail: &mut String, drawn: (f64, String)) {
    if drawn.0 > *error || (drawn.0.is_nan() && !error.is_nan()) {
        *error = drawn.0;
        *detail = format!("{} (a drawn case)", drawn.1);
    }
}
