//! What chapter 3 prints: the image, the BVH that was built (or left
//! out), the rays traced and, with `--report`, the studies.

use super::geometry::Geometry;
use super::leaks::{leak_table, t_precision_table};
use super::render::TraceStats;
use super::stability::{agreement_case, stability_cases};
use super::studies::{error_against_time, intersector_speed, naive_vs_bvh, StudySize};
use crate::core::format::{format_number, format_seconds};
use crate::core::report::Report;
use crate::core::stage::Settings;
use crate::scene::Scene;

/// The report without the studies: facts, and what was built or left out.
pub fn chapter_report(
    scene: &Scene,
    geometry: &Geometry,
    stats: TraceStats,
    seconds: f64,
    spp: u32,
) -> Report {
    let cam = &scene.camera;
    let mut report = Report {
        title: format!("ch3 ray-triangle: {}", scene.name),
        facts: vec![
            ("scene".into(), scene.source.clone()),
            (
                "image".into(),
                format!(
                    "{}x{} pixels, {spp} samples per pixel",
                    cam.width, cam.height
                ),
            ),
            (
                "triangles".into(),
                format!(
                    "{} in {} meshes",
                    geometry.triangles.tris.len(),
                    scene.meshes.len()
                ),
            ),
            (
                "primary rays".into(),
                format!(
                    "{} traced, {} hit ({}%)",
                    stats.rays,
                    stats.hits,
                    format_number(100.0 * stats.hits as f64 / stats.rays.max(1) as f64)
                ),
            ),
            (
                "render time".into(),
                format!(
                    "{} ({} Mrays/s)",
                    format_seconds(seconds),
                    format_number(stats.rays as f64 / seconds.max(1e-9) / 1e6)
                ),
            ),
        ],
        ..Report::default()
    };
    report
        .built
        .push("primary rays from the look-at camera".into());
    match &geometry.bvh {
        Some(b) => report.built.push(format!(
            "BVH (obvhs Bvh2) over {} triangles: {} nodes, built in {}",
            b.triangle_count(),
            b.node_count(),
            format_seconds(b.build_seconds)
        )),
        None => report
            .left_out
            .push("BVH: the scene has no triangles, so every ray misses".into()),
    }
    report
        .built
        .push("watertight ray-triangle test (Woop, Benthin, Wald)".into());
    report
        .left_out
        .push("shading: materials and lights are ignored; the views show the first hit".into());
    report.facts.push((
        "lights".into(),
        format!(
            "{}, not used by this chapter (visibility needs no light)",
            scene.describe_lights()
        ),
    ));
    report
        .left_out
        .push("secondary rays: only the studies spawn them".into());
    report
}

/// Adds every study to `report`, at the given size.
pub fn add_studies(report: &mut Report, scene: &Scene, settings: &Settings, size: &StudySize) {
    let mut et = error_against_time(scene, &size.spp, size.reference_spp, settings.seed);
    let (table, rows) = naive_vs_bvh(&size.triangle_counts, size.naive_budget);
    et.rows.extend(rows);
    report.error_vs_time = Some(et);
    report.tables.push(table);
    let leaks = leak_table(size.leak_rays, settings.seed);
    report.tables.push(leaks.0);
    report.tables.push(t_precision_table());
    report.tables.push(intersector_speed(200_000));
    report.stability = stability_cases(size, &leaks.1);
    report.stability.push(agreement_case(scene));
}
