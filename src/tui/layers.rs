//! The bounce layers of a render: how the bounce control combines them,
//! what the lecture calls each picture, exposure, and what the preview
//! compares.

use glam::Vec3;

use crate::core::difference::NONFINITE;
use crate::core::film::Film;
use crate::core::zview::Z_MAX;

/// How the bounce control combines layers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BounceMode {
    /// Only the light of exactly k bounces.
    Exactly,
    /// The light of 0, 1, …, k bounces.
    UpTo,
}

/// The lecture's name for the light of `k` bounces: direct illumination,
/// one-bounce global illumination, …
pub fn bounce_name(k: u32) -> String {
    const WORDS: [&str; 17] = [
        "zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
        "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen",
    ];
    match WORDS.get(k as usize) {
        Some(_) if k == 0 => "direct illumination".into(),
        Some(w) => format!("{w}-bounce global illumination"),
        None => format!("{k}-bounce global illumination"),
    }
}

/// Layer `k`, or layers 0 to `k` summed. Missing layers count as black.
pub fn combine_layers(layers: &[Film], k: u32, mode: BounceMode, like: &Film) -> Film {
    let mut film = Film::new(like.width, like.height);
    let range = match mode {
        BounceMode::Exactly => k as usize..k as usize + 1,
        BounceMode::UpTo => 0..k as usize + 1,
    };
    for layer in layers
        .get(range.start..range.end.min(layers.len()))
        .unwrap_or(&[])
    {
        if (layer.width, layer.height) == (film.width, film.height) {
            for (p, q) in film.pixels.iter_mut().zip(&layer.pixels) {
                *p += *q;
            }
        }
    }
    film
}

/// Scales a film by 2^stops.
pub fn expose(film: &Film, stops: i32) -> Film {
    let scale = 2f32.powi(stops);
    Film {
        width: film.width,
        height: film.height,
        pixels: film
            .pixels
            .iter()
            .map(|p| *p * Vec3::splat(scale))
            .collect(),
    }
}

/// The colours of the non-finite view: a pixel (count, luminance, 0) of
/// [`super::app::App::displayed_ref`] is green ([`NONFINITE`], the colour
/// of a non-finite difference) where any sample was caught, else the
/// image's luminance exposed by `exposure` stops at a third of its
/// brightness, so the marks stand out on a dim picture.
pub fn paint_caught(film: &Film, exposure: i32) -> Film {
    let scale = 2f32.powi(exposure);
    Film {
        width: film.width,
        height: film.height,
        pixels: film
            .pixels
            .iter()
            .map(|p| match p.x > 0.0 {
                true => NONFINITE,
                false => Vec3::splat((p.y * scale).clamp(0.0, 1.0) / 3.0),
            })
            .collect(),
    }
}

/// What the preview compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compare {
    /// The render.
    Render,
    /// The stage's reference.
    Reference,
    /// render − reference, signed; shown in false colour on a fixed scale
    /// ([`DIFFERENCE_SCALE`], red brighter, blue darker) after it is
    /// averaged to the screen's size.
    Difference,
    /// (render − reference) / reference, the same way
    /// ([`RELATIVE_SCALE`]).
    Relative,
    /// "Noise or wrong?": render − reference over the standard error of
    /// the two, full colour at ±[`Z_MAX`] (only where both images know
    /// their noise).
    Z,
}

/// The difference at which the difference view's colour is full, at
/// exposure 0; each stop of exposure halves it. The grader's failure
/// images use the same scale, so the two compare.
pub const DIFFERENCE_SCALE: f32 = crate::grading::DIFF_SCALE;

/// The relative difference at which the relative view's colour is full,
/// at exposure 0 (±50%); each stop of exposure halves it.
pub const RELATIVE_SCALE: f32 = 0.5;

impl Compare {
    /// Name for the status line and file names.
    pub fn name(self) -> &'static str {
        match self {
            Compare::Render => "render",
            Compare::Reference => "reference",
            Compare::Difference => "difference",
            Compare::Relative => "relative",
            Compare::Z => "z",
        }
    }

    /// The next in the cycle render → reference → difference → relative
    /// → z (where `z`, the z view can be shown) → render.
    pub fn next(self, z: bool) -> Compare {
        match self {
            Compare::Render => Compare::Reference,
            Compare::Reference => Compare::Difference,
            Compare::Difference => Compare::Relative,
            Compare::Relative if z => Compare::Z,
            Compare::Relative | Compare::Z => Compare::Render,
        }
    }

    /// The A/B flip: the reference from anything else, the render from
    /// the reference.
    pub fn flipped(self) -> Compare {
        match self {
            Compare::Reference => Compare::Render,
            _ => Compare::Reference,
        }
    }

    /// Whether the preview shows a false-colour difference (then exposure
    /// sets its scale instead of brightening it).
    pub fn is_difference(self) -> bool {
        matches!(self, Compare::Difference | Compare::Relative | Compare::Z)
    }

    /// The difference shown in full colour at `exposure` stops, and how
    /// to print it: "0.25" or "50%".
    pub fn scale(self, exposure: i32) -> (f32, String) {
        let stops = 2f32.powi(-exposure);
        match self {
            Compare::Relative => {
                let s = RELATIVE_SCALE * stops;
                (s, format!("{}%", 100.0 * s))
            }
            Compare::Z => {
                let s = Z_MAX as f32 * stops;
                (s, format!("{s}σ"))
            }
            _ => {
                let s = DIFFERENCE_SCALE * stops;
                (s, format!("{s}"))
            }
        }
    }

    /// `film` compared with `reference` as this selection shows it: for
    /// the two differences, the signed values (coloured only when drawn,
    /// by [`Compare::paint`], so that averaging them to the screen's size
    /// comes first and noise averages out instead of turning purple).
    pub fn apply<'a>(
        self,
        film: std::borrow::Cow<'a, Film>,
        reference: &'a Film,
    ) -> std::borrow::Cow<'a, Film> {
        use std::borrow::Cow;
        match self {
            Compare::Render => film,
            Compare::Reference => Cow::Borrowed(reference),
            Compare::Difference => Cow::Owned(film.difference_values(reference)),
            Compare::Relative => Cow::Owned(film.relative_values(reference)),
            // Computed by the app, which knows the noise; without it, the
            // render as it is.
            Compare::Z => film,
        }
    }

    /// The colours of `film`, a part of what this selection shows
    /// ([`Compare::apply`], averaged to its size on screen or not): a
    /// signed difference (`signed`) in false colour on its scale at
    /// `exposure`, anything else exposed by `exposure` stops.
    /// For the z view, `pooled` is how many pixels of the full film each
    /// pixel of `film` averages: the z of their mean is √pooled times
    /// their mean z, so the colour's scale shrinks by √pooled.
    pub fn paint(self, film: &Film, signed: bool, exposure: i32, pooled: f32) -> Film {
        if signed && self.is_difference() {
            film.colour_signed(self.scale(exposure).0 / pooled.sqrt())
        } else {
            expose(film, exposure)
        }
    }

    /// The name while the grader's images are shown: the render is the
    /// student's image.
    pub fn grading_name(self) -> &'static str {
        match self {
            Compare::Render => "student",
            other => other.name(),
        }
    }
}
