//! The render worker: one thread that owns the current [`Render`] and runs
//! its passes, sending a [`Snapshot`] after each one (at most every
//! [`SNAPSHOT_EVERY`], and always after the first and the last). The UI
//! thread never waits for it; it only reads the channel.
//!
//! Every job carries a generation number. When a newer job arrives the
//! worker drops the old render (a pass already running finishes first, but
//! its result is not sent), and the UI ignores any snapshot whose
//! generation is not its own, so a stale pass never reaches the screen.
//!
//! A progressive stage ([`Chapter::progressive`]) renders to a [`Target`]:
//! until its own noise estimate is below the target's level, or the sample
//! budget is spent, whichever comes first ([`finished`]). The UI can pause
//! and resume it and move the target without starting over
//! ([`Worker::pause`], [`Worker::retarget`]). When there is nothing to do
//! the worker blocks on its channel: a finished or paused UI costs no CPU.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::mpsc::{channel, Receiver, Sender, TryRecvError};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use crate::core::film::Film;
use crate::core::stage::{Chapter, Render, Settings};
use crate::scene::Scene;

pub use super::target::{finished, Finish, Target, MIN_SPP_FOR_NOISE};

/// Shortest time between two snapshots of one render: a snapshot copies
/// every view and layer, so very short passes are not each shown.
pub const SNAPSHOT_EVERY: Duration = Duration::from_millis(80);

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
    /// For a progressive stage, how far to go (the settings' `spp` is then
    /// ignored); `None`: the stage's own plan.
    pub target: Option<Target>,
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
    /// RMSE of view 0 against the reference, when there is one: the last
    /// point of the error series where the stage keeps one (at the
    /// reference's resolution), else pixel by pixel.
    pub rmse: Option<f64>,
    /// (passes done, passes planned).
    pub progress: (u32, u32),
    /// Samples per pixel so far ([`Render::samples`]).
    pub samples: u32,
    /// The render's own noise estimate ([`Render::noise`]).
    pub noise: Option<f64>,
    /// The mean value of view 0 over pixels and channels.
    pub mean: f64,
    /// The target this render goes to (progressive stages).
    pub target: Option<Target>,
    /// Time spent rendering (pauses not counted).
    pub elapsed: Duration,
    /// Rays traced so far ([`Render::rays`]; 0 when the stage does not count).
    pub rays: u64,
    /// Whether the render is complete.
    pub done: bool,
    /// Why it stopped, once done.
    pub finish: Option<Finish>,
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
        let error_series = render.error_series();
        let rmse = error_series.last().map(|p| p.1).or_else(|| {
            reference
                .as_ref()
                .filter(|r| (r.width, r.height) == (views[0].width, views[0].height))
                .map(|r| views[0].rmse(r))
        });
        let mean = film_mean(&views[0]);
        Snapshot {
            generation,
            layers: render.layers(),
            error_series,
            reference,
            rmse,
            views,
            progress: render.progress(),
            samples: render.samples(),
            noise: render.noise(),
            mean,
            target: None,
            rays: render.rays(),
            elapsed,
            done,
            finish: done.then_some(Finish::Complete),
        }
    }

    /// The noise estimate as a fraction of the image's mean value.
    pub fn relative_noise(&self) -> Option<f64> {
        self.noise
            .filter(|_| self.mean > 0.0)
            .map(|n| n / self.mean)
    }
}

/// The mean over pixels and channels.
pub fn film_mean(film: &Film) -> f64 {
    let n = film.pixels.len().max(1) as f64 * 3.0;
    film.pixels
        .iter()
        .map(|p| p.as_dvec3().element_sum())
        .sum::<f64>()
        / n
}

/// Name of the worker thread (the panic hook uses it).
pub const THREAD_NAME: &str = "raystep-render";

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

/// What the UI tells the worker.
enum Command {
    Start(Job),
    Retarget { generation: u64, target: Target },
    Pause { generation: u64, paused: bool },
}

/// The worker thread and its two channels.
pub struct Worker {
    commands: Option<Sender<Command>>,
    /// Reports from the worker, oldest first.
    pub results: Receiver<Progress>,
    handle: Option<JoinHandle<()>>,
}

impl Worker {
    /// Starts the worker thread; it waits for the first job.
    pub fn spawn() -> Worker {
        let (command_tx, command_rx) = channel::<Command>();
        let (result_tx, result_rx) = channel::<Progress>();
        let handle = std::thread::Builder::new()
            .name(THREAD_NAME.into())
            .spawn(move || work(command_rx, result_tx))
            .expect("spawning the render thread");
        Worker {
            commands: Some(command_tx),
            results: result_rx,
            handle: Some(handle),
        }
    }

    fn send(&self, command: Command) {
        if let Some(tx) = &self.commands {
            // Fails only if the worker is gone; then there is nothing to do.
            let _ = tx.send(command);
        }
    }

    /// Replaces whatever is rendering by `job`.
    pub fn start(&self, job: Job) {
        self.send(Command::Start(job));
    }

    /// Moves the target of render `generation` (ignored for another).
    pub fn retarget(&self, generation: u64, target: Target) {
        self.send(Command::Retarget { generation, target });
    }

