//! The bounce layers of a render: how the bounce control combines them,
//! what the lecture calls each picture, exposure, and what the preview
//! compares.

use glam::Vec3;

use crate::core::film::Film;

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

/// What the preview compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compare {
    /// The render.
    Render,
    /// The stage's reference.
    Reference,
    /// |render - reference|, scaled so the largest difference is white.
    Difference,
}

impl Compare {
    /// Name for the status line and file names.
    pub fn name(self) -> &'static str {
        match self {
            Compare::Render => "render",
            Compare::Reference => "reference",
            Compare::Difference => "difference",
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
