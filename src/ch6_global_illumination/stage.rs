//! Chapter 6 stage: global illumination by Monte Carlo path tracing.
//!
//! The rendering equation L_o = L_e + ∫ f L_i cos θ dω has the unknown L on
//! both sides; path tracing estimates it with one random path per sample
//! ([`integrator`](super::integrator)), bounce after bounce, each contribution filed under its
//! bounce count so the lecture's sequence (direct, 1, 2, 4, 8, 16 bounces)
//! comes out of one render ([`accumulate`](super::accumulate)).
//!
//! Passes of a few samples per pixel accumulate progressively; the front
//! ends read the image, the per-bounce layers and, for the Cornell box, the
//! error against the stored reference ([`reference`](mod@super::reference)) after every pass.

use std::sync::Arc;
use std::time::Instant;

use super::accumulate::{downsample, Accumulator};
use super::engine::{EngineChoice, PathEngine};
use super::figures::{layer_figures, spp_figure, strategy_plot};
use super::inspect::table_lines;
use super::integrator::{PathSettings, Strategy};
use super::path_record::record_path;
use super::reference::StoredReference;
use super::report::{chapter_report, ReportInputs};
use super::sampler::SamplerKind;
use crate::ch1_projection::camera::Camera;
use crate::ch5_reflection::world::World;
use crate::core::error::{Error, Result};
use crate::core::figure::{Figure, FigureContent};
use crate::core::film::film_mean;
use crate::core::report::Report;
use crate::core::run::output_stem;
use crate::core::stage::{
    caught_film, Chapter, ChapterInfo, Inspection, Pass, Render, Settings, Snapshot, Variant, View,
    CAUGHT_VIEW,
};
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
    CAUGHT_VIEW,
];

/// The estimator × sampler combinations a front end can switch between:
/// the lecture's ladder, from "average (uniform sampling)" to
/// "importance-sampling, according to BRDF and light sources", each with
/// independent random numbers and with a low-discrepancy sequence.
pub const VARIANTS: &[Variant] = &[
    Variant {
        name: "uniform-independent",
        about: "uniform sampling (average of random directions), random numbers",
    },
    Variant {
        name: "uniform-sobol",
        about: "uniform sampling (average of random directions), low-discrepancy numbers",
    },
    Variant {
        name: "bsdf-independent",
        about: "importance sampling according to the BRDF, random numbers",
    },
    Variant {
        name: "bsdf-sobol",
        about: "importance sampling according to the BRDF, low-discrepancy numbers",
    },
    Variant {
        name: "light-independent",
        about: "importance sampling according to the light sources (direct + indirect), random numbers",
    },
    Variant {
        name: "light-sobol",
        about: "importance sampling according to the light sources (direct + indirect), low-discrepancy numbers",
    },
    Variant {
        name: "mis-independent",
        about: "importance sampling according to BRDF and light sources, combined (MIS), random numbers",
    },
    Variant {
        name: "mis-sobol",
        about: "importance sampling according to BRDF and light sources, combined (MIS), low-discrepancy numbers",
    },
];

/// Chapter 6 with its settings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GlobalIllumination {
    /// Strategy, bounce limit, roulette.
    pub path: PathSettings,
    /// Independent or Sobol numbers.
    pub sampler: SamplerKind,
    /// Samples per pixel in one progressive pass.
    pub spp_per_pass: u32,
    /// Which engine traces the paths (the same images either way).
    pub engine: EngineChoice,
    /// Keep per-bounce layers (off when only the final image is wanted).
    pub layers: bool,
    /// Also write the spp-doubling figure up to this many samples per
    /// pixel (headless runs only).
    pub spp_figure: Option<u32>,
}

/// The settings `ch6` and the front ends use unless told otherwise: the
/// best estimator and sampler (MIS with Owen-scrambled Sobol numbers), 16
/// bounces, 4 spp per pass, with layers, traced by the lesson's engine.
/// The front ends choose the engine (the fast one unless told `--engine
/// readable`: the registry in `src/fast/chapters.rs`, `ch6`'s command line).
pub const DEFAULT: GlobalIllumination = GlobalIllumination {
    path: PathSettings {
        strategy: Strategy::Mis,
        max_bounces: Some(16),
        rr_min_bounce: 1,
        rr_scale: None,
    },
    sampler: SamplerKind::Sobol,
    spp_per_pass: 4,
    engine: EngineChoice::READABLE,
    layers: true,
    spp_figure: None,
};

impl GlobalIllumination {
    /// The variant index of this estimator and sampler (into [`VARIANTS`]).
    pub fn variant(&self) -> usize {
        let e = Strategy::ALL
            .iter()
            .position(|e| *e == self.path.strategy)
            .unwrap_or(3);
        2 * e + usize::from(self.sampler == SamplerKind::Sobol)
    }

