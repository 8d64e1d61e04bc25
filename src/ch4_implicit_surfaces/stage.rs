//! Chapter 4 stage: sphere tracing the scene's signed distance functions.
//! One ray per pixel marches along f (see [`crate::ch4_implicit_surfaces::march`]); the
//! normal is the normalised gradient; the views show the shaded surface,
//! its normals, depth, the steps each ray took and the residual |f| at
//! the hit.
//!
//! Meshes are chapter 3's: a scene with meshes gets chapter 3's BVH, and
//! each ray's mesh hit and SDF hit meet in [`crate::ch4_implicit_surfaces::hit::nearest_hit`].
//! A scene without meshes builds no BVH; one without SDFs evaluates no f.

use std::sync::Arc;
use std::time::Instant;

use super::render::{trace_image, views, MeshTracer, Method, Pixel};
use crate::ch3_ray_triangle::stage::Geometry;
use crate::ch4_implicit_surfaces::eikonal::{gradient_range, sample_region};
use crate::ch4_implicit_surfaces::march::{Ending, March};
use crate::ch4_implicit_surfaces::normal::NormalScheme;
use crate::ch4_implicit_surfaces::sdf::{Aabb, SdfObject};
use crate::core::error::{Error, Result};
use crate::core::film::Film;
use crate::core::report::{format_number, format_seconds, Report, Table};
use crate::core::stage::{Chapter, Render, Settings, View};
use crate::scene::Scene;

/// The views of chapter 4.
pub const VIEWS: &[View] = &[
    View {
        name: "shaded",
        about: "a headlight: brightness is the cosine between the normal and the ray",
    },
    View {
        name: "normals",
        about: "the gradient normal as colour (x, y, z → r, g, b)",
    },
    View {
        name: "depth",
        about: "hit distance: near is bright",
    },
    View {
        name: "steps",
        about: "evaluations of f per ray as a heat map, from 0 (black) to the step budget (white)",
    },
    View {
        name: "error",
        about: "surface distance error |f| at the hit as a heat map, from 0 to ε",
    },
];

/// Chapter 4 with its march settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereTracing {
    /// ε, step budget, maximum distance, step factor.
    pub march: March,
    /// Plain, over-relaxed or fixed-step.
    pub method: Method,
    /// How normals are estimated.
    pub normals: NormalScheme,
}

/// The settings `ch4` uses unless told otherwise.
pub const DEFAULT: SphereTracing = SphereTracing {
    march: March {
        epsilon: 1e-4,
        max_steps: 256,
        max_distance: 100.0,
        step_factor: 1.0,
    },
    method: Method::Plain,
    normals: NormalScheme::Tetrahedron,
};

impl SphereTracing {
    /// Refuses settings no march can use.
    pub fn check(&self) -> Result<()> {
        let m = &self.march;
        let bad = |what: &str| Err(Error::Usage(what.to_string()));
        if !(m.epsilon.is_finite() && m.epsilon > 0.0) {
            return bad("`--epsilon` must be a positive number");
        }
        if m.max_steps == 0 {
            return bad("`--max-steps` must be at least 1");
        }
        if m.max_distance.is_nan() || m.max_distance <= 0.0 {
            return bad("`--max-distance` must be positive");
        }
        if !(m.step_factor > 0.0 && m.step_factor <= 1.0) {
            return bad("`--step-factor` must be in (0, 1]");
        }
        match self.method {
            Method::OverRelaxed(w) if !(1.0..2.0).contains(&w) => {
                bad("`--omega` must be in [1, 2)")
            }
            Method::FixedStep(d) if !(d.is_finite() && d > 0.0) => {
                bad("`--delta` must be a positive number")
            }
            _ => Ok(()),
        }
    }
}

impl Chapter for SphereTracing {
    fn number(&self) -> u32 {
        4
    }
    fn slug(&self) -> &'static str {
        "sphere-tracing"
    }
    fn title(&self) -> &'static str {
        "Implicit surfaces: signed distance functions and sphere tracing"
    }
    fn views(&self) -> &'static [View] {
        VIEWS
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        self.check()?;
        Ok(Box::new(SphereTracingRender {
            stage: *self,
            scene,
            settings: settings.clone(),
            pixels: Vec::new(),
            films: Vec::new(),
            seconds: 0.0,
            geometry: None,
        }))
    }
}

struct SphereTracingRender {
    stage: SphereTracing,
    scene: Arc<Scene>,
    settings: Settings,
    pixels: Vec<Pixel>,
    films: Vec<Film>,
    seconds: f64,
    /// Chapter 3's triangles and BVH with the seconds they took to build;
    /// only for scenes with meshes.
    geometry: Option<(Geometry, f64)>,
}

impl Render for SphereTracingRender {
    fn pass(&mut self) -> bool {
        let start = Instant::now();
        if self.geometry.is_none() && !self.scene.meshes.is_empty() {
            self.geometry = Some((Geometry::new(&self.scene), start.elapsed().as_secs_f64()));
        }
        let meshes = self.geometry.as_ref().map(|(geometry, _)| MeshTracer {
            geometry,
            meshes: &self.scene.meshes,
        });
        let s = &self.stage;
        let cam = &self.scene.camera;
        self.pixels = trace_image(cam, &self.scene.sdfs, &s.march, s.method, s.normals, meshes);
        self.films = views(
            &self.pixels,
            cam.width,
            cam.height,
            &self.scene.materials,
            &s.march,
        );
        self.seconds = start.elapsed().as_secs_f64();
        true
    }

