//! The terminal UI without a terminal: key handling and bounce/compare
//! logic as pure `update` tests, layout snapshots on ratatui's TestBackend
//! at two sizes, the preview's cell colours, the render worker's
//! generations, and the book's text capture of the UI.

use crate::common;
use std::sync::Arc;
use std::time::Duration;

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use glam::Vec3;
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::widgets::Widget;
use ratatui::Terminal;

use raystep::core::error::Result;
use raystep::core::film::{encode_srgb, Film};
use raystep::core::report::Report;
use raystep::core::stage::{Chapter, ChapterInfo, Pass, Render, Settings, Snapshot, Variant, View};
use raystep::scene::Scene;
use raystep::tui::app::{combine_layers, App, BounceMode, Compare, Focus, Msg};
use raystep::tui::effect::Effect;
use raystep::tui::keys::msg_for_key;
use raystep::tui::picture::{fit, Picture};
use raystep::tui::scenes::{scene_list, SceneEntry};
use raystep::tui::update::{save, update};
use raystep::tui::view::{control_lines, view};
use raystep::tui::worker::{Job, Progress, RenderState, Worker};

/// A stage with everything the UI can show: bounce layers, a reference, an
/// error series, two views and two variants. Layer k is a flat colour.
pub(crate) struct Fake {
    bounces: bool,
}

pub(crate) static FAKE: Fake = Fake { bounces: true };
pub(crate) static FAKE_PLAIN: Fake = Fake { bounces: false };

const W: u32 = 8;
const H: u32 = 4;

fn layer_color(k: usize) -> Vec3 {
    [
        Vec3::new(0.5, 0.0, 0.0),
        Vec3::new(0.0, 0.25, 0.0),
        Vec3::new(0.0, 0.0, 0.125),
    ][k]
}

fn flat(c: Vec3) -> Film {
    let mut f = Film::new(W, H);
    f.pixels.iter_mut().for_each(|p| *p = c);
    f
}

const FAKE_VIEWS: &[View] = &[
    View {
        name: "image",
        about: "the image",
    },
    View {
        name: "depth",
        about: "a ramp",
    },
];

const FAKE_VARIANTS: &[Variant] = &[
    Variant {
        name: "brdf",
        about: "BRDF sampling",
    },
    Variant {
        name: "mis",
        about: "MIS",
    },
];

impl Chapter for Fake {
    fn info(&self) -> ChapterInfo {
        let (number, slug) = if self.bounces {
            (6, "fake-gi")
        } else {
            (2, "fake")
        };
        ChapterInfo {
            bounces: self.bounces,
            variants: if self.bounces { FAKE_VARIANTS } else { &[] },
            ..ChapterInfo::new(number, slug, "A fake stage", FAKE_VIEWS)
        }
    }
    fn start(&self, scene: Arc<Scene>, _settings: &Settings) -> Result<Box<dyn Render>> {
        if scene.name == "no-go" {
            return Err(raystep::Error::Usage(
                "this stage needs a scene with spheres".into(),
            ));
        }
        Ok(Box::new(FakeRender {
            bounces: self.bounces,
            passes: 0,
            planned: 1,
            sleep: Duration::ZERO,
        }))
    }
}

struct FakeRender {
    bounces: bool,
    passes: u32,
    planned: u32,
    sleep: Duration,
}

impl FakeRender {
    fn view(&self, index: usize) -> Film {
        if index == 0 {
            flat(layer_color(0) + layer_color(1) + layer_color(2))
        } else {
            let mut f = Film::new(W, H);
            for x in 0..W {
                for y in 0..H {
                    *f.get_mut(x, y) = Vec3::splat(x as f32 / (W - 1) as f32);
                }
            }
            f
        }
    }

    /// The stage with bounces counts one ray per pixel and pass; the plain
    /// one does not count (0).
    fn pass_info(&self) -> Pass {
        let rays = if self.bounces {
            (W * H * self.passes) as u64
        } else {
            0
        };
        Pass {
            done: self.passes,
            planned: self.planned.max(self.passes),
            rays,
            complete: self.passes >= self.planned,
            ..Pass::default()
        }
    }
}

impl Render for FakeRender {
    fn pass(&mut self) -> Pass {
        std::thread::sleep(self.sleep);
        self.passes += 1;
        self.pass_info()
    }
    fn snapshot(&self) -> Snapshot {
        let error_series = if self.bounces {
            vec![(0.01, 0.3), (0.02, 0.2), (0.04, 0.14), (0.08, 0.1)]
        } else {
            Vec::new()
        };
        Snapshot {
            views: vec![self.view(0), self.view(1)],
            layers: self
                .bounces
                .then(|| (0..3).map(|k| flat(layer_color(k))).collect()),
            reference: self.bounces.then(|| flat(Vec3::new(0.5, 0.25, 0.25))),
            reference_stderr: None,
            reference_factor: 1,
            error_series,
            pass: self.pass_info(),
        }
    }
    fn report(&self) -> Report {
        Report::default()
    }
}

fn renamed(name: &str) -> SceneEntry {
    let mut scene = Scene::builtin();
    scene.name = name.into();
    SceneEntry {
        name: name.into(),
        source: format!("scenes/{name}.toml"),
        scene: Ok(Arc::new(scene)),
        pending: None,
        modified: None,
    }
}

pub(crate) fn scenes() -> Vec<SceneEntry> {
    vec![
        SceneEntry::builtin(),
        renamed("no-go"),
        SceneEntry {
            name: "broken".into(),
            source: "scenes/broken.toml".into(),
            scene: Err("scenes/broken.toml: line 3: unknown key `colour`".into()),
            pending: None,
            modified: None,
        },
    ]
}

