//! What chapter 5 prints: the image and strategy, the lights and BRDFs the
//! scene asked for (and what it left out) and, with `--report`, the studies.

use glam::Vec3;

use super::direct::Estimator;
use super::light::Light;
use super::material::Bsdf;
use super::shading_events::Counters;
use super::world::World;
use crate::core::format::{format_count, format_number, format_seconds};
use crate::core::report::{Report, Table};
use crate::core::stage::Settings;
use crate::scene::Scene;

/// What a chapter-5 render has to say for itself.
pub struct ReportInputs<'a> {
    /// The scene rendered.
    pub scene: &'a Scene,
    /// The command's settings.
    pub settings: &'a Settings,
    /// The estimator used.
    pub estimator: Estimator,
    /// The lights, BSDFs and geometry, once built.
    pub world: Option<&'a World>,
    /// Seconds spent building the world.
    pub build_seconds: f64,
    /// Passes (samples per pixel) done.
    pub passes: u32,
    /// What the estimator counted.
    pub counters: &'a Counters,
    /// Seconds spent rendering.
    pub seconds: f64,
}

/// A light's kind and its quantity with units, for the report.
pub fn describe_light(light: &Light) -> (String, String) {
    let v = |x: Vec3| {
        format!(
            "({}, {}, {})",
            format_number(x.x as f64),
            format_number(x.y as f64),
            format_number(x.z as f64)
        )
    };
    match light {
        Light::Point { intensity, .. } => ("point".into(), format!("I = {} W/sr", v(*intensity))),
        Light::Directional { irradiance, .. } => (
            "directional".into(),
            format!("E = {} W/m² at normal incidence", v(*irradiance)),
        ),
        Light::Spot(s) => (
            "spot".into(),
            format!(
                "I = {} W/sr on the axis, cone {}°",
                v(s.intensity),
                format_number(s.cos_outer.clamp(-1.0, 1.0).acos().to_degrees() as f64)
            ),
        ),
        Light::Area(a) => (
            "area".into(),
            format!(
                "Le = {} W/(m²·sr), {} triangles, A = {} m²{}",
                v(a.le),
                a.triangles.len(),
                format_number(a.area as f64),
                if a.two_sided { ", two-sided" } else { "" }
            ),
        ),
        Light::Environment { radiance } => (
            "environment".into(),
            format!("L = {} W/(m²·sr) from every direction", v(*radiance)),
        ),
        Light::Sky(s) => (
            "sky".into(),
            format!(
                "L from {} (horizon) to {} (zenith), ground {}",
                v(s.horizon),
                v(s.zenith),
                v(s.ground)
            ),
        ),
    }
}

/// The BRDF's name for the report.
pub fn describe_bsdf(b: &Bsdf) -> String {
    match b {
        Bsdf::Lambertian(_) => "Lambertian ρ/π".into(),
        Bsdf::Mirror(_) => "ideal mirror (delta)".into(),
        Bsdf::Glossy(g) => format!("glossy, normalised Phong n = {}", format_number(g.n as f64)),
        Bsdf::Retro(r) => format!("retro-reflective lobe n = {}", format_number(r.n as f64)),
        Bsdf::SemiGloss(s) => format!(
            "semi-gloss: (1 − {0}) ρ/π + {0} · Phong n = {1}",
            format_number(s.ks as f64),
            format_number(s.n as f64)
        ),
        #[allow(unreachable_patterns)]
        _ => "other".into(),
    }
}

