//! Chapter 6 stage: global illumination by Monte Carlo path tracing.
//!
//! The rendering equation L_o = L_e + ∫ f L_i cos θ dω has the unknown L on
//! both sides; path tracing estimates it with one random path per sample
//! ([`integrator`]), bounce after bounce, each contribution filed under its
//! bounce count so the lecture's sequence (direct, 1, 2, 4, 8, 16 bounces)
//! comes out of one render ([`accumulate`]).
//!
//! Passes of a few samples per pixel accumulate progressively; the front
//! ends read the image, the per-bounce layers and, for the Cornell box, the
//! error against the stored reference ([`reference`](mod@reference)) after every pass.

use std::sync::Arc;
use std::time::Instant;

use glam::Vec3;

use super::accumulate::{downsample, Accumulator};
use super::integrator::{Estimator, PathSettings, LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND};
use super::sampler::SamplerKind;
use crate::ch5_reflection::world::World;
use crate::core::error::{Error, Result};
use crate::core::film::Film;
use crate::core::report::{format_number, format_seconds, Report, Table};
use crate::core::stage::{Chapter, Render, Settings, View};
use crate::scene::file::MaterialKind;
use crate::scene::Scene;

/// The views of chapter 6.
pub const VIEWS: &[View] = &[
    View {
        name: "image",
        about: "the path-traced radiance, every bounce",
    },
    View {
        name: "stderr",
        about: "the standard error of each pixel's mean (noise), same scale as the image",
    },
];

/// The estimator × sampler combinations a front end can switch between.
pub const VARIANTS: &[View] = &[
    View {
        name: "uniform-independent",
        about: "uniform hemisphere random walk, independent numbers",
    },
    View {
        name: "uniform-sobol",
        about: "uniform hemisphere random walk, Owen-scrambled Sobol",
    },
    View {
        name: "bsdf-independent",
        about: "BSDF (cosine) sampling only, independent numbers",
    },
    View {
        name: "bsdf-sobol",
        about: "BSDF (cosine) sampling only, Owen-scrambled Sobol",
    },
    View {
        name: "light-independent",
        about: "light sampling without MIS, independent numbers",
    },
    View {
        name: "light-sobol",
        about: "light sampling without MIS, Owen-scrambled Sobol",
    },
    View {
        name: "mis-independent",
        about: "light and BSDF sampling with the power heuristic, independent numbers",
    },
    View {
        name: "mis-sobol",
        about: "light and BSDF sampling with the power heuristic, Owen-scrambled Sobol",
    },
];

/// Chapter 6 with its settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GlobalIllumination {
    /// Estimator, bounce limit, roulette.
    pub path: PathSettings,
    /// Independent or Sobol numbers.
    pub sampler: SamplerKind,
    /// Samples per pixel in one progressive pass.
    pub spp_per_pass: u32,
    /// Keep per-bounce layers (off when only the final image is wanted).
    pub layers: bool,
}

/// The settings `ch6` uses unless told otherwise: MIS, 16 bounces,
/// independent numbers, 4 spp per pass, with layers.
pub const DEFAULT: GlobalIllumination = GlobalIllumination {
    path: PathSettings {
        estimator: Estimator::Mis,
        max_bounces: Some(16),
        rr_min_scatterings: 1,
    },
    sampler: SamplerKind::Independent,
    spp_per_pass: 4,
    layers: true,
};

impl GlobalIllumination {
    /// The variant index of this estimator and sampler (into [`VARIANTS`]).
    pub fn variant(&self) -> usize {
        let e = Estimator::ALL
            .iter()
            .position(|e| *e == self.path.estimator)
            .unwrap_or(3);
        2 * e + usize::from(self.sampler == SamplerKind::Sobol)
    }

    /// The same stage with variant `index` of [`VARIANTS`].
    pub fn with_variant(&self, index: usize) -> GlobalIllumination {
        let mut s = *self;
        s.path.estimator = Estimator::ALL[(index / 2).min(3)];
        s.sampler = if index % 2 == 1 {
            SamplerKind::Sobol
        } else {
            SamplerKind::Independent
        };
        s
    }

    /// Refuses settings no render can use.
    pub fn check(&self) -> Result<()> {
        if self.spp_per_pass == 0 {
            return Err(Error::Usage("samples per pass must be at least 1".into()));
        }
        Ok(())
    }
}