/// A fresh UI on the fake stage with bounces (chapter 6), plus the plain
/// fake (chapter 2).
pub(crate) fn app() -> App {
    let mut app = App::new(vec![&FAKE_PLAIN, &FAKE], scenes(), false);
    app = update(app, Msg::ChapterNumber(6));
    app
}

/// Runs the current job to completion synchronously and feeds the last
/// snapshot to the UI.
pub(crate) fn rendered(app: App) -> App {
    let job = app.job().expect("the selection renders");
    let settings = Settings {
        variant: Some(job.variant),
        ..job.settings.clone()
    };
    let mut render = job.chapter.start(job.scene, &settings).unwrap();
    while !render.pass().complete {}
    let snap = RenderState::capture(&*render, job.generation, Duration::from_millis(12), true);
    update(app, Msg::Progress(Progress::State(Box::new(snap))))
}

pub(crate) fn send(app: App, msgs: &[Msg]) -> App {
    msgs.iter().cloned().fold(app, update)
}

fn pixel(app: &App) -> Vec3 {
    app.displayed().expect("a picture").pixels[0]
}

/// The colour the preview gives the first pixel.
fn painted(app: &App) -> Vec3 {
    app.paint(&app.displayed().expect("a picture")).pixels[0]
}

#[test]
fn bounce_stepping_shows_exactly_k_and_up_to_k_from_the_layers() {
    let app = rendered(app());
    assert!(app.shows_bounces());
    assert_eq!(app.bounce, None);
    let all = layer_color(0) + layer_color(1) + layer_color(2);
    assert_eq!(pixel(&app), all);
    assert_eq!(app.bounce_label(), "all bounces");

    let app = update(app, Msg::BounceUp);
    assert_eq!(app.bounce, Some(0));
    assert_eq!(app.bounce_mode, BounceMode::UpTo);
    assert_eq!(pixel(&app), layer_color(0));
    assert_eq!(app.bounce_label(), "up to 0 bounces: direct illumination");

    let app = update(app, Msg::BounceUp);
    assert_eq!(pixel(&app), layer_color(0) + layer_color(1));
    let app = update(app, Msg::ToggleBounceMode);
    assert_eq!(app.bounce_mode, BounceMode::Exactly);
    assert_eq!(pixel(&app), layer_color(1));
    assert_eq!(app.bounce_label(), "exactly 1 bounce: bounce 1 alone");
    assert!(control_lines(&app)
        .iter()
        .any(|l| l.to_string().contains("bounces exactly 1")));
    let app = update(app, Msg::ToggleBounceMode);
    assert_eq!(
        app.bounce_label(),
        "up to 1 bounce: one-bounce global illumination"
    );
    let app = update(app, Msg::ToggleBounceMode);

    // Past the last layer "exactly" is black; stepping wraps through "all".
    let app = send(app, &vec![Msg::BounceUp; 3]);
    assert_eq!(app.bounce, Some(4));
    assert_eq!(pixel(&app), Vec3::ZERO);
    assert_eq!(app.bounce_label(), "exactly 4 bounces: bounce 4 alone");
    let app = send(app, &vec![Msg::BounceUp; 12]);
    assert_eq!(app.bounce, Some(16));
    assert_eq!(app.bounce_label(), "exactly 16 bounces: bounce 16 alone");
    // Up to k, the lecture's names: direct, one-bounce … sixteen-bounce.
    for (k, name) in [
        (0, "direct illumination"),
        (2, "two-bounce global illumination"),
        (4, "four-bounce global illumination"),
        (8, "eight-bounce global illumination"),
        (16, "sixteen-bounce global illumination"),
    ] {
        assert_eq!(raystep::tui::app::bounce_name(k), name);
    }
    let app = update(app, Msg::BounceUp);
    assert_eq!(app.bounce, None);
    let app = update(app, Msg::BounceDown);
    assert_eq!(app.bounce, Some(16));
    let app = send(app, &vec![Msg::BounceDown; 17]);
    assert_eq!(app.bounce, None);
    // Bounce stepping changes the picture only: no new render.
    assert_eq!(app.generation, 2);
}

#[test]
fn combine_layers_sums_or_picks() {
    let layers: Vec<Film> = (0..3).map(|k| flat(layer_color(k))).collect();
    let like = Film::new(W, H);
    let up_to_2 = combine_layers(&layers, 2, BounceMode::UpTo, &like);
    assert_eq!(up_to_2.pixels[5], Vec3::new(0.5, 0.25, 0.125));
    let exactly_2 = combine_layers(&layers, 2, BounceMode::Exactly, &like);
    assert_eq!(exactly_2.pixels[5], layer_color(2));
}

#[test]
fn chapters_without_bounces_or_reference_hide_those_controls() {
    let app = rendered(update(app(), Msg::ChapterNumber(2)));
    assert!(!app.shows_bounces());
    assert!(!app.shows_compare());
    let lines: Vec<String> = control_lines(&app).iter().map(|l| l.to_string()).collect();
    assert!(
        !lines
            .iter()
            .any(|l| l.contains("bounces") || l.contains("compare") || l.contains("estimator")),
        "{lines:?}"
    );
    let before = pixel(&app);
    let app = send(
        app,
        &[
            Msg::BounceUp,
            Msg::ToggleBounceMode,
            Msg::CycleCompare,
            Msg::NextVariant,
        ],
    );
    assert_eq!(app.bounce, None);
    assert_eq!(app.compare, Compare::Render);
    assert_eq!(
        app.generation, 3,
        "NextVariant without variants restarts nothing"
    );
    assert_eq!(pixel(&app), before);

    // The real chapter 1 has no bounces either.
    let ch1 = raystep::chapters::all()[0];
    assert!(!ch1.info().bounces);
}

