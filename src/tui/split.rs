//! `|`: the pinned render beside the running one, split down the middle of
//! the picture, with the running one as it was when it had rendered as
//! long as the pinned one had: two estimators at equal wall-clock time.
//! The left half is the pinned render, the right half the running one;
//! the controls box says what each is, with its samples and error.

use std::time::Duration;

use ratatui::text::Line;

use super::app::App;
use super::state::EqualTime;
use crate::core::film::Film;

impl App {
    /// `|`: the split view on or off; it needs a render pinned here.
    pub fn toggle_split(&mut self) {
        let Some(p) = self.pinned_here_mut() else {
            self.message = "p pins a render first; | then splits it with the next".into();
            return;
        };
        p.split = !p.split;
        self.message = match p.split {
            true => format!(
                "split: left pinned {}, right the running render at {} s",
                p.label,
                seconds(p.elapsed)
            ),
            false => "split off".into(),
        };
    }

    /// Whether the preview shows the split: on, pinned here, on the main
    /// view, with the running render's equal-time image at hand.
    pub fn shows_split(&self) -> bool {
        let pinned = self.pinned_here();
        self.view == 0
            && self.grading.is_none()
            && self.student.is_none()
            && pinned.is_some_and(|p| p.split && p.equal_time.is_some())
    }

    /// Keeps, beside the pin, the running render's newest state that had
    /// rendered no longer than the pinned one (called with every state).
    pub(super) fn keep_equal_time(&mut self) {
        let (Some(state), Some(p)) = (self.snapshot.as_ref(), self.pinned_here()) else {
            return;
        };
        let other_render = p
            .equal_time
            .as_ref()
            .is_none_or(|e| e.generation != state.generation);
        if !other_render && state.elapsed > p.elapsed {
            return;
        }
        let Some(now) = EqualTime::of(state) else {
            return;
        };
        if let Some(p) = self.pinned_here_mut() {
            p.equal_time = Some(now);
        }
    }

    /// The split picture: the pinned image's left half beside the right
    /// half of the running render's at equal time.
    pub fn split_film(&self) -> Option<Film> {
        let p = self.pinned_here().filter(|_| self.shows_split())?;
        let right = &p.equal_time.as_ref()?.image;
        let left = &p.image;
        if (left.width, left.height) != (right.width, right.height) {
            return None;
        }
        let half = left.width / 2;
        let mut film = left.clone();
        for (i, px) in film.pixels.iter_mut().enumerate() {
            if i as u32 % left.width >= half {
                *px = right.pixels[i];
            }
        }
        Some(film)
    }

    /// The controls box's lines for the split: each half's render, time,
    /// samples and error.
    pub fn split_lines(&self) -> Vec<Line<'static>> {
        let Some(p) = self.pinned_here().filter(|_| self.shows_split()) else {
            return Vec::new();
        };
        let Some(e) = p.equal_time.as_ref() else {
            return Vec::new();
        };
        let rmse = |r: Option<f64>| r.map_or(String::new(), |r| format!(", RMSE {r:.4}"));
        let variant = self
            .current_chapter()
            .and_then(|c| c.info().variants.get(self.variant))
            .map_or("running", |v| v.name);
        // Two short lines a side: the controls box is narrow.
        vec![
            Line::from(format!("left: {}", p.label)),
            Line::from(format!("  {} s{}", seconds(p.elapsed), rmse(p.rmse))),
            Line::from(format!("right: {variant}, {} spp", e.samples)),
            Line::from(format!("  {} s{}", seconds(e.elapsed), rmse(e.rmse))),
        ]
    }
}

fn seconds(d: Duration) -> String {
    format!("{:.1}", d.as_secs_f64())
}
