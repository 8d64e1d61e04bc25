//! The event loop's threads, where [`update`]'s effects go and where the
//! answers come from: the render [`Worker`], student mode's [`Watcher`],
//! the scene reader and the warp view's jobs ([`WarpJobs`]).
//! [`Threads::handle`] is the one way the loop changes the state: a
//! message to `update`, then every [`Effect`] it asked for carried out
//! ([`Threads::perform`]), and any answer fed back as a message.

use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{channel, Receiver, Sender};

use super::app::{App, Msg};
use super::effect::Effect;
use super::scenes::{read_scene, Read};
use super::student::Watcher;
use super::update::{save, update};
use super::warp_jobs::WarpJobs;
use super::worker::{Purpose, Worker};

/// A scene file read in a thread: the entry, the path, what was read.
type SceneAnswer = (usize, PathBuf, Read);

/// Everything that works beside the UI thread.
pub struct Threads {
    /// The render worker (the loop reads its reports).
    pub worker: Worker,
    /// Student mode's watcher, on the chapter [`Effect::Watch`] named;
    /// dropped (its build or render stopped) on the way out.
    student: Option<Watcher>,
    /// The scene file being read: files are read one at a time.
    reading: Option<(usize, PathBuf)>,
    /// Where the scene reader answers.
    reads: (Sender<SceneAnswer>, Receiver<SceneAnswer>),
    /// The warp view's draws and the student's builds.
    warp: WarpJobs,
}

impl Threads {
    /// The worker started, nothing else running yet.
    pub fn spawn() -> Threads {
        Threads {
            worker: Worker::spawn(),
            student: None,
            reading: None,
            reads: channel(),
            warp: WarpJobs::default(),
        }
    }

    /// `update` on `msg`, then the effects it asked for carried out, and
    /// their answers (a save's files, the grader's images) fed back the
    /// same way. Effects left in `app` from before (the first render
    /// [`launch_app`](super::launch_app) asks for) go first.
    pub fn handle(&mut self, app: App, msg: Msg) -> App {
        let mut app = app;
        let mut queue = VecDeque::from([msg]);
        while let Some(msg) = queue.pop_front() {
            app = update(app, msg);
            for effect in std::mem::take(&mut app.effects) {
                queue.extend(self.perform(effect, &app));
            }
        }
        app
    }

    /// Carries out `effect`, which `app` asked for; the answer, for an
    /// effect done here and now.
    pub fn perform(&mut self, effect: Effect, app: &App) -> Option<Msg> {
        match effect {
            Effect::Start(job) => self.worker.start(job),
            Effect::Retarget { generation, target } => self.worker.retarget(generation, target),
            Effect::Pause { generation, paused } => self.worker.pause(generation, paused),
            Effect::Trace {
                generation,
                pixel,
                sample,
            } => self
                .worker
                .inspect(generation, pixel, sample, Purpose::Trace),
            Effect::Story { generation, pixel } => {
                self.worker.inspect(generation, pixel, 0, Purpose::Story)
            }
            Effect::Save => return Some(Msg::Saved(save(app))),
            Effect::LoadGrades => {
                let images = crate::grading::latest_failure_images(&app.grade_dir());
                return Some(Msg::GradeLoaded(images.map_err(|e| e.to_string())));
            }
            Effect::Watch(chapter) => self.watch(chapter, &app.out_dir),
            Effect::WarpBuiltin { index, seed } => self.warp.draw_builtin(index, seed),
            Effect::WarpStudent(seed) => self.warp.draw_student(seed, &app.out_dir),
        }
        None
    }

    /// Student mode's watcher on `chapter` (images under `out`), or none.
    fn watch(&mut self, chapter: Option<u32>, out: &Path) {
        if let Some(w) = self.student.take() {
            w.detach();
        }
        self.student = chapter.map(|n| Watcher::spawn(n, out.to_path_buf()));
    }

    /// What the watcher, the scene reader and the warp jobs sent since the
    /// last call, as messages (the worker's reports are read apart, as the
    /// loop counts them). Also starts reading the scene file `app` waits
    /// for, when no other file is being read.
    pub fn messages(&mut self, app: &App) -> Vec<Msg> {
        let mut msgs = Vec::new();
        if let Some(w) = &self.student {
            msgs.extend(w.events.try_iter().map(|e| Msg::Student(w.chapter, e)));
        }
        if self.reading.is_none() {
            if let Some((index, path)) = app.scene_to_read() {
                self.reading = Some((index, path.clone()));
                let tx = self.reads.0.clone();
                std::thread::spawn(move || {
                    let read = read_scene(&path);
                    let _ = tx.send((index, path, read));
                });
            }
        }
        for (index, path, read) in self.reads.1.try_iter() {
            self.reading = None;
            msgs.push(Msg::SceneRead(index, path, read));
        }
        msgs.extend(self.warp.answers());
        msgs
    }
}
