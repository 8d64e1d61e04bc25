//! The UI's state and the messages that change it; the change itself is
//! [`update`](super::update::update), a pure function from (state, message)
//! to the next state and the [`Effect`]s it asks for. Nothing here touches
//! the terminal, the clock, the disk or a thread: a scene file is read by
//! the event loop, which also looks for edits
//! ([`Msg::SceneRead`], [`Msg::SceneEdited`]).

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Duration;

use ratatui::layout::Rect;

use super::effect::Effect;
pub use super::layers::{bounce_name, combine_layers, expose, BounceMode, Compare};
pub use super::msg::Msg;
use super::scenes::SceneEntry;
use super::worker::{Job, RenderState, Target};
use crate::core::film::Film;
use crate::core::stage::{Chapter, Inspection, Settings};
use crate::grading::FailureImages;

/// A render pinned to compare others against.
#[derive(Clone, Debug)]
pub struct Pinned {
    /// The chapter and scene it was pinned in: it is compared only there.
    pub at: (usize, String),
    /// What it was: "mis-sobol, 256 spp".
    pub label: String,
    /// Its image.
    pub image: Film,
    /// Its standard error per pixel and channel, where known.
    pub stderr: Option<Film>,
    /// How long it had rendered when pinned.
    pub elapsed: Duration,
    /// Its samples per pixel.
    pub samples: u32,
    /// Its error against the reference then, where known.
    pub rmse: Option<f64>,
    /// Whether the preview splits it with the running render (`|`).
    pub split: bool,
    /// The running render at this one's time (for the split, `|`).
    pub equal_time: Option<super::state::EqualTime>,
}

/// The highest bounce count the bounce control steps to.
pub const MAX_BOUNCE: u32 = 16;

/// How long a message stays on the message line when nothing else
/// happens (the next key clears it sooner).
pub const MESSAGE_TTL: Duration = Duration::from_secs(6);

/// Which list the arrow keys move in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Focus {
    /// The chapter list.
    Chapters,
    /// The scene list.
    Scenes,
}

/// Everything the UI knows.
pub struct App {
    /// Every chapter, from [`crate::chapters::all`].
    pub chapters: Vec<&'static dyn Chapter>,
    /// Every scene.
    pub scenes: Vec<SceneEntry>,
    /// Selected chapter.
    pub chapter: usize,
    /// Selected scene.
    pub scene: usize,
    /// Which list the arrow keys move in.
    pub focus: Focus,
    /// Selected view (index into [`ChapterInfo::views`](crate::core::stage::ChapterInfo::views)).
    pub view: usize,
    /// Exposure in stops: the preview is scaled by 2^exposure.
    pub exposure: i32,
    /// Every estimator's error series of the renders shown, by chapter,
    /// scene and estimator ([`super::curves`]).
    pub curves: BTreeMap<(usize, String, usize), Vec<(f64, f64)>>,
    /// The box of pixels chosen for region statistics ([`super::region`]).
    pub region: Option<(u32, u32, u32, u32)>,
    /// Its first corner, while `b` waits for the second.
    pub region_anchor: Option<(u32, u32)>,
    /// Where the picture was on screen when the mouse button went down: a
    /// drag maps through it, though the click itself may have opened the
    /// pixel panel and moved the picture.
    pub pressed: Option<super::state::PictureMap>,
    /// A render pinned with `p` to compare others against (tev's
    /// reference pinning): its chapter and scene, a label, its image and
    /// its standard error where the chapter keeps one.
    pub pinned: Option<Pinned>,
    /// How many keys the help overlay has scrolled past.
    pub help_scroll: usize,
    /// Automatic exposure chosen with `a` (`None`: on for the dark
    /// pictures, the noise view and single bounce layers, off otherwise).
    pub auto_exposure: Option<bool>,
    /// Bounce selection: `None` shows all bounces.
    pub bounce: Option<u32>,
    /// Exactly k or up to k.
    pub bounce_mode: BounceMode,
    /// Render, reference or difference.
    pub compare: Compare,
    /// Selected estimator or sampler (index into [`ChapterInfo::variants`](crate::core::stage::ChapterInfo::variants)).
    pub variant: usize,
    /// Settings of the next render.
    pub settings: Settings,
    /// Whether the help overlay is shown.
    pub help: bool,
    /// The warp test view (`w`), when open.
    pub warp: Option<Box<super::warp::WarpView>>,
    /// Set by [`Msg::Quit`].
    pub quit: bool,
    /// Bumped whenever the render must restart.
    pub generation: u64,
    /// The newest pass of the current render.
    pub snapshot: Option<RenderState>,
    /// Why the current render failed, if it did.
    pub failure: Option<String>,
    /// One line of feedback (e.g. what was saved).
    pub message: String,
    /// Draw the preview in 24-bit colour (else a plain ASCII ramp).
    pub color: bool,
    /// Where `s` saves.
    pub out_dir: PathBuf,
    /// The grader's newest failure images, shown instead of the render
    /// while set (`g`).
    pub grading: Option<FailureImages>,
    /// Student mode (`x`): a watcher runs on its chapter
    /// ([`Effect::Watch`]).
    pub student: Option<super::student::StudentMode>,
    /// How far a progressive chapter renders (a change goes to the running
    /// render: [`Effect::Retarget`]).
    pub target: Target,
    /// Whether the progressive render is paused ([`Effect::Pause`]).
    pub paused: bool,
    /// How the preview is drawn ([`super::graphics::choose`]).
    pub graphics: super::graphics::Graphics,
    /// Inspect mode's cursor, a pixel of the image; `None` when off.
    pub inspect: Option<(u32, u32)>,
    /// The preview's zoom: 1, 2, 4, … (see [`super::zoom`]).
    pub zoom: u32,
    /// The pixel under the mouse, when it is over the picture.
    pub hover: Option<(u32, u32)>,
    /// The terminal's cell size in pixels, for a graphics protocol;
    /// `None` draws half blocks.
    pub font: Option<(u16, u16)>,
    /// The path traced from the inspected pixel (`t`), as the panel shows
    /// it; cleared when the cursor moves or the render restarts.
    pub trace: Option<Box<Inspection>>,
    /// How many paths `t` has traced at this pixel (the next one traces
    /// the next sample).
    pub traces: u32,
    /// The per-pixel story of chapters 3 to 5 for the inspected pixel
    /// (asked of the render when the cursor moves: [`Effect::Story`]).
    pub story: Option<(u32, u32, Vec<String>)>,
    /// Why a chapter refused a scene when it started, per (chapter index,
    /// scene index): the scene list marks those scenes, and switching
    /// chapters avoids them.
    pub refusals: BTreeMap<(usize, usize), String>,
    /// Whether the current scene came with a chapter switch (not picked in
    /// this chapter): a refusal then moves the chapter to a scene it takes.
    pub scene_came_with_chapter: bool,
    /// Which chapters have been shown in this run (a chapter's own scene,
    /// [`ChapterInfo::scene`](crate::core::stage::ChapterInfo::scene), is
    /// chosen only the first time).
    pub opened: Vec<bool>,
    /// The terminal's size, as the event loop last saw it (for scrolling
    /// and the mouse wheel, which depend on the layout).
    pub screen: Rect,
    /// How far the inspect panel is scrolled, in lines.
    pub panel_scroll: u16,
    /// How far the traced path's table is scrolled, in lines.
    pub table_scroll: u16,
    /// How long the current message has been shown.
    pub message_age: Duration,
    /// What [`update`](super::update::update) asks the event loop to do,
    /// oldest first: the loop takes them out after every message.
    pub effects: Vec<Effect>,
}

