//! The render worker: one thread that owns the current [`Render`] and runs
//! its passes, sending a [`RenderState`] after each one (at most every
//! [`SNAPSHOT_EVERY`], and always after the first and the last). The UI
//! thread never waits for it; it only reads the channel.
//!
//! Every job carries a generation number and has its own threads. When a
//! newer job arrives the old render is dropped (a pass already running
//! finishes at the lowest priority, its result not sent), and the UI ignores
//! any snapshot whose generation is not its own.
//!
//! A progressive stage ([`ChapterInfo::progressive`](crate::core::stage::ChapterInfo::progressive)) renders to a [`Target`]:
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

use super::pool::JobPool;
use crate::core::stage::{Chapter, Inspection, Render, Settings};
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
    /// Index into [`ChapterInfo::variants`](crate::core::stage::ChapterInfo::variants) (0 when there are none).
    pub variant: usize,
    /// For a progressive stage, how far to go (the settings' `spp` is then
    /// ignored); `None`: the stage's own plan.
    pub target: Option<Target>,
}

pub use super::state::RenderState;

pub use crate::core::film::film_mean;

pub use super::pool::THREAD_NAME;

/// What the worker reports.
#[derive(Clone, Debug)]
pub enum Progress {
    /// A pass finished.
    State(Box<RenderState>),
    /// The answer to [`Worker::inspect`].
    Inspected {
        /// The generation of the job.
        generation: u64,
        /// What the inspection is for.
        purpose: Purpose,
        /// The render's answer, or why there is none.
        result: Result<Inspection, String>,
    },
    /// The stage refused to start on this scene ([`Chapter::start`]'s
    /// error): the UI remembers it against the (chapter, scene) pair.
    Refused {
        /// The generation of the job.
        generation: u64,
        /// Why.
        message: String,
    },
    /// The stage panicked while starting or in a pass.
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
            Progress::State(s) => s.generation,
            Progress::Inspected { generation, .. }
            | Progress::Refused { generation, .. }
            | Progress::Failed { generation, .. } => *generation,
        }
    }
}

/// What an inspection is for: the story shown beside the inspected pixel,
/// or the path table (`t`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    /// The inspect panel's story lines.
    Story,
    /// The traced path's table.
    Trace,
}

/// What the UI tells the worker.
enum Command {
    Start(Job),
    Inspect {
        generation: u64,
        pixel: (u32, u32),
        sample: u32,
        purpose: Purpose,
    },
    Retarget {
        generation: u64,
        target: Target,
    },
    Pause {
        generation: u64,
        paused: bool,
    },
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

    /// Asks render `generation` what happened at sample `sample` of `pixel`
    /// ([`Render::inspect`]); the answer comes back as
    /// [`Progress::Inspected`] after the pass under way.
    pub fn inspect(&self, generation: u64, pixel: (u32, u32), sample: u32, purpose: Purpose) {
        self.send(Command::Inspect {
            generation,
            pixel,
            sample,
            purpose,
        });
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
    fn snapshot(&self) -> RenderState {
        let mut snap =
            RenderState::capture(&*self.render, self.job.generation, self.active, self.done);
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
    settings.variant = Some(job.variant);
    if let Some(t) = &job.target {
        settings.spp = t.spp.max(1);
    }
    let render = catch_unwind(AssertUnwindSafe(|| {
        job.chapter.info().check_memory(&job.scene)?;
        job.chapter.start(job.scene.clone(), &settings)
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
            let _ = results.send(Progress::Refused {
                generation: job.generation,
                message: e.to_string(),
            });
            None
        }
        Err(p) => {
            let _ = results.send(fail(format!("the stage panicked: {}", panic_message(&*p))));
            None
        }
    }
}

/// The worker thread: each job renders in a thread and a pool of its own
/// ([`render_jobs`], [`JobPool`]), so a new job starts at once even in an
/// old one's long pass. The old job's channel closes and its pool drops to
/// the lowest priority; after its pass it stops (what it sent carries its
/// generation, which the UI drops). Other commands go to the current job.
fn work(commands: Receiver<Command>, results: Sender<Progress>) {
    type Running = (u64, Sender<Command>, JoinHandle<()>, Arc<JobPool>);
    let mut current: Option<Running> = None;
    let mut stopping: Vec<JoinHandle<()>> = Vec::new();
    for command in commands.iter() {
        match command {
            Command::Start(job) => {
                let (tx, rx) = channel();
                let generation = job.generation;
                let _ = tx.send(Command::Start(job));
                let to_ui = results.clone();
                let spawned = JobPool::new().map(Arc::new).and_then(|pool| {
                    let own = pool.clone();
                    std::thread::Builder::new()
                        .name(THREAD_NAME.into())
                        .spawn(move || own.pool.install(|| render_jobs(rx, to_ui)))
                        .ok()
                        .map(|thread| (thread, pool))
                });
                let Some((handle, pool)) = spawned else {
                    let _ = results.send(Progress::Failed {
                        generation,
                        message: "cannot start a render thread".into(),
                    });
                    continue;
                };
                if let Some((_, old, thread, old_pool)) =
                    current.replace((generation, tx, handle, pool))
                {
                    drop(old);
                    old_pool.demote();
                    stopping.push(thread);
                }
            }
            other => {
                if let Some((generation, tx, _, _)) = &current {
                    if other.generation() == Some(*generation) {
                        let _ = tx.send(other);
                    }
                }
            }
        }
        stopping.retain(|t| !t.is_finished());
    }
    // The UI is gone: stop the current job after its pass and wait for it.
    if let Some((_, tx, thread, _)) = current {
        drop(tx);
        let _ = thread.join();
    }
}

impl Command {
    /// The generation a command is about (`None` for a new job).
    fn generation(&self) -> Option<u64> {
        match self {
            Command::Start(_) => None,
            Command::Retarget { generation, .. }
            | Command::Pause { generation, .. }
            | Command::Inspect { generation, .. } => Some(*generation),
        }
    }
}

/// One job's thread: starts its render and runs its passes, taking the
/// commands the worker passes on, until the render is replaced (the
/// channel closes) or the UI is gone.
fn render_jobs(commands: Receiver<Command>, results: Sender<Progress>) {
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
                Command::Inspect {
                    generation,
                    pixel,
                    sample,
                    purpose,
                } if generation == cur.job.generation => {
                    let answer =
                        catch_unwind(AssertUnwindSafe(|| cur.render.inspect(pixel, sample)));
                    let result = match answer {
                        Ok(Some(i)) => Ok(i),
                        Ok(None) => Err("nothing to inspect here yet".to_string()),
                        Err(p) => Err(format!("the stage panicked: {}", panic_message(&*p))),
                    };
                    let inspected = Progress::Inspected {
                        generation,
                        purpose,
                        result,
                    };
                    if results.send(inspected).is_err() {
                        return;
                    }
                }
                Command::Pause { generation, paused } if generation == cur.job.generation => {
                    cur.paused = paused;
                    if paused
                        && results
                            .send(Progress::State(Box::new(cur.snapshot())))
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
            let pass = cur.render.pass();
            let mut done = pass.complete;
            if let (false, Some(target)) = (done, &cur.job.target) {
                let (noise, mean) = pass.noise.map_or((None, 0.0), |(n, m)| (Some(n), m));
                done = finished(target, pass.samples, noise, mean).is_some();
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
                    if results.send(Progress::State(Box::new(snap))).is_err() {
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
