//! Rendering to convergence: the pure stopping rule, the keys that pause
//! and move the target, and the real worker going on pass after pass until
//! the noise target or the budget stops it, then going on again when the
//! target moves, without starting over.

use std::sync::Arc;
use std::time::{Duration, Instant};

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use glam::Vec3;

use raystep::core::error::Result;
use raystep::core::film::Film;
use raystep::core::report::Report;
use raystep::core::stage::{Chapter, ChapterInfo, Pass, Render, Settings, Variant, View};
use raystep::scene::Scene;
use raystep::tui::app::{App, Msg};
use raystep::tui::keys::msg_for_key;
use raystep::tui::scenes::SceneEntry;
use raystep::tui::update::update;
use raystep::tui::worker::{
    finished, Finish, Job, Progress, RenderState, Target, Worker, MIN_SPP_FOR_NOISE,
};

/// A progressive stage whose noise is exactly 1/√spp of a flat image of
/// value 1: the sample variance of a unit-variance estimator.
struct Noisy;

static NOISY: Noisy = Noisy;

const VARIANTS: &[Variant] = &[
    Variant {
        name: "uniform",
        about: "uniform sampling",
    },
    Variant {
        name: "best",
        about: "the best",
    },
];

impl Chapter for Noisy {
    fn info(&self) -> ChapterInfo {
        ChapterInfo {
            variants: VARIANTS,
            default_variant: 1,
            progressive: true,
            ..ChapterInfo::new(
                6,
                "noisy",
                "A progressive fake",
                &[View {
                    name: "image",
                    about: "",
                }],
            )
        }
    }
    fn start(&self, _: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        Ok(Box::new(NoisyRender {
            samples: 0,
            spp: settings.spp,
            passes: 0,
        }))
    }
}

struct NoisyRender {
    samples: u32,
    spp: u32,
    passes: u32,
}

impl NoisyRender {
    fn pass_info(&self) -> Pass {
        Pass {
            done: self.passes,
            planned: self.spp.max(self.passes),
            samples: self.samples,
            rays: 0,
            noise: (self.samples >= 2).then(|| (1.0 / (self.samples as f64).sqrt(), 1.0)),
            complete: self.samples >= self.spp,
        }
    }
}

impl Render for NoisyRender {
    fn pass(&mut self) -> Pass {
        if self.samples < self.spp {
            std::thread::sleep(Duration::from_millis(10));
            self.samples += 1.min(self.spp - self.samples);
            self.passes += 1;
        }
        self.pass_info()
    }
    fn snapshot(&self) -> raystep::core::stage::Snapshot {
        let mut f = Film::new(4, 2);
        f.pixels.iter_mut().for_each(|p| *p = Vec3::ONE);
        raystep::core::stage::Snapshot {
            views: vec![f],
            pass: self.pass_info(),
            ..Default::default()
        }
    }
    fn report(&self) -> Report {
        Report::default()
    }
    fn set_spp(&mut self, spp: u32) {
        self.spp = spp;
    }
}

fn job(generation: u64, target: Target) -> Job {
    Job {
        generation,
        chapter: &NOISY,
        scene: Arc::new(Scene::builtin()),
        settings: Settings::default(),
        variant: 1,
        target: Some(target),
    }
}

/// Every snapshot of `generation` until one is done.
fn until_done(worker: &Worker, generation: u64) -> Vec<RenderState> {
    let mut seen = Vec::new();
    loop {
        match worker.results.recv_timeout(Duration::from_secs(30)) {
            Ok(Progress::State(s)) if s.generation == generation => {
                let done = s.done;
                seen.push(*s);
                if done {
                    return seen;
                }
            }
            Ok(Progress::State(_) | Progress::Inspected { .. }) => {}
            Ok(Progress::Failed { message, .. } | Progress::Refused { message, .. }) => {
                panic!("{message}")
            }
            Err(e) => panic!("no snapshot: {e}"),
        }
    }
}