#[test]
fn compare_cycles_render_reference_difference() {
    let app = rendered(app());
    let render = pixel(&app);
    let reference = Vec3::new(0.5, 0.25, 0.25);
    let app = update(app, Msg::CycleCompare);
    assert_eq!(app.compare, Compare::Reference);
    assert_eq!(pixel(&app), reference);
    let app = update(app, Msg::CycleCompare);
    assert_eq!(app.compare, Compare::Difference);
    // render − reference = (0, 0, −0.125): the view holds the signed
    // number (the readout and the EXR show it), and paints it blue, on
    // the fixed scale 0.25.
    assert_eq!(render - reference, Vec3::new(0.0, 0.0, -0.125));
    assert_eq!(pixel(&app), Vec3::new(0.0, 0.0, -0.125));
    assert_eq!(painted(&app), Vec3::new(0.0, 0.0, 0.5));
    let legend = |app: &App| {
        control_lines(app)
            .iter()
            .map(|l| l.to_string())
            .collect::<Vec<_>>()
    };
    assert!(
        legend(&app).contains(&"−0.25 blue · 0 · +0.25 red".to_string()),
        "{:?}",
        legend(&app)
    );
    // A stop of exposure halves the scale (the colours are not brightened).
    let app = update(app, Msg::ExposureUp);
    assert_eq!(painted(&app), Vec3::new(0.0, 0.0, 1.0));
    assert_eq!(pixel(&app), Vec3::new(0.0, 0.0, -0.125));
    assert_eq!(app.display_exposure(), 0);
    assert!(legend(&app).contains(&"−0.125 blue · 0 · +0.125 red".to_string()));
    let app = update(app, Msg::ExposureReset);
    // Relative: −0.125 / 0.25 = −50%, full blue on the ±50% scale.
    let app = update(app, Msg::CycleCompare);
    assert_eq!(app.compare, Compare::Relative);
    assert_eq!(pixel(&app), Vec3::new(0.0, 0.0, -0.5));
    assert_eq!(painted(&app), Vec3::new(0.0, 0.0, 1.0));
    assert!(
        legend(&app).contains(&"−50% blue · 0 · +50% red".to_string()),
        "{:?}",
        legend(&app)
    );
    let app = update(app, Msg::CycleCompare);
    assert_eq!(app.compare, Compare::Render);
    assert_eq!(pixel(&app), render);
    // The status line carries the error against the reference.
    let status = raystep::tui::view::status_line(&app).to_string();
    assert!(status.contains("rmse"), "{status}");
}

#[test]
fn lists_views_exposure_and_variants() {
    let app = app();
    assert_eq!(app.focus, Focus::Chapters);
    assert_eq!(app.chapter, 1);
    let app = update(app, Msg::Up);
    assert_eq!(app.chapter, 0);
    let g = app.generation;
    let app = update(app, Msg::Up);
    assert_eq!(
        (app.chapter, app.generation),
        (0, g),
        "no restart at the top"
    );

    let app = update(app, Msg::SwitchFocus);
    assert_eq!(app.focus, Focus::Scenes);
    let app = update(app, Msg::Down);
    assert_eq!(app.scene, 1);
    assert_eq!(app.generation, g + 1);
    // A stage refuses a scene it cannot render when it starts; the worker
    // shows that error (see `a_failed_start_is_shown`).
    assert!(app.problem().is_none());
    let job = app.job().expect("a loaded scene gets a job");
    let why = job.chapter.start(job.scene.clone(), &job.settings).err();
    let why = why.expect("the fake refuses no-go").to_string();
    assert!(why.contains("spheres"), "{why}");
    let app = update(app, Msg::Down);
    assert!(app.problem().unwrap().contains("unknown key `colour`"));
    assert!(app.job().is_none());
    let app = send(app, &[Msg::Down, Msg::Up, Msg::Up]);
    assert_eq!(app.scene, 0);
    assert!(app.job().is_some());

    let app = rendered(update(app, Msg::ChapterNumber(6)));
    let app = update(app, Msg::NextView);
    assert_eq!(app.view_name(), "depth");
    let app = send(app, &[Msg::NextView]);
    assert_eq!(app.view_name(), "image");
    let app = update(app, Msg::PrevView);
    assert_eq!(app.view_name(), "depth");
    let other = update(update(app, Msg::ChapterNumber(2)), Msg::ChapterNumber(6));
    assert_eq!(other.view, 0, "a new chapter starts on its first view");
    let app = rendered(update(other, Msg::NextView));

    let app = send(app, &vec![Msg::ExposureUp; 12]);
    assert_eq!(app.exposure, 10);
    let app = update(app, Msg::ExposureReset);
    assert_eq!(app.exposure, 0);

    let g = app.generation;
    let app = update(app, Msg::NextVariant);
    assert_eq!((app.variant, app.generation), (1, g + 1));
    assert!(app.snapshot.is_none(), "a restart drops the old picture");
    let app = update(app, Msg::NextVariant);
    assert_eq!(app.variant, 0);
}

#[test]
fn stale_passes_are_dropped() {
    let app = rendered(app());
    let old = app.snapshot.clone().unwrap();
    let app = update(app, Msg::ChapterNumber(2));
    assert!(app.snapshot.is_none());
    let app = update(app, Msg::Progress(Progress::State(Box::new(old))));
    assert!(
        app.snapshot.is_none(),
        "a pass of the old render must not show"
    );
    let app = update(
        app,
        Msg::Progress(Progress::Failed {
            generation: 1,
            message: "old".into(),
        }),
    );
    assert!(app.failure.is_none());
}

fn key(code: KeyCode) -> KeyEvent {
    KeyEvent::new(code, KeyModifiers::NONE)
}

