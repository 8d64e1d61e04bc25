//! Resolving the sample buffer into images: each view averages a value
//! over the samples of a pixel (that average is the anti-aliasing), with
//! black where nothing is covered.

use glam::Vec3;
use rayon::prelude::*;

use super::coverage::SampleBuffer;
use super::interpolate::{interpolate_phi, screen_barycentrics, Interpolation};
use super::setup::ScreenTriangle;
use crate::core::film::Film;
use crate::core::stage::{View, ViewScale};

/// The views of chapter 2, in the order [`resolve`] returns them.
pub const VIEWS: &[View] = &[
    View {
        name: "color",
        about: "vertex colours (or material colours lit by a headlight) interpolated perspective-correctly",
    },
    View {
        name: "affine",
        about: "the same colours interpolated with screen-space barycentrics (affine): wrong on slanted triangles",
    },
    View {
        name: "normals",
        about: "world-space geometric normal n as 0.5 + 0.5·n",
    },
    View {
        name: "depth",
        about: "1/depth from the depth buffer, scaled over the visible range: near is bright",
    },
    View {
        name: "barycentrics",
        about: "(φi, φj, φk) of each triangle as red, green, blue",
    },
    View {
        name: "triangle-id",
        about: "one colour per triangle",
    },
];

/// A colour for a triangle index, from a hash so neighbours differ.
pub fn id_color(id: u32) -> Vec3 {
    let h = crate::core::sampling::mix64(id as u64 + 1);
    let c = |k: u32| 0.2 + 0.8 * ((h >> (k * 16)) & 0xffff) as f32 / 65535.0;
    Vec3::new(c(0), c(1), c(2))
}

/// The visible range of 1/w in `buf`, which the depth view is scaled over
/// (∞ and 0 where nothing is covered).
pub fn depth_range(buf: &SampleBuffer) -> ViewScale {
    let (lo, hi) = buf
        .samples
        .iter()
        .filter(|s| s.is_covered())
        .fold((f32::INFINITY, 0.0f32), |(lo, hi), s| {
            (lo.min(s.inv_w), hi.max(s.inv_w))
        });
    ViewScale { lo, hi }
}

/// Every view of a rasterized frame, the depth view scaled over `depth`
/// (the [`depth_range`] of the whole image).
// ANCHOR: resolve
pub fn resolve(buf: &SampleBuffer, tris: &[ScreenTriangle], depth: ViewScale) -> Vec<Film> {
    let (w, h, spp) = (buf.width, buf.height, buf.spp);
    let (lo, hi) = (depth.lo, depth.hi);
    let pixels: Vec<[Vec3; 6]> = (0..w * h)
        .into_par_iter()
        .map(|i| {
            let (x, y) = (i % w, buf.first_row + i / w);
            let mut sum = [Vec3::ZERO; 6];
            for s in 0..spp {
                let sample = buf.samples[(i * spp + s) as usize];
                if !sample.is_covered() {
                    continue;
                }
                let tri = &tris[sample.tri as usize];
                let phi = screen_barycentrics(tri, buf.position(x, y, s));
                let (a, _) = interpolate_phi(tri, phi, Interpolation::Perspective);
                let (b, _) = interpolate_phi(tri, phi, Interpolation::Affine);
                let v = |a: &[f64; 6], k: usize| {
                    Vec3::new(a[k] as f32, a[k + 1] as f32, a[k + 2] as f32)
                };
                let shade = if hi > lo {
                    (sample.inv_w - lo) / (hi - lo)
                } else {
                    1.0
                };
                sum[0] += v(&a, 0);
                sum[1] += v(&b, 0);
                sum[2] += tri.normal * 0.5 + Vec3::splat(0.5);
                sum[3] += Vec3::splat(0.15 + 0.85 * shade);
                sum[4] += v(&a, 3);
                sum[5] += id_color(tri.id);
            }
            sum.map(|s| s / spp as f32)
        })
        .collect();
    (0..VIEWS.len())
        .map(|k| Film {
            width: w,
            height: h,
            pixels: pixels.iter().map(|p| p[k]).collect(),
        })
        .collect()
}
// ANCHOR_END: resolve