    /// The same stage with variant `index` of [`VARIANTS`].
    pub fn with_variant(&self, index: usize) -> GlobalIllumination {
        let mut s = *self;
        s.path.strategy = Strategy::ALL[(index / 2).min(3)];
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

const TITLE: &str = "Global illumination: Monte Carlo path tracing, bounce by bounce";

impl Chapter for GlobalIllumination {
    fn info(&self) -> ChapterInfo {
        ChapterInfo {
            variants: VARIANTS,
            default_variant: self.variant(),
            progressive: true,
            radiance: true,
            bounces: self.layers,
            // The spp figure's samples; the layers take most of the memory.
            extra_spp: self.spp_figure.map_or(0, |max| 1 << max.max(1).ilog2()),
            ..ChapterInfo::new(6, "global-illumination", TITLE, VIEWS)
                .with_memory(if self.layers { 1280 } else { 128 }, 544)
                .with_bands()
        }
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        crate::core::stage::require_light(6, &scene)?;
        let stage = self.with_variant(self.info().variant(settings)?);
        stage.check()?;
        Ok(Box::new(PathTracingRender::new(stage, scene, settings)?))
    }
}

/// A progressive path-traced render.
pub struct PathTracingRender {
    stage: GlobalIllumination,
    scene: Arc<Scene>,
    camera: Camera,
    settings: Settings,
    /// The engine (with its world) and its build time, once a pass built it.
    engine: Option<(Box<dyn PathEngine>, f64)>,
    /// The sums so far.
    pub acc: Accumulator,
    seconds: f64,
    started: Option<Instant>,
    /// The stored reference and how many times larger the render is.
    reference: Option<(StoredReference, u32)>,
    errors: Vec<(f64, f64)>,
}

impl PathTracingRender {
    /// A render of `scene` that has not started.
    pub fn new(stage: GlobalIllumination, scene: Arc<Scene>, settings: &Settings) -> Result<Self> {
        let rows = settings.rows_of(scene.camera.height);
        // A band of the image has no reference to compare with.
        let whole = rows.len() as u32 == scene.camera.height;
        let reference = if whole {
            StoredReference::for_render(&scene)
        } else {
            None
        };
        Ok(PathTracingRender {
            stage,
            camera: Camera::new(scene.camera)?,
            acc: Accumulator::of_rows(scene.camera.width, rows, stage.layers),
            scene,
            settings: settings.clone(),
            engine: None,
            seconds: 0.0,
            started: None,
            reference,
            errors: Vec::new(),
        })
    }

    /// Samples in the pass after `done` samples: 1, 1, 2, 4, … up to
    /// `spp_per_pass`, so the first picture comes after one sample per
    /// pixel. (Each pixel's samples are added in order whatever the passes,
    /// so the image does not depend on them.)
    fn pass_size(&self, done: u32) -> u32 {
        self.stage.spp_per_pass.min(done.max(1))
    }

    /// Passes to reach `spp` samples from `done`.
    fn passes_between(&self, mut done: u32, spp: u32) -> u32 {
        let mut passes = 0;
        while done < spp {
            done += self.pass_size(done).min(spp - done);
            passes += 1;
        }
        passes
    }

    fn planned(&self) -> u32 {
        self.passes_between(0, self.settings.spp.max(1))
    }

    /// The RMSE of the current image against the stored reference, at the
    /// reference's resolution (the image box-downsampled to it).
    pub fn reference_rmse(&self) -> Option<f64> {
        let (r, factor) = self.reference.as_ref()?;
        Some(downsample(&self.acc.mean(), *factor).rmse(&r.mean))
    }

    /// Seconds spent rendering passes (not building the world).
    pub fn seconds(&self) -> f64 {
        self.seconds
    }

    /// The world the passes trace in, once the first pass has built it.
    pub fn world(&self) -> Option<&World> {
        self.engine.as_ref().map(|(e, _)| e.world())
    }

    /// The camera.
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The stage settings this render runs with (its variant applied).
    pub fn stage(&self) -> &GlobalIllumination {
        &self.stage
    }

    /// The seed of every random number.
    pub fn seed(&self) -> u64 {
        self.settings.seed
    }

    /// Where the render is (the cheap facts a driver reads every pass).
    fn pass_info(&self) -> Pass {
        let done = self.passes_between(0, self.acc.samples);
        Pass {
            done,
            planned: done.max(self.planned()),
            samples: self.acc.samples,
            // Path segments and shadow rays, as the integrator counted them.
            rays: self.acc.stats.rays,
            noise: self.noise().map(|n| (n, film_mean(&self.acc.mean()))),
            complete: self.acc.samples >= self.settings.spp.max(1),
        }
    }

    /// The noise of view 0 (see [`Pass::noise`]), at the reference's
    /// resolution when there is one.
    fn noise(&self) -> Option<f64> {
        if self.acc.samples < 2 {
            return None;
        }
        // A block mean of f² independent pixels has Σ var / f⁴.
        let var = self.acc.variance_of_mean();
        let var = match &self.reference {
            Some((_, f)) if *f > 1 => {
                let mut v = downsample(&var, *f);
                let k = 1.0 / (f * f) as f32;
                v.pixels.iter_mut().for_each(|p| *p *= k);
                v
            }
            _ => var,
        };
        let n = var.pixels.len().max(1) as f64 * 3.0;
        let sum: f64 = var.pixels.iter().map(|p| p.as_dvec3().element_sum()).sum();
        Some((sum / n).sqrt())
    }
}

impl Render for PathTracingRender {
    fn pass(&mut self) -> Pass {
        let started = *self.started.get_or_insert_with(Instant::now);
        if self.engine.is_none() {
            let t = Instant::now();
            let engine = self.stage.engine.make(&self.scene);
            self.engine = Some((engine, t.elapsed().as_secs_f64()));
        }
        let spp = self.settings.spp.max(1);
        if self.acc.samples < spp {
            let count = self.pass_size(self.acc.samples).min(spp - self.acc.samples);
            let t = Instant::now();
            let (engine, _) = self.engine.as_ref().expect("built above");
            self.acc.add_samples(
                &**engine,
                &self.camera,
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
        self.pass_info()
    }

    fn set_spp(&mut self, spp: u32) {
        self.settings.spp = spp.max(1);
    }

    fn snapshot(&self) -> Snapshot {
        let mut image = self.acc.mean();
        image.scrub_nonfinite();
        let mut stderr = self.acc.variance_of_mean().sqrt_clamped();
        stderr.scrub_nonfinite();
        let caught = caught_film(self.acc.width, self.acc.height, &self.acc.caught);
        let (reference, reference_stderr) = self
            .reference
            .as_ref()
            .map(|(r, k)| r.upsampled(*k))
            .unzip();
        Snapshot {
            views: vec![image, stderr, caught],
            layers: self.acc.render_layers(),
            reference,
            reference_stderr,
            reference_factor: self.reference.as_ref().map_or(1, |(_, k)| *k),
            error_series: self.errors.clone(),
            pass: self.pass_info(),
        }
    }

    /// Sample `sample` of `pixel` as this render traced it, as a table;
    /// `None` before the first pass (the world is built there).
    fn inspect(&self, pixel: (u32, u32), sample: u32) -> Option<Inspection> {
        let world = self.world()?;
        if pixel.0 >= self.camera.width || pixel.1 >= self.camera.height {
            return None;
        }
        let (path, sampler, seed) = (&self.stage.path, self.stage.sampler, self.settings.seed);
        let record = record_path(world, &self.camera, path, sampler, seed, pixel, sample);
        let nee = path.strategy.samples_lights() && !world.lights.lights.is_empty();
        Some(Inspection {
            pixel,
            sample,
            lines: table_lines(&self.scene, world, &record, nee),
        })
    }

    /// Its figures: the bounce strip and every layer as EXR (when the stage
    /// keeps layers), the spp-doubling strip (with `--spp-figure`) and,
    /// with the studies, the strategy plots.
    fn report(&self) -> Report {
        let mut report = chapter_report(&ReportInputs {
            scene: &self.scene,
            settings: &self.settings,
            path: self.stage.path,
            sampler: self.stage.sampler,
            layers: self.stage.layers,
            acc: &self.acc,
            engine: self.engine.as_ref().map(|(e, s)| (&**e, *s)),
            seconds: self.seconds,
            reference_rmse: self.reference_rmse().map(|e| {
                let (r, _) = self.reference.as_ref().expect("an RMSE needs a reference");
                (e, r.mean.width, r.mean.height)
            }),
            no_reference: self
                .reference
                .is_none()
                .then(|| StoredReference::why_none(&self.scene))
                .flatten(),
        });
        let stem = output_stem(6, &self.scene.name);
        // A band of the image makes no figures: they show the whole image
        // (and the spp strip would render all of it again).
        if self.acc.height < self.camera.height {
            report.left_out.push(
                "per-bounce layers and figures: the image is rendered in bands, too large to \
                 hold whole, and they show all of it"
                    .into(),
            );
            return report;
        }
        let mut figures = layer_figures(&self.acc, &stem);
        if let (Some(max), Some((engine, _))) = (self.stage.spp_figure, &self.engine) {
            figures.push(spp_figure(
                &self.stage.path,
                self.stage.sampler,
                (&**engine, &self.camera),
                self.settings.seed,
                max,
                &stem,
            ));
        }
        if let Some(et) = &report.error_vs_time {
            for name in ["cornell", "furnace"] {
                figures.push(Figure {
                    file: format!("{stem}-strategies-{name}.png"),
                    content: FigureContent::Plot(strategy_plot(et, name), 760, 440),
                });
            }
        }
        report.figures = figures;
        report
    }
}
