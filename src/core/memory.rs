//! Memory refused before it runs out. A run's largest allocations grow
//! with its pixels (film, layers, views, the encoded outputs) and its
//! triangles (the mesh, the trees); each chapter states its measured bytes
//! per pixel and per triangle ([`ChapterInfo::bytes_per_pixel`],
//! [`ChapterInfo::bytes_per_triangle`]), and [`check`] refuses a run whose
//! estimate exceeds what this process may still get: its address-space
//! limit (`ulimit -v`, as a course's sandbox or a CI runner sets), its
//! control group's limit, and the memory the machine has available. A
//! refused run is an error that says so; an allocation that fails aborts
//! the process (exit 134) with no word about why.

use crate::core::error::{Error, Result};
use crate::core::stage::ChapterInfo;
use crate::scene::Scene;

/// Address space a run takes besides its pixels and triangles: the
/// program, its threads' stacks and the allocator's per-thread arenas.
pub const BASE_BYTES: u64 = 256 << 20;

/// What a run of `info`'s chapter on `scene` (at its size) will allocate,
/// about, in bytes: an upper bound from measured peaks (see the chapters'
/// `bytes_per_pixel`).
pub fn estimate(info: &ChapterInfo, scene: &Scene) -> u64 {
    let pixels = scene.camera.width as u64 * scene.camera.height as u64;
    BASE_BYTES
        .saturating_add(pixels.saturating_mul(info.bytes_per_pixel))
        .saturating_add((scene.triangle_count() as u64).saturating_mul(info.bytes_per_triangle))
}

/// The most this process may still allocate, and what limits it; `None`
/// where nothing can be told (not Linux).
pub fn available() -> Option<(u64, &'static str)> {
    let mut best: Option<(u64, &'static str)> = None;
    let mut take = |bytes: Option<u64>, what: &'static str| {
        if let Some(b) = bytes {
            if best.is_none_or(|(a, _)| b < a) {
                best = Some((b, what));
            }
        }
    };
    take(address_space_left(), "the address-space limit (ulimit -v)");
    take(cgroup_left(), "the control group's memory limit");
    take(meminfo_available(), "the memory this machine has available");
    best
}

/// Refuses a run of `info`'s chapter on `scene` that would need more than
/// [`available`] gives, naming both and what to lower.
pub fn check(info: &ChapterInfo, scene: &Scene) -> Result<()> {
    let need = estimate(info, scene);
    let Some((have, what)) = available() else {
        return Ok(());
    };
    if need <= have {
        return Ok(());
    }
    let gib = |b: u64| b as f64 / (1u64 << 30) as f64;
    Err(Error::Usage(format!(
        "chapter {} on {} ({}x{} pixels, {} triangles) needs about {:.1} GiB, more than the \
         {:.1} GiB left under {what}; lower --width and --height (or use a smaller mesh)",
        info.number,
        crate::core::text::escape(&scene.name),
        scene.camera.width,
        scene.camera.height,
        scene.triangle_count(),
        gib(need),
        gib(have),
    )))
}

/// Bytes reading and parsing a scene or OBJ file takes per byte of it, at
/// most: the text, and the vertices and faces parsed from it (measured: a
/// 75 MB OBJ of 2 million triangles peaks at 384 MB in chapter 1).
pub const BYTES_PER_FILE_BYTE: u64 = 6;

/// Refuses to read a file of `len` bytes at `path` when reading and parsing
/// it would need more than [`available`] gives.
pub fn check_file(path: &std::path::Path, len: u64) -> Result<()> {
    // The program is loaded by now: only the allocator's room is added.
    let need = (64u64 << 20).saturating_add(len.saturating_mul(BYTES_PER_FILE_BYTE));
    let Some((have, what)) = available() else {
        return Ok(());
    };
    if need <= have {
        return Ok(());
    }
    let mib = |b: u64| b >> 20;
    Err(Error::Usage(format!(
        "{}: reading this {} MiB file needs about {} MiB, more than the {} MiB left under \
         {what}",
        path.display(),
        mib(len),
        mib(need),
        mib(have)
    )))
}

/// A number of kB on the line of `text` that starts with `key`.
fn kib_field(text: &str, key: &str) -> Option<u64> {
    let line = text.lines().find(|l| l.starts_with(key))?;
    let kib: u64 = line[key.len()..]
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    Some(kib * 1024)
}

fn address_space_left() -> Option<u64> {
    #[cfg(target_os = "linux")]
    {
        use nix::sys::resource::{getrlimit, Resource, RLIM_INFINITY};
        let (soft, _) = getrlimit(Resource::RLIMIT_AS).ok()?;
        if soft == RLIM_INFINITY {
            return None;
        }
        let status = std::fs::read_to_string("/proc/self/status").ok()?;
        let used = kib_field(&status, "VmSize:")?;
        Some(soft.saturating_sub(used))
    }
    #[cfg(not(target_os = "linux"))]
    None
}

fn cgroup_left() -> Option<u64> {
    let read = |f: &str| std::fs::read_to_string(format!("/sys/fs/cgroup/{f}")).ok();
    let max: u64 = read("memory.max")?.trim().parse().ok()?;
    let current: u64 = read("memory.current")?.trim().parse().ok()?;
    Some(max.saturating_sub(current))
}

fn meminfo_available() -> Option<u64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    Some(kib_field(&info, "MemAvailable:")? + kib_field(&info, "SwapFree:").unwrap_or(0))
}