#[test]
fn the_stopping_rule_takes_the_nearer_of_noise_and_budget() {
    let t = Target {
        spp: 256,
        noise: Some(0.1),
    };
    // Noise 1/√spp of a mean of 1: clean at 100 spp, before the budget.
    let noise = |spp: u32| Some(1.0 / (spp as f64).sqrt());
    assert_eq!(finished(&t, 64, noise(64), 1.0), None);
    assert_eq!(finished(&t, 100, noise(100), 1.0), Some(Finish::Clean));
    assert_eq!(finished(&t, 256, noise(256), 1.0), Some(Finish::Budget));
    // Relative to the image: twice as bright, clean sooner.
    assert_eq!(finished(&t, 64, noise(64), 2.0), Some(Finish::Clean));
    // A noise estimate from too few samples is not trusted.
    assert_eq!(
        finished(&t, MIN_SPP_FOR_NOISE - 1, Some(0.0), 1.0),
        None,
        "too few samples"
    );
    // Without a noise level (or a noise estimate) only the budget stops.
    let budget_only = Target {
        spp: 8,
        noise: None,
    };
    assert_eq!(finished(&budget_only, 7, Some(0.0), 1.0), None);
    assert_eq!(finished(&budget_only, 8, None, 1.0), Some(Finish::Budget));
    assert_eq!(finished(&t, 64, None, 1.0), None);
}

#[test]
fn doubling_the_target_doubles_the_budget_and_lowers_the_noise_level_by_root_two() {
    let t = Target::DEFAULT.doubled();
    assert_eq!(t.spp, 2 * Target::DEFAULT.spp);
    let (a, b) = (t.noise.unwrap(), Target::DEFAULT.noise.unwrap());
    assert!((a * std::f64::consts::SQRT_2 - b).abs() < 1e-12);
    assert_eq!(t.halved(), Target::DEFAULT);
    let one = Target {
        spp: 1,
        noise: None,
    };
    assert_eq!(one.halved(), one, "never below one sample");
}

#[test]
fn the_worker_goes_on_until_the_noise_target_then_further_when_it_moves() {
    let worker = Worker::spawn();
    // 1/√spp ≤ 0.25 at 16 spp, long before the budget.
    let target = Target {
        spp: 1024,
        noise: Some(0.25),
    };
    worker.start(job(1, target));
    let seen = until_done(&worker, 1);
    let last = seen.last().unwrap();
    assert_eq!(last.samples, 16, "stops as soon as it is clean");
    assert_eq!(last.finish, Some(Finish::Clean));
    assert_eq!(last.target, Some(target));
    // Samples grow and the noise estimate falls, snapshot after snapshot.
    assert!(seen.windows(2).all(|w| w[0].samples < w[1].samples));
    let mut noise: Vec<f64> = seen.iter().filter_map(|s| s.noise).collect();

    // A lower level: the same render goes on (the samples keep counting up
    // from 16, they do not start over).
    let lower = Target {
        spp: 1024,
        noise: Some(0.125),
    };
    worker.retarget(1, lower);
    let more = until_done(&worker, 1);
    assert!(more.iter().all(|s| s.samples >= 16), "started over");
    noise.extend(more.iter().filter_map(|s| s.noise));
    assert!(noise.len() >= 3, "{noise:?}");
    assert!(noise.windows(2).all(|w| w[1] <= w[0]), "{noise:?}");
    assert!(noise.last().unwrap() < &noise[0]);
    let last = more.last().unwrap();
    assert_eq!(last.samples, 64);
    assert_eq!(last.finish, Some(Finish::Clean));

    // A budget below what is done stops at once, nothing added.
    worker.retarget(
        1,
        Target {
            spp: 32,
            noise: None,
        },
    );
    let stopped = until_done(&worker, 1);
    assert_eq!(stopped.last().unwrap().samples, 64);
    assert_eq!(stopped.last().unwrap().finish, Some(Finish::Budget));
    // A retarget for an old generation is ignored.
    worker.retarget(0, Target::DEFAULT);
    assert!(worker
        .results
        .recv_timeout(Duration::from_millis(200))
        .is_err());
    worker.stop();
}

