//! Chapter 5 stage: the reflection equation with shadow rays, on meshes
//! and SDFs alike (through [`crate::ch5_reflection::world::World`]). Each pixel averages
//! `spp` camera rays through jittered positions; each ray's radiance is
//! [`direct::Estimator::radiance`](super::direct::Estimator::radiance): what it hits emits, plus light reflected
//! from every light, plus what an ideal mirror sees.
//!
//! The variants are the four strategies for lights with extent (uniform,
//! BSDF, light, MIS); delta lights are the same in all four.

use std::sync::Arc;
use std::time::Instant;

use glam::Vec3;

use super::direct::{Estimator, Strategy};
use super::light_terms::pixel_light;
use super::names::light_name;
use super::render::render_pass;
use super::report::{chapter_report, ReportInputs};
use super::shading_events::Counters;
use super::shadowing::scene_cannot_shadow;
use crate::ch1_projection::camera::Camera;
use crate::ch5_reflection::world::World;
use crate::core::error::Result;
use crate::core::figure::{Figure, FigureContent};
use crate::core::film::Film;
use crate::core::format::{num, rgb};
use crate::core::report::Report;
use crate::core::stage::{
    caught_film, fixed_pass, Chapter, ChapterInfo, Inspection, Pass, Render, Settings, Snapshot,
    Variant, View, CAUGHT_VIEW,
};
use crate::scene::Scene;

/// The views of chapter 5.
pub const VIEWS: &[View] = &[
    View {
        name: "radiance",
        about: "reflected radiance (direct light only), linear HDR; PNG tone-mapped by sRGB",
    },
    CAUGHT_VIEW,
];

