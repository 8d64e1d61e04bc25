//! Temporaries a killed run left behind. [`write_atomically`](super::film::write_atomically)
//! writes every output under a hidden name first (`.PID.tmp…-name`, and
//! `.PID.old…-name` for the copy of a file an output set replaces) and a
//! signal handler removes them on INT, TERM or HUP; SIGKILL, a crash of
//! the machine or a power cut leave them. The next run writing into the
//! same folder removes those of processes that no longer run.

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The process id in a temporary's name, or `None` for any other file.
fn owner(name: &str) -> Option<u32> {
    let rest = name.strip_prefix('.')?;
    let (pid, kind) = rest.split_once('.')?;
    if pid.is_empty() || !pid.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    (kind.starts_with("tmp") || kind.starts_with("old"))
        .then(|| pid.parse().ok())
        .flatten()
}

/// Whether process `pid` runs (`true` where this cannot be told).
fn runs(pid: u32) -> bool {
    #[cfg(unix)]
    {
        use nix::errno::Errno;
        let Ok(raw) = i32::try_from(pid) else {
            return false;
        };
        // Signal 0 checks that the process exists; EPERM: it does, as
        // another user's.
        !matches!(
            nix::sys::signal::kill(nix::unistd::Pid::from_raw(raw), None),
            Err(Errno::ESRCH)
        )
    }
    #[cfg(not(unix))]
    {
        let _ = pid;
        true
    }
}

/// Removes from `dir` the temporaries of processes that no longer run;
/// how many. Another run's live temporaries, this process's own and every
/// other file stay.
pub fn sweep(dir: &Path) -> usize {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let mut removed = 0;
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name.to_str().and_then(owner) else {
            continue;
        };
        let is_file = entry.file_type().is_ok_and(|t| t.is_file());
        if is_file && pid != std::process::id() && !runs(pid) {
            removed += std::fs::remove_file(entry.path()).is_ok() as usize;
        }
    }
    removed
}

/// [`sweep`], once per folder per process.
pub fn sweep_once(dir: &Path) {
    static SWEPT: Mutex<Option<HashSet<PathBuf>>> = Mutex::new(None);
    let Ok(mut swept) = SWEPT.lock() else {
        return;
    };
    if swept
        .get_or_insert_with(HashSet::new)
        .insert(dir.to_path_buf())
    {
        sweep(dir);
    }
}
