//! What the UI asks of the render worker and what it hears back: a
//! [`Job`] to render, the [`Progress`] reports, and what an inspection is
//! for ([`Purpose`]). Plain data; the [`worker`](super::worker) thread
//! does the work.

use std::sync::Arc;

use super::state::RenderState;
use super::target::Target;
use crate::core::stage::{Chapter, Inspection, Settings};
use crate::scene::Scene;

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

impl std::fmt::Debug for Job {
    /// The chapter by its number and the scene by its name.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Job")
            .field("generation", &self.generation)
            .field("chapter", &self.chapter.info().number)
            .field("scene", &self.scene.name)
            .field("variant", &self.variant)
            .field("target", &self.target)
            .finish_non_exhaustive()
    }
}

/// What the worker reports.
#[derive(Clone, Debug)]
pub enum Progress {
    /// A pass finished.
    State(Box<RenderState>),
    /// The answer to [`Worker::inspect`](super::worker::Worker::inspect).
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
