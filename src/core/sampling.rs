//! Deterministic random numbers.
//!
//! Every random number in raystep is a pure function of (seed, pixel,
//! sample index, dimension). There is no generator state to share between
//! threads, so an image is the same bytes whichever thread renders which
//! pixel, on 1 core or 64.

/// A 64-bit mixing function (the finaliser of SplitMix64): a good hash of
/// one integer into another.
#[inline]
pub fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A uniform number in [0, 1) for (seed, pixel, sample, dimension): the
/// hash of the sample ([`sample_hash`]), then of the dimension
/// ([`dimension_random`]). A sampler that draws many dimensions of one
/// sample hashes the sample once and keeps it (chapter 6's `PathSampler`).
// ANCHOR: random
#[inline]
pub fn random(seed: u64, pixel: u64, sample: u64, dimension: u64) -> f32 {
    dimension_random(sample_hash(seed, pixel, sample), dimension)
}

/// The hash of (seed, pixel, sample), shared by every dimension of that
/// sample.
#[inline]
pub fn sample_hash(seed: u64, pixel: u64, sample: u64) -> u64 {
    let mut h = mix64(seed ^ 0x9e37_79b9_7f4a_7c15);
    h = mix64(h ^ pixel);
    mix64(h ^ sample.wrapping_mul(0x2545_f491_4f6c_dd1d))
}

/// The number of dimension `dimension` of the sample hashed to `sample`
/// ([`sample_hash`]), uniform in [0, 1).
#[inline]
pub fn dimension_random(sample: u64, dimension: u64) -> f32 {
    let h = mix64(sample ^ dimension.wrapping_mul(0xd6e8_feb8_6659_fd93));
    // The top 24 bits give every float in [0, 1) a multiple of 2^-24 apart,
    // so the result is never 1.0.
    (h >> 40) as f32 * (1.0 / (1u64 << 24) as f32)
}
// ANCHOR_END: random

/// A sampler for one (seed, pixel, sample): each call to [`Sampler::next`]
/// takes the next dimension.
#[derive(Clone, Debug)]
pub struct Sampler {
    seed: u64,
    pixel: u64,
    sample: u64,
    dimension: u64,
}

impl Sampler {
    /// The sampler of sample `sample` of pixel `pixel`.
    pub fn new(seed: u64, pixel: u64, sample: u64) -> Sampler {
        Sampler {
            seed,
            pixel,
            sample,
            dimension: 0,
        }
    }

    /// The next number in [0, 1). (Not an iterator: it never ends.)
    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> f32 {
        let r = random(self.seed, self.pixel, self.sample, self.dimension);
        self.dimension += 1;
        r
    }

    /// Two numbers in [0, 1).
    pub fn next2(&mut self) -> glam::Vec2 {
        glam::Vec2::new(self.next(), self.next())
    }
}

/// The numbers of one sample, drawn in order: what a camera sample needs
/// of a sampler (chapter 3's `camera_sample` takes any), whether it is
/// [`Sampler`] or chapter 6's `PathSampler`.
pub trait SampleNumbers {
    /// The next two numbers in [0, 1).
    fn next2(&mut self) -> glam::Vec2;
}

impl SampleNumbers for Sampler {
    fn next2(&mut self) -> glam::Vec2 {
        Sampler::next2(self)
    }
}