#[test]
fn a_paused_render_sends_nothing_until_resumed() {
    let worker = Worker::spawn();
    let budget = Target {
        spp: 100,
        noise: None,
    };
    let wall = Instant::now();
    worker.start(job(3, budget));
    // The first pass is shown, then pause.
    let first = worker
        .results
        .recv_timeout(Duration::from_secs(10))
        .unwrap();
    assert_eq!(first.generation(), 3);
    worker.pause(3, true);
    // Drain what was under way; the pause snapshot comes last, once the
    // pass under way ends. The gap that ends the drain is long enough for
    // a pass on a loaded machine: a shorter one could end the drain before
    // the pause snapshot, which would then arrive "while paused".
    let mut at_pause = 0;
    while let Ok(Progress::State(s)) = worker.results.recv_timeout(Duration::from_secs(3)) {
        at_pause = s.samples;
    }
    assert!(at_pause < 100, "paused before the end");
    // Paused: nothing more arrives.
    assert!(worker
        .results
        .recv_timeout(Duration::from_millis(300))
        .is_err());
    worker.pause(3, false);
    let rest = until_done(&worker, 3);
    let last = rest.last().unwrap();
    assert_eq!(last.samples, 100);
    assert!(rest.iter().all(|s| s.samples >= at_pause));
    // The 3.3 s and more of waiting above are not rendering time.
    assert!(
        last.elapsed + Duration::from_secs(2) < wall.elapsed(),
        "{:?} of {:?}",
        last.elapsed,
        wall.elapsed()
    );
    worker.stop();
}

fn app() -> App {
    App::new(vec![&NOISY], vec![SceneEntry::builtin()], false)
}

fn snapshot(app: &App, samples: u32, done: bool) -> Msg {
    let render = NoisyRender {
        samples,
        spp: app.target.spp,
        passes: samples,
    };
    let mut snap = RenderState::capture(&render, app.generation, Duration::ZERO, done);
    snap.target = Some(app.target);
    Msg::Progress(Progress::State(Box::new(snap)))
}

#[test]
fn a_progressive_chapter_opens_on_its_best_variant_and_asks_for_its_target() {
    let app = app();
    assert_eq!(app.variant, 1, "the chapter's default variant");
    let job = app.job().unwrap();
    assert_eq!(job.target, Some(Target::DEFAULT));
    // The ladder is one key away in both directions, labelled.
    let app = update(app, Msg::NextVariant);
    assert_eq!(app.variant, 0);
    assert!(
        app.message.contains("step 1/2: uniform sampling"),
        "{}",
        app.message
    );
    let app = update(app, Msg::PrevVariant);
    assert_eq!(app.variant, 1);
    assert!(
        app.message.contains("step 2/2: the best"),
        "{}",
        app.message
    );
}

#[test]
fn space_pauses_and_resumes_and_a_restart_unpauses() {
    let app = app();
    let app = update(app, Msg::TogglePause);
    assert!(!app.paused, "nothing to pause before the first picture");
    let mut app = update(app, Msg::ToggleHelp);
    app = update(app, Msg::ToggleHelp);
    let msg = snapshot(&app, 4, false);
    let app = update(app, msg);
    let app = update(app, Msg::TogglePause);
    assert!(app.paused);
    assert!(app.message.contains("paused"));
    let app = update(app, Msg::TogglePause);
    assert!(!app.paused);
    let app = update(app, Msg::TogglePause);
    let generation = app.generation;
    // Changing the estimator starts over, running.
    let app = update(app, Msg::NextVariant);
    assert_eq!(app.generation, generation + 1);
    assert!(!app.paused);
    // A finished render cannot be paused; the message says how to go on.
    let msg = snapshot(&app, 16, true);
    let app = update(app, msg);
    let app = update(app, Msg::TogglePause);
    assert!(!app.paused);
    assert!(app.message.contains("raises the target"), "{}", app.message);
}

