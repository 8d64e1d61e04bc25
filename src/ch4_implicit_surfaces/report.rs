//! What chapter 4 prints: the march settings, what the rays met (SDF hits,
//! mesh hits, escapes, step budgets), the Eikonal check and, with
//! `--report`, the studies.

use super::eikonal::eikonal_check;
use super::march::March;
use super::normal::NormalScheme;
use super::render::Method;
use super::render::{Pixel, TraceStats};
use crate::ch3_ray_triangle::geometry::Geometry;
use crate::core::film::Film;
use crate::core::format::{format_number, format_seconds};
use crate::core::report::{Report, Table};
use crate::core::stage::Settings;
use crate::scene::Scene;

/// What the report is made from: the stage's settings and the traced
/// image.
pub struct ReportInputs<'a> {
    /// The march's step rules.
    pub march: &'a March,
    /// Sphere tracing, over-relaxed, or the fixed step.
    pub method: Method,
    /// How normals were estimated.
    pub normals: NormalScheme,
    /// The scene traced.
    pub scene: &'a Scene,
    /// The run's settings.
    pub settings: &'a Settings,
    /// Every traced pixel.
    pub pixels: &'a [Pixel],
    /// The views made from them.
    pub films: &'a [Film],
    /// Seconds the trace took.
    pub seconds: f64,
    /// The mesh part of the scene and its BVH build time, if it has one.
    pub geometry: Option<&'a (Geometry, f64)>,
}

/// The chapter's report on a traced image.
pub fn chapter_report(inputs: &ReportInputs) -> Report {
    let ReportInputs {
        march,
        method,
        normals,
        scene,
        settings,
        pixels,
        films,
        seconds,
        geometry,
    } = *inputs;
    let cam = &scene.camera;
    let m = march;
    let stats = TraceStats::of(pixels);
    let n = pixels.len().max(1) as f64;
    let nonfinite: u64 = films.iter().map(|f| f.clone().scrub_nonfinite()).sum();
    let mut report = Report {
        title: format!("ch4 sphere tracing: {}", scene.name),
        facts: vec![
            ("scene".into(), scene.source.clone()),
            (
                "image".into(),
                format!(
                    "{}x{} pixels, one ray through each pixel centre",
                    cam.width, cam.height
                ),
            ),
            (
                "march".into(),
                format!(
                    "{}, ε = {}, step budget {}, max distance {}, step factor {}, {} normals",
                    method.describe(),
                    format_number(m.epsilon as f64),
                    m.max_steps,
                    format_number(m.max_distance as f64),
                    format_number(m.step_factor as f64),
                    match normals {
                        NormalScheme::Central => "central-difference (6 taps)",
                        NormalScheme::Tetrahedron => "tetrahedron (4 taps)",
                    }
                ),
            ),
            (
                "camera rays".into(),
                format!(
                    "{} mesh hits (nearest hit); sphere tracing against the SDFs: {} SDF hits, \
                     {} escaped, {} ran out of steps ({:.2}%), {} started inside",
                    stats.mesh_hits,
                    stats.hits,
                    stats.escaped,
                    stats.budget,
                    100.0 * stats.budget as f64 / n,
                    stats.inside
                ),
            ),
            (
                "steps".into(),
                format!(
                    "{} evaluations of f, {:.1} per ray on average, at most {}; {} oversteps; \
                     {} steps where f changed faster than the ray moved (not 1-Lipschitz)",
                    stats.evaluations,
                    stats.evaluations as f64 / n,
                    stats.max_steps,
                    stats.oversteps,
                    stats.lipschitz_violations
                ),
            ),
            ("render time".into(), format_seconds(seconds)),
        ],
        nonfinite_caught: nonfinite + stats.nonfinite as u64,
        ..Report::default()
    };

    // What the scene led the stage to build and to leave out.
    report.built.push("camera rays".into());
    if scene.sdfs.is_empty() {
        report
            .left_out
            .push("SDF evaluation: the scene has no [[sdfs]] (0 evaluations of f)".into());
    } else {
        report.built.push(format!(
            "sphere tracer over {} SDF objects ({} evaluations of f)",
            scene.sdfs.len(),
            stats.evaluations
        ));
    }
    match geometry {
        None => report
            .left_out
            .push("meshes and BVH: the scene has no meshes, none loaded, no BVH built".into()),
        Some((g, build_seconds)) => report.built.push(format!(
            "chapter 3's BVH over {} meshes ({} triangles, {} nodes, built in {}): \
             mesh hits meet SDF hits in nearest_hit",
            scene.meshes.len(),
            scene.triangle_count(),
            g.bvh.as_ref().map_or(0, |b| b.node_count()),
            format_seconds(*build_seconds)
        )),
    }
    report.facts.push((
        "lights".into(),
        format!(
            "{}, not used by this chapter (it shades with a headlight)",
            scene.describe_lights()
        ),
    ));
    report
        .left_out
        .push("sampling: one ray per pixel centre (--spp ignored)".into());
    if settings.spp != 1 {
        report.facts.push((
            "note".into(),
            format!("--spp {} has no effect in chapter 4", settings.spp),
        ));
    }

    if !scene.sdfs.is_empty() {
        let mut t = Table::new(
            "Eikonal check: ‖∇f‖ sampled over each object's bounds (4096 points)",
            &[
                "object",
                "built from",
                "declared",
                "L",
                "min",
                "1%",
                "99%",
                "max",
                "verdict",
            ],
        );
        for row in eikonal_check(&scene.sdfs) {
            let r = &row.range;
            t.row(vec![
                row.name,
                row.construction,
                row.declared.word().into(),
                format_number(row.lipschitz as f64),
                format_number(r.min as f64),
                format_number(r.p01 as f64),
                format_number(r.p99 as f64),
                format_number(r.max as f64),
                r.verdict().into(),
            ]);
        }
        report.tables.push(t);
    }
    if settings.studies {
        report.error_vs_time = Some(super::studies::error_against_time());
        report.stability = super::stability::stability_cases();
    }
    report
}
