//! Error against run time for the four strategies, on two problems with a
//! closed-form answer:
//!
//! - *area*: a point on a Lambertian floor under a 1 m × 1 m emitter hung
//!   1 m above and beside it; the truth is ρ/π times Lambert's polygon
//!   irradiance ([`crate::ch5_reflection::radiometry::polygon_irradiance`]);
//! - *environment*: the same floor under the sky gradient, with nothing to
//!   shadow it; the truth is ρ/π · (π h + 2π/3 (z − h)).
//!
//! Each row is one estimate of N samples, repeated with independent seeds;
//! the error is the RMSE of those repeats against the truth and the time is
//! the mean time of one estimate. Monte Carlo error falls as N^(-1/2), and
//! time grows as N, so the log-log slope of error against time is near -1/2.

use std::time::Instant;

use glam::{DVec3, Vec3};

use super::direct::{Estimator, Strategy};
use super::shading_events::Counters;
use crate::ch4_implicit_surfaces::hit::Surface;
use crate::ch5_reflection::radiometry::polygon_irradiance;
use crate::ch5_reflection::world::{Interaction, World};
use crate::core::plot::{LogLogPlot, Look};
use crate::core::report::{ErrorTime, Measurement};
use crate::core::sampling::Sampler;
use crate::scene::{LightSampling, Scene};

/// Sizes of the study.
#[derive(Clone, Debug, PartialEq)]
pub struct Study {
    /// Samples per estimate, one row each.
    pub counts: Vec<u32>,
    /// Independent estimates per row (the RMSE is over these).
    pub repeats: u32,
}

impl Default for Study {
    fn default() -> Self {
        Study {
            counts: vec![4, 16, 64, 256, 1024],
            repeats: 64,
        }
    }
}

/// The floor's albedo in both problems.
pub const RHO: f32 = 0.5;
/// The area light's radiance.
pub const LE: f32 = 4.0;

/// The area problem: floor, 1 m² light facing down at height 1 beside the
/// shading point.
pub const AREA_SCENE: &str = r#"
[[materials]]
name = "floor"
reflectance = [0.5, 0.5, 0.5]
[[materials]]
name = "lamp"
reflectance = [0, 0, 0]
emission = [4, 4, 4]
[[objects]]
shape = "rectangle"
size = [4, 4]
material = "floor"
[[objects]]
shape = "rectangle"
size = [1, 1]
material = "lamp"
rotate = { axis = [1, 0, 0], degrees = 180 }
translate = [0.5, 0.25, 1]
"#;

/// The environment problem: a floor facing +y under the sky.
pub const SKY_SCENE: &str = r#"
[[materials]]
name = "floor"
reflectance = [0.5, 0.5, 0.5]
[[objects]]
shape = "rectangle"
size = [4, 4]
material = "floor"
rotate = { axis = [1, 0, 0], degrees = -90 }
[[lights]]
type = "sky"
zenith = [0.2, 0.4, 1.0]
horizon = [1.0, 1.0, 1.0]
ground = [0.1, 0.1, 0.1]
"#;

/// A problem: the world, the shading point on the floor, and the truth.
pub struct Problem {
    /// The world.
    pub world: World,
    /// The floor point being shaded (its normal faces the light).
    pub it: Interaction,
    /// The exact reflected radiance towards the normal.
    pub truth: Vec3,
    /// Whether the estimator traces shadow and sampled-direction rays
    /// ([`Estimator::trace_light_rays`](super::direct::Estimator::trace_light_rays)).
    pub trace_light_rays: bool,
}

fn world_of(text: &str, light_sampling: LightSampling) -> (Scene, World) {
    let scene = Scene {
        light_sampling,
        ..Scene::from_text(text, "study").expect("the study scenes are valid (tested)")
    };
    let world = World::new(&scene);
    (scene, world)
}

/// The area-light problem.
pub fn area_problem() -> Problem {
    area_problem_sampled_by(LightSampling::Area)
}

/// The area-light problem with its light sampled by `sampling`.
pub fn area_problem_sampled_by(sampling: LightSampling) -> Problem {
    let (scene, world) = world_of(AREA_SCENE, sampling);
    let corners = [
        DVec3::new(0.0, -0.25, 1.0),
        DVec3::new(1.0, -0.25, 1.0),
        DVec3::new(1.0, 0.75, 1.0),
        DVec3::new(0.0, 0.75, 1.0),
    ];
    let e = polygon_irradiance(DVec3::ZERO, DVec3::Z, &corners, LE as f64);
    let truth = Vec3::splat((RHO as f64 / std::f64::consts::PI * e) as f32);
    Problem {
        it: floor_point(&world, Vec3::Z),
        world,
        truth,
        trace_light_rays: !super::shadowing::scene_cannot_shadow(&scene),
    }
}