impl App {
    /// A UI on chapter 0 and scene 0 (or the chapter's own scene) at
    /// generation 1, not rendering yet: [`launch_app`](super::launch_app)
    /// asks for the first render, and a scene file not read yet is read
    /// by the event loop ([`App::scene_to_read`]).
    pub fn new(chapters: Vec<&'static dyn Chapter>, scenes: Vec<SceneEntry>, color: bool) -> App {
        let variant = chapters.first().map_or(0, |c| c.info().default_variant);
        let mut app = App {
            chapters,
            scenes,
            chapter: 0,
            scene: 0,
            focus: Focus::Chapters,
            view: 0,
            exposure: 0,
            auto_exposure: None,
            help_scroll: 0,
            pinned: None,
            region: None,
            region_anchor: None,
            pressed: None,
            curves: BTreeMap::new(),
            bounce: None,
            bounce_mode: BounceMode::UpTo,
            compare: Compare::Render,
            variant,
            settings: Settings::default(),
            help: false,
            warp: None,
            quit: false,
            generation: 1,
            snapshot: None,
            failure: None,
            message: String::new(),
            color,
            out_dir: PathBuf::from("out"),
            grading: None,
            student: None,
            target: Target::DEFAULT,
            paused: false,
            graphics: super::graphics::Graphics::HalfBlocks,
            font: None,
            inspect: None,
            zoom: 1,
            hover: None,
            trace: None,
            traces: 0,
            story: None,
            refusals: BTreeMap::new(),
            scene_came_with_chapter: false,
            opened: Vec::new(),
            screen: Rect::new(0, 0, 80, 24),
            panel_scroll: 0,
            table_scroll: 0,
            message_age: Duration::ZERO,
            effects: Vec::new(),
        };
        if !app.chapters.is_empty() {
            if let Some(i) = app.opening_scene(0) {
                app.scene = i;
            }
            app.opened = vec![true];
        }
        app
    }

    /// Where the grader writes its failure images: `grade/` in the save
    /// folder, as `cargo run --bin grade` does by default (`out/grade`).
    pub fn grade_dir(&self) -> PathBuf {
        self.out_dir.join("grade")
    }

    /// Student mode's newest images, when it has some.
    pub fn student_render(&self) -> Option<&crate::grading::live::StudentRender> {
        self.student.as_ref()?.render.as_ref()
    }

