//! What [`update`](super::update::update) asks of the world outside the
//! state: an [`Effect`]. `update` stays pure: it puts the effects of a
//! message in the state's outbox ([`App::effects`](super::app::App::effects)),
//! and the event loop takes them out after every message and carries them
//! out ([`Threads::perform`](super::threads::Threads::perform)); an answer
//! (a save's files, the grader's images, a traced path) comes back to
//! `update` as a message.
//!
//! This is the component pattern of ratatui's templates: the loop keeps no
//! copy of the state to compare against, it does what it is told.

use super::job::Job;
use super::target::Target;

/// Something for the event loop to do.
#[derive(Debug)]
pub enum Effect {
    /// Render `job`, a new generation, in place of the render under way.
    Start(Job),
    /// Move the target of render `generation` (the budget and noise level
    /// it renders to).
    Retarget {
        /// The render.
        generation: u64,
        /// Its new target.
        target: Target,
    },
    /// Pause or resume render `generation`.
    Pause {
        /// The render.
        generation: u64,
        /// Paused (`true`) or running.
        paused: bool,
    },
    /// Trace sample `sample` of `pixel` in render `generation` (`t` in
    /// chapter 6); the answer comes back as [`Msg::Traced`](super::msg::Msg::Traced).
    Trace {
        /// The render.
        generation: u64,
        /// The inspected pixel.
        pixel: (u32, u32),
        /// Which of its samples.
        sample: u32,
    },
    /// Ask render `generation` for the story of `pixel` (the inspect
    /// panel of chapters 3 to 5).
    Story {
        /// The render.
        generation: u64,
        /// The inspected pixel.
        pixel: (u32, u32),
    },
    /// Save what the preview shows ([`save`](super::save::save)); the
    /// answer comes back as [`Msg::Saved`](super::msg::Msg::Saved).
    Save,
    /// Read the grader's newest failure images; the answer comes back as
    /// [`Msg::GradeLoaded`](super::msg::Msg::GradeLoaded).
    LoadGrades,
    /// Watch this chapter's exercise files for student mode (the watcher
    /// of another chapter stops); `None`: no watcher.
    Watch(Option<u32>),
    /// Draw built-in warp routine `index`'s directions with `seed` and
    /// test them, in a thread; the answer comes back as
    /// [`Msg::WarpBuiltin`](super::msg::Msg::WarpBuiltin).
    WarpBuiltin {
        /// The routine.
        index: usize,
        /// The seed of its numbers.
        seed: u64,
    },
    /// Build and run the student's warp routine with this seed, in a
    /// thread, cancelling the build under way (`None`: only cancel); the
    /// answer comes back as [`Msg::WarpStudent`](super::msg::Msg::WarpStudent).
    WarpStudent(Option<u64>),
}
