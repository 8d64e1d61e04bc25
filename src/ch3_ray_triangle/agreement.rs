//! Chapter 3 against chapter 2: the same question ("which triangle is seen
//! at this pixel centre?") answered by rasterization (coverage plus a depth
//! buffer) and by ray tracing (the first hit along the pixel's ray). Where
//! both are right they agree everywhere except at edges, where a pixel
//! centre lies within rounding distance of the line between two triangles
//! or of a silhouette.

use glam::Vec2;
use rayon::prelude::*;

use crate::ch1_projection::camera::Camera;
use crate::ch2_rasterization::frame::render_frame;
use crate::ch3_ray_triangle::geometry::Geometry;
use crate::core::error::Result;
use crate::scene::Scene;

/// How the two first-hit images compare.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Agreement {
    /// Pixels compared.
    pub pixels: usize,
    /// Pixels where the triangle seen differs (or one sees nothing).
    pub differ: usize,
    /// Of those, pixels that are not on an edge in either image: these
    /// should not exist.
    pub differ_off_edges: usize,
}

const MISS: u32 = u32::MAX;

/// The triangle seen at each pixel centre by chapter 2's rasterizer and by
/// chapter 3's ray tracer, compared.
// ANCHOR: agreement
// ANCHOR: agreement_ids
pub fn raster_agreement(scene: &Scene, geometry: &Geometry) -> Result<Agreement> {
    let cam = &Camera::of(scene);
    let (w, h) = (cam.width as usize, cam.height as usize);
    // Chapter 2: one sample at each pixel centre, depth-tested.
    let frame = render_frame(cam, &scene.meshes, &scene.materials, 1, 0, false)?;
    let raster: Vec<u32> = frame
        .buffer
        .samples
        .iter()
        .map(|s| {
            if s.tri == MISS {
                MISS
            } else {
                frame.tris[s.tri as usize].id
            }
        })
        .collect();
    // Chapter 3: the first hit along the ray through each pixel centre.
    let traced: Vec<u32> = (0..w * h)
        .into_par_iter()
        .map(|i| {
            let centre = Vec2::new((i % w) as f32 + 0.5, (i / w) as f32 + 0.5);
            geometry
                .closest(&cam.ray(centre))
                .map_or(MISS, |hit| hit.triangle)
        })
        .collect();
    // ANCHOR_END: agreement_ids
    // ANCHOR: agreement_edges
    // An edge pixel sees something else than one of its four neighbours.
    let on_edge = |ids: &[u32], i: usize| {
        let (x, y) = (i % w, i / w);
        (x > 0 && ids[i - 1] != ids[i])
            || (x + 1 < w && ids[i + 1] != ids[i])
            || (y > 0 && ids[i - w] != ids[i])
            || (y + 1 < h && ids[i + w] != ids[i])
    };
    let differing: Vec<usize> = (0..w * h).filter(|&i| raster[i] != traced[i]).collect();
    Ok(Agreement {
        pixels: w * h,
        differ: differing.len(),
        differ_off_edges: differing
            .iter()
            .filter(|&&i| !on_edge(&raster, i) && !on_edge(&traced, i))
            .count(),
    })
}
// ANCHOR_END: agreement_edges
// ANCHOR_END: agreement
