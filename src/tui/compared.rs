//! What the preview shows of a render beside its reference: the film
//! (the render, the reference, their signed difference or relative
//! difference, or the z view), its colours, and the z view's verdict on
//! "noise or wrong?".
//!
//! A difference is computed as signed numbers and coloured only when
//! drawn ([`App::paint_pooled`]), after it was averaged to its size on
//! screen: noise that averages out then shows black. The z view divides
//! the difference by the standard error of the two images
//! ([`crate::core::zview`]); a displayed pixel that averages k pixels of
//! it is shown as the z of their mean, √k times their mean z (exact
//! where their noise is alike).

use std::borrow::Cow;

use super::app::{combine_layers, App, Compare, Pinned};
use crate::core::film::Film;
use crate::core::preview::LUMA;
use crate::core::stage::CAUGHT_VIEW;
use crate::core::zview::{verdict_at, z_film, Verdict};

impl App {
    /// What the preview shows, before exposure: the selected view, or for
    /// the main view the selected bounces, compared as selected.
    pub fn displayed(&self) -> Option<Film> {
        self.displayed_ref().map(Cow::into_owned)
    }

    /// [`App::displayed`], borrowed where no new film has to be computed
    /// (the common case: a view or the reference as it is), so a redraw
    /// does not copy a whole film.
    pub fn displayed_ref(&self) -> Option<Cow<'_, Film>> {
        if let Some(film) = self.split_film() {
            return Some(Cow::Owned(film));
        }
        if self.shows_caught() {
            return self.caught_overlay().map(Cow::Owned);
        }
        if self.compare == Compare::Z {
            if let Some((image, stderr, reference, reference_stderr)) = self.z_inputs() {
                return Some(Cow::Owned(z_film(
                    &image,
                    stderr,
                    reference,
                    reference_stderr,
                )));
            }
        }
        match self.film_and_reference()? {
            (film, Some(reference)) => Some(self.compare.apply(film, reference)),
            (film, None) => Some(film),
        }
    }

    /// The render (the selected bounces, or the student's image) and the
    /// reference it is compared with, when there is one of its size.
    pub fn compared_pair(&self) -> Option<(Cow<'_, Film>, &Film)> {
        match self.film_and_reference()? {
            (film, Some(reference)) => Some((film, reference)),
            (_, None) => None,
        }
    }

    /// The film shown before comparing (the student's image, or the
    /// selected view and bounces) and, where it is compared, what with:
    /// the grader's reference, or for the main view a reference of its
    /// size.
    fn film_and_reference(&self) -> Option<(Cow<'_, Film>, Option<&Film>)> {
        match (&self.grading, &self.student) {
            (Some(g), _) => return Some((Cow::Borrowed(&g.student), Some(&g.reference))),
            (None, Some(s)) => {
                let r = s.render.as_ref()?;
                return Some((Cow::Borrowed(&r.student), Some(&r.reference)));
            }
            (None, None) => {}
        }
        let film = self.main_film()?;
        let reference = self
            .reference_pair()
            .map(|(r, _)| r)
            .filter(|r| self.view == 0 && (r.width, r.height) == (film.width, film.height));
        Some((film, reference))
    }

    /// What the render is compared with, and that image's standard error
    /// where known: the render pinned with `p` in this chapter and scene,
    /// else the stage's reference.
    pub fn reference_pair(&self) -> Option<(&Film, Option<&Film>)> {
        if let Some(p) = self.pinned_here() {
            return Some((&p.image, p.stderr.as_ref()));
        }
        let snap = self.snapshot.as_ref()?;
        Some((snap.reference.as_ref()?, snap.reference_stderr.as_ref()))
    }

    /// The pinned render, if it was pinned in this chapter and scene.
    pub fn pinned_here(&self) -> Option<&Pinned> {
        let scene = self.current_scene()?.name.as_str();
        self.pinned
            .as_ref()
            .filter(|p| p.at.0 == self.chapter && p.at.1 == scene)
    }

    /// [`App::pinned_here`], to change.
    pub(super) fn pinned_here_mut(&mut self) -> Option<&mut Pinned> {
        self.pinned_here()?;
        self.pinned.as_mut()
    }

    /// `p`: pins the render shown (its whole image and standard error) so
    /// that the compare views set the next renders against it, e.g. another
    /// estimator's; again, unpins.
    pub fn toggle_pin(&mut self) {
        if self.pinned_here().is_some() {
            self.pinned = None;
            self.message = "unpinned: compared with the reference again".into();
            return;
        }
        let (Some(snap), Some(scene)) = (self.snapshot.as_ref(), self.current_scene()) else {
            self.message = "nothing rendered to pin yet".into();
            return;
        };
        let Some(image) = snap.views.first() else {
            return;
        };
        let stderr = self.stderr_view().cloned();
        let variant = self
            .current_chapter()
            .map(|c| c.info())
            .and_then(|i| i.variants.get(self.variant))
            .map_or(String::new(), |v| format!("{}, ", v.name));
        let label = format!("{variant}{} spp", snap.samples);
        let pinned = Pinned {
            at: (self.chapter, scene.name.clone()),
            label,
            image: image.clone(),
            stderr,
            elapsed: snap.elapsed,
            samples: snap.samples,
            rmse: snap.rmse,
            split: false,
            equal_time: None,
        };
        self.message = format!(
            "pinned {}: r compares the renders that follow with it",
            pinned.label
        );
        self.pinned = Some(pinned);
    }

    /// Whether the preview shows where samples were NaN or infinite (the
    /// view [`CAUGHT_VIEW`]).
    pub fn shows_caught(&self) -> bool {
        self.view_name() == CAUGHT_VIEW.name && self.grading.is_none() && self.student.is_none()
    }

    /// The counts of [`CAUGHT_VIEW`] over the picture: per pixel (count,
    /// luminance of the image, 0), so that averaged to the screen's size a
    /// cell still knows whether any of its pixels caught one (see
    /// [`super::layers::paint_caught`]).
    fn caught_overlay(&self) -> Option<Film> {
        let snap = self.snapshot.as_ref()?;
        let (counts, image) = (snap.views.get(self.view)?, snap.views.first()?);
        let pixels = counts
            .pixels
            .iter()
            .zip(&image.pixels)
            .map(|(c, p)| glam::Vec3::new(c.x, p.dot(LUMA), 0.0))
            .collect();
        Some(Film {
            width: counts.width,
            height: counts.height,
            pixels,
        })
    }

    /// The render's standard error: its view named "stderr", where the
    /// chapter keeps one.
    pub fn stderr_view(&self) -> Option<&Film> {
        let info = self.current_chapter()?.info();
        let k = info.views.iter().position(|v| v.name == "stderr")?;
        self.snapshot.as_ref()?.views.get(k)
    }

    /// The selected view, or for the main view the selected bounces.
    pub fn main_film(&self) -> Option<Cow<'_, Film>> {
        let snap = self.snapshot.as_ref()?;
        let mut film = Cow::Borrowed(snap.views.get(self.view)?);
        if self.view == 0 && self.shows_bounces() {
            if let (Some(k), Some(layers)) = (self.bounce, &snap.layers) {
                film = Cow::Owned(combine_layers(layers, k, self.bounce_mode, &film));
            }
        }
        Some(film)
    }

    /// What the z view needs, when the render has all of it: the main
    /// image (the selected bounces), its standard error (the view named
    /// "stderr"), the reference and the reference's standard error, all
    /// of one size.
    fn z_inputs(&self) -> Option<(Cow<'_, Film>, &Film, &Film, &Film)> {
        if self.view != 0 || self.grading.is_some() || self.student_render().is_some() {
            return None;
        }
        let stderr = self.stderr_view()?;
        let (reference, reference_stderr) = self.reference_pair()?;
        let reference_stderr = reference_stderr?;
        let image = self.main_film()?;
        let size = (image.width, image.height);
        [stderr, reference, reference_stderr]
            .iter()
            .all(|f| (f.width, f.height) == size)
            .then_some((image, stderr, reference, reference_stderr))
    }

    /// Whether the z view can be shown: the render has its standard error
    /// and the reference its own.
    pub fn z_available(&self) -> bool {
        self.z_inputs().is_some()
    }

    /// The z view's verdict on the whole image, when it can be shown.
    pub fn verdict(&self) -> Option<Verdict> {
        let (image, stderr, reference, reference_stderr) = self.z_inputs()?;
        let snap = self.snapshot.as_ref()?;
        // A pinned render has the render's size, and its few samples count
        // as the render's do; the stored reference may be enlarged to the
        // render's size, and has thousands of samples.
        let (factor, reference_samples) = match self.pinned_here() {
            Some(p) => (1, p.samples),
            None => (snap.reference_factor, 0),
        };
        Some(verdict_at(
            factor,
            &image,
            stderr,
            reference,
            reference_stderr,
            (snap.samples, reference_samples),
        ))
    }

    /// Whether [`App::displayed_ref`] is a signed difference or the z
    /// view (the grader's images, or the main view beside a reference of
    /// its size).
    pub fn shows_signed(&self) -> bool {
        if self.compare == Compare::Z {
            return self.z_available();
        }
        let main = self.view == 0
            && self.snapshot.as_ref().is_some_and(|s| {
                let size = s.views.first().map(|v| (v.width, v.height));
                self.reference_pair().map(|(r, _)| (r.width, r.height)) == size
            });
        self.compare.is_difference()
            && (self.grading.is_some() || self.student_render().is_some() || main)
    }

    /// The colours of `film`, a part of what the preview shows at full
    /// size: see [`App::paint_pooled`].
    pub fn paint(&self, film: &Film) -> Film {
        self.paint_pooled(film, 1.0)
    }

    /// The colours of `film`, a part of what the preview shows, each of
    /// its pixels the mean of `pooled` pixels of the full film: see
    /// [`Compare::paint`]; a z view's scale shrinks by √pooled.
    pub fn paint_pooled(&self, film: &Film, pooled: f32) -> Film {
        if self.shows_caught() {
            return super::layers::paint_caught(film, self.display_exposure());
        }
        let pooled = if self.compare == Compare::Z {
            pooled.max(1.0)
        } else {
            1.0
        };
        let signed = self.shows_signed();
        let stops = if signed {
            self.exposure
        } else {
            self.display_exposure()
        };
        self.compare.paint(film, signed, stops, pooled)
    }

    /// The exposure the preview applies: none to a false-colour difference
    /// (its colours are final; exposure set its scale), the automatic one
    /// where that is on, else the chosen one.
    pub fn display_exposure(&self) -> i32 {
        if self.shows_signed() {
            0
        } else if self.auto_exposure_on() {
            self.auto_stops()
        } else {
            self.exposure
        }
    }

    /// Whether automatic exposure applies: chosen with `a`, or by default
    /// for the dark pictures (the noise view, a single bounce layer).
    pub fn auto_exposure_on(&self) -> bool {
        let dark = (self.view == 0 && self.bounce.is_some() && self.shows_bounces())
            || self.view_name() == "stderr";
        !self.shows_signed() && self.auto_exposure.unwrap_or(dark)
    }

    /// The stops that bring the picture's mean to 0.18, the middle grey of
    /// a photograph (0 for a black picture), within ±10.
    pub fn auto_stops(&self) -> i32 {
        let film = match self.shows_caught() {
            // The picture under the marks is the image.
            true => self
                .snapshot
                .as_ref()
                .and_then(|s| s.views.first())
                .map(Cow::Borrowed),
            false => self.displayed_ref(),
        };
        let Some(film) = film else {
            return 0;
        };
        let (sum, n) = film
            .pixels
            .iter()
            .filter(|p| p.is_finite())
            .fold((0.0f64, 0usize), |(s, n), p| {
                (s + f64::from(p.element_sum()) / 3.0, n + 1)
            });
        let mean = sum / n.max(1) as f64;
        if mean > 0.0 {
            ((0.18 / mean).log2().round() as i32).clamp(-10, 10)
        } else {
            0
        }
    }

    /// `+`, `-` (`Some(±1)`) and `0` (`None`): a picture under automatic
    /// exposure steps from where it is and leaves automatic exposure; a
    /// difference's scale steps as it is.
    pub fn step_exposure(&mut self, step: Option<i32>) {
        if self.auto_exposure_on() {
            self.exposure = self.auto_stops();
            self.auto_exposure = Some(false);
        }
        self.exposure = step.map_or(0, |s| (self.exposure + s).clamp(-10, 10));
    }
}
