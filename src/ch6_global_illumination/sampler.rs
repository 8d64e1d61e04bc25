//! Where a path's random numbers come from: independent numbers, or a
//! low-discrepancy sequence (Owen-scrambled Sobol, the `sobol_burley`
//! crate). Either way every number is a pure function of (seed, pixel,
//! sample index, dimension), so images do not depend on threads.

use glam::Vec2;

use crate::core::sampling::{dimension_random, mix64, sample_hash};

/// Which numbers drive the paths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SamplerKind {
    /// Independent uniform numbers ([`crate::core::sampling::random`]).
    Independent,
    /// Owen-scrambled Sobol points (Burley 2020), scrambled per pixel, in
    /// independently scrambled groups of four dimensions ("padding"), so a
    /// path of any length gets well-spread numbers in every group. Sample
    /// indices past 2^16 (the crate's limit) fall back to independent
    /// numbers.
    Sobol,
}

impl SamplerKind {
    /// A short name for tables and file names.
    pub fn name(self) -> &'static str {
        match self {
            SamplerKind::Independent => "independent",
            SamplerKind::Sobol => "sobol",
        }
    }

    /// The Russian roulette scale s that suits these numbers (survive with
    /// q = min(1, s · max β)), unless the settings say otherwise
    /// ([`PathSettings::rr_scale`](super::integrator::PathSettings::rr_scale)):
    /// 1 for independent numbers, 2 for Sobol points, whose other noise is
    /// smaller, so the noise roulette adds costs them more (the book's
    /// appendix "Making it fast" measures both scales with both samplers,
    /// `ch6-bench-rr-scale-1.txt` and `-2.txt`).
    pub fn roulette_scale(self) -> u32 {
        match self {
            SamplerKind::Independent => 1,
            SamplerKind::Sobol => 2,
        }
    }
}

/// The numbers of one sample of one pixel, one dimension after another.
#[derive(Clone, Debug)]
pub struct PathSampler {
    kind: SamplerKind,
    sample: u64,
    dimension: u64,
    /// [`crate::core::sampling::random`]'s hash of (seed, pixel, sample), which
    /// every dimension shares: computed once, so each number costs one mix
    /// (only for independent numbers; 0 where the Sobol tables answer).
    prefix: u64,
    /// The Sobol scramble seed of this pixel (one more mix per group of
    /// four dimensions; 0 for independent numbers).
    pixel_scramble: u64,
    /// The Sobol group whose four numbers are in `group_values`
    /// (`u64::MAX`: none yet).
    group: u64,
    /// The four numbers of that group, computed together (the crate's
    /// `sample_4d` does all four with SIMD at the cost of about one).
    group_values: [f32; 4],
}

/// The largest sample index the Sobol tables cover.
const SOBOL_MAX_SAMPLES: u64 = 1 << 16;

impl crate::core::sampling::SampleNumbers for PathSampler {
    fn next2(&mut self) -> Vec2 {
        PathSampler::next2(self)
    }
}

impl PathSampler {
    /// The sampler of sample `sample` of pixel `pixel`.
    pub fn new(kind: SamplerKind, seed: u64, pixel: u64, sample: u64) -> PathSampler {
        let sobol = kind == SamplerKind::Sobol && sample < SOBOL_MAX_SAMPLES;
        PathSampler {
            kind,
            sample,
            dimension: 0,
            // What `random(seed, pixel, sample, d)` hashes before `d`, for
            // the samplers that draw independent numbers (0, unused, for the
            // others: the hash is most of the cost of a new sampler).
            prefix: if sobol {
                0
            } else {
                sample_hash(seed, pixel, sample)
            },
            pixel_scramble: if kind == SamplerKind::Sobol {
                mix64(seed ^ mix64(pixel))
            } else {
                0
            },
            group: u64::MAX,
            group_values: [0.0; 4],
        }
    }

    /// Where its numbers come from.
    pub fn kind(&self) -> SamplerKind {
        self.kind
    }

    /// The sample index, when this sampler draws Sobol points from the
    /// byte tables (`None`: independent numbers, or an index past them).
    pub fn sobol_index(&self) -> Option<u32> {
        (self.kind == SamplerKind::Sobol && self.sample < SOBOL_MAX_SAMPLES)
            .then_some(self.sample as u32)
    }

    /// The hash every number shares, when this sampler draws independent
    /// numbers (`dimension_random(prefix, d)`; `None`: Sobol points).
    pub fn independent_prefix(&self) -> Option<u64> {
        self.sobol_index().is_none().then_some(self.prefix)
    }

    /// The Sobol scramble seed of this pixel.
    pub fn pixel_scramble(&self) -> u64 {
        self.pixel_scramble
    }

    /// The next number in [0, 1). (Not an iterator: it never ends.)
    #[inline]
    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> f32 {
        let d = self.dimension;
        self.dimension += 1;
        match self.kind {
            SamplerKind::Sobol if self.sample < SOBOL_MAX_SAMPLES => {
                let group = d / 4;
                if group != self.group {
                    self.group = group;
                    self.group_values =
                        sobol_group_by_table(self.sample, self.pixel_scramble, group);
                }
                self.group_values[(d % 4) as usize]
            }
            _ => {
                // The last step of `random`: the same number, one mix.
                dimension_random(self.prefix, d)
            }
        }
    }

    /// The next two numbers.
    #[inline]
    pub fn next2(&mut self) -> Vec2 {
        let x = self.next();
        Vec2::new(x, self.next())
    }

