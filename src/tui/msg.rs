//! Everything that can happen to the UI: the messages
//! [`update`](super::update::update) takes.

use std::path::PathBuf;

use super::worker::Progress;
use crate::grading::FailureImages;

/// Everything that can happen to the UI.
#[derive(Clone, Debug)]
pub enum Msg {
    /// Move up in the focused list.
    Up,
    /// Move down in the focused list.
    Down,
    /// Switch focus between the chapter and scene lists.
    SwitchFocus,
    /// Select the chapter with this lecture number.
    ChapterNumber(u32),
    /// Next view of the chapter.
    NextView,
    /// Previous view of the chapter.
    PrevView,
    /// One stop brighter.
    ExposureUp,
    /// One stop darker.
    ExposureDown,
    /// Exposure back to 0.
    ExposureReset,
    /// Automatic exposure on or off.
    ToggleAutoExposure,
    /// One bounce more (after 16: all bounces).
    BounceUp,
    /// One bounce less (before 0: all bounces).
    BounceDown,
    /// Toggle "exactly k" / "up to k".
    ToggleBounceMode,
    /// Render → reference → difference → relative difference → render.
    CycleCompare,
    /// A/B: flip between the render and the reference.
    Flip,
    /// Next estimator or sampler (the next step of the lecture's ladder).
    NextVariant,
    /// Previous estimator or sampler.
    PrevVariant,
    /// Pause or resume a progressive render.
    TogglePause,
    /// Twice the sample budget, and the noise level it reaches.
    TargetUp,
    /// Inspect mode on (cursor at the centre) or off.
    ToggleInspect,
    /// Move the inspect cursor by (dx, dy) pixels.
    CursorMove(i32, i32),
    /// Half the sample budget, and the noise level it reaches.
    TargetDown,
    /// Trace one path from the inspected pixel (the next sample each time).
    TracePath,
    /// The traced path, or why there is none.
    Traced(Result<Box<crate::core::stage::Inspection>, String>),
    /// The story of the inspected pixel (chapters 3 to 5): pixel, lines.
    Story(u32, u32, Vec<String>),
    /// A mouse click at terminal cell (`column`, `row`) of a terminal of
    /// `width` x `height` cells.
    Click {
        /// Cell column.
        column: u16,
        /// Cell row.
        row: u16,
        /// Terminal width in cells.
        width: u16,
        /// Terminal height in cells.
        height: u16,
    },
    /// Show the grader's newest failure images (student vs reference), or
    /// go back to the render.
    ToggleGrading,
    /// The grader's images were read: the pair, none, or the error.
    GradeLoaded(Result<Option<FailureImages>, String>),
    /// Student mode on (the current chapter's capstone, live) or off.
    ToggleStudent,
    /// A report from the student-mode watcher of this chapter.
    Student(u32, super::student::StudentEvent),
    /// Save the current view.
    Save,
    /// The save finished: the files written, or the error.
    Saved(Result<Vec<PathBuf>, String>),
    /// The mouse moved to cell (`column`, `row`) with its left button down,
    /// on a terminal of `width` x `height` cells: a region is dragged out.
    Drag {
        /// Cell column.
        column: u16,
        /// Cell row.
        row: u16,
        /// Terminal width in cells.
        width: u16,
        /// Terminal height in cells.
        height: u16,
    },
    /// `p`: pin the render shown to compare the next ones against, or unpin.
    TogglePin,
    /// `|`: the pinned render and the running one split side by side at
    /// equal time, or not.
    ToggleSplit,
    /// `b`: a region's corner at the cursor, or clear the region.
    MarkRegion,
    /// The mouse moved to a cell.
    Hover {
        /// Its column.
        column: u16,
        /// Its row.
        row: u16,
    },
    /// Zoom the preview in (+1) or out (−1).
    Zoom(i32),
    /// Show or hide the help overlay.
    ToggleHelp,
    /// Open or close the warp test view.
    ToggleWarp,
    /// The warp view's next (+1) or previous (−1) routine.
    WarpStep(i64),
    /// The warp view's routine again with new random numbers.
    WarpReseed,
    /// A scene file the event loop read in a thread: the entry, the path,
    /// what it read.
    SceneRead(usize, std::path::PathBuf, super::scenes::Read),
    /// The event loop saw that this entry's scene file was edited since it
    /// was read ([`SceneEntry::edited`](super::scenes::SceneEntry::edited)):
    /// it is read again, and renders anew.
    SceneEdited(usize),
    /// The student's routine drew (seed, its draws or why not).
    WarpStudent(u64, Result<crate::core::warp_test::Drawn, String>),
    /// A built-in routine's test, drawn in a thread: routine, seed, test.
    WarpBuiltin(usize, u64, Box<crate::core::warp_test::WarpTest>),
    /// Quit.
    Quit,
    /// Esc: close what is open (the help, the path table, inspect mode,
    /// the grader's images, student mode), the innermost first; never
    /// quits.
    Close,
    /// Scroll the path table, or else the inspect panel, by this many
    /// lines (negative: up).
    Scroll(i32),
    /// The mouse wheel at terminal cell (`column`, `row`): scrolls the
    /// panel or table under it by `lines`.
    Wheel {
        /// Cell column.
        column: u16,
        /// Cell row.
        row: u16,
        /// Lines to scroll (negative: up).
        lines: i32,
    },
    /// The terminal's size in cells (at the start and on every resize).
    Resize(u16, u16),
    /// Time passed since the last tick: an old message clears
    /// ([`MESSAGE_TTL`](super::app::MESSAGE_TTL)).
    Tick(std::time::Duration),
    /// A report from the render worker.
    Progress(Progress),
    /// Text was pasted (bracketed paste): never read as keys.
    Pasted,
}

impl Msg {
    /// Whether the user did this (a key, a click, the wheel): such a
    /// message clears the message line before it acts, and closes the help
    /// overlay. Answers from the threads (the worker, a save, the grader,
    /// the student-mode watcher, a scene file read or edited, the warp
    /// view's draws), a new terminal size, the clock and the mouse moving
    /// over the terminal (a key hint follows it) do neither.
    pub fn is_action(&self) -> bool {
        !matches!(
            self,
            Msg::Progress(_)
                | Msg::Saved(_)
                | Msg::GradeLoaded(_)
                | Msg::Student(..)
                | Msg::Traced(_)
                | Msg::Story(..)
                | Msg::SceneRead(..)
                | Msg::SceneEdited(_)
                | Msg::WarpBuiltin(..)
                | Msg::WarpStudent(..)
                | Msg::Resize(..)
                | Msg::Tick(_)
                | Msg::Hover { .. }
        )
    }
}
