//! Which vector instructions the fast engine's ray queries use, chosen
//! at run time: the one module with `unsafe` code (this file's dispatch
//! and the AVX vector type in `avx.rs`).
//!
//! The release build targets the x86-64 baseline (SSE2), so that the
//! binary runs on any x86-64 CPU. Each query's kernels
//! ([`super::kernels`], written once over a vector type) are compiled
//! three times: with the `wide` crate's vectors for the baseline (SSE2 on
//! x86-64, NEON on aarch64, the only path on other architectures), and
//! with one AVX register of eight lanes (`avx.rs`) for AVX2 and for
//! AVX-512 CPUs (with AVX-512 enabled the compiler may use its mask
//! registers). The shading's and the random numbers' lane loops are
//! compiled for each level too. [`Level::detect`] picks the widest
//! the CPU has; `RAYSTEP_SIMD` (`portable`, `avx2`, `avx512`) asks for a
//! narrower one.
//!
//! Every path computes the same bits: each lane's arithmetic is the same
//! IEEE operations in the same order, and neither Rust nor the kernel
//! fuses a multiply and an add (tests render with each path and compare
//! the bytes).

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;

use crate::ch5_reflection::world::RayQueries;

use super::bvh8::Bvh8;
use super::lanes::RayData;
use super::level::Level;
use super::shade8::{self, In8, Out8};
use crate::ch5_reflection::light::area::AreaLight;

/// The closest hit of `ray` in (0, t_max), with the instructions the
/// tree was built for ([`Bvh8::level`]).
///
/// Every dispatcher of this file that takes a tree reads the level from
/// the tree, never from its caller: `Bvh8::level` is a private field that
/// only `Bvh8::build` sets, to a level [`Level::available`] said this CPU
/// has, so no argument can send a CPU instructions it lacks.
#[inline]
pub fn closest(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    match bvh.level() {
        // SAFETY: `bvh.level()` is AVX-512 only if `Bvh8::build` found
        // that this CPU has every feature `closest_avx512` enables (the
        // list `Level::available` asks for), and the function needs
        // nothing else.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { closest_avx512(bvh, ray, t_max) },
        // SAFETY: as above, for AVX2 and `closest_avx2`'s features.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { closest_avx2(bvh, ray, t_max) },
        _ => closest_portable(bvh, ray, t_max),
    }
}

/// Whether anything is hit in (0, t_max), with the tree's instructions.
#[inline]
pub fn occluded(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    match bvh.level() {
        // SAFETY: as in `closest`: the level is the tree's.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { occluded_avx512(bvh, ray, t_max) },
        // SAFETY: as in `closest`: the level is the tree's.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { occluded_avx2(bvh, ray, t_max) },
        _ => occluded_portable(bvh, ray, t_max),
    }
}

/// [`closest`] in (0, ∞) for each of a round's `rays`, `hits[i]` for
/// `rays[i]` (`hits` is emptied first): one dispatch and one traversal
/// stack for the whole round, and the loop compiled with the tree's
/// instructions, so the per-ray call and set-up costs stay out of it.
pub fn closest_all(bvh: &Bvh8, rays: &[Ray], hits: &mut Vec<Option<Hit>>) {
    hits.clear();
    let stack = &mut vec![(0u32, 0f32); bvh.stack_size()];
    match bvh.level() {
        // SAFETY: as in `closest`: the level is the tree's.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { closest_all_avx512(bvh, rays, stack, hits) },
        // SAFETY: as in `closest`: the level is the tree's.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { closest_all_avx2(bvh, rays, stack, hits) },
        _ => {
            for ray in rays {
                hits.push(super::portable::closest(bvh, ray, f32::INFINITY, stack));
            }
        }
    }
}

/// [`closest_all`] for a round of camera rays, eight at a time through
/// the group traversal of [`packet`](super::packet) (the last few one at
/// a time), with the tree's instructions: the same lane loops on every
/// path, so the same bits.
pub fn closest_packets(bvh: &Bvh8, rays: &[Ray], hits: &mut Vec<Option<Hit>>) {
    hits.clear();
    hits.resize(rays.len(), None);
    match bvh.level() {
        // SAFETY: as in `closest`: the level is the tree's.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { closest_packets_avx512(bvh, rays, hits) },
        // SAFETY: as in `closest`: the level is the tree's.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { closest_packets_avx2(bvh, rays, hits) },
        _ => closest_packets_lanes(bvh, rays, hits),
    }
}

