//! The whole rasterization pipeline for one frame: set every triangle up
//! (transform, clip, project, snap), find the samples each one covers
//! keeping the nearest in the depth buffer, and resolve the samples into
//! the views.

use std::time::Instant;

use super::coverage::{rasterize, SampleBuffer};
use super::setup::{setup_scene, ScreenTriangle, SetupStats};
use super::views::{depth_range, resolve};
use crate::ch1_projection::camera::Camera;
use crate::core::error::{Error, Result};
use crate::core::film::Film;
use crate::core::stage::Settings;
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
pub fn render_frame(
    cam: &Camera,
    meshes: &[Mesh],
    materials: &[Material],
    spp: u32,
    seed: u64,
    cull_back_faces: bool,
) -> Result<Frame> {
    let settings = Settings {
        spp,
        seed,
        ..Settings::default()
    };
    render_frame_with(cam, meshes, materials, &settings, cull_back_faces)
}

/// [`render_frame`] with a stage's settings: their samples and seed, only
/// the rows [`Settings::rows`] asks for, and the depth view scaled over
/// [`Settings::scale`] when it is given (else over what the frame sees).
// ANCHOR: render_frame
pub fn render_frame_with(
    cam: &Camera,
    meshes: &[Mesh],
    materials: &[Material],
    settings: &Settings,
    cull_back_faces: bool,
) -> Result<Frame> {
    let (spp, seed, rows) = (settings.spp, settings.seed, settings.rows_of(cam.height));
    let samples = cam.width as u64 * rows.len() as u64 * spp as u64;
    if spp == 0 || samples > MAX_SAMPLES {
        return Err(Error::Usage(format!(
            "`--spp {spp}` at {}x{}: need 1 to {} samples per pixel at this size",
            cam.width,
            rows.len(),
            (MAX_SAMPLES / (cam.width as u64 * rows.len().max(1) as u64)).max(1)
        )));
    }
    let t0 = Instant::now();
    let (tris, stats) = setup_scene(cam, meshes, materials, cull_back_faces);
    let t1 = Instant::now();
    let buffer = rasterize(&tris, cam.width, rows, spp, seed);
    let t2 = Instant::now();
    let depth = settings.scale.unwrap_or_else(|| depth_range(&buffer));
    let films = resolve(&buffer, &tris, depth);
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