    fn progress(&self) -> (u32, u32) {
        (u32::from(!self.films.is_empty()), 1)
    }

    /// One primary ray per traced pixel (the single pass).
    fn rays(&self) -> u64 {
        self.pixels.len() as u64
    }

    fn view(&self, index: usize) -> Film {
        crate::core::stage::view_of(&self.films, index, &self.scene.camera)
    }

    fn report(&self) -> Report {
        chapter_report(
            &self.stage,
            &self.scene,
            &self.settings,
            &self.pixels,
            &self.films,
            self.seconds,
            self.geometry.as_ref(),
        )
    }
}

/// Counts over the traced pixels.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TraceStats {
    /// Rays that hit.
    pub hits: usize,
    /// Rays that went past the maximum distance.
    pub escaped: usize,
    /// Rays that ran out of steps.
    pub budget: usize,
    /// Evaluations of f over all rays (normals not included).
    pub evaluations: u64,
    /// The most steps one ray took.
    pub max_steps: u32,
    /// Steps that crossed the surface.
    pub oversteps: u64,
    /// Steps where f changed faster than the ray moved (f not 1-Lipschitz).
    pub lipschitz_violations: u64,
    /// Rays that started inside an object.
    pub inside: usize,
    /// Non-finite distances or hit positions met.
    pub nonfinite: usize,
}

impl TraceStats {
    /// Counts over `pixels`.
    pub fn of(pixels: &[Pixel]) -> TraceStats {
        let mut s = TraceStats::default();
        for p in pixels {
            match p.trace.ending {
                Ending::Hit => s.hits += 1,
                Ending::Escaped => s.escaped += 1,
                Ending::Budget => s.budget += 1,
            }
            s.evaluations += p.trace.steps as u64;
            s.max_steps = s.max_steps.max(p.trace.steps);
            s.oversteps += p.trace.oversteps as u64;
            s.lipschitz_violations += p.trace.lipschitz_violations as u64;
            s.inside += usize::from(p.trace.inside);
            let bad_hit = matches!(p.hit, Some(h) if !(h.t.is_finite() && h.normal.is_finite()));
            if bad_hit || !p.trace.t.is_finite() {
                s.nonfinite += 1;
            }
        }
        s
    }
}

/// One object's row of the Eikonal check.
#[derive(Clone, Debug, PartialEq)]
pub struct EikonalRow {
    /// The object's name.
    pub name: String,
    /// What it is built from.
    pub construction: String,
    /// What the construction guarantees.
    pub declared: crate::ch4_implicit_surfaces::sdf::Exactness,
    /// The largest ‖∇f‖ it allows.
    pub lipschitz: f32,
    /// What was measured.
    pub range: crate::ch4_implicit_surfaces::eikonal::GradientRange,
}

/// Samples ‖∇f‖ over every object's bounds (4096 points each).
pub fn eikonal_check(objects: &[SdfObject]) -> Vec<EikonalRow> {
    // Planes are infinite: sample them over the box around everything else.
    let finite = objects
        .iter()
        .map(|o| o.sdf.bounds())
        .filter(Aabb::is_finite)
        .reduce(|a, b| a.union(&b))
        .unwrap_or(Aabb::around(glam::Vec3::ZERO, glam::Vec3::splat(2.0)));
    objects
        .iter()
        .map(|o| {
            let region = sample_region(&o.sdf.bounds(), &finite);
            let h = 1e-3 * region.size().max_element().max(1e-3);
            EikonalRow {
                name: o.name.clone(),
                construction: o.sdf.describe(),
                declared: o.sdf.exactness(),
                lipschitz: o.sdf.lipschitz(),
                range: gradient_range(&|p| o.sdf.eval(p), &region, 4096, h),
            }
        })
        .collect()
}

fn chapter_report(
    stage: &SphereTracing,
    scene: &Scene,
    settings: &Settings,
    pixels: &[Pixel],
    films: &[Film],
    seconds: f64,
    geometry: Option<&(Geometry, f64)>,
) -> Report {
    let cam = &scene.camera;
    let m = &stage.march;
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
                    stage.method.describe(),
                    format_number(m.epsilon as f64),
                    m.max_steps,
                    format_number(m.max_distance as f64),
                    format_number(m.step_factor as f64),
                    match stage.normals {
                        NormalScheme::Central => "central-difference (6 taps)",
                        NormalScheme::Tetrahedron => "tetrahedron (4 taps)",
                    }
                ),
            ),
            (
                "rays".into(),
                format!(
                    "{} hit, {} escaped, {} ran out of steps ({:.2}%), {} started inside",
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
    report.left_out.push(match scene.lights.len() {
        0 => "lights: the scene has none; shading is a headlight".into(),
        k => format!("{k} lights: chapter 4 shades with a headlight"),
    });
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