/// The chapter's report.
pub fn chapter_report(r: &ReportInputs) -> Report {
    let scene = r.scene;
    let cam = &scene.camera;
    let est = r.estimator;
    let c = r.counters;
    let mut report = Report {
        title: format!("ch5 reflection: {}", scene.name),
        facts: vec![
            ("scene".into(), scene.source.clone()),
            ("lights".into(), scene.describe_lights()),
            (
                "image".into(),
                format!(
                    "{}x{} pixels, {} samples per pixel (jittered)",
                    cam.width,
                    cam.height,
                    r.passes
                ),
            ),
            (
                "strategy".into(),
                format!(
                    "{} for lights with extent{}; delta lights in closed form; mirrors followed up to {} bounces",
                    est.strategy.name(),
                    scene.light_sampling.note(),
                    est.max_mirror_bounces
                ),
            ),
            (
                "rays".into(),
                format!(
                    "{} shadow rays, {} sampled-direction rays, {} mirror bounces",
                    c.shadow_rays, c.direction_rays, c.mirror_bounces
                ),
            ),
            ("render time".into(), format_seconds(r.seconds)),
        ],
        nonfinite_caught: c.nonfinite,
        ..Report::default()
    };
    let Some(world) = r.world else {
        return report;
    };

    // What the scene led the stage to build and to leave out.
    report.built.push("camera rays".into());
    match &world.wide {
        Some(wide) => report.built.push(format!(
            "chapter 3's BVH, 4 wide, over {} meshes ({} triangles, {} nodes, {} leaves, built with the lights in {})",
            scene.meshes.len(),
            scene.triangle_count(),
            wide.node_count(),
            wide.leaf_count(),
            format_seconds(r.build_seconds)
        )),
        None => report
            .left_out
            .push("meshes and BVH: the scene has no meshes".into()),
    }
    if scene.sdfs.is_empty() {
        report
            .left_out
            .push("sphere tracing: the scene has no [[sdfs]]".into());
    } else {
        report.built.push(format!(
            "chapter 4's sphere tracer over {} SDF objects",
            scene.sdfs.len()
        ));
        if scene
            .sdfs
            .iter()
            .any(|o| world.materials[o.material].is_emissive())
        {
            report.left_out.push(
                "light sampling of emissive SDFs: they have no area table; only sampled directions find them"
                    .into(),
            );
        }
    }
    let areas: Vec<_> = world
        .lights
        .lights
        .iter()
        .filter_map(|l| match l {
            Light::Area(a) => Some(a),
            _ => None,
        })
        .collect();
    if areas.is_empty() {
        report
            .left_out
            .push("light-sampling tables: the scene has no area lights".into());
    } else {
        report.built.push(format!(
            "light-sampling tables (triangle areas) for {}, {} triangles",
            format_count(areas.len(), "area light"),
            areas.iter().map(|a| a.triangles.len()).sum::<usize>()
        ));
    }
    if world.lights.environment.is_none() {
        report
            .left_out
            .push("environment: rays that escape see black".into());
    }
    if est.trace_light_rays {
        report
            .built
            .push("shadow rays and sampled-direction rays".into());
    } else {
        report.left_out.push(
            "shadow rays and sampled-direction rays: one flat or convex mesh and nothing else, \
             so no surface can shadow another"
                .into(),
        );
    }
    if world.lights.is_empty() {
        report.left_out.push(
            "lights: the scene has none, so it is black but for emitters seen directly".into(),
        );
    }

    let mut lights = Table::new("Lights", &["#", "kind", "quantity"]);
    for (i, l) in world.lights.lights.iter().enumerate() {
        let (kind, q) = describe_light(l);
        lights.row(vec![i.to_string(), kind, q]);
    }
    if !lights.rows.is_empty() {
        report.tables.push(lights);
    }
    let mut materials = Table::new("Materials", &["name", "BRDF", "ρ"]);
    for (m, b) in world.materials.iter().zip(&world.bsdfs) {
        materials.row(vec![
            m.name.clone(),
            describe_bsdf(b),
            format!(
                "({}, {}, {})",
                format_number(m.reflectance.x as f64),
                format_number(m.reflectance.y as f64),
                format_number(m.reflectance.z as f64)
            ),
        ]);
    }
    report.tables.push(materials);

    if r.settings.studies {
        report.error_vs_time = Some(super::studies::error_against_time(
            &super::studies::Study::default(),
        ));
        let cases = super::stability::stability_cases();
        report.nonfinite_caught += super::stability::caught(&cases);
        report.stability = cases.into_iter().map(|c| c.case).collect();
    }
    report
}
