//! What chapter 1 prints: the camera, what was drawn and left out, every
//! vertex through every step of the projection, farther-is-smaller, the
//! vanishing points and, with `--report`, the studies.

use super::camera::{project_pinhole, Camera};
use super::perspective::{farther_is_smaller, vanishing_points};
use super::stability::stability_cases;
use super::studies::error_against_time;
use super::wireframe::{DrawStats, NEAR};
use crate::core::film::Film;
use crate::core::format::{format_number, format_vec2, format_vec3};
use crate::core::report::{Report, Table};
use crate::core::stage::Settings;
use crate::scene::Scene;

/// The chapter's report on `scene`, drawn by `cam`.
pub fn chapter_report(
    scene: &Scene,
    cam: &Camera,
    settings: &Settings,
    stats: &DrawStats,
    seconds: f64,
    films: &[Film],
) -> Report {
    let d = &cam.desc;
    let vertices: usize = scene.meshes.iter().map(|m| m.positions.len()).sum();
    let edges: usize = scene.meshes.iter().map(|m| m.edges().len()).sum();
    let nonfinite = films.iter().map(|f| f.clone().scrub_nonfinite()).sum();
    let mut report = Report {
        title: format!("ch1 projection: {}", scene.name),
        facts: vec![
            ("scene".into(), scene.source.clone()),
            (
                "camera".into(),
                format!(
                    "eye {} target {} up {}, vertical fov {}°, {}x{} pixels",
                    format_vec3(d.eye), format_vec3(d.target), format_vec3(d.up), d.fov_degrees, cam.width, cam.height
                ),
            ),
            (
                "drawn".into(),
                format!(
                    "{} meshes, {vertices} vertices, {edges} edges: {} whole, {} clipped at the near plane (z = -{NEAR}), {} behind the camera; {} vertices drawn, {} culled",
                    scene.meshes.len(), stats.edges_whole, stats.edges_clipped, stats.edges_culled,
                    stats.vertices_drawn, stats.vertices_culled
                ),
            ),
            ("render time".into(), crate::core::format::format_seconds(seconds)),
        ],
        nonfinite_caught: nonfinite,
        ..Report::default()
    };

    // What the scene led the stage to build and to leave out.
    report.built.push("look-at camera and viewport".into());
    report
        .built
        .push(format!("wireframes of {} meshes", scene.meshes.len()));
    report
        .left_out
        .push("shading: materials give edge colours only".into());
    report.facts.push((
        "lights".into(),
        format!(
            "{}, not used by this chapter (projection needs no light)",
            scene.describe_lights()
        ),
    ));
    report
        .left_out
        .push("depth buffer, BVH and sampling: one deterministic pass (--spp ignored)".into());
    if settings.spp != 1 {
        report.facts.push((
            "note".into(),
            format!("--spp {} has no effect in chapter 1", settings.spp),
        ));
    }

    report.tables.push(vertex_table(scene, cam));
    report.tables.push(farther_is_smaller(cam));
    let vp = vanishing_points(cam, &scene.meshes);
    if !vp.is_empty() {
        let mut t = Table::new(
            "Parallel lines meet at infinity: vanishing points (pixels)",
            &[
                "world direction",
                "lines",
                "analytic",
                "where the drawn lines meet",
                "rms miss (px)",
            ],
        );
        for v in vp {
            t.row(vec![
                format_vec3(v.direction.as_dvec3()),
                v.lines.to_string(),
                format_vec2(v.analytic),
                v.measured
                    .map(format_vec2)
                    .unwrap_or_else(|| "lines coincide".into()),
                v.measured
                    .map(|_| format_number(v.rms_miss as f64))
                    .unwrap_or_default(),
            ]);
        }
        report.tables.push(t);
    }
    if settings.studies {
        report.error_vs_time = Some(error_against_time(cam));
        report.stability = stability_cases(cam);
    }
    report
}

/// Every vertex of the small meshes (at most 8 vertices, like the lecture's
/// tetrahedron) through every step of the projection.
pub fn vertex_table(scene: &Scene, cam: &Camera) -> Table {
    let mut t = Table::new(
        "Projected vertices (meshes of at most 8 vertices)",
        &[
            "mesh",
            "vertex",
            "world (x, y, z)",
            "camera (x, y, z)",
            "image plane (u, v)",
            "pixel (x, y)",
        ],
    );
    for m in scene
        .meshes
        .iter()
        .filter(|m| m.positions.len() <= 8)
        .take(4)
    {
        for (i, p) in m.positions.iter().enumerate() {
            let c = cam.to_camera(*p);
            let (uv, px) = match project_pinhole(c) {
                Some(uv) => (
                    format_vec2(uv),
                    format_vec2(cam.raster_from_image_plane(uv)),
                ),
                None => ("behind the camera".into(), "-".into()),
            };
            t.row(vec![
                m.name.clone(),
                i.to_string(),
                format_vec3(p.as_dvec3()),
                format_vec3(c.as_dvec3()),
                uv,
                px,
            ]);
        }
    }
    if t.rows.is_empty() {
        t.title += ": none in this scene";
    }
    t
}
