//! Chapter 2 as a stage: setup, coverage with a depth buffer, resolve into
//! the views, and the report (mesh checks, setup counts, the anti-aliasing
//! study and the stiff cases).

use std::sync::Arc;
use std::time::Instant;

use super::coverage::{rasterize, SampleBuffer};
use super::setup::{setup_scene, ScreenTriangle, SetupStats};
use super::views::{resolve, VIEWS};
use crate::ch1_projection::camera::Camera;
use crate::ch2_rasterization::mesh_check::check_mesh;
use crate::core::error::{Error, Result};
use crate::core::film::Film;
use crate::core::report::{Report, Table};
use crate::core::stage::{Chapter, Render, Settings, View};
use crate::scene::mesh::Mesh;
use crate::scene::{Material, Scene};

/// The most samples a frame may hold (8 bytes each: 1 GiB).
pub const MAX_SAMPLES: u64 = 1 << 27;

/// Chapter 2: rasterization.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rasterization {
    /// Drop triangles that face away from the camera.
    pub cull_back_faces: bool,
}

/// Chapter 2 with its default options, for the chapter list.
pub static RASTERIZATION: Rasterization = Rasterization {
    cull_back_faces: false,
};

/// One rasterized frame and everything the report needs from it.
#[derive(Clone, Debug)]
pub struct Frame {
    /// The screen triangles after setup.
    pub tris: Vec<ScreenTriangle>,
    /// What setup did.
    pub stats: SetupStats,
    /// The depth buffer: nearest triangle per sample.
    pub buffer: SampleBuffer,
    /// The views, in [`VIEWS`] order.
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

impl Chapter for Rasterization {
    fn number(&self) -> u32 {
        2
    }
    fn slug(&self) -> &'static str {
        "rasterization"
    }
    fn title(&self) -> &'static str {
        "Rasterization: coverage, barycentrics, depth buffer"
    }
    fn views(&self) -> &'static [View] {
        VIEWS
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        let cam = &scene.camera;
        let samples = cam.width as u64 * cam.height as u64 * settings.spp as u64;
        if settings.spp == 0 || samples > MAX_SAMPLES {
            return Err(Error::Usage(format!(
                "`--spp {}` is out of range at {}x{} (1 to {})",
                settings.spp,
                cam.width,
                cam.height,
                (MAX_SAMPLES / (cam.width as u64 * cam.height as u64)).max(1)
            )));
        }
        Ok(Box::new(RasterRender {
            scene,
            settings: settings.clone(),
            options: *self,
            frame: None,
        }))
    }
}

struct RasterRender {
    scene: Arc<Scene>,
    settings: Settings,
    options: Rasterization,
    frame: Option<Frame>,
}

impl Render for RasterRender {
    fn pass(&mut self) -> bool {
        let s = &self.scene;
        // `start` checked the sample count, so this cannot fail.
        self.frame = render_frame(
            &s.camera,
            &s.meshes,
            &s.materials,
            self.settings.spp,
            self.settings.seed,
            self.options.cull_back_faces,
        )
        .ok();
        true
    }

    fn progress(&self) -> (u32, u32) {
        (u32::from(self.frame.is_some()), 1)
    }

    fn view(&self, index: usize) -> Film {
        let films = self.frame.as_ref().map_or(&[][..], |f| &f.films[..]);
        crate::core::stage::view_of(films, index, &self.scene.camera)
    }

    fn report(&self) -> Report {
        chapter_report(
            &self.scene,
            &self.settings,
            self.options,
            self.frame.as_ref(),
        )
    }
}

