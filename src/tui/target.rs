//! How far a progressive render goes: a [`Target`] of samples and noise,
//! and the rule [`finished`] that says when it is reached. Pure: the
//! worker applies it after every pass, the tests call it directly.

/// The noise estimate is trusted from this many samples per pixel on (with
/// fewer, a rare bright path is often not yet in the sample variance).
pub const MIN_SPP_FOR_NOISE: u32 = 16;

/// How far a progressive render goes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Target {
    /// The sample budget: samples per pixel at most.
    pub spp: u32,
    /// Stop once the noise estimate is at most this fraction of the
    /// image's mean value (`None`: only the budget stops).
    pub noise: Option<f64>,
}

impl Target {
    /// The default: up to 1024 samples per pixel, or until the noise
    /// estimate is 8% of the image's mean value, where the Cornell box
    /// looks clean (RMSE about 0.01 per pixel at 256x256; with Sobol
    /// numbers the estimate, which assumes independent samples, is about
    /// twice the true error).
    pub const DEFAULT: Target = Target {
        spp: 1024,
        noise: Some(0.08),
    };

    /// Twice the samples and the noise level they reach (noise falls as
    /// 1/√spp).
    pub fn doubled(self) -> Target {
        Target {
            spp: self.spp.saturating_mul(2).min(1 << 20),
            noise: self.noise.map(|n| n / std::f64::consts::SQRT_2),
        }
    }

    /// Half the samples (at least 1) and the noise level they reach.
    pub fn halved(self) -> Target {
        if self.spp <= 1 {
            return self;
        }
        Target {
            spp: self.spp / 2,
            noise: self.noise.map(|n| n * std::f64::consts::SQRT_2),
        }
    }
}

/// Why a progressive render stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Finish {
    /// The stage's own plan is complete (non-progressive stages).
    Complete,
    /// The noise estimate reached the target's level.
    Clean,
    /// The sample budget is spent.
    Budget,
}

/// Whether a render with `samples` per pixel, noise estimate `noise` and
/// image mean `mean` has reached `target`, and why. Noise is trusted only
/// from [`MIN_SPP_FOR_NOISE`] samples on.
pub fn finished(target: &Target, samples: u32, noise: Option<f64>, mean: f64) -> Option<Finish> {
    if samples >= target.spp {
        return Some(Finish::Budget);
    }
    let clean = match (noise, target.noise) {
        (Some(n), Some(level)) => samples >= MIN_SPP_FOR_NOISE && n <= level * mean,
        _ => false,
    };
    clean.then_some(Finish::Clean)
}
