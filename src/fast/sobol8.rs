//! The fast engine's random numbers for eight paths at once. Sobol points: the same bits
//! as [`sobol_group_by_table`](crate::ch6_global_illumination::sampler::sobol_group_by_table)
//! (and so as `sobol_burley::sample_4d`), each step one pass over eight
//! lanes of integers, so the compiler runs them in vector registers. And
//! independent numbers: `dimension_random`'s hash, lane by lane.

use sobol_burley::parts::{hash, owen_scramble_rev};

use crate::ch6_global_illumination::sampler::{byte_tables, owen_dim};
use crate::core::sampling::mix64;

/// Dimensions 4 `group` .. 4 `group` + 4 of Sobol samples `sample[j]` in
/// pixels with scramble seeds `pixel_scramble[j]`, for eight paths j:
/// `out[d][j]`. Every sample index must be below 2^16 (the tables' range).
#[inline(always)]
pub fn sobol_group8(sample: &[u32; 8], pixel_scramble: &[u64; 8], group: u64) -> [[f32; 8]; 4] {
    let [out] = sobol_groups8::<1>(sample, pixel_scramble, group);
    out
}

/// [`sobol_group8`] for `G` groups at once, `group` .. `group` + `G`:
/// `out[g][d][j]`. Each number is a long chain of dependent multiplies
/// (the seed's hash, the index shuffle, the scramble), so one group alone
/// keeps the processor waiting on them; the groups' chains are
/// independent, and computed side by side they overlap.
#[inline(always)]
pub fn sobol_groups8<const G: usize>(
    sample: &[u32; 8],
    pixel_scramble: &[u64; 8],
    group: u64,
) -> [[[f32; 8]; 4]; G] {
    sobol_groups8_wanted(sample, pixel_scramble, group, u32::MAX)
}

/// [`sobol_groups8`] of only the dimensions whose bits are set in
/// `wanted` (bit 4g + d for dimension d of group g); the others are 0.
/// The same bits where wanted: a path vertex of a diffuse scene draws
/// eight numbers and uses five or six of them.
// Lane loops index several arrays by lane, on purpose (vector code).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
pub fn sobol_groups8_wanted<const G: usize>(
    sample: &[u32; 8],
    pixel_scramble: &[u64; 8],
    group: u64,
    wanted: u32,
) -> [[[f32; 8]; 4]; G] {
    let (seed, rev) = sobol_indices8::<G>(sample, pixel_scramble, group);
    let t = byte_tables();
    let mut sobol = [[[0u32; 8]; 4]; G];
    for g in 0..G {
        for j in 0..8 {
            let (hi, lo) = (
                t[0][(rev[g][j] >> 24) as usize],
                t[1][((rev[g][j] >> 16) & 0xff) as usize],
            );
            for d in 0..4 {
                sobol[g][d][j] = hi[d] ^ lo[d];
            }
        }
    }
    sobol_finish8(&sobol, &seed, wanted)
}

/// The first steps of [`sobol_groups8`]: each group's scramble seed per
/// path, and each path's shuffled sample index in that group (reversed
/// bits), `[g][j]`.
// Lane loops index several arrays by lane, on purpose (vector code).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
pub fn sobol_indices8<const G: usize>(
    sample: &[u32; 8],
    pixel_scramble: &[u64; 8],
    group: u64,
) -> ([[u32; 8]; G], [[u32; 8]; G]) {
    let mut seed = [[0u32; 8]; G];
    let mut rev = [[0u32; 8]; G];
    for g in 0..G {
        for j in 0..8 {
            seed[g][j] = mix64(pixel_scramble[j] ^ (group + g as u64)) as u32;
        }
    }
    for g in 0..G {
        for j in 0..8 {
            rev[g][j] = owen_scramble_rev(sample[j].reverse_bits(), hash(seed[g][j] ^ 0x79c68e4a));
        }
    }
    (seed, rev)
}

/// The last steps of [`sobol_groups8`]: the Sobol points `sobol[g][d][j]`
/// (reversed bits) scrambled with their groups' seeds and turned into
/// numbers in [0, 1); only the dimensions `wanted` (bit 4g + d), the
/// others left 0.
// Lane loops index several arrays by lane, on purpose (vector code).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
pub fn sobol_finish8<const G: usize>(
    sobol: &[[[u32; 8]; 4]; G],
    seed: &[[u32; 8]; G],
    wanted: u32,
) -> [[[f32; 8]; 4]; G] {
    let mut out = [[[0.0f32; 8]; 4]; G];
    for g in 0..G {
        for d in 0..4 {
            if wanted >> (4 * g + d) & 1 == 0 {
                continue;
            }
            for j in 0..8 {
                out[g][d][j] = owen_dim(sobol[g][d][j], seed[g][j].wrapping_mul(0x9c8f2d3b), d);
            }
        }
    }
    out
}

/// The Sobol point of dimensions 0..4 as eight-entry tables, for look-ups
/// with a vector permute: table `c` holds, for each value v of three bits
/// of a reversed index (bits 16 + 3c .. 16 + 3c + 3; the last one only
/// bit 31), the XOR of those bits' direction numbers. A point is the XOR
/// of six look-ups, the same bits as the byte tables' two.
pub fn chunk_tables() -> &'static [[[u32; 8]; 4]; 6] {
    static TABLES: std::sync::OnceLock<[[[u32; 8]; 4]; 6]> = std::sync::OnceLock::new();
    TABLES.get_or_init(|| {
        let mut t = [[[0u32; 8]; 4]; 6];
        for (c, table) in t.iter_mut().enumerate() {
            let shift = 16 + 3 * c as u32;
            for v in 0..8u32 {
                // Bits past 31 do not exist: the last table's upper half
                // repeats its lower.
                let bits = if shift + 3 > 32 { v & 1 } else { v };
                let point: [u32; 4] = sobol_burley::parts::sobol_int4_rev(bits << shift, 0).into();
                for d in 0..4 {
                    table[d][v as usize] = point[d];
                }
            }
        }
        t
    })
}

/// Dimensions `first .. first + 8` of eight paths' independent numbers
/// (`prefix[j]`: each path's shared hash): `out[d][j]`, the same bits as
/// [`dimension_random`](crate::core::sampling::dimension_random).
#[inline(always)]
pub fn independent8(prefix: &[u64; 8], first: u64) -> [[f32; 8]; 8] {
    independent8_wanted(prefix, first, u8::MAX)
}

/// [`independent8`] of only the dimensions whose bits are set in
/// `wanted` (bit d for dimension `first + d`); the others are 0.
// Lane loops index several arrays by lane, on purpose (vector code).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
pub fn independent8_wanted(prefix: &[u64; 8], first: u64, wanted: u8) -> [[f32; 8]; 8] {
    let mut out = [[0.0f32; 8]; 8];
    for d in 0..8 {
        if wanted >> d & 1 == 0 {
            continue;
        }
        let dim = (first + d as u64).wrapping_mul(0xd6e8_feb8_6659_fd93);
        for j in 0..8 {
            let h = mix64(prefix[j] ^ dim);
            // The top 24 bits, exactly representable: as an i32 first, which
            // vector instructions convert directly (the same value).
            out[d][j] = ((h >> 40) as i32) as f32 * (1.0 / (1u64 << 24) as f32);
        }
    }
    out
}