#[test]
fn keys_map_to_messages() {
    let app = app();
    let m = |k| msg_for_key(&app, k).map(|m| format!("{m:?}"));
    assert_eq!(m(key(KeyCode::Char('q'))).as_deref(), Some("Quit"));
    // Esc closes what is open and never quits.
    assert_eq!(m(key(KeyCode::Esc)).as_deref(), Some("Close"));
    assert_eq!(
        m(KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL)).as_deref(),
        Some("Quit")
    );
    assert_eq!(m(key(KeyCode::Char(']'))).as_deref(), Some("BounceUp"));
    assert_eq!(
        m(key(KeyCode::Char('m'))).as_deref(),
        Some("ToggleBounceMode")
    );
    assert_eq!(
        m(key(KeyCode::Char('3'))).as_deref(),
        Some("ChapterNumber(3)")
    );
    assert_eq!(m(key(KeyCode::Down)).as_deref(), Some("Down"));
    assert_eq!(m(key(KeyCode::Char('z'))).as_deref(), Some("Zoom(1)"));
    assert_eq!(m(key(KeyCode::Char('y'))), None);

    // With the help open, Esc closes it, and any other key only closes it.
    let app = update(app, Msg::ToggleHelp);
    let closed = update(app, Msg::Close);
    assert!(!closed.help && !closed.quit);
    let app = update(closed, Msg::ToggleHelp);
    let app = update(app, Msg::NextView);
    assert!(!app.help);
    assert_eq!(app.view, 0);
    let app = update(app, Msg::Quit);
    assert!(app.quit);
}

#[test]
fn save_writes_the_view_as_png_and_the_film_as_exr() {
    let dir = common::temp_dir("tui-save");
    let mut app = update(app(), Msg::Save);
    assert!(
        !app.effects.iter().any(|e| matches!(e, Effect::Save)),
        "nothing to save before the first pass: {:?}",
        app.effects
    );
    assert_eq!(app.message, "nothing to save yet");
    app = rendered(app);
    app.out_dir = dir.clone();
    // (The first render was asked for: what follows asks for a save alone.)
    app.effects.clear();
    app = send(
        app,
        &[
            Msg::BounceUp,
            Msg::ToggleBounceMode,
            Msg::ExposureUp,
            Msg::Save,
        ],
    );
    let asked = std::mem::take(&mut app.effects);
    assert!(matches!(asked[..], [Effect::Save]), "{asked:?}");
    // What the event loop does with it.
    let files = save(&app).unwrap();
    // The name says chapter, scene, view, bounce layer, estimator and
    // exposure (the fake counts no samples).
    assert_eq!(
        files,
        vec![
            dir.join("tui-ch6-cornell-box-image-exactly0-brdf-ev+1.png"),
            dir.join("tui-ch6-cornell-box-image-exactly0-brdf-ev+1.exr")
        ]
    );
    // PNG: layer 0 (0.5 red) one stop up = 1.0; EXR: the film, unexposed.
    let png = Film::read_png(&files[0]).unwrap();
    assert_eq!(png.pixels[0], Vec3::new(1.0, 0.0, 0.0));
    let exr = Film::read_exr(&files[1]).unwrap();
    assert_eq!(exr.pixels[0], layer_color(0));
    let app = update(app, Msg::Saved(Ok(files)));
    assert!(app.effects.is_empty(), "{:?}", app.effects);
    assert!(app.message.starts_with("saved "), "{}", app.message);
}

#[test]
fn preview_cells_carry_the_films_colours() {
    // A 2x2 film, red on top and blue below, drawn into one row of cells.
    let mut film = Film::new(2, 2);
    *film.get_mut(0, 0) = Vec3::new(1.0, 0.0, 0.0);
    *film.get_mut(1, 0) = Vec3::new(1.0, 0.0, 0.0);
    *film.get_mut(0, 1) = Vec3::new(0.0, 0.0, 0.2);
    *film.get_mut(1, 1) = Vec3::new(0.0, 0.0, 0.2);
    let area = Rect::new(0, 0, 2, 1);
    let mut buf = Buffer::empty(area);
    Picture {
        film: &film,
        color: true,
    }
    .render(area, &mut buf);
    let blue = encode_srgb(0.2);
    for x in 0..2 {
        let cell = &buf[(x, 0)];
        assert_eq!(cell.symbol(), "▀");
        assert_eq!(cell.fg, Color::Rgb(255, 0, 0));
        assert_eq!(cell.bg, Color::Rgb(0, 0, blue));
    }

    // Through the whole UI: every preview cell carries the fake's colour.
    let mut app = rendered(App::new(vec![&FAKE], scenes(), true));
    app.exposure = 0;
    let mut terminal = Terminal::new(TestBackend::new(60, 20)).unwrap();
    terminal.draw(|f| view(&app, f)).unwrap();
    let c = layer_color(0) + layer_color(1) + layer_color(2);
    let [r, g, b] = c.to_array().map(encode_srgb);
    let buffer = terminal.backend().buffer();
    let painted: Vec<_> = buffer
        .content()
        .iter()
        .filter(|cell| cell.symbol() == "▀")
        .collect();
    assert!(painted.len() > 50, "only {} preview cells", painted.len());
    for cell in painted {
        assert_eq!(
            (cell.fg, cell.bg),
            (Color::Rgb(r, g, b), Color::Rgb(r, g, b))
        );
    }
}

#[test]
fn fit_keeps_the_aspect_ratio_with_two_pixels_per_cell() {
    // A square film in a 40x10 area: 20 cells wide, 10 tall, centred.
    assert_eq!(
        fit(Rect::new(0, 0, 40, 10), 256, 256),
        Rect::new(10, 0, 20, 10)
    );
    // A wide film in a tall area: full width.
    assert_eq!(
        fit(Rect::new(0, 0, 20, 40), 320, 240),
        Rect::new(0, 16, 20, 8)
    );
    assert_eq!(fit(Rect::new(3, 3, 0, 5), 10, 10).width, 0);
}

