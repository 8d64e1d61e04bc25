//! The fast engine's random numbers with the CPU's vector instructions:
//! the same bits as the lane loops of [`sobol8`](super::super::sobol8) on
//! every path (a test compares them).
//!
//! SAFETY (for every `unsafe` block below): the AVX2 functions run only
//! where `Level::available` found AVX2, as each call site checks.

use super::super::level::Level;

/// [`sobol_groups8`](super::super::sobol8::sobol_groups8), groups `group` ..
/// `group + G` (one for the camera's pixel positions, two for a path
/// vertex's eight numbers), with `level`'s instructions (the same bits on
/// every path).
#[inline]
pub fn sobol_groups8_at<const G: usize>(
    level: Level,
    sample: &[u32; 8],
    pixel_scramble: &[u64; 8],
    group: u64,
) -> [[[f32; 8]; 4]; G] {
    sobol_groups8_wanted_at(level, sample, pixel_scramble, group, u32::MAX)
}

/// [`sobol_groups8_wanted`](super::super::sobol8::sobol_groups8_wanted) (only the
/// dimensions `wanted`) with `level`'s instructions.
#[inline]
pub fn sobol_groups8_wanted_at<const G: usize>(
    level: Level,
    sample: &[u32; 8],
    pixel_scramble: &[u64; 8],
    group: u64,
    wanted: u32,
) -> [[[f32; 8]; 4]; G] {
    match level {
        // SAFETY: `level.available()` checked that this CPU has AVX2, all
        // the function needs.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 | Level::Avx512 if level.available() => unsafe {
            sobol_groups8_avx2(sample, pixel_scramble, group, wanted)
        },
        _ => super::super::sobol8::sobol_groups8_wanted(sample, pixel_scramble, group, wanted),
    }
}

/// [`sobol_groups8`](super::super::sobol8::sobol_groups8) with the Sobol point
/// looked up by vector permutes ([`chunk_tables`](super::super::sobol8::chunk_tables)):
/// eight lanes' look-ups of a dimension in six permutes, where the byte
/// tables take two scalar loads per lane and a transpose. The same bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn sobol_groups8_avx2<const G: usize>(
    sample: &[u32; 8],
    pixel_scramble: &[u64; 8],
    group: u64,
    wanted: u32,
) -> [[[f32; 8]; 4]; G] {
    use std::arch::x86_64::*;
    let (seed, rev) = super::super::sobol8::sobol_indices8::<G>(sample, pixel_scramble, group);
    let t = super::super::sobol8::chunk_tables();
    let mut sobol = [[[0u32; 8]; 4]; G];
    for g in 0..G {
        // SAFETY: the CPU has AVX2 (the caller checked), and every load
        // and store reads or writes a whole `[u32; 8]`.
        unsafe {
            let r = _mm256_loadu_si256(rev[g].as_ptr().cast());
            let mut acc = [_mm256_setzero_si256(); 4];
            for (c, table) in t.iter().enumerate() {
                // A permute reads the low three bits of each lane's index.
                let index = _mm256_srlv_epi32(r, _mm256_set1_epi32(16 + 3 * c as i32));
                for d in 0..4 {
                    let entries = _mm256_loadu_si256(table[d].as_ptr().cast());
                    let v = _mm256_permutevar8x32_epi32(entries, index);
                    acc[d] = _mm256_xor_si256(acc[d], v);
                }
            }
            for d in 0..4 {
                _mm256_storeu_si256(sobol[g][d].as_mut_ptr().cast(), acc[d]);
            }
        }
    }
    super::super::sobol8::sobol_finish8(&sobol, &seed, wanted)
}

/// [`independent8`](super::super::sobol8::independent8) with `level`'s
/// instructions (the same bits on every path).
#[inline]
pub fn independent8_at(level: Level, prefix: &[u64; 8], first: u64) -> [[f32; 8]; 8] {
    independent8_wanted_at(level, prefix, first, u8::MAX)
}

/// [`independent8_wanted`](super::super::sobol8::independent8_wanted) (only the
/// dimensions `wanted`) with `level`'s instructions.
#[inline]
pub fn independent8_wanted_at(
    level: Level,
    prefix: &[u64; 8],
    first: u64,
    wanted: u8,
) -> [[f32; 8]; 8] {
    match level {
        // SAFETY: `level.available()` checked that this CPU has AVX2, all
        // the function needs.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 | Level::Avx512 if level.available() => unsafe {
            independent8_avx2(prefix, first, wanted)
        },
        _ => super::super::sobol8::independent8_wanted(prefix, first, wanted),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn independent8_avx2(prefix: &[u64; 8], first: u64, wanted: u8) -> [[f32; 8]; 8] {
    super::super::sobol8::independent8_wanted(prefix, first, wanted)
}