/// The sky problem.
pub fn sky_problem() -> Problem {
    let (scene, world) = world_of(SKY_SCENE, LightSampling::Area);
    let sky = match world.lights.lights.first() {
        Some(crate::ch5_reflection::light::Light::Sky(s)) => *s,
        _ => unreachable!("the sky scene has a sky"),
    };
    let truth = RHO / std::f32::consts::PI * sky.irradiance_up();
    Problem {
        it: floor_point(&world, Vec3::Y),
        world,
        truth,
        trace_light_rays: !super::shadowing::scene_cannot_shadow(&scene),
    }
}

fn floor_point(world: &World, n: Vec3) -> Interaction {
    Interaction {
        t: 1.0,
        p: Vec3::ZERO,
        n,
        material: world.mesh_material[0],
        surface: Surface::Mesh(0),
    }
}

impl Problem {
    /// One estimate of the reflected radiance with `n` samples.
    pub fn estimate(&self, strategy: Strategy, n: u32, seed: u64, repeat: u64) -> (Vec3, Counters) {
        let est = Estimator {
            strategy,
            max_mirror_bounces: 0,
            trace_light_rays: self.trace_light_rays,
        };
        let mut c = Counters::default();
        let mut sum = Vec3::ZERO;
        for i in 0..n {
            let mut s = Sampler::new(seed, repeat, i as u64);
            sum += est.reflected(&self.world, &self.it, self.it.n, &mut s, &mut c);
        }
        (sum / n.max(1) as f32, c)
    }

    /// RMSE over `repeats` estimates of `n` samples, and the mean seconds
    /// per estimate: the faster of two timed runs (the estimates are
    /// the same each time), so a busy machine disturbs the times less.
    pub fn rmse(&self, strategy: Strategy, n: u32, repeats: u32) -> (f64, f64) {
        let mut best = f64::INFINITY;
        let mut se = 0.0f64;
        for _ in 0..2 {
            let start = Instant::now();
            se = 0.0;
            for r in 0..repeats {
                let (l, _) = self.estimate(strategy, n, 0x5eed, r as u64);
                se += (l - self.truth).length_squared() as f64 / 3.0;
            }
            best = best.min(start.elapsed().as_secs_f64());
        }
        let seconds = best / repeats.max(1) as f64;
        ((se / repeats.max(1) as f64).sqrt(), seconds)
    }
}

/// What the name of a series with the light sampled by solid angle adds
/// to its strategy's.
const BY_SOLID_ANGLE: &str = " by solid angle";

/// The study: both problems, four strategies, every sample count; and on
/// the area problem, light sampling and MIS once more with the light
/// sampled by solid angle.
pub fn error_against_time(study: &Study) -> ErrorTime {
    let mut et = ErrorTime {
        reference:
            "closed forms: Lambert's polygon formula (area), the sky's irradiance (environment)"
                .into(),
        error_name: "RMSE".into(),
        rows: Vec::new(),
        show_slopes: true,
    };
    let by_area = Strategy::ALL.map(|s| (s, s.name().to_string()));
    let by_solid_angle =
        [Strategy::Light, Strategy::Mis].map(|s| (s, format!("{}{BY_SOLID_ANGLE}", s.name())));
    for (name, problem, strategies) in [
        ("area", area_problem(), &by_area[..]),
        (
            "area",
            area_problem_sampled_by(LightSampling::SolidAngle),
            &by_solid_angle[..],
        ),
        ("environment", sky_problem(), &by_area[..]),
    ] {
        for (strategy, label) in strategies {
            for &n in &study.counts {
                let (error, seconds) = problem.rmse(*strategy, n, study.repeats);
                et.rows.push(Measurement {
                    series: format!("{name}: {label}"),
                    variant: format!("{n} samples"),
                    seconds,
                    samples: n as u64,
                    error,
                    notes: format!("{} repeats", study.repeats),
                });
            }
        }
    }
    et
}

/// The study's two log-log plots, one per problem: (file name, plot). The
/// strategies keep one colour and marker each in every plot of the book.
pub fn plots(et: &ErrorTime) -> Vec<(String, LogLogPlot)> {
    // A strategy keeps its colour with the light sampled by solid angle,
    // dashed.
    let look = |series: &str| {
        let label = series.split_once(": ").map_or(series, |(_, label)| label);
        let (strategy, dashed) = match label.strip_suffix(BY_SOLID_ANGLE) {
            Some(strategy) => (strategy, true),
            None => (label, false),
        };
        let i = Strategy::ALL
            .iter()
            .position(|s| s.name() == strategy)
            .unwrap_or(Strategy::ALL.len());
        Look {
            dashed,
            ..Look::nth(i)
        }
    };
    [
        ("area", "Area light: error against time"),
        ("environment", "Sky: error against time"),
    ]
    .into_iter()
    .map(|(group, title)| {
        let mut plot = et.plot(group, title, look);
        plot.y_label = "RMSE of the reflected radiance".into();
        (format!("ch5-error-time-{group}.png"), plot)
    })
    .collect()
}