fn text(buffer: &Buffer) -> String {
    let area = buffer.area;
    let mut out = String::new();
    for y in 0..area.height {
        let mut line = String::new();
        for x in 0..area.width {
            line.push_str(buffer[(x, y)].symbol());
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}

pub(crate) fn draw(app: &App, w: u16, h: u16) -> String {
    let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
    terminal.draw(|f| view(app, f)).unwrap();
    text(terminal.backend().buffer())
}

#[test]
fn layout_snapshots_at_two_sizes() {
    let app = rendered(app());
    let app = send(
        app,
        &[
            Msg::BounceUp,
            Msg::BounceUp,
            Msg::ToggleBounceMode,
            Msg::SwitchFocus,
        ],
    );
    let small = draw(&app, 80, 24);
    let large = draw(&app, 140, 40);
    // The controls this render has are shown.
    for t in [&small, &large] {
        assert!(t.contains("exactly 1"), "{t}");
        assert!(t.contains("compare: render"), "{t}");
        assert!(t.contains("estimator 1/2: brdf"), "{t}");
        assert!(t.contains("no-go"), "{t}");
    }
    assert!(large.contains("error vs time"), "{large}");
    insta::assert_snapshot!("tui_80x24", small);
    insta::assert_snapshot!("tui_140x40", large);
    let app = update(app, Msg::ToggleHelp);
    insta::assert_snapshot!("tui_help_80x24", draw(&app, 80, 24));
}

#[test]
fn the_worker_discards_stale_passes() {
    struct Slow;
    static SLOW: Slow = Slow;
    impl Chapter for Slow {
        fn info(&self) -> ChapterInfo {
            ChapterInfo::new(
                7,
                "slow",
                "slow",
                &[View {
                    name: "image",
                    about: "",
                }],
            )
        }
        fn start(&self, _: Arc<Scene>, _: &Settings) -> Result<Box<dyn Render>> {
            Ok(Box::new(FakeRender {
                bounces: false,
                passes: 0,
                planned: 4,
                sleep: Duration::from_millis(20),
            }))
        }
    }
    let worker = Worker::spawn();
    let scene = Arc::new(Scene::builtin());
    let job = |generation| Job {
        generation,
        chapter: &SLOW,
        scene: scene.clone(),
        settings: Settings::default(),
        variant: 0,
        target: None,
    };
    worker.start(job(1));
    let first = worker
        .results
        .recv_timeout(Duration::from_secs(10))
        .unwrap();
    assert_eq!(first.generation(), 1);
    worker.start(job(2));
    let mut seen = Vec::new();
    loop {
        let p = worker
            .results
            .recv_timeout(Duration::from_secs(10))
            .unwrap();
        seen.push(p.generation());
        if let Progress::State(s) = &p {
            if s.generation == 2 && s.done {
                assert_eq!(s.progress, (4, 4));
                break;
            }
        }
    }
    // At most the pass that was running when job 2 came; never after it.
    let first_new = seen.iter().position(|g| *g == 2).unwrap();
    assert!(seen[first_new..].iter().all(|g| *g == 2), "{seen:?}");
    assert!(first_new <= 1, "{seen:?}");
    worker.stop();
}

/// The book's capture of the UI: chapter 1 on the built-in Cornell box, in
/// plain (NO_COLOR) style so the text shows the picture. Regenerate with
/// `RAYSTEP_UPDATE_FIGURES=1 cargo test tui::`.
#[test]
fn book_capture_is_current() {
    let root = common::root();
    let mut scenes = vec![SceneEntry::builtin()];
    for name in ["bunny", "railroad", "tetrahedron"] {
        scenes.push(SceneEntry::load(&root.join(format!("scenes/{name}.toml"))));
    }
    let ch1 = raystep::chapters::all()[0];
    let app = rendered(App::new(vec![ch1], scenes, false));
    let figures = [
        ("tui.txt", draw(&app, 100, 32)),
        ("tui-help.txt", draw(&update(app, Msg::ToggleHelp), 100, 32)),
    ];
    for (name, capture) in figures {
        let path = root.join("book/src/figures").join(name);
        let update = std::env::var_os("RAYSTEP_UPDATE_FIGURES").is_some();
        if update || (!path.exists() && std::env::var_os("CI").is_none()) {
            std::fs::write(&path, &capture).unwrap();
        }
        let stored = std::fs::read_to_string(&path).unwrap_or_default();
        assert_eq!(
            stored,
            capture,
            "{} is stale: RAYSTEP_UPDATE_FIGURES=1 cargo test tui::",
            path.display()
        );
    }
}

#[test]
fn the_scene_list_has_the_builtin_scene_and_shows_load_errors() {
    let dir = common::temp_dir("tui-scenes");
    common::write_files(
        &dir,
        &[
            ("b-broken.toml", "[camera]\nfov = \"wide\"\n"),
            (
                "a-tet.toml",
                &std::fs::read_to_string(common::root().join("scenes/tetrahedron.toml")).unwrap(),
            ),
            ("notes.txt", "not a scene"),
        ],
    );
    let list = scene_list(&dir);
    let names: Vec<&str> = list.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["cornell-box (built-in)", "a-tet", "b-broken"]);
    // Listed at once, read when chosen.
    assert!(list[1..].iter().all(|e| e.pending.is_some()), "{list:?}");
    let mut list = list;
    list.iter_mut().for_each(|e| e.ensure_loaded());
    assert!(list[1].scene.is_ok());
    let err = list[2].scene.as_ref().unwrap_err();
    assert!(err.contains("b-broken.toml"), "{err}");
    // A folder that does not exist still gives the built-in scene.
    assert_eq!(scene_list(&dir.join("missing")).len(), 1);
}

#[test]
fn the_book_documents_every_key() {
    let page = std::fs::read_to_string(common::root().join("book/src/running.md")).unwrap();
    let section = page
        .split("## The terminal UI")
        .nth(1)
        .expect("running.md has a section on the terminal UI");
    for (keys, _) in raystep::tui::keys::KEYS {
        for k in keys.split_whitespace().filter(|k| *k != "…") {
            assert!(
                section.contains(&format!("`{k}`")),
                "running.md does not document `{k}`"
            );
        }
    }
}

#[test]
fn the_status_line_shows_rays_per_second_only_when_the_stage_counts() {
    // 8x4 pixels, one pass, 12 ms: 32 / 0.012 s = 2.67k rays/s.
    let app = rendered(app());
    assert_eq!(app.snapshot.as_ref().unwrap().rays, 32);
    let status = raystep::tui::view::status_line(&app).to_string();
    assert!(status.contains("│ 2.67k rays/s"), "{status}");
    let plain = rendered(update(app, Msg::ChapterNumber(2)));
    assert_eq!(plain.snapshot.as_ref().unwrap().rays, 0);
    let status = raystep::tui::view::status_line(&plain).to_string();
    assert!(!status.contains("rays/s"), "{status}");
    assert_eq!(raystep::tui::view::format_rate(7_250_000.0), "7.25M");
    assert_eq!(raystep::tui::view::format_rate(123_456.0), "123k");
    assert_eq!(raystep::tui::view::format_rate(12.0), "12.0");
}

#[test]
fn the_real_chapters_3_to_6_count_their_rays() {
    let scene = Arc::new(Scene::builtin().with_resolution(16, 12).unwrap());
    let pixels = 16 * 12;
    // Chapter 3: one sample of every pixel per pass; chapter 4: one ray
    // per pixel in its single pass. Chapters 5 and 6: at least one camera
    // ray per pixel, and in the closed Cornell box every camera ray hits a
    // wall, so shadow rays come on top.
    for (n, camera_rays_only) in [(3, true), (4, true), (5, false), (6, false)] {
        let chapter = raystep::chapters::all()
            .into_iter()
            .find(|c| c.info().number == n)
            .unwrap();
        let settings = Settings {
            spp: 2,
            ..Settings::default()
        };
        let mut render = chapter.start(scene.clone(), &settings).unwrap();
        assert_eq!(render.snapshot().pass.rays, 0, "ch{n} before a pass");
        render.pass();
        let rays = render.snapshot().pass.rays;
        if camera_rays_only {
            assert_eq!(rays, pixels, "ch{n} after one pass");
        } else {
            assert!(rays > pixels, "ch{n} after one pass: {rays}");
        }
    }
}

/// Two pairs of failure images as the grader writes them, the second newer.
fn grade_images(dir: &std::path::Path) {
    std::fs::create_dir_all(dir).unwrap();
    let old = std::time::SystemTime::now() - Duration::from_secs(60);
    for (stem, student, when) in [
        ("ch1-old", Vec3::ONE, old),
        (
            "ch1-pinhole",
            Vec3::new(1.0, 0.0, 0.0),
            std::time::SystemTime::now(),
        ),
    ] {
        let s = dir.join(format!("{stem}-student.png"));
        flat(student).write_png(&s).unwrap();
        flat(Vec3::new(0.0, 0.0, 1.0))
            .write_png(&dir.join(format!("{stem}-reference.png")))
            .unwrap();
        std::fs::File::options()
            .write(true)
            .open(&s)
            .unwrap()
            .set_modified(when)
            .unwrap();
    }
    // A student image without its reference is not a pair.
    flat(Vec3::ZERO)
        .write_png(&dir.join("ch9-lonely-student.png"))
        .unwrap();
}

#[test]
fn g_shows_the_graders_newest_failure_student_against_reference() {
    use raystep::grading::latest_failure_images;
    let out = common::temp_dir("tui-grade");
    let mut app = rendered(app());
    app.out_dir = out.clone();
    // No grader output yet: a message saying how to make some.
    assert!(latest_failure_images(&app.grade_dir()).unwrap().is_none());
    app.effects.clear();
    let mut app = update(app, Msg::ToggleGrading);
    let asked = std::mem::take(&mut app.effects);
    assert!(matches!(asked[..], [Effect::LoadGrades]), "{asked:?}");
    let app = update(app, Msg::GradeLoaded(Ok(None)));
    assert!(app.effects.is_empty() && app.grading.is_none());
    assert!(app.message.contains("--bin grade"), "{}", app.message);

    grade_images(&app.grade_dir());
    let images = latest_failure_images(&app.grade_dir()).unwrap().unwrap();
    assert_eq!(images.stem, "ch1-pinhole");
    let mut app = update(app, Msg::GradeLoaded(Ok(Some(images))));
    assert!(app.message.contains("ch1-pinhole"), "{}", app.message);
    assert!(app.shows_compare());
    // r cycles student → reference → difference, with the names to match.
    let red = Vec3::new(1.0, 0.0, 0.0);
    let blue = Vec3::new(0.0, 0.0, 1.0);
    for (name, colour) in [
        ("student", red),
        ("reference", blue),
        // (1, 0, 0) − (0, 0, 1): the channel that differs most, x, is
        // brighter by 1, beyond the ±0.25 scale: full red.
        ("difference", red),
        ("relative", red),
    ] {
        assert_eq!(app.compare_name(), name);
        assert_eq!(painted(&app), colour, "{name}");
        let lines: Vec<String> = control_lines(&app).iter().map(|l| l.to_string()).collect();
        assert!(lines.contains(&format!("compare: {name}")), "{lines:?}");
        assert!(app.save_stem().ends_with(&format!("ch1-pinhole-{name}")));
        app = update(app, Msg::CycleCompare);
    }
    let screen = draw(&app, 80, 24);
    assert!(screen.contains("grade · ch1-pinhole · student"), "{screen}");
    // g again: back to the render.
    let render = flat(layer_color(0) + layer_color(1) + layer_color(2)).pixels[0];
    app.effects.clear();
    let app = update(app, Msg::ToggleGrading);
    assert!(app.grading.is_none() && app.effects.is_empty());
    assert_eq!(pixel(&app), render);
    assert_eq!(
        msg_for_key(&app, key(KeyCode::Char('g')))
            .map(|m| format!("{m:?}"))
            .as_deref(),
        Some("ToggleGrading")
    );
}

#[test]
fn x_shows_the_students_capstone_live_and_follows_the_chapter() {
    use raystep::grading::live::{LiveError, StudentRender};
    use raystep::tui::student::StudentEvent;
    let app = rendered(app());
    assert_eq!(
        msg_for_key(&app, key(KeyCode::Char('x')))
            .map(|m| format!("{m:?}"))
            .as_deref(),
        Some("ToggleStudent")
    );
    // On: the current chapter's capstone, before the watcher reports.
    let app = update(app, Msg::ToggleStudent);
    let s = app.student.as_ref().expect("student mode on");
    assert_eq!((s.chapter, s.id.as_str()), (6, "ch6/path_radiance"));
    assert!(app.message.contains("path_radiance.rs"), "{}", app.message);
    let done =
        |r: std::result::Result<StudentRender, LiveError>| Msg::Student(6, StudentEvent::Done(r));
    let status = |app: &App| app.student.as_ref().unwrap().status.clone();
    let app = update(app, Msg::Student(6, StudentEvent::Building));
    assert_eq!(status(&app), "building…");
    let screen = draw(&app, 80, 24);
    assert!(screen.contains("student · ch6/path_radiance"), "{screen}");
    assert!(screen.contains("building…"), "{screen}");
    // The stub, then a compile error: a status each, and no picture.
    let id = "ch6/path_radiance".to_string();
    let file = "chapters/ch6-global-illumination/exercises/path_radiance.rs".to_string();
    let app = update(
        app,
        done(Err(LiveError::NotStarted {
            id: id.clone(),
            file,
        })),
    );
    assert_eq!(status(&app), "ch6/path_radiance: not started (todo!)");
    assert!(app.student_render().is_none() && app.displayed().is_none());
    let message = "error: expected `;`, found `todo`\n --> /home/s/raystep/chapters/\
                   ch6-global-illumination/exercises/path_radiance.rs:42:14\n   |\n"
        .to_string();
    let app = update(
        app,
        done(Err(LiveError::DoesNotCompile {
            id: id.clone(),
            message,
        })),
    );
    assert_eq!(
        status(&app),
        "compile error: ch6-global-illumination/exercises/path_radiance.rs:42:14: \
         expected `;`, found `todo`"
    );
    assert!(draw(&app, 100, 24).contains("compile error: ch6-global"));
    assert!(app
        .student
        .as_ref()
        .unwrap()
        .details
        .contains("path_radiance.rs:42:14"));
    // A report from another chapter's watcher is dropped.
    let app = update(app, Msg::Student(2, StudentEvent::Building));
    assert!(status(&app).starts_with("compile error"));
    // Images: student / reference / difference with r, as `g` does.
    let (red, blue) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 1.0));
    let images = |matches| StudentRender {
        id: id.clone(),
        student: flat(red),
        reference: flat(blue),
        matches,
        detail: "32 of 32 blocks differ".into(),
    };
    let mut app = update(app, done(Ok(images(false))));
    assert_eq!(status(&app), "differs: 32 pixels / RMSE 0.8165");
    assert!(app.shows_compare());
    for (name, colour) in [
        ("student", red),
        ("reference", blue),
        // (1, 0, 0) − (0, 0, 1): the channel that differs most, x, is
        // brighter by 1, beyond the ±0.25 scale: full red.
        ("difference", red),
        ("relative", red),
    ] {
        assert_eq!(app.compare_name(), name);
        assert_eq!(painted(&app), colour, "{name}");
        assert_eq!(
            app.save_stem(),
            format!("tui-student-ch6-path_radiance-{name}")
        );
        app = update(app, Msg::CycleCompare);
    }
    let screen = draw(&app, 100, 24);
    assert!(
        screen.contains("student · ch6/path_radiance · student"),
        "{screen}"
    );
    assert!(screen.contains("differs: 32 pixels"), "{screen}");
    let app = update(app, done(Ok(images(true))));
    assert_eq!(status(&app), "student matches reference");
    let timed = LiveError::TimedOut {
        id: id.clone(),
        seconds: 20.0,
        doing: "calling path_radiance for the camera rays of row 3 of 32".into(),
    };
    let app = update(app, done(Err(timed)));
    assert_eq!(
        status(&app),
        "ch6/path_radiance timed out after 20 s while calling path_radiance for the \
         camera rays of row 3 of 32"
    );
    assert!(app.student_render().is_none());
    // Student mode follows the chapter: chapter 2's capstone, from scratch.
    let app = update(app, Msg::ChapterNumber(2));
    let s = app.student.as_ref().unwrap();
    assert_eq!((s.chapter, s.id.as_str()), (2, "ch2/rasterize_triangle"));
    assert!(s.render.is_none() && s.status == "starting…");
    // x again: back to the render.
    let app = update(app, Msg::ToggleStudent);
    assert!(app.student.is_none());
    assert_eq!(app.compare, Compare::Render);
    assert_eq!(app.message, "back to the render");
}

