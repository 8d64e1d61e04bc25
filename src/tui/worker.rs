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
use crate::core::stage::Render;

pub use super::target::{finished, Finish, Target, MIN_SPP_FOR_NOISE};

/// Shortest time between two snapshots of one render: a snapshot copies
/// every view and layer, so very short passes are not each shown.
pub const SNAPSHOT_EVERY: Duration = Duration::from_millis(80);

pub use super::job::{Job, Progress, Purpose};

pub use super::state::RenderState;

pub use crate::core::film::film_mean;

pub use super::pool::THREAD_NAME;

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
        let busy = current.as_ref().is_some_and(|c| !c.paused && !c.done);
        let Some(mut incoming) = incoming(&commands, busy) else {
            return;
        };
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
            if cur.obey(command, &results).is_err() {
                return;
            }
        }
        let Some(cur) = current.as_mut().filter(|c| !c.paused && !c.done) else {
            continue;
        };
        match cur.pass(&results) {
            Pass::Ran => {}
            Pass::Failed => current = None,
            Pass::UiGone => return,
        }
    }
}

/// The commands that came since the last pass; when there is nothing to
/// render (`busy` false), waits for one first. `None`: the channel closed.
fn incoming(commands: &Receiver<Command>, busy: bool) -> Option<Vec<Command>> {
    let mut incoming = Vec::new();
    if !busy {
        incoming.push(commands.recv().ok()?);
    }
    loop {
        match commands.try_recv() {
            Ok(c) => incoming.push(c),
            Err(TryRecvError::Empty) => return Some(incoming),
            Err(TryRecvError::Disconnected) => return None,
        }
    }
}

/// How a pass went.
enum Pass {
    /// It ran (and its snapshot was sent if one was due).
    Ran,
    /// The stage panicked; the UI was told.
    Failed,
    /// The UI is gone.
    UiGone,
}

/// The UI is gone: the job's thread stops.
struct UiGone;

impl Current {
    /// Carries out a command about this render (one about another
    /// generation is dropped).
    fn obey(&mut self, command: Command, results: &Sender<Progress>) -> Result<(), UiGone> {
        match command {
            Command::Retarget { generation, target } if generation == self.job.generation => {
                self.job.target = Some(target);
                self.render.set_spp(target.spp);
                // Go on (or stop at once, if already past it).
                self.done = false;
            }
            Command::Inspect {
                generation,
                pixel,
                sample,
                purpose,
            } if generation == self.job.generation => {
                let answer = catch_unwind(AssertUnwindSafe(|| self.render.inspect(pixel, sample)));
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
                results.send(inspected).map_err(|_| UiGone)?;
            }
            Command::Pause { generation, paused } if generation == self.job.generation => {
                self.paused = paused;
                if paused {
                    let snap = Progress::State(Box::new(self.snapshot()));
                    results.send(snap).map_err(|_| UiGone)?;
                }
            }
            _ => {}
        }
        Ok(())
    }

    /// Runs one pass, and sends its snapshot when one is due (at most
    /// every [`SNAPSHOT_EVERY`], and always after the last pass).
    fn pass(&mut self, results: &Sender<Progress>) -> Pass {
        let t = Instant::now();
        let pass = catch_unwind(AssertUnwindSafe(|| {
            let pass = self.render.pass();
            let mut done = pass.complete;
            if let (false, Some(target)) = (done, &self.job.target) {
                let (noise, mean) = pass.noise.map_or((None, 0.0), |(n, m)| (Some(n), m));
                done = finished(target, pass.samples, noise, mean).is_some();
            }
            done
        }));
        self.active += t.elapsed();
        let failed = |message: String| Progress::Failed {
            generation: self.job.generation,
            message,
        };
        let done = match pass {
            Ok(done) => done,
            Err(p) => {
                let message = format!("the stage panicked: {}", panic_message(&*p));
                let _ = results.send(failed(message));
                return Pass::Failed;
            }
        };
        self.done = done;
        let due = self.sent.is_none_or(|s| s.elapsed() >= SNAPSHOT_EVERY);
        if !(done || due) {
            return Pass::Ran;
        }
        let Ok(snap) = catch_unwind(AssertUnwindSafe(|| self.snapshot())) else {
            let message = "the stage panicked while showing its image".to_string();
            let _ = results.send(failed(message));
            return Pass::Failed;
        };
        if results.send(Progress::State(Box::new(snap))).is_err() {
            return Pass::UiGone;
        }
        self.sent = Some(Instant::now());
        Pass::Ran
    }
}
