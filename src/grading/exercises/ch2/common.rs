//! What the capstone's clause checks share: the test image, the mark of
//! an untouched pixel, how a clause reports, how a triangle is named.

use glam::{DVec2, Vec3};

use crate::core::film::Film;
use crate::exercise::{Check, Symptom};

/// Something that draws a triangle: the candidate, the reference or a model.
pub(super) type Draw<'a> = &'a dyn Fn([Vec3; 3], [Vec3; 3], u32, u32, &mut [f32], &mut [Vec3]);

/// What no rasterizer writes: a pixel still this colour was not drawn.
pub(super) const UNTOUCHED: Vec3 = Vec3::splat(-1.0);

/// The test image of the clause checks.
pub(super) const W: u32 = 64;
pub(super) const H: u32 = 48;

/// `tri` (corner colours `colors`) drawn by `f` alone into fresh buffers
/// of `width` × `height` (depth ∞, every pixel [`UNTOUCHED`]): the depth
/// and the image it left.
pub(super) fn drawn_alone(
    f: Draw,
    tri: [Vec3; 3],
    colors: [Vec3; 3],
    (width, height): (u32, u32),
) -> (Vec<f32>, Vec<Vec3>) {
    let n = (width * height) as usize;
    let (mut depth, mut image) = (vec![f32::INFINITY; n], vec![UNTOUCHED; n]);
    f(tri, colors, width, height, &mut depth, &mut image);
    (depth, image)
}

/// A clause's result: `error` against `tolerance` (a NaN fails).
pub(super) fn failed(
    (error, tolerance): (f64, f64),
    detail: String,
    images: Option<(Film, Film)>,
    s: Option<Symptom>,
) -> Check {
    Check {
        error: if error.is_nan() { f64::INFINITY } else { error },
        tolerance,
        detail,
        images,
        symptom: s,
    }
}

/// A triangle's corners as raster (x, y) and depth.
pub(super) fn corners(t: &[Vec3; 3]) -> String {
    let c = t.map(|v| format!("({}, {}) at {} m", v.x, v.y, v.z));
    format!("{}, {}, {}", c[0], c[1], c[2])
}

/// The 2D edge function in f64 (exact for the hand-placed test triangles'
/// corners; within 10⁻¹⁶ relative for drawn ones).
pub(super) fn edge64(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)
}