/// A scene file edited while the UI runs is read again (the UI checks the
/// current scene's file once a second): the render restarts on the new
/// scene and the message says so. An unchanged file is left alone.
#[test]
fn an_edited_scene_file_is_reloaded() {
    let dir = common::temp_dir("tui-reload");
    let text = std::fs::read_to_string(common::root().join("scenes/tetrahedron.toml")).unwrap();
    common::write_files(&dir, &[("tet.toml", &text)]);
    let path = dir.join("tet.toml");
    let mut app = App::new(raystep::chapters::all(), scene_list(&dir), false);
    app = update(app, Msg::SwitchFocus);
    app = update(app, Msg::Down);
    // Chosen, not read yet: the UI does not read files itself.
    assert!(app.scene_to_read().is_some() && app.job().is_none());
    let waiting = raystep::tui::view::status_line(&app).to_string();
    assert!(waiting.contains("reading the scene…"), "{waiting}");
    let generation = app.generation;
    let (index, file) = app.scene_to_read().unwrap();
    let read = raystep::tui::scenes::read_scene(&file);
    app = update(app, Msg::SceneRead(index, file, read));
    assert!(
        app.job().is_some() && app.generation > generation,
        "read: it renders"
    );
    let width = |app: &App| {
        app.current_scene()
            .unwrap()
            .scene
            .as_ref()
            .unwrap()
            .camera
            .width
    };
    let before = width(&app);
    let changed = |app: &App| app.current_scene().unwrap().edited();
    assert!(!changed(&app), "nothing changed yet");
    // Edit the file (a later modification time, as an editor gives it).
    let edited = text.replace(&format!("width = {before}"), "width = 77");
    assert_ne!(edited, text, "the scene sets its width");
    std::fs::write(&path, &edited).unwrap();
    let later = std::time::SystemTime::now() + Duration::from_secs(2);
    std::fs::File::options()
        .write(true)
        .open(&path)
        .unwrap()
        .set_modified(later)
        .unwrap();
    let generation = app.generation;
    assert!(changed(&app));
    // What the event loop does: tell `update`, then read the file in a
    // thread (here at once) and hand it back.
    let index = app.scene;
    app = update(app, Msg::SceneEdited(index));
    let (index, file) = app.scene_to_read().expect("read again");
    let read = raystep::tui::scenes::read_scene(&file);
    app.effects.clear();
    app = update(app, Msg::SceneRead(index, file, read));
    assert_eq!(width(&app), 77);
    assert!(app.generation > generation, "the render restarts");
    assert!(
        matches!(&app.effects[..], [Effect::Start(job)] if job.generation == app.generation),
        "{:?}",
        app.effects
    );
    assert!(
        app.message.contains("reloading") && app.message.contains("tet.toml"),
        "{}",
        app.message
    );
    assert!(!changed(&app));
}

