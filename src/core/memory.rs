//! Memory refused before it runs out. A run's largest allocations grow
//! with its pixels (film, layers, views, the encoded outputs) and its
//! triangles (the mesh, the trees); each chapter states its measured bytes
//! per pixel and per triangle
//! ([`ChapterInfo::bytes_per_pixel`](crate::core::stage::ChapterInfo::bytes_per_pixel),
//! [`ChapterInfo::bytes_per_triangle`](crate::core::stage::ChapterInfo::bytes_per_triangle)),
//! and [`check`] refuses a run whose
//! estimate exceeds what this process may still get: its address-space
//! limit (`ulimit -v`, as a course's sandbox or a CI runner sets), its
//! control group's limit, and the memory the machine has available. A
//! refused run is an error that says so; an allocation that fails aborts
//! the process (exit 134) with no word about why.

use crate::core::error::{Error, Result};

/// Address space a run takes besides its pixels and triangles: the
/// program, its threads' stacks and the allocator's per-thread arenas.
pub const BASE_BYTES: u64 = 256 << 20;

/// A run's size: what its allocations grow with, and by how much.
#[derive(Clone, Copy, Debug)]
pub struct Run {
    /// Pixels of its image.
    pub pixels: u64,
    /// Triangles of its scene.
    pub triangles: u64,
    /// Bytes per pixel, at most (the chapter's).
    pub per_pixel: u64,
    /// Bytes per triangle, at most (the chapter's).
    pub per_triangle: u64,
}

impl Run {
    /// What the run will allocate, about, in bytes: an upper bound from
    /// measured peaks.
    pub fn estimate(&self) -> u64 {
        BASE_BYTES
            .saturating_add(self.pixels.saturating_mul(self.per_pixel))
            .saturating_add(self.triangles.saturating_mul(self.per_triangle))
    }
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

/// Refuses `run` (described by `what`, e.g. "chapter 3 on cornell-box
/// (64x64 pixels, 36 triangles)") when it would need more than
/// [`available`] gives, naming both and what to lower.
pub fn check(what: &str, run: &Run) -> Result<()> {
    let need = run.estimate();
    let Some((have, limit)) = available() else {
        return Ok(());
    };
    if need <= have {
        return Ok(());
    }
    let gib = |b: u64| b as f64 / (1u64 << 30) as f64;
    Err(Error::Usage(format!(
        "{what} needs about {:.1} GiB, more than the {:.1} GiB left under {limit}; lower \
         --width and --height (or use a smaller mesh)",
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