#[inline(always)]
fn closest_packets_lanes(bvh: &Bvh8, rays: &[Ray], hits: &mut [Option<Hit>]) {
    let eights = rays.len() / 8 * 8;
    let stack = &mut vec![(0u32, 0f32); bvh.stack_size()];
    for (r, h) in rays[..eights].chunks_exact(8).zip(hits.chunks_exact_mut(8)) {
        super::packet::closest8(bvh, r, h, stack);
    }
    for (ray, hit) in rays[eights..].iter().zip(&mut hits[eights..]) {
        *hit = bvh.closest_with(&RayData::new(ray), f32::INFINITY, stack);
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn closest_packets_avx2(bvh: &Bvh8, rays: &[Ray], hits: &mut [Option<Hit>]) {
    closest_packets_lanes(bvh, rays, hits)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn closest_packets_avx512(bvh: &Bvh8, rays: &[Ray], hits: &mut [Option<Hit>]) {
    closest_packets_lanes(bvh, rays, hits)
}

/// [`occluded`] for each of a round's shadow rays `(ray, t_max)`,
/// `blocked[i]` for `rays[i]` (`blocked` is emptied first), as
/// [`closest_all`] does it.
pub fn occluded_all(bvh: &Bvh8, rays: &[(Ray, f32)], blocked: &mut Vec<bool>) {
    blocked.clear();
    let stack = &mut vec![(0u32, 0f32); bvh.stack_size()];
    match bvh.level() {
        // SAFETY: as in `closest`: the level is the tree's.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { occluded_all_avx512(bvh, rays, stack, blocked) },
        // SAFETY: as in `closest`: the level is the tree's.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { occluded_all_avx2(bvh, rays, stack, blocked) },
        _ => {
            for (ray, t_max) in rays {
                blocked.push(super::portable::occluded(bvh, ray, *t_max, stack));
            }
        }
    }
}

impl RayQueries for Bvh8 {
    fn closest(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        closest(self, ray, t_max)
    }
    fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        occluded(self, ray, t_max)
    }
    fn describe(&self) -> String {
        format!(
            "the fast engine's BVH, 8 wide ({} nodes, {} leaves; {} instructions)",
            self.nodes.len(),
            self.leaves.len(),
            self.level().name()
        )
    }
}

/// A tree the engine and the world's queries share.
pub struct SharedTree(pub std::sync::Arc<Bvh8>);

impl RayQueries for SharedTree {
    fn closest(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        closest(&self.0, ray, t_max)
    }
    fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        occluded(&self.0, ray, t_max)
    }
    fn describe(&self) -> String {
        Bvh8::describe(&self.0)
    }
}

/// The widest level this CPU has (or `RAYSTEP_SIMD` asks for), found once.
pub fn best() -> Level {
    static BEST: std::sync::OnceLock<Level> = std::sync::OnceLock::new();
    *BEST.get_or_init(Level::detect)
}

/// One vertex of eight paths ([`shade8::shade8`]) with `level`'s
/// instructions: the same lane loops, compiled for AVX2's eight-lane
/// registers where the CPU has them, and with AVX-512's 32 registers and
/// mask registers where it has those (the same operations, so the same
/// bits).
#[inline]
pub(super) fn shade8_at(level: Level, x: &In8, o: &mut Out8) {
    match level {
        // SAFETY: `level.available()` checked that this CPU has AVX-512
        // and the rest of the list.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 if level.available() => unsafe { shade8_avx512(x, o) },
        // SAFETY: `level.available()` checked that this CPU has AVX2, all
        // the function needs.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 if level.available() => unsafe { shade8_avx2(x, o) },
        _ => shade8::shade8(x, o),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn shade8_avx2(x: &In8, o: &mut Out8) {
    shade8::shade8(x, o)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn shade8_avx512(x: &In8, o: &mut Out8) {
    shade8::shade8(x, o)
}

/// [`fill_light8`](super::pick8::fill_light8) with `level`'s
/// instructions (the same lane loops, so the same bits).
#[inline]
pub(super) fn fill_light8_at(level: Level, light: &AreaLight, p_choose: f32, x: &mut In8) -> bool {
    match level {
        // SAFETY: `level.available()` checked that this CPU has AVX-512
        // and the rest of the list.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 if level.available() => unsafe { fill_light8_avx512(light, p_choose, x) },
        // SAFETY: `level.available()` checked that this CPU has AVX2.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 if level.available() => unsafe { fill_light8_avx2(light, p_choose, x) },
        _ => super::pick8::fill_light8(light, p_choose, x),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn fill_light8_avx2(light: &AreaLight, p_choose: f32, x: &mut In8) -> bool {
    super::pick8::fill_light8(light, p_choose, x)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt")]
unsafe fn fill_light8_avx512(light: &AreaLight, p_choose: f32, x: &mut In8) -> bool {
    super::pick8::fill_light8(light, p_choose, x)
}

/// Entries of a traversal stack kept on the call stack: a small one for
/// small trees (up to 2 levels; clearing it is part of every query), a
/// larger one up to 9 levels (over 8^9 leaves), else one on the heap.
const SMALL_STACK: usize = 16;
const ON_STACK: usize = 64;

/// Runs `$query` with `$stack` a traversal stack big enough for `$bvh`.
/// (A macro, not a helper taking a closure: a closure is compiled
/// without the AVX features of its caller, and the kernels inside it
/// would become calls.)
macro_rules! with_stack {
    ($bvh:expr, |$stack:ident| $query:expr) => {{
        let n = $bvh.stack_size();
        if n <= SMALL_STACK {
            let $stack = &mut [(0u32, 0f32); SMALL_STACK];
            $query
        } else if n <= ON_STACK {
            let $stack = &mut [(0u32, 0f32); ON_STACK];
            $query
        } else {
            let $stack = &mut vec![(0, 0.0); n];
            $query
        }
    }};
}

#[inline(always)]
fn closest_portable(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
    with_stack!(bvh, |stack| super::portable::closest(
        bvh, ray, t_max, stack
    ))
}

#[inline(always)]
fn occluded_portable(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
    with_stack!(bvh, |stack| super::portable::occluded(
        bvh, ray, t_max, stack
    ))
}

#[cfg(target_arch = "x86_64")]
mod avx;
mod numbers;

pub use numbers::{
    independent8_at, independent8_wanted_at, sobol_groups8_at, sobol_groups8_wanted_at,
};

/// Defines one level's AVX entry points: a query for one ray and the
/// round loops of `closest_all` and `occluded_all`, all compiled with the
/// level's target features. They run the kernels with AVX's vector type
/// (`avx`), which keep the leaf test in registers and visit the same nodes
/// and leaves in the same order as the lane loops of `Bvh8::closest_with`,
/// so every path finds the same hit.
macro_rules! level_entries {
    (
        $closest:ident, $occluded:ident, $closest_all:ident, $occluded_all:ident,
        $avx:ident, $features:literal
    ) => {
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = $features)]
        unsafe fn $closest(bvh: &Bvh8, ray: &Ray, t_max: f32) -> Option<Hit> {
            let mut hit = None;
            with_stack!(bvh, |stack| avx::$avx::closest(
                bvh, ray, t_max, stack, &mut hit
            ));
            hit
        }

        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = $features)]
        unsafe fn $occluded(bvh: &Bvh8, ray: &Ray, t_max: f32) -> bool {
            with_stack!(bvh, |stack| avx::$avx::occluded(bvh, ray, t_max, stack))
        }

        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = $features)]
        unsafe fn $closest_all(
            bvh: &Bvh8,
            rays: &[Ray],
            stack: &mut [(u32, f32)],
            hits: &mut Vec<Option<Hit>>,
        ) {
            hits.resize(rays.len(), None);
            for (ray, hit) in rays.iter().zip(hits.iter_mut()) {
                avx::$avx::closest(bvh, ray, f32::INFINITY, stack, hit);
            }
        }

        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = $features)]
        unsafe fn $occluded_all(
            bvh: &Bvh8,
            rays: &[(Ray, f32)],
            stack: &mut [(u32, f32)],
            blocked: &mut Vec<bool>,
        ) {
            for (ray, t_max) in rays {
                blocked.push(avx::$avx::occluded(bvh, ray, *t_max, stack));
            }
        }
    };
}

level_entries!(
    closest_avx512,
    occluded_avx512,
    closest_all_avx512,
    occluded_all_avx512,
    v512,
    "avx512f,avx512vl,avx512bw,avx512dq,avx2,fma,bmi1,bmi2,lzcnt,popcnt"
);
level_entries!(
    closest_avx2,
    occluded_avx2,
    closest_all_avx2,
    occluded_all_avx2,
    v2,
    "avx2,fma,bmi1,bmi2,lzcnt,popcnt"
);
