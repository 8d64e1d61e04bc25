//! Chapter 5 stage: the reflection equation with shadow rays, on meshes
//! and SDFs alike (through [`crate::ch5_reflection::world::World`]). Each pixel averages
//! `spp` camera rays through jittered positions; each ray's radiance is
//! [`direct::Estimator::radiance`]: what it hits emits, plus light reflected
//! from every light, plus what an ideal mirror sees.
//!
//! The variants are the four strategies for lights with extent (uniform,
//! cosine, light, MIS); delta lights are the same in all four.

use std::sync::Arc;
use std::time::Instant;

use glam::{Vec2, Vec3};
use rayon::prelude::*;

use super::direct::{Counters, Estimator, Strategy};
use crate::ch5_reflection::light::Light;
use crate::ch5_reflection::material::Bsdf;
use crate::ch5_reflection::world::World;
use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::report::{format_number, format_seconds, Report, Table};
use crate::core::sampling::Sampler;
use crate::core::stage::{Chapter, Render, Settings, View};
use crate::scene::mesh::Mesh;
use crate::scene::Scene;

/// The views of chapter 5.
pub const VIEWS: &[View] = &[View {
    name: "radiance",
    about: "reflected radiance (direct light only), linear HDR; PNG tone-mapped by sRGB",
}];

/// The strategies, as the front ends' variants.
pub const VARIANTS: &[View] = &[
    View {
        name: "uniform",
        about: "uniform hemisphere directions: finds lights by chance",
    },
    View {
        name: "cosine",
        about: "BRDF sampling: cosine-weighted on Lambertian surfaces, the lobe on glossy ones",
    },
    View {
        name: "light",
        about: "a point on each light (area lights by area, the sky by brightness)",
    },
    View {
        name: "mis",
        about: "one light and one BRDF sample, power heuristic",
    },
];

/// Chapter 5 with its estimator settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reflection {
    /// The strategy used by [`Chapter::start`].
    pub strategy: Strategy,
    /// Mirror bounces followed.
    pub max_mirror_bounces: u32,
}

/// What `ch5` uses unless told otherwise: MIS, up to 4 mirror bounces.
pub const DEFAULT: Reflection = Reflection {
    strategy: Strategy::Mis,
    max_mirror_bounces: 4,
};

impl Chapter for Reflection {
    fn number(&self) -> u32 {
        5
    }
    fn slug(&self) -> &'static str {
        "reflection"
    }
    fn title(&self) -> &'static str {
        "Radiometry, lights, BRDFs and the reflection equation"
    }
    fn views(&self) -> &'static [View] {
        VIEWS
    }
    fn is_radiance(&self) -> bool {
        true
    }
    fn variants(&self) -> &'static [View] {
        VARIANTS
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        Ok(Box::new(ReflectionRender::new(*self, scene, settings)))
    }
    fn start_variant(
        &self,
        scene: Arc<Scene>,
        settings: &Settings,
        variant: usize,
    ) -> Result<Box<dyn Render>> {
        let stage = Reflection {
            strategy: Strategy::ALL[variant.min(3)],
            ..*self
        };
        stage.start(scene, settings)
    }
}

/// Whether no surface of `scene` can shadow any other point of it: no
/// SDFs, no emissive surfaces, and one mesh that is flat or convex (a
/// point on a convex surface sees nothing of it above its tangent plane).
/// Such a scene needs no shadow rays.
// ANCHOR: cannot_shadow
pub fn scene_cannot_shadow(scene: &Scene) -> bool {
    scene.sdfs.is_empty()
        && !scene.has_emitters()
        && scene.meshes.len() == 1
        && is_convex(&scene.meshes[0])
}
// ANCHOR_END: cannot_shadow

/// Whether every vertex lies on or behind every face's plane (a single flat
/// polygon passes: all vertices lie on its plane).
fn is_convex(mesh: &Mesh) -> bool {
    let scale = mesh
        .positions
        .iter()
        .fold(0.0f32, |m, p| m.max(p.abs().max_element()))
        .max(1e-6);
    mesh.triangles.iter().all(|t| {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let Some(n) = (b - a).cross(c - a).try_normalize() else {
            return true;
        };
        mesh.positions
            .iter()
            .all(|p| (*p - a).dot(n) <= 1e-4 * scale)
    })
}

struct ReflectionRender {
    stage: Reflection,
    scene: Arc<Scene>,
    settings: Settings,
    world: Option<World>,
    build_seconds: f64,
    sums: Vec<Vec3>,
    passes: u32,
    counters: Counters,
    seconds: f64,
}

