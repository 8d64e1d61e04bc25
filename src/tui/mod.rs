//! The terminal UI of `cargo run --release`, behind the default `tui`
//! feature (the rest of the library never uses ratatui or crossterm).
//!
//! Built after ratatui's templates: the state ([`app`]), the messages
//! ([`msg`]) and a pure [`update::update`] in [`update`](mod@update),
//! which says what should happen outside as [`effect::Effect`]s; a pure
//! [`view::view`]; key mapping in [`keys`]; a render [`worker`] thread
//! that sends a snapshot after every pass; the other [`threads`], which
//! carry out the effects; and this module's event loop, which owns the
//! terminal. The UI drives chapters only through
//! [`crate::core::stage::Chapter`] and [`crate::core::stage::Render`], so a
//! new chapter appears here by being listed in [`crate::chapters::all`].
//!
//! The loop polls for keys with a short timeout (so a key is handled within
//! a frame, well under 50 ms), drains the threads' channels, hands every
//! message to `update` and carries out the effects it asks for, and
//! redraws at most [`FRAME`] apart, and only when something changed. It
//! keeps no copy of the state to compare against. The terminal is
//! restored on quit, on an error and on a panic of the UI thread (a panic
//! hook restores it and then prints the panic).

#![forbid(unsafe_code)]
#![warn(missing_docs)]

// The crates below under their own names, so that paths read as in them
// (`crate::core::…`, `crate::grading::…`).
use raystep_fast::chapters;
use raystep_grading as grading;
use raystep_lessons::{core, scene};

pub mod answers;
pub mod app;
pub mod bench;
pub mod compared;
pub mod curves;
pub mod effect;
pub mod gauge;
pub mod graphics;
pub mod inspect;
pub mod job;
pub mod keys;
pub mod labels;
pub mod last;
pub mod layers;
pub mod loading;
pub mod msg;
pub mod painter;
pub mod picture;
pub mod placement;
pub mod pool;
pub mod query;
pub mod readouts;
pub mod region;
pub mod save;
pub mod scenes;
pub mod screen;
pub mod screen_update;
pub mod shown;
pub mod signals;
pub mod sixel;
pub mod split;
pub mod state;
pub mod stats;
pub mod student;
pub mod student_update;
pub mod target;
pub mod terminal;
pub mod threads;
pub mod update;
pub mod view;
pub mod warp;
pub mod warp_jobs;
pub mod worker;
pub mod zoom;

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use crossterm::event::{self, Event, KeyCode, KeyModifiers};
use ratatui::backend::CrosstermBackend;
use ratatui::Terminal;

use app::{App, Msg};
use effect::Effect;
pub use terminal::restore_terminal;
use terminal::{answer_signal, install_panic_hook, take_terminal, Restore};

/// Shortest time between two redraws (about 30 per second).
pub const FRAME: Duration = Duration::from_millis(33);