impl Chapter for GlobalIllumination {
    fn number(&self) -> u32 {
        6
    }
    fn slug(&self) -> &'static str {
        "global-illumination"
    }
    fn title(&self) -> &'static str {
        "Global illumination: Monte Carlo path tracing, bounce by bounce"
    }
    fn views(&self) -> &'static [View] {
        VIEWS
    }
    fn has_bounces(&self) -> bool {
        self.layers
    }
    fn is_radiance(&self) -> bool {
        true
    }
    fn variants(&self) -> &'static [View] {
        VARIANTS
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        self.check()?;
        Ok(Box::new(PathTracingRender::new(*self, scene, settings)))
    }
    fn start_variant(
        &self,
        scene: Arc<Scene>,
        settings: &Settings,
        variant: usize,
    ) -> Result<Box<dyn Render>> {
        self.with_variant(variant).start(scene, settings)
    }
}

/// A progressive path-traced render.
pub struct PathTracingRender {
    stage: GlobalIllumination,
    scene: Arc<Scene>,
    settings: Settings,
    world: Option<(World, f64)>,
    /// The sums so far.
    pub acc: Accumulator,
    seconds: f64,
    started: Option<Instant>,
    reference: Option<super::reference::StoredReference>,
    errors: Vec<(f64, f64)>,
}

impl PathTracingRender {
    /// A render of `scene` that has not started.
    pub fn new(stage: GlobalIllumination, scene: Arc<Scene>, settings: &Settings) -> Self {
        let (w, h) = (scene.camera.width, scene.camera.height);
        let reference = super::reference::StoredReference::for_scene(&scene)
            .filter(|r| w % r.mean.width == 0 && h % r.mean.height == 0);
        PathTracingRender {
            stage,
            acc: Accumulator::new(w, h, stage.layers),
            scene,
            settings: settings.clone(),
            world: None,
            seconds: 0.0,
            started: None,
            reference,
            errors: Vec::new(),
        }
    }

    fn planned(&self) -> u32 {
        self.settings.spp.max(1).div_ceil(self.stage.spp_per_pass)
    }

    /// The RMSE of the current image against the stored reference, at the
    /// reference's resolution (the image box-downsampled to it).
    pub fn reference_rmse(&self) -> Option<f64> {
        let r = self.reference.as_ref()?;
        let factor = self.acc.width / r.mean.width;
        Some(downsample(&self.acc.mean(), factor).rmse(&r.mean))
    }

    /// Seconds spent rendering passes (not building the world).
    pub fn seconds(&self) -> f64 {
        self.seconds
    }
}

impl Render for PathTracingRender {
    fn pass(&mut self) -> bool {
        let started = *self.started.get_or_insert_with(Instant::now);
        if self.world.is_none() {
            let t = Instant::now();
            let world = World::new(&self.scene);
            self.world = Some((world, t.elapsed().as_secs_f64()));
        }
        let spp = self.settings.spp.max(1);
        if self.acc.samples < spp {
            let count = self.stage.spp_per_pass.min(spp - self.acc.samples);
            let t = Instant::now();
            let (world, _) = self.world.as_ref().expect("built above");
            self.acc.add_samples(
                world,
                &self.scene.camera,
                &self.stage.path,
                self.stage.sampler,
                self.settings.seed,
                count,
            );
            self.seconds += t.elapsed().as_secs_f64();
            if let Some(e) = self.reference_rmse() {
                self.errors.push((started.elapsed().as_secs_f64(), e));
            }
        }
        self.acc.samples >= spp
    }

    fn progress(&self) -> (u32, u32) {
        (
            self.acc.samples.div_ceil(self.stage.spp_per_pass),
            self.planned(),
        )
    }

    fn rays(&self) -> u64 {
        // Path segments and shadow rays, as the integrator counted them.
        self.acc.stats.rays
    }

    fn view(&self, index: usize) -> Film {
        let mut film = match index {
            1 => {
                let mut v = self.acc.variance_of_mean();
                v.pixels
                    .iter_mut()
                    .for_each(|p| *p = p.max(Vec3::ZERO).powf(0.5));
                v
            }
            _ => self.acc.mean(),
        };
        film.scrub_nonfinite();
        film
    }

