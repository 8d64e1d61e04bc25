//! The render worker: one thread that owns the current [`Render`] and runs
//! its passes, sending a [`Snapshot`] after each one. The UI thread never
//! waits for it; it only reads the channel.
//!
//! Every job carries a generation number. When a newer job arrives the
//! worker drops the old render (a pass already running finishes first, but
//! its result is not sent), and the UI ignores any snapshot whose
//! generation is not its own, so a stale pass never reaches the screen.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::mpsc::{channel, Receiver, Sender, TryRecvError};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use crate::core::film::Film;
use crate::core::stage::{Chapter, Render, Settings};
use crate::scene::Scene;

/// Name of the worker thread (the panic hook uses it).
pub const THREAD_NAME: &str = "raystep-render";

/// What to render.
#[derive(Clone)]
pub struct Job {
    /// The UI's generation when it asked for this render.
    pub generation: u64,
    /// The stage.
    pub chapter: &'static dyn Chapter,
    /// The scene.
    pub scene: Arc<Scene>,
    /// The settings.
    pub settings: Settings,
    /// Index into [`Chapter::variants`] (0 when there are none).
    pub variant: usize,
}

/// Everything the UI shows of a render after one pass.
#[derive(Clone, Debug)]
pub struct Snapshot {
    /// The generation of the job this comes from.
    pub generation: u64,
    /// Every view of the chapter, in the order of [`Chapter::views`].
    pub views: Vec<Film>,
    /// Per-bounce layers ([`Render::layers`]).
    pub layers: Option<Vec<Film>>,
    /// The reference ([`Render::reference`]).
    pub reference: Option<Film>,
    /// Error against time ([`Render::error_series`]).
    pub error_series: Vec<(f64, f64)>,
    /// RMSE of view 0 against the reference, when there is one.
    pub rmse: Option<f64>,
    /// (passes done, passes planned).
    pub progress: (u32, u32),
    /// Time since the render started.
    pub elapsed: Duration,
    /// Rays traced so far ([`Render::rays`]; 0 when the stage does not count).
    pub rays: u64,
    /// Whether the render is complete.
    pub done: bool,
}

impl Snapshot {
    /// Reads everything the UI needs from `render`.
    pub fn capture(
        chapter: &dyn Chapter,
        render: &dyn Render,
        generation: u64,
        elapsed: Duration,
        done: bool,
    ) -> Snapshot {
        let views: Vec<Film> = (0..chapter.views().len().max(1))
            .map(|i| render.view(i))
            .collect();
        let reference = render.reference();
        let rmse = reference
            .as_ref()
            .filter(|r| (r.width, r.height) == (views[0].width, views[0].height))
            .map(|r| views[0].rmse(r));
        Snapshot {
            generation,
            layers: render.layers(),
            error_series: render.error_series(),
            reference,
            rmse,
            views,
            progress: render.progress(),
            rays: render.rays(),
            elapsed,
            done,
        }
    }
}

impl Snapshot {
    /// Rays per second since the render started, when the stage counts
    /// rays and some time has passed.
    pub fn rays_per_second(&self) -> Option<f64> {
        let secs = self.elapsed.as_secs_f64();
        (self.rays > 0 && secs > 0.0).then(|| self.rays as f64 / secs)
    }
}

/// What the worker reports.
#[derive(Clone, Debug)]
pub enum Progress {
    /// A pass finished.
    Snapshot(Box<Snapshot>),
    /// The render could not start, or a pass panicked.
    Failed {
        /// The generation of the job.
        generation: u64,
        /// What went wrong.
        message: String,
    },
}

impl Progress {
    /// The generation this report belongs to.
    pub fn generation(&self) -> u64 {
        match self {
            Progress::Snapshot(s) => s.generation,
            Progress::Failed { generation, .. } => *generation,
        }
    }
}

/// The worker thread and its two channels.
pub struct Worker {
    jobs: Option<Sender<Job>>,
    /// Reports from the worker, oldest first.
    pub results: Receiver<Progress>,
    handle: Option<JoinHandle<()>>,
}

impl Worker {
    /// Starts the worker thread; it waits for the first job.
    pub fn spawn() -> Worker {
        let (job_tx, job_rx) = channel::<Job>();
        let (result_tx, result_rx) = channel::<Progress>();
        let handle = std::thread::Builder::new()
            .name(THREAD_NAME.into())
            .spawn(move || work(job_rx, result_tx))
            .expect("spawning the render thread");
        Worker {
            jobs: Some(job_tx),
            results: result_rx,
            handle: Some(handle),
        }
    }

    /// Replaces whatever is rendering by `job`.
    pub fn start(&self, job: Job) {
        if let Some(tx) = &self.jobs {
            // Fails only if the worker is gone; then there is nothing to do.
            let _ = tx.send(job);
        }
    }
}

impl Worker {
    /// Closes the job channel and waits for the worker to finish its
    /// current pass (the UI quits without waiting: it just drops the worker).
    pub fn stop(mut self) {
        self.jobs.take();
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

/// The newest job waiting in `jobs`, if any; `Err` when the UI has gone.
fn newest(jobs: &Receiver<Job>) -> Result<Option<Job>, ()> {
    let mut latest = None;
    loop {
        match jobs.try_recv() {
            Ok(job) => latest = Some(job),
            Err(TryRecvError::Empty) => return Ok(latest),
            Err(TryRecvError::Disconnected) => return latest.map(Some).ok_or(()),
        }
    }
}

fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "panic".into())
}

fn work(jobs: Receiver<Job>, results: Sender<Progress>) {
    let mut next = None;
    loop {
        // Wait for a job when idle.
        let job = match next.take() {
            Some(job) => job,
            None => match jobs.recv() {
                Ok(job) => job,
                Err(_) => return,
            },
        };
        let started = Instant::now();
        let fail = |message: String| Progress::Failed {
            generation: job.generation,
            message,
        };
        let render = catch_unwind(AssertUnwindSafe(|| {
            job.chapter
                .start_variant(job.scene.clone(), &job.settings, job.variant)
        }));
        let mut render = match render {
            Ok(Ok(r)) => r,
            Ok(Err(e)) => {
                let _ = results.send(fail(e.to_string()));
                continue;
            }
            Err(p) => {
                let _ = results.send(fail(format!("the stage panicked: {}", panic_message(&*p))));
                continue;
            }
        };
        // Render passes until done or replaced.
        loop {
            let pass = catch_unwind(AssertUnwindSafe(|| {
                let done = render.pass();
                let snap = Snapshot::capture(
                    job.chapter,
                    &*render,
                    job.generation,
                    started.elapsed(),
                    done,
                );
                (done, snap)
            }));
            match newest(&jobs) {
                Ok(Some(newer)) => {
                    next = Some(newer);
                    break;
                }
                Ok(None) => {}
                Err(()) => return,
            }
            match pass {
                Ok((done, snap)) => {
                    if results.send(Progress::Snapshot(Box::new(snap))).is_err() {
                        return;
                    }
                    if done {
                        break;
                    }
                }
                Err(p) => {
                    let _ =
                        results.send(fail(format!("the stage panicked: {}", panic_message(&*p))));
                    break;
                }
            }
        }
    }
}