/// An answer from a thread (here a scene file read) is not something the
/// user did: with the help open it is taken all the same, and the help
/// stays open; it does not clear the message line either.
#[test]
fn answers_from_threads_neither_close_the_help_nor_clear_the_message() {
    let dir = common::temp_dir("tui-answer-help");
    let text = std::fs::read_to_string(common::root().join("scenes/tetrahedron.toml")).unwrap();
    common::write_files(&dir, &[("tet.toml", &text)]);
    let app = App::new(raystep::chapters::all(), scene_list(&dir), false);
    let mut app = send(app, &[Msg::SwitchFocus, Msg::Down, Msg::ToggleHelp]);
    assert!(app.help && app.job().is_none(), "chosen, not read yet");
    app.message = "reloading tet.toml: the file changed".into();
    let (index, file) = app.scene_to_read().unwrap();
    let read = raystep::tui::scenes::read_scene(&file);
    let app = update(app, Msg::SceneRead(index, file, read));
    assert!(app.help, "the help stays open");
    assert!(app.job().is_some(), "the scene was read: it renders");
    assert_eq!(app.message, "reloading tet.toml: the file changed");
    // Nor does the mouse moving over the terminal (in a real terminal
    // it moves all the time).
    let app = update(app, Msg::Hover { column: 3, row: 4 });
    assert!(app.help, "the help stays open under a moving mouse");
    assert_eq!(app.message, "reloading tet.toml: the file changed");
    // A key still closes the help, and only that.
    let app = update(app, Msg::NextView);
    assert!(!app.help && app.view == 0);
}

#[test]
fn the_error_chart_is_log_log_with_the_half_slope_guide() {
    use raystep::tui::view::{log_log, LogLog};
    let LogLog { data, guide, x, y } =
        log_log(&[(1.0, 0.1), (0.0, 0.5), (4.0, 0.05), (2.0, f64::NAN)]);
    // Points that cannot be on a log axis are left out.
    assert_eq!(data.len(), 2);
    assert!(
        (data[1].0 - 4f64.log10()).abs() < 1e-12 && (data[1].1 - 0.05f64.log10()).abs() < 1e-12
    );
    assert_eq!(
        (x, y),
        ((0.0, 1.0), (-2.0, -1.0)),
        "whole decades around the points"
    );
    // The guide goes through the last point with slope −1/2 from edge to edge.
    let slope = (guide[1].1 - guide[0].1) / (guide[1].0 - guide[0].0);
    assert!((slope + 0.5).abs() < 1e-12);
    let at = guide[0].1 - 0.5 * (data[1].0 - guide[0].0);
    assert!((at - data[1].1).abs() < 1e-12);
    assert_eq!((guide[0].0, guide[1].0), (0.0, 1.0));
    let empty = log_log(&[]);
    assert!(empty.data.is_empty() && empty.guide.is_empty());
}