    /// Pauses or resumes render `generation` (ignored for another).
    pub fn pause(&self, generation: u64, paused: bool) {
        self.send(Command::Pause { generation, paused });
    }

    /// Closes the command channel and waits for the worker to finish its
    /// current pass (the UI quits without waiting: it just drops the worker).
    pub fn stop(mut self) {
        self.commands.take();
        if let Some(h) = self.handle.take() {
            let _ = h.join();
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

/// The render the worker is on.
struct Current {
    job: Job,
    render: Box<dyn Render>,
    paused: bool,
    done: bool,
    /// Time spent in passes.
    active: Duration,
    /// When the last snapshot was sent (`None`: none yet).
    sent: Option<Instant>,
}

impl Current {
    fn snapshot(&self) -> Snapshot {
        let mut snap = Snapshot::capture(
            self.job.chapter,
            &*self.render,
            self.job.generation,
            self.active,
            self.done,
        );
        snap.target = self.job.target;
        if let (true, Some(t)) = (self.done, &self.job.target) {
            snap.finish = finished(t, snap.samples, snap.noise, snap.mean).or(snap.finish);
        }
        snap
    }
}

fn start(job: Job, results: &Sender<Progress>) -> Option<Current> {
    let fail = |message: String| Progress::Failed {
        generation: job.generation,
        message,
    };
    let mut settings = job.settings.clone();
    if let Some(t) = &job.target {
        settings.spp = t.spp.max(1);
    }
    let render = catch_unwind(AssertUnwindSafe(|| {
        job.chapter
            .start_variant(job.scene.clone(), &settings, job.variant)
    }));
    match render {
        Ok(Ok(render)) => Some(Current {
            job,
            render,
            paused: false,
            done: false,
            active: Duration::ZERO,
            sent: None,
        }),
        Ok(Err(e)) => {
            let _ = results.send(fail(e.to_string()));
            None
        }
        Err(p) => {
            let _ = results.send(fail(format!("the stage panicked: {}", panic_message(&*p))));
            None
        }
    }
}

fn work(commands: Receiver<Command>, results: Sender<Progress>) {
    let mut current: Option<Current> = None;
    loop {
        // Wait for a command when there is nothing to render; otherwise
        // take whatever came in since the last pass.
        let busy = current.as_ref().is_some_and(|c| !c.paused && !c.done);
        let mut incoming = Vec::new();
        if !busy {
            match commands.recv() {
                Ok(c) => incoming.push(c),
                Err(_) => return,
            }
        }
        loop {
            match commands.try_recv() {
                Ok(c) => incoming.push(c),
                Err(TryRecvError::Empty) => break,
                Err(TryRecvError::Disconnected) => return,
            }
        }
        // Only the newest job matters.
        if let Some(i) = incoming
            .iter()
            .rposition(|c| matches!(c, Command::Start(_)))
        {
            let Command::Start(job) = incoming.swap_remove(i) else {
                unreachable!()
            };
            incoming.retain(|c| !matches!(c, Command::Start(_)));
            current = start(job, &results);
        }
        for command in incoming {
            let Some(cur) = current.as_mut() else { break };
            match command {
                Command::Retarget { generation, target } if generation == cur.job.generation => {
                    cur.job.target = Some(target);
                    cur.render.set_spp(target.spp);
                    // Go on (or stop at once, if already past it).
                    cur.done = false;
                }
                Command::Pause { generation, paused } if generation == cur.job.generation => {
                    cur.paused = paused;
                    if paused
                        && results
                            .send(Progress::Snapshot(Box::new(cur.snapshot())))
                            .is_err()
                    {
                        return;
                    }
                }
                _ => {}
            }
        }
        let Some(cur) = current.as_mut() else {
            continue;
        };
        if cur.paused || cur.done {
            continue;
        }
        let t = Instant::now();
        let pass = catch_unwind(AssertUnwindSafe(|| {
            let mut done = cur.render.pass();
            if let (false, Some(target)) = (done, &cur.job.target) {
                // The noise costs a pass over the image: only once trusted.
                let samples = cur.render.samples();
                let noise = (samples >= MIN_SPP_FOR_NOISE && target.noise.is_some())
                    .then(|| cur.render.noise())
                    .flatten();
                let mean = noise.map_or(0.0, |_| film_mean(&cur.render.view(0)));
                done = finished(target, samples, noise, mean).is_some();
            }
            done
        }));
        cur.active += t.elapsed();
        match pass {
            Ok(done) => {
                cur.done = done;
                let due = cur.sent.is_none_or(|s| s.elapsed() >= SNAPSHOT_EVERY);
                if done || due {
                    let snap = catch_unwind(AssertUnwindSafe(|| cur.snapshot()));
                    let Ok(snap) = snap else {
                        let _ = results.send(Progress::Failed {
                            generation: cur.job.generation,
                            message: "the stage panicked while showing its image".into(),
                        });
                        current = None;
                        continue;
                    };
                    if results.send(Progress::Snapshot(Box::new(snap))).is_err() {
                        return;
                    }
                    cur.sent = Some(Instant::now());
                }
            }
            Err(p) => {
                let _ = results.send(Progress::Failed {
                    generation: cur.job.generation,
                    message: format!("the stage panicked: {}", panic_message(&*p)),
                });
                current = None;
            }
        }
    }
}
