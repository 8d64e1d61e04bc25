//! One ray per pixel through the scene, in parallel, and the views made
//! from the traces: the SDF part is sphere traced, the mesh part (if any)
//! goes through chapter 3's BVH, and the nearer hit wins. Each pixel is a
//! pure function of its position, so the images are the same on any number
//! of threads.

use glam::{Vec2, Vec3};
use rayon::prelude::*;

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::geometry::Geometry;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::unit_normal;
use crate::ch4_implicit_surfaces::distance::{scene_distance, SdfObject};
use crate::ch4_implicit_surfaces::hit::{nearest_hit, Surface, SurfaceHit};
use crate::ch4_implicit_surfaces::march::{
    fixed_step, over_relaxed, sphere_trace, Ending, March, Trace,
};
use crate::ch4_implicit_surfaces::normal::{normal, NormalScheme};
use crate::core::film::Film;
use crate::core::stage::ViewScale;
use crate::scene::mesh::Mesh;
use crate::scene::Material;

/// The scene's meshes as chapter 3 traces them (watertight triangles in
/// a BVH), for scenes that mix meshes with SDFs.
#[derive(Clone, Copy)]
pub struct MeshTracer<'a> {
    /// Chapter 3's triangles and BVH.
    pub geometry: &'a Geometry,
    /// The scene's meshes, for each triangle's material.
    pub meshes: &'a [Mesh],
}

impl MeshTracer<'_> {
    /// The first mesh hit along `ray`, as a surface hit.
    pub fn hit(&self, ray: &Ray) -> Option<SurfaceHit> {
        let hit = self.geometry.closest(ray)?;
        let mesh = self.geometry.triangles.mesh[hit.triangle as usize] as usize;
        let n =
            unit_normal(self.geometry.triangles.tris[hit.triangle as usize]).unwrap_or(Vec3::ZERO);
        Some(SurfaceHit {
            t: hit.t,
            // Face the viewer, as SDF normals do.
            normal: if n.dot(ray.dir) > 0.0 { -n } else { n },
            material: self.meshes[mesh].material,
            surface: Surface::Mesh(mesh),
        })
    }
}

/// Which march.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Method {
    /// Sphere tracing.
    Plain,
    /// Over-relaxed sphere tracing with this ω.
    OverRelaxed(f32),
    /// Constant steps of this length.
    FixedStep(f32),
}

impl Method {
    /// A short name for reports.
    pub fn describe(&self) -> String {
        match self {
            Method::Plain => "sphere tracing".into(),
            Method::OverRelaxed(w) => format!("over-relaxed sphere tracing (ω = {w})"),
            Method::FixedStep(d) => format!("fixed-step march (Δ = {d})"),
        }
    }
}

/// Marches one ray with `method`.
pub fn march(f: &dyn Fn(Vec3) -> f32, ray: &Ray, m: &March, method: Method) -> Trace {
    match method {
        Method::Plain => sphere_trace(f, ray, m),
        Method::OverRelaxed(omega) => over_relaxed(f, ray, m, omega),
        Method::FixedStep(delta) => fixed_step(f, ray, delta, m),
    }
}

/// What one pixel's ray found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pixel {
    /// The march.
    pub trace: Trace,
    /// The surface hit after "nearest hit wins".
    pub hit: Option<SurfaceHit>,
    /// The ray.
    pub ray: Ray,
}

/// Traces every pixel of rows `rows` of `camera`'s image (all of them:
/// `0..camera.height`) against `objects` (no SDF objects: no evaluation
/// at all, every pixel a miss).
pub fn trace_image(
    camera: &Camera,
    rows: std::ops::Range<u32>,
    objects: &[SdfObject],
    m: &March,
    method: Method,
    normals: NormalScheme,
    meshes: Option<MeshTracer>,
) -> Vec<Pixel> {
    let w = camera.width;
    (rows.start * w..rows.end * w)
        .into_par_iter()
        .map(|i| {
            let ray = pixel_ray(camera, i % w, i / w);
            trace_pixel(&ray, objects, m, method, normals, meshes)
        })
        .collect()
}

/// Traces one ray.
// ANCHOR: trace_pixel
pub fn trace_pixel(
    ray: &Ray,
    objects: &[SdfObject],
    m: &March,
    method: Method,
    normals: NormalScheme,
    meshes: Option<MeshTracer>,
) -> Pixel {
    let empty = Trace {
        ending: Ending::Escaped,
        t: 0.0,
        steps: 0,
        inside: false,
        oversteps: 0,
        lipschitz_violations: 0,
        residual: f32::INFINITY,
    };
    // Meshes through chapter 3's BVH; nothing when the scene has none.
    let mesh_hit = meshes.and_then(|mt| mt.hit(ray));
    if objects.is_empty() {
        return Pixel {
            trace: empty,
            hit: mesh_hit,
            ray: *ray,
        };
    }
    let f = |p: Vec3| scene_distance(objects, p).0;
    let trace = march(&f, ray, m, method);
    let sdf_hit = trace.hit().map(|t| {
        let p = ray.at(t);
        let object = scene_distance(objects, p).1;
        let h = m.epsilon_at(p).max(1e-4);
        let n = normal(&f, p, h, normals, -ray.dir);
        SurfaceHit {
            t,
            // Face the viewer: from inside, the gradient points away.
            normal: if n.dot(ray.dir) > 0.0 { -n } else { n },
            material: objects[object].material,
            surface: Surface::Sdf(object),
        }
    });
    Pixel {
        trace,
        hit: nearest_hit(sdf_hit, mesh_hit),
        ray: *ray,
    }
}
// ANCHOR_END: trace_pixel

