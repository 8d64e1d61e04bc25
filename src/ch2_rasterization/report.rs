//! What chapter 2 prints: setup and coverage counts, timings, the mesh
//! checks and, with `--report`, the studies.

use super::checker::{checker_counts, CHECKER_SIZE};
use super::frame::Frame;
use super::mesh_check::check_mesh;
use super::stability::stability_cases;
use super::studies::error_against_time;
use crate::core::report::{Report, Table};
use crate::core::stage::Settings;
use crate::scene::Scene;

/// The chapter's report for a rendered (or not yet rendered) frame.
pub fn chapter_report(
    scene: &Scene,
    settings: &Settings,
    cull_back_faces: bool,
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
                s.triangles, s.clipped_near, crate::ch1_projection::wireframe::NEAR, s.behind, s.clipped_guard,
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
                crate::core::format::format_seconds(f.seconds[0]),
                crate::core::format::format_seconds(f.seconds[1]),
                crate::core::format::format_seconds(f.seconds[2])
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
    if cull_back_faces {
        report.built.push("back-face culling".into());
    } else {
        report
            .left_out
            .push("back-face culling: off (the depth buffer alone decides)".into());
    }
    report.facts.push((
        "lights".into(),
        format!(
            "{}, not used by this chapter (material colours are lit by a headlight instead)",
            scene.describe_lights()
        ),
    ));
    report
        .left_out
        .push("BVH and rays: rasterization walks triangles, not pixels".into());

    report.tables.push(mesh_check_table(scene));
    if settings.studies {
        report.error_vs_time = Some(error_against_time(settings.seed));
        let (w, h) = CHECKER_SIZE;
        let c = checker_counts(w, h);
        let pct = |n: usize| 100.0 * n as f64 / c.floor_pixels.max(1) as f64;
        report.facts.push((
            "checker floor".into(),
            format!(
                "{w}x{h}, {} floor pixels (centres); square colour differs from the ray cast \
                 on {} ({:.2}%) perspective-correct, {} ({:.1}%) affine",
                c.floor_pixels,
                c.perspective_vs_exact,
                pct(c.perspective_vs_exact),
                c.affine_vs_exact,
                pct(c.affine_vs_exact),
            ),
        ));
        report.stability = stability_cases();
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