    /// The selected chapter, if there is any.
    pub fn current_chapter(&self) -> Option<&'static dyn Chapter> {
        self.chapters.get(self.chapter).copied()
    }

    /// The selected scene entry.
    pub fn current_scene(&self) -> Option<&SceneEntry> {
        self.scenes.get(self.scene)
    }

    /// Why scene `index` cannot be rendered in the selected chapter, if
    /// that is known: its load error, or the chapter's refusal when it
    /// last started on it.
    pub fn scene_problem(&self, index: usize) -> Option<String> {
        self.problem_in(self.chapter, index)
    }

    /// Why scene `index` cannot be rendered in chapter `chapter` (an index
    /// into [`App::chapters`]), if that is known.
    pub fn problem_in(&self, chapter: usize, index: usize) -> Option<String> {
        let entry = self.scenes.get(index)?;
        if entry.pending.is_some() {
            // Not read yet: nothing known against it.
            return None;
        }
        match &entry.scene {
            Err(e) => Some(e.clone()),
            Ok(_) => self.refusals.get(&(chapter, index)).cloned(),
        }
    }

    /// Why the current selection cannot render, if it cannot.
    pub fn problem(&self) -> Option<String> {
        if self.current_chapter().is_none() {
            return Some("no chapters".into());
        }
        self.scene_problem(self.scene)
    }

    /// The render job for the current selection, or `None` when it cannot
    /// render.
    pub fn job(&self) -> Option<Job> {
        if self.problem().is_some() {
            return None;
        }
        let chapter = self.current_chapter()?;
        let scene = self.current_scene()?.scene.clone().ok()?;
        Some(Job {
            generation: self.generation,
            chapter,
            scene,
            settings: self.settings.clone(),
            variant: self.variant,
            target: self.progressive().then_some(self.target),
        })
    }

    /// Whether `t` traces paths here: chapter 6 (the path tracer).
    pub fn traces_paths(&self) -> bool {
        self.current_chapter().is_some_and(|c| c.info().number == 6) && self.grading.is_none()
    }

    /// Whether the selected chapter renders progressively to a target.
    pub fn progressive(&self) -> bool {
        self.current_chapter().is_some_and(|c| c.info().progressive)
    }

    /// The share of the whole image's light that the selected bounces
    /// carry (sum over pixels and channels), when bounces are selected.
    pub fn bounce_share(&self) -> Option<f64> {
        let snap = self.snapshot.as_ref()?;
        let (k, layers) = (self.bounce?, snap.layers.as_ref()?);
        let image = snap.views.first()?;
        let sum = |f: &Film| {
            f.pixels
                .iter()
                .map(|p| p.as_dvec3().element_sum())
                .sum::<f64>()
        };
        let total = sum(image);
        (self.shows_bounces() && total > 0.0)
            .then(|| sum(&combine_layers(layers, k, self.bounce_mode, image)) / total)
    }

    /// Whether the bounce control is shown: the chapter has bounces and the
    /// render delivered layers.
    pub fn shows_bounces(&self) -> bool {
        self.current_chapter().is_some_and(|c| c.info().bounces)
            && self.snapshot.as_ref().is_some_and(|s| s.layers.is_some())
    }

    /// Whether the compare control is shown: the render has a reference,
    /// or the grader's images are shown.
    pub fn shows_compare(&self) -> bool {
        self.grading.is_some()
            || self.student_render().is_some()
            || self
                .snapshot
                .as_ref()
                .is_some_and(|s| s.reference.is_some())
            || self.pinned_here().is_some()
    }

    /// Starts over: a new generation, no picture yet.
    pub(super) fn restart(&mut self) {
        self.generation += 1;
        self.paused = false;
        self.grading = None;
        self.snapshot = None;
        self.failure = None;
        self.trace = None;
        self.story = None;
        let (views, variants) = self
            .current_chapter()
            .map(|c| (c.info().views.len(), c.info().variants.len()))
            .unwrap_or((1, 0));
        if self.view >= views {
            self.view = 0;
        }
        if self.variant >= variants.max(1) {
            self.variant = 0;
        }
    }

    pub(super) fn select_chapter(&mut self, index: usize) {
        if index < self.chapters.len() && index != self.chapter {
            self.chapter = index;
            // Views and estimators differ between chapters: start at the
            // first view and the chapter's best estimator.
            self.view = 0;
            self.variant = self.chapters[index].info().default_variant;
            self.compare = Compare::Render;
            if let Some(scene) = self.opening_scene(index) {
                if scene != self.scene {
                    self.scene = scene;
                }
            }
            if self.opened.len() <= index {
                self.opened.resize(index + 1, false);
            }
            self.opened[index] = true;
            self.scene_came_with_chapter = true;
            self.restart();
        }
    }

    pub(super) fn select_scene(&mut self, index: usize) {
        if index < self.scenes.len() && index != self.scene {
            self.scene = index;
            self.scene_came_with_chapter = false;
            self.restart();
        }
    }
}
