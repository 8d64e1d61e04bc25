//! What the UI holds of a render after a pass: [`RenderState`], read
//! from the stage's [`Snapshot`](crate::core::stage::Snapshot) by the
//! [`worker`](super::worker).

use std::time::Duration;

use super::target::{Finish, Target};
use crate::core::film::{film_mean, Film};
use crate::core::stage::Render;

/// Everything the UI shows of a render after one pass.
#[derive(Clone, Debug)]
pub struct RenderState {
    /// The generation of the job this comes from.
    pub generation: u64,
    /// Every view of the chapter, in the order of [`ChapterInfo::views`](crate::core::stage::ChapterInfo::views).
    pub views: Vec<Film>,
    /// Per-bounce layers ([`Snapshot::layers`](crate::core::stage::Snapshot::layers)).
    pub layers: Option<Vec<Film>>,
    /// The reference ([`Snapshot::reference`](crate::core::stage::Snapshot::reference)).
    pub reference: Option<Film>,
    /// The reference's standard error ([`Snapshot::reference_stderr`](crate::core::stage::Snapshot::reference_stderr)).
    pub reference_stderr: Option<Film>,
    /// The reference's enlargement ([`Snapshot::reference_factor`](crate::core::stage::Snapshot::reference_factor)).
    pub reference_factor: u32,
    /// Error against time ([`Snapshot::error_series`](crate::core::stage::Snapshot::error_series)).
    pub error_series: Vec<(f64, f64)>,
    /// RMSE of view 0 against the reference, when there is one: the last
    /// point of the error series where the stage keeps one (at the
    /// reference's resolution), else pixel by pixel.
    pub rmse: Option<f64>,
    /// (passes done, passes planned).
    pub progress: (u32, u32),
    /// Samples per pixel so far ([`Pass::samples`](crate::core::stage::Pass::samples)).
    pub samples: u32,
    /// The render's own noise estimate ([`Pass::noise`](crate::core::stage::Pass::noise)).
    pub noise: Option<f64>,
    /// The mean value of view 0 over pixels and channels.
    pub mean: f64,
    /// The target this render goes to (progressive stages).
    pub target: Option<Target>,
    /// Time spent rendering (pauses not counted).
    pub elapsed: Duration,
    /// Rays traced so far ([`Pass::rays`](crate::core::stage::Pass::rays); 0 when the stage does not count).
    pub rays: u64,
    /// Whether the render is complete.
    pub done: bool,
    /// Why it stopped, once done.
    pub finish: Option<Finish>,
}

impl RenderState {
    /// Reads everything the UI needs from `render`.
    pub fn capture(
        render: &dyn Render,
        generation: u64,
        elapsed: Duration,
        done: bool,
    ) -> RenderState {
        let snap = render.snapshot();
        let rmse = snap.rmse();
        let mean = snap.views.first().map_or(0.0, film_mean);
        let pass = snap.pass;
        RenderState {
            generation,
            layers: snap.layers,
            error_series: snap.error_series,
            reference: snap.reference,
            reference_stderr: snap.reference_stderr,
            reference_factor: snap.reference_factor.max(1),
            rmse,
            views: snap.views,
            progress: (pass.done, pass.planned),
            samples: pass.samples,
            noise: pass.noise.map(|(n, _)| n),
            mean,
            target: None,
            rays: pass.rays,
            elapsed,
            done,
            finish: done.then_some(Finish::Complete),
        }
    }

    /// The noise estimate as a fraction of the image's mean value.
    pub fn relative_noise(&self) -> Option<f64> {
        self.noise
            .filter(|_| self.mean > 0.0)
            .map(|n| n / self.mean)
    }
}

impl RenderState {
    /// Rays per second since the render started, when the stage counts
    /// rays and some time has passed.
    pub fn rays_per_second(&self) -> Option<f64> {
        let secs = self.elapsed.as_secs_f64();
        (self.rays > 0 && secs > 0.0).then(|| self.rays as f64 / secs)
    }
}

/// The running render as it was at the pinned render's time: its newest
/// state that had rendered no longer than the pinned one (its first, if
/// even that took longer).
#[derive(Clone, Debug)]
pub struct EqualTime {
    /// The render it belongs to.
    pub generation: u64,
    /// Its image then.
    pub image: Film,
    /// How long it had rendered.
    pub elapsed: Duration,
    /// Its samples per pixel then.
    pub samples: u32,
    /// Its error against the reference then, where known.
    pub rmse: Option<f64>,
}

impl EqualTime {
    /// What `state` shows of the running render (none without an image).
    pub fn of(state: &RenderState) -> Option<EqualTime> {
        Some(EqualTime {
            generation: state.generation,
            image: state.views.first()?.clone(),
            elapsed: state.elapsed,
            samples: state.samples,
            rmse: state.rmse,
        })
    }
}

/// Where the picture sits on screen, to map a cell to its pixel
/// (`super::screen` does).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PictureMap {
    /// The cells the picture covers.
    pub cells: ratatui::layout::Rect,
    /// The part of the image shown: all of it, or the zoomed window.
    pub window: Window,
}

/// A window of an image: its top-left pixel and size (what it shows:
/// `super::zoom`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Window {
    /// First column.
    pub x0: u32,
    /// First row.
    pub y0: u32,
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
}