#[test]
fn target_keys_move_the_target_without_restarting() {
    let app = app();
    let generation = app.generation;
    let app = update(app, Msg::TargetUp);
    assert_eq!(app.target, Target::DEFAULT.doubled());
    assert!(app.message.contains("2048 spp"), "{}", app.message);
    let app = update(app, Msg::TargetDown);
    let app = update(app, Msg::TargetDown);
    assert_eq!(app.target, Target::DEFAULT.halved());
    assert_eq!(app.generation, generation, "the render goes on");
    assert_eq!(app.job().unwrap().target, Some(Target::DEFAULT.halved()));
}

#[test]
fn the_new_keys_map_to_their_messages() {
    let app = app();
    let key = |c| KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE);
    assert!(matches!(
        msg_for_key(&app, key(' ')),
        Some(Msg::TogglePause)
    ));
    assert!(matches!(msg_for_key(&app, key('>')), Some(Msg::TargetUp)));
    assert!(matches!(msg_for_key(&app, key('<')), Some(Msg::TargetDown)));
    assert!(matches!(
        msg_for_key(&app, key('E')),
        Some(Msg::PrevVariant)
    ));
    assert!(matches!(
        msg_for_key(&app, key('e')),
        Some(Msg::NextVariant)
    ));
}

#[test]
fn the_flags_choose_the_chapter_the_scene_and_the_budget() {
    use raystep::tui::{launch_app, Launch};
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let launch = Launch {
        scenes_dir: root.join("scenes"),
        out_dir: "out".into(),
        chapter: Some(6),
        scene: Some(root.join("scenes/cornell-glass.toml")),
        spp: Some(64),
        graphics: Default::default(),
        stats: false,
        readable: false,
        remember: None,
    };
    let mut app = launch_app(&launch, false);
    // What the event loop does in a thread: read the chosen scene.
    app.read_scene_now();
    let chapter = app.current_chapter().unwrap();
    assert_eq!(chapter.info().number, 6);
    assert_eq!(app.variant, chapter.info().default_variant);
    assert_eq!(
        chapter.info().variants[app.variant].name,
        "mis-sobol",
        "chapter 6 opens on its best estimator"
    );
    assert_eq!(app.current_scene().unwrap().name, "cornell-glass");
    let job = app.job().expect("chapter 6 renders the glass box");
    assert_eq!(job.target.map(|t| t.spp), Some(64));
    // A scene outside the listed folder is added to the list and opened.
    let elsewhere = Launch {
        scenes_dir: root.join("no-such-folder"),
        scene: Some(root.join("scenes/tetrahedron.toml")),
        ..launch
    };
    let app = launch_app(&elsewhere, false);
    assert_eq!(app.scenes.len(), 2, "the built-in scene and the file");
    assert_eq!(app.current_scene().unwrap().name, "tetrahedron");
}

/// A stage whose pass waits until the test lets it go: a pass that takes
/// as long as the test wants.
struct Stuck;

static STUCK: Stuck = Stuck;
static RELEASE: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

impl Chapter for Stuck {
    fn info(&self) -> ChapterInfo {
        ChapterInfo::new(
            4,
            "stuck",
            "A pass that waits",
            &[View {
                name: "image",
                about: "",
            }],
        )
    }
    fn start(&self, _: Arc<Scene>, _: &Settings) -> Result<Box<dyn Render>> {
        Ok(Box::new(StuckRender))
    }
}

struct StuckRender;

impl Render for StuckRender {
    fn pass(&mut self) -> Pass {
        while !RELEASE.load(std::sync::atomic::Ordering::SeqCst) {
            std::thread::sleep(Duration::from_millis(5));
        }
        Pass {
            done: 1,
            planned: 1,
            complete: true,
            ..Pass::default()
        }
    }
    fn snapshot(&self) -> raystep::core::stage::Snapshot {
        raystep::core::stage::Snapshot {
            views: vec![Film::new(2, 2)],
            ..Default::default()
        }
    }
    fn report(&self) -> Report {
        Report::default()
    }
}

