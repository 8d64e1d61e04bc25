//! The thread pool of one render job (see [`super::worker`]).

use std::sync::Arc;

/// Name of the render threads.
pub const THREAD_NAME: &str = "raystep-render";

/// The threads one job renders on: a rayon pool of its own, so the rows of
/// a new job never queue behind the rows of the pass it replaced (in one
/// shared pool they did: a pool's threads finish the tasks they hold
/// before they take new ones).
pub(super) struct JobPool {
    pub(super) pool: rayon::ThreadPool,
    /// The pool's threads, as the kernel knows them (Linux).
    #[cfg(target_os = "linux")]
    threads: Arc<std::sync::Mutex<Vec<rustix::thread::Pid>>>,
}

impl JobPool {
    /// As many threads as the global pool (`--threads`, else one per core).
    pub(super) fn new() -> Option<JobPool> {
        let builder = rayon::ThreadPoolBuilder::new()
            .num_threads(rayon::current_num_threads())
            .thread_name(|i| format!("{THREAD_NAME}-{i}"));
        #[cfg(target_os = "linux")]
        {
            let threads = Arc::new(std::sync::Mutex::new(Vec::new()));
            let seen = threads.clone();
            let builder = builder.start_handler(move |_| {
                if let Ok(mut t) = seen.lock() {
                    t.push(rustix::thread::gettid());
                }
            });
            builder.build().ok().map(|pool| JobPool { pool, threads })
        }
        #[cfg(not(target_os = "linux"))]
        builder.build().ok().map(|pool| JobPool { pool })
    }

    /// The job was replaced: its pass goes on until it ends (a pass cannot
    /// be interrupted), but at the lowest priority (nice 19), so the new
    /// job has the cores. Elsewhere than on Linux the two share them.
    pub(super) fn demote(&self) {
        #[cfg(target_os = "linux")]
        if let Ok(threads) = self.threads.lock() {
            for &tid in threads.iter() {
                // Lowering a thread's own process's priority needs no
                // privilege; if it fails the jobs just share the cores.
                let _ = rustix::process::setpriority_process(Some(tid), 19);
            }
        }
    }
}