/// The chapter's report for a rendered (or not yet rendered) frame.
pub fn chapter_report(
    scene: &Scene,
    settings: &Settings,
    options: Rasterization,
    frame: Option<&Frame>,
) -> Report {
    let cam = &scene.camera;
    let mut report = Report {
        title: format!("ch2 rasterization: {}", scene.name),
        ..Report::default()
    };
    report.facts.push(("scene".into(), scene.source.clone()));
    report.facts.push((
        "image".into(),
        format!(
            "{}x{} pixels, {} samples per pixel ({}), seed {}",
            cam.width,
            cam.height,
            settings.spp,
            match settings.spp {
                1 => "pixel centres".to_string(),
                n if (n as f64).sqrt().fract() == 0.0 => "stratified, jittered".into(),
                _ => "uniformly jittered".into(),
            },
            settings.seed
        ),
    ));
    if let Some(f) = frame {
        let s = &f.stats;
        report.facts.push((
            "setup".into(),
            format!(
                "{} triangles: {} cut at the near plane (z = -{}), {} behind the camera, {} cut by the guard band, {} back faces culled, {} zero-area pieces, {} off screen, {} non-finite; {} screen triangles",
                s.triangles, s.clipped_near, crate::ch1_projection::stage::NEAR, s.behind, s.clipped_guard,
                s.culled_back, s.zero_area, s.off_screen, s.nonfinite, s.screen_triangles
            ),
        ));
        let covered = f.buffer.samples.iter().filter(|s| s.is_covered()).count();
        report.facts.push((
            "coverage".into(),
            format!("{covered} of {} samples covered", f.buffer.samples.len()),
        ));
        report.facts.push((
            "render time".into(),
            format!(
                "setup {}, coverage and depth test {}, resolve {}",
                crate::core::report::format_seconds(f.seconds[0]),
                crate::core::report::format_seconds(f.seconds[1]),
                crate::core::report::format_seconds(f.seconds[2])
            ),
        ));
        report.nonfinite_caught = f
            .films
            .iter()
            .map(|film| film.clone().scrub_nonfinite())
            .sum::<u64>()
            + s.nonfinite as u64;
    }

    // What the scene led the stage to build and to leave out.
    report.built.push(format!(
        "depth buffer of {}x{}x{} samples",
        cam.width, cam.height, settings.spp
    ));
    if let Some(f) = frame {
        if f.stats.clipped_near > 0 {
            report.built.push(format!(
                "near-plane clipping ({} triangles cut)",
                f.stats.clipped_near
            ));
        } else {
            report
                .left_out
                .push("near-plane clipping: no triangle crosses the near plane".into());
        }
    }
    let colored = scene.meshes.iter().filter(|m| m.colors.is_some()).count();
    if colored > 0 {
        report
            .built
            .push(format!("vertex-colour interpolation ({colored} meshes)"));
    } else {
        report.left_out.push(
            "vertex colours: no mesh has them, triangles take their material's colour".into(),
        );
    }
    if options.cull_back_faces {
        report.built.push("back-face culling".into());
    } else {
        report
            .left_out
            .push("back-face culling: off (the depth buffer alone decides)".into());
    }
    report.left_out.push(match scene.lights.len() {
        0 => "lights: the scene has none".into(),
        n => format!("{n} lights: rasterization here does no shading"),
    });
    report
        .left_out
        .push("BVH and rays: rasterization walks triangles, not pixels".into());

    report.tables.push(mesh_check_table(scene));
    if settings.studies {
        report.error_vs_time = Some(super::studies::antialiasing_study(settings.seed));
        report.stability = super::studies::stability_cases();
    }
    report
}

/// The manifold and boundary checks of every mesh of a scene.
pub fn mesh_check_table(scene: &Scene) -> Table {
    let mut t = Table::new(
        "Mesh checks (manifold, boundary)",
        &[
            "mesh",
            "V",
            "E",
            "F",
            "V-E+F",
            "boundary edges",
            "boundary loops (edges)",
            "non-manifold edges",
            "non-manifold vertices",
            "flipped edges",
            "verdict",
        ],
    );
    for m in &scene.meshes {
        let c = check_mesh(m);
        let loops = if c.boundary_loops.is_empty() {
            "none".to_string()
        } else {
            format!(
                "{}: {}",
                c.boundary_loops.len(),
                c.boundary_loops
                    .iter()
                    .take(6)
                    .map(|l| l.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
                    + if c.boundary_loops.len() > 6 {
                        ", ..."
                    } else {
                        ""
                    }
            )
        };
        t.row(vec![
            m.name.clone(),
            c.vertices.to_string(),
            c.edges.to_string(),
            c.triangles.to_string(),
            c.euler().to_string(),
            c.boundary_edges.to_string(),
            loops,
            c.nonmanifold_edges.len().to_string(),
            c.nonmanifold_vertices.len().to_string(),
            c.inconsistent_edges.to_string(),
            c.verdict(),
        ]);
    }
    t
}