/// The strategies, as the front ends' variants, in the order of
/// [`Strategy::ALL`].
pub const VARIANTS: &[Variant] = &[
    Variant {
        name: "uniform",
        about: "uniform hemisphere directions: finds lights by chance",
    },
    Variant {
        name: "bsdf",
        about: "BRDF sampling: cosine-weighted on Lambertian surfaces, the lobe on glossy ones",
    },
    Variant {
        name: "light",
        about: "a point on each light (area lights by area, the sky by brightness)",
    },
    Variant {
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

impl Reflection {
    /// The variant index of this stage's strategy (into [`VARIANTS`]).
    pub fn variant(&self) -> usize {
        Strategy::ALL
            .iter()
            .position(|s| *s == self.strategy)
            .unwrap_or(0)
    }

    /// The same stage with variant `index` of [`VARIANTS`].
    pub fn with_variant(&self, index: usize) -> Reflection {
        Reflection {
            strategy: Strategy::ALL[index.min(Strategy::ALL.len() - 1)],
            ..*self
        }
    }
}

impl Chapter for Reflection {
    fn info(&self) -> ChapterInfo {
        ChapterInfo {
            variants: VARIANTS,
            default_variant: self.variant(),
            progressive: true,
            radiance: true,
            ..ChapterInfo::new(
                5,
                "reflection",
                "Radiometry, lights, BRDFs and the reflection equation",
                VIEWS,
            )
            .with_memory(64, 528)
            .with_bands()
        }
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        crate::core::stage::require_light(5, &scene)?;
        let stage = self.with_variant(self.info().variant(settings)?);
        Ok(Box::new(ReflectionRender::new(stage, scene, settings)?))
    }
}

struct ReflectionRender {
    stage: Reflection,
    scene: Arc<Scene>,
    camera: Camera,
    settings: Settings,
    world: Option<World>,
    build_seconds: f64,
    sums: Vec<Vec3>,
    /// Per pixel, the samples that were NaN or infinite (left out).
    caught: Vec<u32>,
    passes: u32,
    counters: Counters,
    seconds: f64,
}

impl ReflectionRender {
    fn new(stage: Reflection, scene: Arc<Scene>, settings: &Settings) -> Result<ReflectionRender> {
        let rows = settings.rows_of(scene.camera.height);
        let n = scene.camera.width as usize * rows.len();
        Ok(ReflectionRender {
            stage,
            camera: Camera::new(scene.camera)?,
            scene,
            settings: settings.clone(),
            world: None,
            build_seconds: 0.0,
            sums: vec![Vec3::ZERO; n],
            caught: vec![0; n],
            passes: 0,
            counters: Counters::default(),
            seconds: 0.0,
        })
    }

    fn estimator(&self) -> Estimator {
        Estimator {
            strategy: self.stage.strategy,
            max_mirror_bounces: self.stage.max_mirror_bounces,
            trace_light_rays: !scene_cannot_shadow(&self.scene),
        }
    }
}

impl ReflectionRender {
    fn pass_info(&self) -> Pass {
        // One camera ray per pixel and pass, plus the shadow, direction and
        // mirror rays the estimator traced.
        let (w, h) = self
            .settings
            .film_size(self.camera.width, self.camera.height);
        let c = &self.counters;
        let rays = w as u64 * h as u64 * self.passes as u64
            + c.shadow_rays
            + c.direction_rays
            + c.mirror_bounces;
        let spp = self.settings.spp.max(1);
        Pass {
            samples: self.passes,
            ..fixed_pass(self.passes, spp, rays)
        }
    }
}

impl Render for ReflectionRender {
    fn pass(&mut self) -> Pass {
        let spp = self.settings.spp.max(1);
        if self.passes < spp {
            let start = Instant::now();
            if self.world.is_none() {
                self.world = Some(World::new(&self.scene));
                self.build_seconds = start.elapsed().as_secs_f64();
            }
            let estimator = self.estimator();
            let world = self.world.as_ref().expect("built above");
            let c = render_pass(
                world,
                &self.camera,
                &estimator,
                self.settings.seed,
                self.passes,
                self.settings.rows_of(self.camera.height),
                &mut self.sums,
                &mut self.caught,
            );
            self.counters += c;
            self.passes += 1;
            self.seconds += start.elapsed().as_secs_f64();
        }
        self.pass_info()
    }

    fn set_spp(&mut self, spp: u32) {
        self.settings.spp = spp.max(1);
    }

    fn snapshot(&self) -> Snapshot {
        let (w, h) = self
            .settings
            .film_size(self.camera.width, self.camera.height);
        let mut film = Film::new(w, h);
        let k = self.passes.max(1) as f32;
        for (p, s) in film.pixels.iter_mut().zip(&self.sums) {
            *p = *s / k;
        }
        film.scrub_nonfinite();
        Snapshot {
            views: vec![film, caught_film(w, h, &self.caught)],
            pass: self.pass_info(),
            ..Snapshot::default()
        }
    }

    /// Sample `sample` of `pixel` as this render's estimator traced it:
    /// what the camera ray hit and each light's share, with its MIS weights.
    fn inspect(&self, pixel: (u32, u32), sample: u32) -> Option<Inspection> {
        let world = self.world.as_ref()?;
        if pixel.0 >= self.camera.width || pixel.1 >= self.camera.height {
            return None;
        }
        let est = self.estimator();
        let p = pixel_light(world, &self.camera, &est, self.settings.seed, pixel, sample);
        let mut lines = vec![format!("sample {sample}: L = {}", rgb(p.total))];
        if !p.hit {
            lines.push(" miss: the sky".into());
        } else if p.delta {
            lines.push(" mirror/glass: what its ray sees".into());
        }
        lines.push(format!(" emitted {}", rgb(p.emitted)));
        for t in &p.lights {
            lines.push(format!("light {}", light_name(&self.scene, world, t.light)));
            let shadow = if t.shadowed { " (shadow)" } else { "" };
            lines.push(format!(
                "  light smp {} w {}{shadow}",
                rgb(t.sampled),
                num(t.weight)
            ));
            if t.found_weight > 0.0 {
                lines.push(format!(
                    "  brdf smp {} w {}",
                    rgb(t.found),
                    num(t.found_weight)
                ));
            }
        }
        Some(Inspection {
            pixel,
            sample,
            lines,
        })
    }

    /// With `--report`, its figures are the study's plots, one per problem.
    fn report(&self) -> Report {
        let mut report = chapter_report(&ReportInputs {
            scene: &self.scene,
            settings: &self.settings,
            estimator: self.estimator(),
            world: self.world.as_ref(),
            build_seconds: self.build_seconds,
            passes: self.passes,
            counters: &self.counters,
            seconds: self.seconds,
        });
        let plots: Vec<_> = report
            .error_vs_time
            .iter()
            .flat_map(super::studies::plots)
            .collect();
        for (file, plot) in plots {
            report.figures.push(Figure {
                file,
                content: FigureContent::Plot(plot, 760, 420),
            });
        }
        report
    }
}