/// Whether colour is allowed: `NO_COLOR` unset or empty.
pub fn color_allowed() -> bool {
    std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// Whether the main binary should open the UI: stdout is a terminal that
/// can draw one (`TERM=dumb` cannot: it gets the headless summary, as a
/// pipe does).
pub fn should_open() -> bool {
    std::io::stdout().is_terminal() && std::env::var("TERM").map_or(true, |t| t != "dumb")
}

/// Set this environment variable to make the UI panic after its first
/// frame (the end-to-end test checks that the terminal is restored).
pub const TEST_PANIC: &str = "RAYSTEP_TUI_TEST_PANIC";

/// Set this environment variable to make the UI's event loop fail with an
/// error after its first frame (the end-to-end test checks that the
/// terminal is restored before the error is printed).
pub const TEST_ERROR: &str = "RAYSTEP_TUI_TEST_ERROR";

/// What the main binary's flags ask the UI to open with.
#[derive(Clone, Debug, Default)]
pub struct Launch {
    /// The folder of scenes listed after the built-in scene.
    pub scenes_dir: PathBuf,
    /// Where `s` saves.
    pub out_dir: PathBuf,
    /// The chapter to open (lecture number); the first when `None`.
    pub chapter: Option<u32>,
    /// A scene file to open: selected in the list (added if the folder
    /// does not hold it).
    pub scene: Option<PathBuf>,
    /// The sample budget of progressive chapters.
    pub spp: Option<u32>,
    /// How the preview is drawn (`--graphics`; `--halfblocks` forces
    /// half blocks).
    pub graphics: graphics::Choice,
    /// Print the bytes written to the terminal per second on quit
    /// (`--stats`).
    pub stats: bool,
    /// Chapter 6 with the lesson's readable engine (`--engine readable`).
    pub readable: bool,
    /// Where the last chapter, scene and view are remembered
    /// ([`last::path`]); `None`: nothing is remembered.
    pub remember: Option<PathBuf>,
}

/// The UI's first state for `launch`: its chapter, scene and budget
/// selected, asking for its first render ([`Effect::Start`] in
/// [`App::effects`]; none while its scene waits to be read).
pub fn launch_app(launch: &Launch, color: bool) -> App {
    launch_app_with(launch, color, None)
}

/// [`launch_app`], opening on what the last run showed (`last`) where the
/// flags do not choose: the flags' chapter and scene win over it.
pub fn launch_app_with(launch: &Launch, color: bool, last: Option<&last::Last>) -> App {
    let mut entries = scenes::scene_list(&launch.scenes_dir);
    let chosen = launch.scene.as_ref().map(|path| {
        let same = |e: &scenes::SceneEntry| {
            let a = std::fs::canonicalize(&e.source).ok();
            a.is_some() && a == std::fs::canonicalize(path).ok()
        };
        entries.iter().position(same).unwrap_or_else(|| {
            entries.push(scenes::SceneEntry::load(path));
            entries.len() - 1
        })
    });
    let mut app = App::new(
        crate::chapters::with_engine(launch.readable),
        entries,
        color,
    );
    app.out_dir = launch.out_dir.clone();
    if let Some(spp) = launch.spp {
        app.target.spp = spp.max(1);
    }
    let remembered_scene = last.and_then(|l| {
        let found = app.scenes.iter().position(|e| e.source == l.scene);
        found.or_else(|| {
            let path = std::path::Path::new(&l.scene);
            (path.extension().is_some_and(|e| e == "toml") && path.is_file()).then(|| {
                app.scenes.push(scenes::SceneEntry::load(path));
                app.scenes.len() - 1
            })
        })
    });
    let number = launch.chapter.or(last.map(|l| l.chapter));
    if let Some(i) = app
        .chapters
        .iter()
        .position(|c| Some(c.info().number) == number)
    {
        app.select_chapter(i);
    }
    if let Some(i) = chosen.or(remembered_scene.filter(|_| launch.scene.is_none())) {
        app.select_scene(i);
    }
    if let (Some(l), None) = (last, launch.chapter) {
        let views = app.current_chapter().map(|c| c.info().views).unwrap_or(&[]);
        if let Some(v) = views.iter().position(|v| v.name == l.view) {
            app.view = v;
        }
    }
    // The selection is made: its render is the first.
    let job = app.job();
    app.effects.extend(job.map(Effect::Start));
    app
}

/// Runs the UI until the user quits.
pub fn run(launch: &Launch) -> std::io::Result<()> {
    let mut warnings = Vec::new();
    let last = match launch.remember.as_deref().map(last::load) {
        Some(Ok(l)) => l,
        Some(Err(e)) => {
            warnings.push(format!("warning: ignored {e}"));
            None
        }
        None => None,
    };
    let app = launch_app_with(launch, color_allowed(), last.as_ref());
    let mut report = None;
    let result = run_app(launch, app, &mut report);
    // The terminal is restored by now: warnings can be read.
    warnings.extend(report);
    if let (Ok(Some(now)), Some(file)) = (&result, &launch.remember) {
        if let Err(e) = last::store(file, now) {
            warnings.push(format!("warning: could not remember the last view: {e}"));
        }
    }
    for w in warnings {
        eprintln!("{w}");
    }
    result.map(|_| ())
}

/// Runs the UI on `app` until the user quits; what it showed last.
/// With `--stats`, `report` gets the bytes written per second.
fn run_app(
    launch: &Launch,
    mut app: App,
    report: &mut Option<String>,
) -> std::io::Result<Option<last::Last>> {
    install_panic_hook();
    let signals = signals::Signals::install(restore_terminal);
    let _restore = Restore;
    take_terminal()?;
    // Asked once, before crossterm reads keys.
    let chosen = graphics::pick(launch.graphics);
    (app.graphics, app.font) = (chosen.graphics, chosen.font);
    if let Some(note) = chosen.note {
        app.message = note;
    }
    let out = stats::Counting::new(std::io::stdout());
    let mut rates = stats::Rates::new(Instant::now(), out.count());
    let mut terminal = Terminal::new(CrosstermBackend::new(out))?;
    terminal.clear()?;
    let last = event_loop(&mut terminal, app, &mut rates, signals.as_ref());
    *report = launch.stats.then(|| rates.report());
    last
}

/// The loop: answers signals, looks for edited scene files, hands every
/// message to [`threads::Threads::handle`] (which carries out the effects
/// `update` asks for), draws when something changed, and waits for a key
/// at most until the next frame is due.
fn event_loop(
    terminal: &mut stats::Term,
    mut app: App,
    rates: &mut stats::Rates,
    signals: Option<&signals::Signals>,
) -> std::io::Result<Option<last::Last>> {
    let mut threads = threads::Threads::spawn();
    let size = terminal.size()?;
    // Also carries out what `launch_app` asked for: the first render.
    app = threads.handle(app, Msg::Resize(size.width, size.height));
    let mut frames = Frames {
        painter: painter::Painter::for_process(app.graphics),
        dirty: true,
        last: None,
    };
    let mut ticked = Instant::now();
    // When the current scene's file was last looked at for edits.
    let mut checked = Instant::now();
    loop {
        rates.tick(Instant::now());
        while let Some(signal) = signals.and_then(|s| s.try_recv()) {
            answer_signal(signal, terminal, &mut frames.painter)?;
            frames.dirty = true;
        }
        if checked.elapsed() >= Duration::from_secs(1) {
            checked = Instant::now();
            // Edited since it was read: read again (a stat, not a read).
            if app.current_scene().is_some_and(|e| e.edited()) {
                let edited = Msg::SceneEdited(app.scene);
                app = threads.handle(app, edited);
                frames.dirty = true;
            }
        }
        for msg in threads.messages(&app) {
            app = threads.handle(app, msg);
            frames.dirty = true;
        }
        if app.quit {
            return Ok(last::of(&app));
        }
        // Old messages clear (the message line then shows the mode's keys).
        let elapsed = ticked.elapsed();
        ticked = Instant::now();
        if !app.message.is_empty() {
            app = threads.handle(app, Msg::Tick(elapsed));
            frames.dirty |= app.message.is_empty();
        }
        let timeout = frames.draw(terminal, &app)?;
        if let Some(msg) = input(terminal, &app, &mut frames, timeout)? {
            app = threads.handle(app, msg);
            frames.dirty = true;
        }
        while let Ok(progress) = threads.worker.results.try_recv() {
            app = threads.handle(app, Msg::Progress(progress));
            frames.dirty = true;
            rates.busy();
        }
    }
}

/// The screen as the loop draws it.
struct Frames {
    painter: painter::Painter,
    /// Something changed since the last frame.
    dirty: bool,
    /// When the last frame was drawn.
    last: Option<Instant>,
}

impl Frames {
    /// Draws `app` if something changed and a frame is due (at most
    /// [`FRAME`] apart); how long to wait for a key: at most until the
    /// next frame is due.
    fn draw(&mut self, terminal: &mut stats::Term, app: &App) -> std::io::Result<Duration> {
        let since = self.last.map_or(FRAME, |t| t.elapsed());
        if self.dirty && since >= FRAME {
            painter::draw_frame(terminal, app, &mut self.painter)?;
            self.last = Some(Instant::now());
            self.dirty = self.painter.pending();
            // For the end-to-end tests: a panic, or an error, while the UI
            // owns the terminal.
            if std::env::var_os(TEST_PANIC).is_some() {
                panic!("{TEST_PANIC} is set: a deliberate panic after the first frame");
            }
            if std::env::var_os(TEST_ERROR).is_some() {
                return Err(std::io::Error::other(format!(
                    "{TEST_ERROR} is set: a deliberate error after the first frame"
                )));
            }
        }
        Ok(if self.dirty {
            FRAME.saturating_sub(since).max(Duration::from_millis(1))
        } else {
            Duration::from_millis(20)
        })
    }
}

/// Waits up to `timeout` for a terminal event: the message it makes, if
/// any. Ctrl-Z suspends here; a resize also resizes the terminal.
fn input(
    terminal: &mut stats::Term,
    app: &App,
    frames: &mut Frames,
    timeout: Duration,
) -> std::io::Result<Option<Msg>> {
    if !event::poll(timeout)? {
        return Ok(None);
    }
    Ok(match event::read()? {
        Event::Key(key)
            if key.code == KeyCode::Char('z') && key.modifiers.contains(KeyModifiers::CONTROL) =>
        {
            // Ctrl-Z, a key in raw mode: suspend as TSTP would.
            answer_signal(signals::Signal::Suspend, terminal, &mut frames.painter)?;
            frames.dirty = true;
            None
        }
        Event::Paste(_) => Some(Msg::Pasted),
        Event::Key(key) => keys::msg_for_key(app, key),
        Event::Mouse(m) => {
            let size = terminal.size()?;
            keys::msg_for_mouse(m, (size.width, size.height))
        }
        Event::Resize(width, height) => {
            terminal.autoresize()?;
            frames.painter.invalidate(terminal.backend_mut())?;
            Some(Msg::Resize(width, height))
        }
        _ => None,
    })
}
