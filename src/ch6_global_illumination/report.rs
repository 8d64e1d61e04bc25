//! What chapter 6 prints: the render's settings and counts, its error
//! against the stored reference, the mean of every bounce layer, what the
//! scene made the stage build or leave out and, with `--report`, the
//! studies.

use glam::Vec3;

use super::accumulate::Accumulator;
use super::engine::PathEngine;
use super::integrator::{PathSettings, Strategy};
use super::layers::{LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND};
use super::sampler::SamplerKind;
use super::stability::stability_cases;
use super::studies::{error_against_time, strategy_table};
use crate::core::format::{format_count, format_number, format_seconds};
use crate::core::report::{Report, Table};
use crate::core::stage::Settings;
use crate::scene::file::MaterialKind;
use crate::scene::Scene;

/// What a chapter-6 render has to say for itself.
pub struct ReportInputs<'a> {
    /// The scene rendered.
    pub scene: &'a Scene,
    /// The command's settings.
    pub settings: &'a Settings,
    /// Strategy, bounce limit, roulette.
    pub path: PathSettings,
    /// Where the random numbers came from.
    pub sampler: SamplerKind,
    /// Whether per-bounce layers were kept.
    pub layers: bool,
    /// The sums so far.
    pub acc: &'a Accumulator,
    /// The engine that traced the paths (and its world) and the seconds
    /// it took to build, once built.
    pub engine: Option<(&'a dyn PathEngine, f64)>,
    /// Seconds spent rendering passes.
    pub seconds: f64,
    /// RMSE against the stored reference and the reference's size.
    pub reference_rmse: Option<(f64, u32, u32)>,
    /// Why there is no RMSE although a reference of the scene's name is
    /// stored (its content differs): one line for the report.
    pub no_reference: Option<String>,
}

/// The chapter's report.
pub fn chapter_report(r: &ReportInputs) -> Report {
    let scene = r.scene;
    let acc = r.acc;
    let st = &acc.stats;
    let mut report = Report {
        title: format!("ch6 global illumination: {}", scene.name),
        ..Report::default()
    };
    let facts = [
        ("scene", scene.source.clone()),
        ("lights", scene.describe_lights()),
        ("resolution", format!("{}x{}", acc.width, acc.height)),
        ("samples per pixel", acc.samples.to_string()),
        (
            "estimator",
            format!(
                "{} ({} numbers){}",
                r.path.strategy.name(),
                r.sampler.name(),
                scene.light_sampling.note()
            ),
        ),
        (
            "max bounces",
            r.path
                .max_bounces
                .map_or("unlimited (Russian roulette ends paths)".into(), |k| {
                    k.to_string()
                }),
        ),
        ("Russian roulette", r.path.roulette_text(Some(r.sampler))),
        ("paths", st.paths.to_string()),
        ("rays (segments and shadow rays)", st.rays.to_string()),
        ("render time", format_seconds(r.seconds)),
        (
            "paths/s",
            format_number(st.paths as f64 / r.seconds.max(1e-9)),
        ),
        (
            "rays/s",
            format_number(st.rays as f64 / r.seconds.max(1e-9)),
        ),
    ];
    report.facts = facts.into_iter().map(|(k, v)| (k.to_string(), v)).collect();
    if st.cut > 0 {
        let why = if super::integrator::roulette_cannot_end(r.scene) {
            " (every surface reflects all the light it receives: roulette cannot end these paths)"
        } else {
            ""
        };
        report.facts.push((
            "paths cut at the safety limit".into(),
            format!("{} of {}{why}", st.cut, st.paths),
        ));
    }
    if let Some((e, w, h)) = r.reference_rmse {
        report.facts.push((
            "RMSE against the stored reference".into(),
            if (w, h) == (r.scene.camera.width, r.scene.camera.height) {
                format!("{} (per pixel, at {w}x{h})", format_number(e))
            } else {
                format!(
                    "{} (at {w}x{h}, image box-downsampled to it)",
                    format_number(e),
                )
            },
        ));
    }
    if let Some(why) = &r.no_reference {
        report
            .facts
            .push(("no stored reference".into(), why.clone()));
    }
    if acc.layers.is_some() {
        let mut t = Table::new(
            "Mean radiance per bounce layer (E: emitters seen directly; k: k + 1 scatterings)",
            &["layer", "mean R", "mean G", "mean B"],
        );
        for slot in 0..LAYER_SLOTS {
            let f = acc.layer(slot).expect("layers kept");
            let m = f.pixels.iter().sum::<Vec3>() / f.pixels.len().max(1) as f32;
            let name = match slot {
                0 => "E".to_string(),
                SLOT_BEYOND => format!("> {LAYERS_SHOWN}"),
                s => (s - 1).to_string(),
            };
            t.row(vec![
                name,
                format_number(m.x as f64),
                format_number(m.y as f64),
                format_number(m.z as f64),
            ]);
        }
        report.tables.push(t);
    }
    // Dropped contributions, and any non-finite pixel left in the sums.
    report.nonfinite_caught = st.nonfinite + acc.mean().scrub_nonfinite();
    built_and_left_out(&mut report, r);
    if r.settings.studies {
        add_studies(&mut report, r.settings);
    }
    report
}