#[test]
fn a_new_render_does_not_wait_for_the_old_ones_pass() {
    let worker = Worker::spawn();
    worker.start(Job {
        generation: 1,
        chapter: &STUCK,
        scene: Arc::new(Scene::builtin()),
        settings: Settings::default(),
        variant: 0,
        target: None,
    });
    // The stuck pass is under way; switch to another render, which
    // finishes while the first pass still waits.
    std::thread::sleep(Duration::from_millis(50));
    worker.start(job(
        2,
        Target {
            spp: 4,
            noise: None,
        },
    ));
    let seen = until_done(&worker, 2);
    assert_eq!(seen.last().unwrap().samples, 4);
    assert!(
        !RELEASE.load(std::sync::atomic::Ordering::SeqCst),
        "the first pass is still waiting"
    );
    // Let it go: the old render's thread ends; nothing of it is needed.
    RELEASE.store(true, std::sync::atomic::Ordering::SeqCst);
    worker.stop();
}

/// Chapter 6 as it is, except that its passes say when they start and end.
struct Watched(&'static dyn Chapter);

/// When the watched render's first pass started and ended.
static REAL_PASS: std::sync::Mutex<(Option<Instant>, Option<Instant>)> =
    std::sync::Mutex::new((None, None));

impl Chapter for Watched {
    fn info(&self) -> ChapterInfo {
        self.0.info()
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        Ok(Box::new(WatchedRender(self.0.start(scene, settings)?)))
    }
}

struct WatchedRender(Box<dyn Render>);

impl Render for WatchedRender {
    fn pass(&mut self) -> Pass {
        REAL_PASS.lock().unwrap().0.get_or_insert_with(Instant::now);
        let pass = self.0.pass();
        REAL_PASS.lock().unwrap().1.get_or_insert_with(Instant::now);
        pass
    }
    fn snapshot(&self) -> raystep::core::stage::Snapshot {
        self.0.snapshot()
    }
    fn report(&self) -> Report {
        self.0.report()
    }
}

/// The same with the real renderer and the real pools (issue 48):
/// chapter 6's first pass over the Cornell box at 1600x1600 takes seconds;
/// a small render started while it runs is done before that pass is half
/// way. With one rayon pool for both, the small render's rows queued
/// behind the big pass's and its picture came only at the pass's end.
/// (Times of one run compared with each other, with a margin of ten: the
/// order of events, not a speed target.)
#[test]
fn a_new_scene_does_not_wait_for_the_old_ones_real_pass() {
    let ch6 = *raystep::chapters::all().last().unwrap();
    assert_eq!(ch6.info().number, 6);
    let watched: &'static Watched = Box::leak(Box::new(Watched(ch6)));
    let cornell = Scene::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/cornell-box.toml"
    )))
    .unwrap();
    let worker = Worker::spawn();
    let job = |generation, size, chapter: &'static dyn Chapter| {
        let mut scene = cornell.clone();
        (scene.camera.width, scene.camera.height) = (size, size);
        Job {
            generation,
            chapter,
            scene: Arc::new(scene),
            settings: Settings::default(),
            variant: 0,
            target: Some(Target {
                spp: 4,
                noise: None,
            }),
        }
    };
    worker.start(job(1, 1600, watched));
    let started = loop {
        if let Some(t) = REAL_PASS.lock().unwrap().0 {
            break t;
        }
        std::thread::sleep(Duration::from_millis(1));
    };
    // Let the big pass spread over the pool's threads.
    std::thread::sleep(Duration::from_millis(50));
    worker.start(job(2, 24, ch6));
    until_done(&worker, 2);
    let new_done = Instant::now();
    // The old pass goes on (at the lowest priority); wait for its end.
    let ended = loop {
        if let Some(t) = REAL_PASS.lock().unwrap().1 {
            break t;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let (waited, pass) = (new_done - started, ended - started);
    assert!(
        waited < pass / 2,
        "the new render was done {waited:?} into the old pass, which took {pass:?}"
    );
}