    /// The eight numbers of dimensions `first .. first + 8` (`first` a
    /// multiple of four), the same bits [`PathSampler::next`] would give
    /// them: what one path vertex draws, for a loop that draws them all at
    /// once (the fast engine's wavefront).
    pub fn eight_at(&self, first: u64) -> [f32; 8] {
        debug_assert!(first.is_multiple_of(4));
        match self.sobol_index() {
            Some(_) => {
                let a = sobol_group_by_table(self.sample, self.pixel_scramble, first / 4);
                let b = sobol_group_by_table(self.sample, self.pixel_scramble, first / 4 + 1);
                [a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]]
            }
            None => std::array::from_fn(|i| dimension_random(self.prefix, first + i as u64)),
        }
    }

    /// Skips `n` numbers, as if they had been drawn (for a loop that drew
    /// them for several samplers at once).
    pub fn skip(&mut self, n: u64) {
        self.dimension += n;
    }

    /// Skips to the first dimension of the next group of four, so each
    /// bounce starts its numbers in a fresh Sobol group.
    #[inline]
    pub fn align(&mut self) {
        self.dimension = self.dimension.div_ceil(4) * 4;
    }
}

/// Dimensions 4g .. 4g + 4 of Sobol sample `sample` in a pixel with
/// scramble seed `pixel_scramble`: the four dimensions of the crate's first
/// set, scrambled with a seed of their own per group.
// ANCHOR: sobol_group
pub fn sobol_group(sample: u64, pixel_scramble: u64, group: u64) -> [f32; 4] {
    let scramble = mix64(pixel_scramble ^ group) as u32;
    sobol_burley::sample_4d(sample as u32, 0, scramble).map(|u| u.min(1.0 - f32::EPSILON / 2.0))
}
// ANCHOR_END: sobol_group

/// [`sobol_group`] with its slowest step, the Sobol point itself (up to
/// sixteen XORs of direction numbers, one per bit of the shuffled index),
/// replaced by two table lookups: the point is linear in the index's bits,
/// so the XOR of the directions of each byte's bits can be stored once for
/// all 256 values of each of the index's two bytes. Every other step is
/// the crate's, the last ones ([`owen_finish`]) in integer lanes the CPU's
/// vector instructions run, so the numbers are the same bits as
/// [`sobol_group`]'s (a test compares them); this is what the path tracer
/// calls.
// ANCHOR: sobol_by_table
pub fn sobol_group_by_table(sample: u64, pixel_scramble: u64, group: u64) -> [f32; 4] {
    use sobol_burley::parts::{hash, owen_scramble_rev};
    let seed = mix64(pixel_scramble ^ group) as u32;
    // The crate's `sample_4d(sample, 0, seed)`, step by step.
    let rev = owen_scramble_rev((sample as u32).reverse_bits(), hash(seed ^ 0x79c68e4a));
    let t = byte_tables();
    let (hi, lo) = (
        t[0][(rev >> 24) as usize],
        t[1][((rev >> 16) & 0xff) as usize],
    );
    let sobol = std::array::from_fn(|d| hi[d] ^ lo[d]);
    owen_finish(sobol, seed)
}
// ANCHOR_END: sobol_by_table

/// For each byte of a reversed sample index (bits 31..24, then 23..16;
/// the crate uses the top 16), the XOR of the direction numbers of its set
/// bits, for all 256 values: dimension set 0's Sobol point of any index is
/// then `t[0][top byte] ^ t[1][next byte]`.
pub fn byte_tables() -> &'static [[[u32; 4]; 256]; 2] {
    static TABLES: std::sync::OnceLock<Box<[[[u32; 4]; 256]; 2]>> = std::sync::OnceLock::new();
    TABLES.get_or_init(|| {
        let mut t = Box::new([[[0u32; 4]; 256]; 2]);
        for (k, table) in t.iter_mut().enumerate() {
            for (b, entry) in table.iter_mut().enumerate() {
                let rev = (b as u32) << (24 - 8 * k);
                *entry = sobol_burley::parts::sobol_int4_rev(rev, 0).into();
            }
        }
        t
    })
}

/// The crate's per-dimension scramble constants of dimension set 0.
const DIMENSION: [u32; 4] = [0x912f69ba, 0x174f18ab, 0x691e72ca, 0xb40cc1b8];

/// The last steps of the crate's `sample_4d` for dimension `d` of a Sobol
/// point `n` (reversed bits), with `s` the seed times the crate's
/// multiplier: the Owen scramble with the dimension's own seed, the bits
/// put back in order, the conversion to [0, 1).
#[inline(always)]
pub fn owen_dim(mut n: u32, s: u32, d: usize) -> f32 {
    // The crate's `hash_int4` of the dimension's scramble seed.
    let mut h = s ^ DIMENSION[d] ^ 0xe6fe3beb;
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846ca68b);
    h ^= h >> 16;
    // Its `owen_scramble_int4_rev`.
    n ^= n.wrapping_mul(0x3d20adea);
    n = n.wrapping_add(h);
    n = n.wrapping_mul((h >> 16) | 1);
    n ^= n.wrapping_mul(0x05526c56);
    n ^= n.wrapping_mul(0x53a22864);
    let n = n.reverse_bits();
    let u = f32::from_bits((n >> 9) | 0x3f800000) - 1.0;
    u.min(1.0 - f32::EPSILON / 2.0)
}

/// The last steps of the crate's `sample_4d` on a Sobol point's four
/// dimensions (reversed bits): the Owen scramble with a seed per dimension,
/// the bits put back in order, the conversion to [0, 1). Written lane by
/// lane in integers, so that the compiler can run the four lanes in one
/// vector register, and any width gives the same bits.
#[inline(always)]
pub fn owen_finish(sobol: [u32; 4], seed: u32) -> [f32; 4] {
    let s = seed.wrapping_mul(0x9c8f2d3b);
    std::array::from_fn(|d| owen_dim(sobol[d], s, d))
}