/// Requirement 3: what the scene made the stage build, and leave out.
fn built_and_left_out(report: &mut Report, r: &ReportInputs) {
    let scene = r.scene;
    let (b, l) = (&mut report.built, &mut report.left_out);
    let world = r.engine.map(|(e, s)| (e.world(), s));
    match world.and_then(|(w, s)| w.mesh_queries().map(|q| (w, q, s))) {
        Some((w, q, s)) => b.push(format!(
            "{} over {} triangles; world built in {}",
            q.describe(),
            w.triangles.tris.len(),
            format_seconds(s)
        )),
        None => l.push("BVH: the scene has no meshes".into()),
    }
    if let Some((engine, _)) = r.engine {
        let (built, left_out) = engine.notes(&r.path);
        b.extend(built);
        l.extend(left_out);
    }
    if scene.sdfs.is_empty() {
        l.push("sphere tracing: the scene has no SDFs".into());
    } else {
        b.push(format!(
            "chapter 4's sphere tracing for {} SDF objects",
            scene.sdfs.len()
        ));
    }
    let lights = world.map(|(w, _)| &w.lights);
    let n_lights = lights.map_or(0, |l| l.lights.len());
    let samples_lights = matches!(r.path.strategy, Strategy::Light | Strategy::Mis);
    if n_lights == 0 {
        l.push("light sampling: the scene has no lights or emitters (paths find light only by hitting it)".into());
    } else if samples_lights {
        let env = lights.is_some_and(|l| l.environment.is_some());
        b.push(format!(
            "light sampling over {}{}",
            format_count(n_lights, "light"),
            if env {
                " (the environment sampled by cosine)"
            } else {
                ""
            }
        ));
    } else {
        l.push(format!(
            "light sampling: the {} estimator does not sample lights",
            r.path.strategy.name()
        ));
    }
    if r.layers {
        b.push(format!(
            "per-bounce layers: E, k = 0..{LAYERS_SHOWN}, beyond ({LAYER_SLOTS} sums per pixel)"
        ));
    } else {
        l.push("per-bounce layers: only the final image was asked for".into());
    }
    if scene
        .materials
        .iter()
        .any(|m| m.kind == MaterialKind::Glass)
    {
        b.push("smooth dielectric (Fresnel reflection, Snell refraction)".into());
    } else {
        l.push("dielectric: no glass in the scene".into());
    }
}

/// Adds the studies to a report: error against time, the strategy table
/// and the stiff cases. Below 16 spp (a quick run, such as the main
/// program's tour of every chapter) they run small: 2 spp per series and
/// the tests' sizes; otherwise up to `spp` (at most 64) per series.
fn add_studies(report: &mut Report, settings: &Settings) {
    let quick = settings.spp < 16;
    let max_spp = if quick {
        2
    } else {
        settings.spp.min(64).next_power_of_two()
    };
    report.facts.push((
        "studies".into(),
        if quick {
            "quick (under 16 spp): 2 spp per series and the tests' small stiff cases; \
             run with --spp 16 or more for the full study"
                .into()
        } else {
            format!("up to {max_spp} spp per series")
        },
    ));
    let et = error_against_time(max_spp);
    report.tables.push(strategy_table(&et));
    report.error_vs_time = Some(et);
    report.stability = stability_cases(quick);
}
