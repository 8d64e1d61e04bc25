//! What keeps a student's code in its box while it is graded: resource
//! limits, no file system and no new process, thread or socket for the
//! `raystep-grade-child` process, its
//! own process group so that the grader can stop it and everything it
//! started, and (in the `grade` command) a sweep for the processes it left
//! running detached (through the `nix` crate's safe wrappers of the
//! system calls).
//!
//! On other systems than Unix the limits are skipped and only the child
//! itself is killed; on Linux kernels without Landlock the file-system
//! rule is skipped, and off Linux on x86-64, AArch64 or RISC-V the
//! system-call rule ([`crate::seccomp`]). [`Limits::confine`]
//! says which held, and the grader prints it.

/// The limits of one `grade-student` process.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// Address space, bytes.
    pub memory: u64,
    /// CPU time over all threads, seconds.
    pub cpu_seconds: u64,
    /// The largest file it may write, bytes.
    pub file_size: u64,
}

impl Limits {
    /// For a check with a time limit of `timeout` seconds: 4 GiB of address
    /// space (the largest check, chapter 6's, stays under 1 GiB), CPU time
    /// for every core over the whole limit and a second more, and no file
    /// written (the process sends its transcript through a pipe).
    pub fn for_timeout(timeout: f64) -> Limits {
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get()) as f64;
        Limits {
            memory: 4 << 30,
            cpu_seconds: (timeout * cores).ceil() as u64 + 1,
            file_size: 0,
        }
    }

    /// Closes this process (the student's) into its sandbox: the
    /// resource limits, no file system at all (Landlock: no file opened,
    /// read or written from now on), and no new process, thread or socket
    /// (seccomp). Returns what could not be enforced on this system, one
    /// phrase each (empty when everything holds).
    pub fn confine(&self) -> Vec<String> {
        let mut missing = Vec::new();
        #[cfg(unix)]
        {
            use nix::sys::resource::{setrlimit, Resource};
            let limits = [
                (Resource::RLIMIT_AS, self.memory, "memory"),
                (Resource::RLIMIT_CPU, self.cpu_seconds, "CPU time"),
                (Resource::RLIMIT_FSIZE, self.file_size, "file size"),
                (Resource::RLIMIT_CORE, 0, "core dumps"),
            ];
            for (resource, value, what) in limits {
                if setrlimit(resource, value, value).is_err() {
                    missing.push(format!("the {what} limit"));
                }
            }
        }
        #[cfg(not(unix))]
        missing.push("resource limits (not on this system)".into());
        if let Err(e) = close_file_system() {
            missing.push(format!("the file-system rule ({e})"));
        }
        if let Err(e) = crate::seccomp::forbid_escapes() {
            missing.push(format!("the system-call rule ({e})"));
        }
        missing
    }
}

/// Lets this process open no file from now on (reading or writing),
/// through Landlock; what it has open stays usable.
#[cfg(target_os = "linux")]
fn close_file_system() -> Result<(), String> {
    use landlock::{Access, AccessFs, Ruleset, RulesetAttr, RulesetStatus, ABI};
    let status = Ruleset::default()
        .handle_access(AccessFs::from_all(ABI::V3))
        .and_then(|r| r.create())
        .and_then(|r| r.restrict_self())
        .map_err(|e| e.to_string())?;
    match status.ruleset {
        RulesetStatus::NotEnforced => Err("this kernel has no Landlock".into()),
        _ => Ok(()),
    }
}

#[cfg(not(target_os = "linux"))]
fn close_file_system() -> Result<(), String> {
    Err("only on Linux".into())
}

/// Starts `cmd` as the leader of a process group of its own, so that
/// [`kill_group`] reaches everything it starts (unless that leaves the
/// group on purpose: see [`kill_orphans`]).
pub fn own_group(cmd: &mut std::process::Command) {
    #[cfg(unix)]
    {
        use std::os::unix::process::CommandExt;
        cmd.process_group(0);
    }
    #[cfg(not(unix))]
    let _ = cmd;
}

/// Kills the process group led by `pid` (started with [`own_group`]).
pub fn kill_group(pid: u32) {
    #[cfg(unix)]
    if let Ok(pid) = i32::try_from(pid) {
        // A group that no longer exists gives ESRCH: nothing to do.
        let _ = nix::sys::signal::killpg(
            nix::unistd::Pid::from_raw(pid),
            nix::sys::signal::Signal::SIGKILL,
        );
    }
    #[cfg(not(unix))]
    let _ = pid;
}

/// Makes this process the one that inherits its descendants' orphans
/// (Linux's child subreaper), so that [`kill_orphans`] can find a process a
/// student's code started and detached. Only the `grade` command does this:
/// in a process with children of its own (the test harness, the terminal
/// UI) an orphan may be someone else's.
pub fn become_subreaper() {
    #[cfg(target_os = "linux")]
    let _ = nix::sys::prctl::set_child_subreaper(true);
}

/// Kills and reaps every child of this process: once a check's process
/// has been reaped, any child left is an orphan of its (the subreaper took
/// it). Returns how many there were.
pub fn kill_orphans() -> usize {
    #[cfg(target_os = "linux")]
    {
        let me = std::process::id().to_string();
        let mut killed = 0;
        let Ok(entries) = std::fs::read_dir("/proc") else {
            return 0;
        };
        for entry in entries.flatten() {
            let name = entry.file_name();
            let Some(pid) = name.to_str().and_then(|n| n.parse::<i32>().ok()) else {
                continue;
            };
            let Ok(stat) = std::fs::read_to_string(entry.path().join("stat")) else {
                continue;
            };
            // `pid (comm) state ppid …`: comm may hold spaces and
            // parentheses, so read after the last ')'.
            let parent = stat
                .rsplit_once(')')
                .and_then(|(_, rest)| rest.split_whitespace().nth(1));
            if parent == Some(me.as_str()) {
                let pid = nix::unistd::Pid::from_raw(pid);
                let _ = nix::sys::signal::kill(pid, nix::sys::signal::Signal::SIGKILL);
                let _ = nix::sys::wait::waitpid(pid, None);
                killed += 1;
            }
        }
        killed
    }
    #[cfg(not(target_os = "linux"))]
    0
}