    fn layers(&self) -> Option<Vec<Film>> {
        // The trait's convention: layers[0] is direct illumination with
        // the emitters seen directly included, layers[k] bounce k; the
        // last holds everything beyond.
        let e = self.acc.layer(0)?;
        let mut out = Vec::with_capacity(LAYER_SLOTS - 1);
        for slot in 1..LAYER_SLOTS {
            let mut f = self.acc.layer(slot)?;
            if slot == 1 {
                for (p, q) in f.pixels.iter_mut().zip(&e.pixels) {
                    *p += *q;
                }
            }
            f.scrub_nonfinite();
            out.push(f);
        }
        Some(out)
    }

    fn reference(&self) -> Option<Film> {
        let r = self.reference.as_ref()?;
        let factor = self.acc.width / r.mean.width;
        Some(super::reference::upsample(&r.mean, factor))
    }

    fn error_series(&self) -> Vec<(f64, f64)> {
        self.errors.clone()
    }

    fn report(&self) -> Report {
        let mut report = self.base_report();
        if self.settings.studies {
            super::studies::add_studies(&mut report, &self.settings);
        }
        report
    }
}

impl PathTracingRender {
    fn base_report(&self) -> Report {
        let scene = &self.scene;
        let acc = &self.acc;
        let st = &acc.stats;
        let mut report = Report {
            title: format!("ch6 global illumination: {}", scene.name),
            ..Report::default()
        };
        let s = self.stage;
        let facts = [
            ("resolution", format!("{}x{}", acc.width, acc.height)),
            ("samples per pixel", acc.samples.to_string()),
            (
                "estimator",
                format!("{} ({} numbers)", s.path.estimator.name(), s.sampler.name()),
            ),
            (
                "max bounces",
                s.path
                    .max_bounces
                    .map_or("unlimited (Russian roulette ends paths)".into(), |k| {
                        k.to_string()
                    }),
            ),
            (
                "Russian roulette",
                format!("after {} scatterings", s.path.rr_min_scatterings),
            ),
            ("paths", st.paths.to_string()),
            ("rays (segments and shadow rays)", st.rays.to_string()),
            ("render time", format_seconds(self.seconds)),
            (
                "paths/s",
                format_number(st.paths as f64 / self.seconds.max(1e-9)),
            ),
            (
                "rays/s",
                format_number(st.rays as f64 / self.seconds.max(1e-9)),
            ),
        ];
        report.facts = facts.into_iter().map(|(k, v)| (k.to_string(), v)).collect();
        if st.cut > 0 {
            report.facts.push((
                "paths cut at the safety limit".into(),
                format!("{} of {}", st.cut, st.paths),
            ));
        }
        if let Some(e) = self.reference_rmse() {
            let r = self.reference.as_ref().expect("rmse implies a reference");
            report.facts.push((
                "RMSE against the stored reference".into(),
                format!(
                    "{} (at {}x{}, image box-downsampled to it)",
                    format_number(e),
                    r.mean.width,
                    r.mean.height
                ),
            ));
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
        built_and_left_out(&mut report, scene, self.world.as_ref(), &self.stage);
        report
    }
}

/// Requirement 3: what the scene made the stage build, and leave out.
fn built_and_left_out(
    report: &mut Report,
    scene: &Scene,
    world: Option<&(World, f64)>,
    stage: &GlobalIllumination,
) {
    let (b, l) = (&mut report.built, &mut report.left_out);
    match world.and_then(|(w, s)| w.wide.as_ref().map(|wide| (w, wide, *s))) {
        Some((w, wide, s)) => b.push(format!(
            "chapter 3's BVH, 4 wide, over {} triangles ({} nodes, {} leaves; world built in {})",
            w.triangles.tris.len(),
            wide.node_count(),
            wide.leaf_count(),
            format_seconds(s)
        )),
        None => l.push("BVH: the scene has no meshes".into()),
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
    let samples_lights = matches!(
        stage.path.estimator,
        Estimator::LightSampling | Estimator::Mis
    );
    if n_lights == 0 {
        l.push("light sampling: the scene has no lights or emitters (paths find light only by hitting it)".into());
    } else if samples_lights {
        let env = lights.is_some_and(|l| l.environment.is_some());
        b.push(format!(
            "light sampling over {n_lights} lights{}",
            if env {
                " (the environment sampled by cosine)"
            } else {
                ""
            }
        ));
    } else {
        l.push(format!(
            "light sampling: the {} estimator does not sample lights",
            stage.path.estimator.name()
        ));
    }
    if stage.layers {
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
