//! Which vector instructions the fast engine's ray queries use, chosen
//! at run time, and the one place with `unsafe` code.
//!
//! The release build targets the x86-64 baseline (SSE2), so that the
//! binary runs on any x86-64 CPU. The queries' lane loops are compiled
//! three times: for AVX-512, for AVX2, and for the baseline (the
//! portable path, which is also the only one on other architectures).
//! [`Level::detect`] picks the widest the CPU has; `RAYSTEP_SIMD`
//! (`portable`, `avx2`, `avx512`) asks for a narrower one.
//!
//! Every path computes the same bits: each lane's arithmetic is the same
//! IEEE operations in the same order whatever the vector width, and Rust
//! never fuses a multiply and an add on its own (tests render with each
//! path and compare the bytes).

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;

use super::bvh8::{Bvh8, RayData};

/// A set of vector instructions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    /// The build's baseline (SSE2 on x86-64).
    Portable,
    /// AVX2 and FMA (x86-64).
    Avx2,
    /// AVX-512 F, VL, BW and DQ (x86-64).
    Avx512,
}

impl Level {
    /// Every level, narrowest first.
    pub const ALL: [Level; 3] = [Level::Portable, Level::Avx2, Level::Avx512];

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Level::Portable => "portable",
            Level::Avx2 => "avx2",
            Level::Avx512 => "avx512",
        }
    }

    /// Whether this CPU has the level's instructions.
    pub fn available(self) -> bool {
        #[cfg(target_arch = "x86_64")]
        {
            match self {
                Level::Portable => true,
                Level::Avx2 => {
                    std::arch::is_x86_feature_detected!("avx2")
                        && std::arch::is_x86_feature_detected!("fma")
                }
                Level::Avx512 => {
                    Level::Avx2.available()
                        && std::arch::is_x86_feature_detected!("avx512f")
                        && std::arch::is_x86_feature_detected!("avx512vl")
                        && std::arch::is_x86_feature_detected!("avx512bw")
                        && std::arch::is_x86_feature_detected!("avx512dq")
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            self == Level::Portable
        }
    }

    /// The widest level this CPU has, or the one `RAYSTEP_SIMD` names
    /// if the CPU has it (a name it does not know, or a level the CPU
    /// lacks, is ignored with a warning on stderr).
    pub fn detect() -> Level {
        let best = Level::ALL
            .into_iter()
            .rev()
            .find(|l| l.available())
            .unwrap_or(Level::Portable);
        let Ok(asked) = std::env::var("RAYSTEP_SIMD") else {
            return best;
        };
        match Level::ALL.into_iter().find(|l| l.name() == asked) {
            Some(l) if l.available() => l,
            Some(l) => {
                eprintln!(
                    "RAYSTEP_SIMD={asked}: this CPU has no {}; using {}",
                    l.name(),
                    best.name()
                );
                best
            }
            None => {
                eprintln!(
                    "RAYSTEP_SIMD={asked}: expected portable, avx2 or avx512; using {}",
                    best.name()
                );
                best
            }
        }
    }
}

/// The closest hit of `ray` in (0, t_max) with `level`'s instructions.
#[inline]
pub fn closest(level: Level, bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    match level {
        // SAFETY: a `Bvh8` holds only levels `Level::available` said this
        // CPU has (`Bvh8::build` checks), and the function needs nothing
        // else than those instructions.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { closest_avx512(bvh, ray, t_max) },
        // SAFETY: as above.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { closest_avx2(bvh, ray, t_max) },
        _ => closest_lanes(bvh, ray, t_max),
    }
}

/// Whether anything is hit in (0, t_max), with `level`'s instructions.
#[inline]
pub fn occluded(level: Level, bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    match level {
        // SAFETY: as in `closest`.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { occluded_avx512(bvh, ray, t_max) },
        // SAFETY: as in `closest`.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { occluded_avx2(bvh, ray, t_max) },
        _ => occluded_lanes(bvh, ray, t_max),
    }
}

/// Entries of a traversal stack kept on the call stack; deeper trees
/// (more than 9 levels, over 8^9 leaves) get one on the heap.
const ON_STACK: usize = 64;

#[inline(always)]
fn closest_lanes(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    let r = RayData::new(ray);
    if bvh.stack_size() <= ON_STACK {
        let mut stack = [(0u32, 0f32); ON_STACK];
        bvh.closest_with(&r, t_max, &mut stack)
    } else {
        bvh.closest_with(&r, t_max, &mut vec![(0, 0.0); bvh.stack_size()])
    }
}

#[inline(always)]
fn occluded_lanes(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    let r = RayData::new(ray);
    if bvh.stack_size() <= ON_STACK {
        let mut stack = [(0u32, 0f32); ON_STACK];
        bvh.occluded_with(&r, t_max, &mut stack)
    } else {
        bvh.occluded_with(&r, t_max, &mut vec![(0, 0.0); bvh.stack_size()])
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn closest_avx512(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    closest_lanes(bvh, ray, t_max)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn closest_avx2(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    closest_lanes(bvh, ray, t_max)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn occluded_avx512(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    occluded_lanes(bvh, ray, t_max)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn occluded_avx2(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    occluded_lanes(bvh, ray, t_max)
}