impl ReflectionRender {
    fn new(stage: Reflection, scene: Arc<Scene>, settings: &Settings) -> ReflectionRender {
        let n = scene.camera.width as usize * scene.camera.height as usize;
        ReflectionRender {
            stage,
            scene,
            settings: settings.clone(),
            world: None,
            build_seconds: 0.0,
            sums: vec![Vec3::ZERO; n],
            passes: 0,
            counters: Counters::default(),
            seconds: 0.0,
        }
    }

    fn estimator(&self) -> Estimator {
        Estimator {
            strategy: self.stage.strategy,
            max_mirror_bounces: self.stage.max_mirror_bounces,
            shadow_rays: !scene_cannot_shadow(&self.scene),
        }
    }
}

/// Adds sample `sample` of every pixel to `sums`, rows in parallel; every
/// random number comes from (seed, pixel, sample), so the result does not
/// depend on the number of threads.
// ANCHOR: render_pass
pub fn render_pass(
    world: &World,
    scene: &Scene,
    estimator: &Estimator,
    seed: u64,
    sample: u32,
    sums: &mut [Vec3],
) -> Counters {
    let cam = &scene.camera;
    let w = cam.width as usize;
    sums.par_chunks_mut(w)
        .enumerate()
        .map(|(y, row)| {
            let mut c = Counters::default();
            for (x, px) in row.iter_mut().enumerate() {
                let pixel = (y * w + x) as u64;
                let mut s = Sampler::new(seed, pixel, sample as u64);
                let raster = Vec2::new(x as f32, y as f32) + s.next2();
                let l = estimator.radiance(world, &cam.ray(raster), &mut s, &mut c);
                if l.is_finite() {
                    *px += l;
                } else {
                    c.nonfinite += 1;
                }
            }
            c
        })
        .reduce(Counters::default, |mut a, b| {
            a += b;
            a
        })
}
// ANCHOR_END: render_pass

impl Render for ReflectionRender {
    fn pass(&mut self) -> bool {
        let spp = self.settings.spp.max(1);
        if self.passes >= spp {
            return true;
        }
        let start = Instant::now();
        if self.world.is_none() {
            self.world = Some(World::new(&self.scene));
            self.build_seconds = start.elapsed().as_secs_f64();
        }
        let estimator = self.estimator();
        let world = self.world.as_ref().expect("built above");
        let c = render_pass(
            world,
            &self.scene,
            &estimator,
            self.settings.seed,
            self.passes,
            &mut self.sums,
        );
        self.counters += c;
        self.passes += 1;
        self.seconds += start.elapsed().as_secs_f64();
        self.passes >= spp
    }

    fn progress(&self) -> (u32, u32) {
        (self.passes, self.settings.spp.max(1))
    }

    fn rays(&self) -> u64 {
        // One camera ray per pixel and pass, plus the shadow, direction and
        // mirror rays the estimator traced.
        let cam = &self.scene.camera;
        let c = &self.counters;
        cam.width as u64 * cam.height as u64 * self.passes as u64
            + c.shadow_rays
            + c.direction_rays
            + c.mirror_bounces
    }

    fn view(&self, _index: usize) -> Film {
        let cam = &self.scene.camera;
        let mut film = Film::new(cam.width, cam.height);
        let k = self.passes.max(1) as f32;
        for (p, s) in film.pixels.iter_mut().zip(&self.sums) {
            *p = *s / k;
        }
        film.scrub_nonfinite();
        film
    }

    fn report(&self) -> Report {
        chapter_report(self)
    }
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

fn chapter_report(r: &ReflectionRender) -> Report {
    let scene = &r.scene;
    let cam = &scene.camera;
    let est = r.estimator();
    let c = &r.counters;
    let mut report = Report {
        title: format!("ch5 reflection: {}", scene.name),
        facts: vec![
            ("scene".into(), scene.source.clone()),
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
                    "{} for lights with extent; delta lights in closed form; mirrors followed up to {} bounces",
                    est.strategy.name(),
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
    let Some(world) = &r.world else {
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
            "light-sampling tables (triangle areas) for {} area lights, {} triangles",
            areas.len(),
            areas.iter().map(|a| a.triangles.len()).sum::<usize>()
        ));
    }
    if world.lights.environment.is_none() {
        report
            .left_out
            .push("environment: rays that escape see black".into());
    }
    if est.shadow_rays {
        report.built.push("shadow rays".into());
    } else {
        report.left_out.push(
            "shadow rays: one flat or convex mesh and nothing else, so no surface can shadow another"
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
