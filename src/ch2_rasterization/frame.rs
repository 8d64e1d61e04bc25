//! The whole rasterization pipeline for one frame: set every triangle up
//! (transform, clip, project, snap), find the samples each one covers
//! keeping the nearest in the depth buffer, and resolve the samples into
//! the views.

use std::time::Instant;

use super::coverage::{rasterize, SampleBuffer};
use super::setup::{setup_scene, ScreenTriangle, SetupStats};
use super::views::resolve;
use crate::ch1_projection::camera::Camera;
use crate::core::error::{Error, Result};
use crate::core::film::Film;
use crate::scene::mesh::Mesh;
use crate::scene::Material;

/// The most samples a frame may hold (8 bytes each: 1 GiB).
pub const MAX_SAMPLES: u64 = 1 << 27;

/// One rasterized frame and everything the report needs from it.
#[derive(Clone, Debug)]
pub struct Frame {
    /// The screen triangles after setup.
    pub tris: Vec<ScreenTriangle>,
    /// What setup did.
    pub stats: SetupStats,
    /// The depth buffer: nearest triangle per sample.
    pub buffer: SampleBuffer,
    /// The views, in [`super::views::VIEWS`] order.
    pub films: Vec<Film>,
    /// Seconds spent in setup, coverage and resolve.
    pub seconds: [f64; 3],
}

/// Rasterizes `meshes` seen by `cam` with `spp` samples per pixel.
// ANCHOR: render_frame
pub fn render_frame(
    cam: &Camera,
    meshes: &[Mesh],
    materials: &[Material],
    spp: u32,
    seed: u64,
    cull_back_faces: bool,
) -> Result<Frame> {
    let samples = cam.width as u64 * cam.height as u64 * spp as u64;
    if spp == 0 || samples > MAX_SAMPLES {
        return Err(Error::Usage(format!(
            "`--spp {spp}` at {}x{}: need 1 to {} samples per pixel at this size",
            cam.width,
            cam.height,
            (MAX_SAMPLES / (cam.width as u64 * cam.height as u64)).max(1)
        )));
    }
    let t0 = Instant::now();
    let (tris, stats) = setup_scene(cam, meshes, materials, cull_back_faces);
    let t1 = Instant::now();
    let buffer = rasterize(&tris, cam.width, cam.height, spp, seed);
    let t2 = Instant::now();
    let films = resolve(&buffer, &tris);
    let seconds = [
        (t1 - t0).as_secs_f64(),
        (t2 - t1).as_secs_f64(),
        t2.elapsed().as_secs_f64(),
    ];
    Ok(Frame {
        tris,
        stats,
        buffer,
        films,
        seconds,
    })
}
// ANCHOR_END: render_frame