/// The camera ray through the centre of pixel (`x`, `y`), as
/// [`trace_image`] shoots it.
pub fn pixel_ray(camera: &Camera, x: u32, y: u32) -> Ray {
    camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5))
}

/// One pixel's march written down: every evaluation of f as (t, f(t)),
/// the one at the origin first, and the pixel as [`trace_pixel`] finds it.
#[derive(Clone, Debug, PartialEq)]
pub struct MarchSteps {
    /// (t, f at o + t d) of every evaluation, in order.
    pub steps: Vec<(f32, f32)>,
    /// The pixel (the march's ending, the hit after meshes are compared).
    pub pixel: Pixel,
}

/// Marches `ray` as [`trace_pixel`] does, noting every evaluation.
pub fn march_steps(
    ray: &Ray,
    objects: &[SdfObject],
    m: &March,
    method: Method,
    normals: NormalScheme,
    meshes: Option<MeshTracer>,
) -> MarchSteps {
    let pixel = trace_pixel(ray, objects, m, method, normals, meshes);
    let log = std::cell::RefCell::new(Vec::new());
    if !objects.is_empty() {
        let f = |p: Vec3| {
            let d = scene_distance(objects, p).0;
            log.borrow_mut().push(((p - ray.origin).dot(ray.dir), d));
            d
        };
        march(&f, ray, m, method);
    }
    MarchSteps {
        steps: log.into_inner(),
        pixel,
    }
}

/// The colour of a miss.
pub const BACKGROUND: Vec3 = Vec3::new(0.04, 0.05, 0.07);

/// A heat map: black, blue, red, yellow, white for x from 0 to 1.
pub fn heat(x: f32) -> Vec3 {
    let x = if x.is_finite() {
        x.clamp(0.0, 1.0)
    } else {
        1.0
    };
    let stops = [
        Vec3::ZERO,
        Vec3::new(0.1, 0.1, 0.8),
        Vec3::new(0.9, 0.1, 0.1),
        Vec3::new(1.0, 0.9, 0.1),
        Vec3::ONE,
    ];
    let s = x * 4.0;
    let i = (s.floor() as usize).min(3);
    stops[i].lerp(stops[i + 1], s - i as f32)
}

/// The distances of the hits among `pixels`, the least and the greatest
/// (0 without hits): what the depth view is scaled over.
pub fn hit_range(pixels: &[Pixel]) -> ViewScale {
    let hits = pixels.iter().filter_map(|p| p.hit.map(|h| h.t));
    ViewScale {
        lo: hits.clone().fold(f32::INFINITY, f32::min),
        hi: hits.fold(0.0, f32::max),
    }
}

/// The five views: shaded (headlight), normals, depth (scaled over
/// `depth`, the [`hit_range`] of the whole image), steps, error.
pub fn views(
    pixels: &[Pixel],
    (w, h): (u32, u32),
    materials: &[Material],
    m: &March,
    depth: ViewScale,
) -> Vec<Film> {
    let mut films: Vec<Film> = (0..5).map(|_| Film::new(w, h)).collect();
    let (t_min, t_max) = (depth.lo, depth.hi.max(depth.lo));
    for (i, px) in pixels.iter().enumerate() {
        let steps = heat(px.trace.steps as f32 / m.max_steps as f32);
        films[3].pixels[i] = steps;
        let Some(hit) = px.hit else {
            films[0].pixels[i] = BACKGROUND;
            continue;
        };
        // A headlight: light from the eye, so brightness is cos θ.
        let cos = hit.normal.dot(-px.ray.dir).abs();
        films[0].pixels[i] = materials[hit.material].reflectance * (0.1 + 0.9 * cos);
        films[1].pixels[i] = hit.normal * 0.5 + Vec3::splat(0.5);
        let depth = if t_max > t_min {
            1.0 - (hit.t - t_min) / (t_max - t_min)
        } else {
            1.0
        };
        films[2].pixels[i] = Vec3::splat(0.15 + 0.85 * depth);
        let eps = m.epsilon_at(px.ray.at(hit.t));
        films[4].pixels[i] = heat(px.trace.residual.abs() / eps);
    }
    films
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
    /// Pixels whose nearest hit is a mesh (chapter 3's BVH), whatever the
    /// march did.
    pub mesh_hits: usize,
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
            s.mesh_hits += usize::from(matches!(
                p.hit,
                Some(SurfaceHit {
                    surface: Surface::Mesh(_),
                    ..
                })
            ));
            let bad_hit = matches!(p.hit, Some(h) if !(h.t.is_finite() && h.normal.is_finite()));
            if bad_hit || !p.trace.t.is_finite() {
                s.nonfinite += 1;
            }
        }
        s
    }
}
