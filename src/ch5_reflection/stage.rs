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
use super::render::render_pass;
use super::report::{chapter_report, ReportInputs};
use super::shading_events::Counters;
use super::shadowing::scene_cannot_shadow;
use crate::ch1_projection::camera::Camera;
use crate::ch5_reflection::world::World;
use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::report::Report;
use crate::core::stage::{Chapter, Render, Settings, View};
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
        name: "bsdf",
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
    fn default_variant(&self) -> usize {
        Strategy::ALL
            .iter()
            .position(|s| *s == self.strategy)
            .unwrap_or(0)
    }
    fn progressive(&self) -> bool {
        true
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        Ok(Box::new(ReflectionRender::new(*self, scene, settings)?))
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

struct ReflectionRender {
    stage: Reflection,
    scene: Arc<Scene>,
    camera: Camera,
    settings: Settings,
    world: Option<World>,
    build_seconds: f64,
    sums: Vec<Vec3>,
    passes: u32,
    counters: Counters,
    seconds: f64,
}

impl ReflectionRender {
    fn new(stage: Reflection, scene: Arc<Scene>, settings: &Settings) -> Result<ReflectionRender> {
        let n = scene.camera.width as usize * scene.camera.height as usize;
        Ok(ReflectionRender {
            stage,
            camera: Camera::new(scene.camera)?,
            scene,
            settings: settings.clone(),
            world: None,
            build_seconds: 0.0,
            sums: vec![Vec3::ZERO; n],
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
            &self.camera,
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

    fn samples(&self) -> u32 {
        self.passes
    }

    fn set_spp(&mut self, spp: u32) {
        self.settings.spp = spp.max(1);
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
        chapter_report(&ReportInputs {
            scene: &self.scene,
            settings: &self.settings,
            estimator: self.estimator(),
            world: self.world.as_ref(),
            build_seconds: self.build_seconds,
            passes: self.passes,
            counters: &self.counters,
            seconds: self.seconds,
        })
    }

    /// With `--report`: the study's plots, one per problem.
    fn extra_files(
        &self,
        report: &Report,
        dir: &std::path::Path,
        _stem: &str,
    ) -> Result<Vec<std::path::PathBuf>> {
        let mut files = Vec::new();
        for (name, plot) in report.error_vs_time.iter().flat_map(super::studies::plots) {
            let path = dir.join(name);
            plot.write_png(&path, 760, 420)?;
            files.push(path);
        }
        Ok(files)
    }
}
