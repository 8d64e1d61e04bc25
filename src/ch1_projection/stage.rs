//! Chapter 1 stage: projection. Every vertex of the scene goes through the
//! camera (world → camera space → image plane → pixels) and every edge is
//! drawn as a line between its projected ends, after the part behind the
//! camera has been clipped away. No triangle is filled yet: that is
//! chapter 2.

use std::sync::Arc;
use std::time::Instant;

use glam::{DVec3, Vec2, Vec3};

use crate::ch1_projection::camera::{project_pinhole, Camera};
use crate::core::draw;
use crate::core::error::Result;
use crate::core::film::Film;
use crate::core::report::{format_number, ErrorTime, Measurement, Report, StabilityCase, Table};
use crate::core::stage::{Chapter, Render, Settings, View};
use crate::scene::mesh::Mesh;
use crate::scene::{Material, Scene};

/// How far in front of the pinhole an edge must be to be drawn. Edges that
/// cross this plane are cut there, so their visible part is kept.
pub const NEAR: f32 = 1e-3;

/// Keeps the part of the camera-space segment a→b that lies in front of the
/// near plane z = -near; `None` if nothing does.
// ANCHOR: clip_near
pub fn clip_to_near(a: Vec3, b: Vec3, near: f32) -> Option<(Vec3, Vec3)> {
    // Signed distances past the near plane: ≤ 0 means in front of it.
    let (da, db) = (a.z + near, b.z + near);
    let cut = |from: Vec3, to: Vec3, d_from: f32, d_to: f32| {
        // The point where the distance is zero, placed exactly on the plane.
        let p = from.lerp(to, d_from / (d_from - d_to));
        Vec3::new(p.x, p.y, -near)
    };
    match (da <= 0.0, db <= 0.0) {
        (true, true) => Some((a, b)),
        (true, false) => Some((a, cut(a, b, da, db))),
        (false, true) => Some((cut(a, b, da, db), b)),
        // Both behind, or a NaN made both tests false: nothing to draw.
        (false, false) => None,
    }
}
// ANCHOR_END: clip_near

/// An edge as it appears on the image, after clipping at the near plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectedEdge {
    /// Raster position of the first end.
    pub a: Vec2,
    /// Raster position of the second end.
    pub b: Vec2,
    /// Depth (-z) of each end.
    pub depth: [f32; 2],
    /// Whether the near plane cut the edge.
    pub clipped: bool,
}

/// Clips a camera-space edge at the near plane and projects what is left;
/// `None` when nothing is in front of the camera or the ends are not finite.
// ANCHOR: project_edge
pub fn project_edge(cam: &Camera, a: Vec3, b: Vec3) -> Option<ProjectedEdge> {
    let (ca, cb) = clip_to_near(a, b, NEAR)?;
    let (ua, ub) = (project_pinhole(ca)?, project_pinhole(cb)?);
    Some(ProjectedEdge {
        a: cam.raster_from_image_plane(ua),
        b: cam.raster_from_image_plane(ub),
        depth: [-ca.z, -cb.z],
        clipped: (ca, cb) != (a, b),
    })
}
// ANCHOR_END: project_edge

/// Counts from drawing a scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawStats {
    /// Edges drawn whole.
    pub edges_whole: usize,
    /// Edges cut at the near plane and drawn in part.
    pub edges_clipped: usize,
    /// Edges entirely behind the near plane.
    pub edges_culled: usize,
    /// Vertices drawn as dots.
    pub vertices_drawn: usize,
    /// Vertices on or behind the camera plane.
    pub vertices_culled: usize,
}

/// The three views of chapter 1.
pub const VIEWS: &[View] = &[
    View {
        name: "wireframe",
        about: "edges in their material's colour; vertices as dots that shrink with distance",
    },
    View {
        name: "depth",
        about: "edges shaded by 1/depth, interpolated along each edge: near is bright",
    },
    View {
        name: "points",
        about: "vertices only: farther is smaller",
    },
];

/// The colour a material gets in a wireframe: its hue at full brightness.
fn wire_color(m: &Material) -> Vec3 {
    if m.is_emissive() {
        return Vec3::new(1.0, 0.95, 0.6);
    }
    let c = m.reflectance;
    if c.max_element() > 0.0 {
        c / c.max_element() * 0.9
    } else {
        Vec3::splat(0.3)
    }
}

/// Draws `meshes` as seen by `camera`: the three [`VIEWS`] in order.
// ANCHOR: draw_scene
pub fn draw_scene(
    camera: &Camera,
    meshes: &[Mesh],
    materials: &[Material],
) -> (Vec<Film>, DrawStats) {
    let (w, h) = (camera.width, camera.height);
    let mut films = vec![Film::new(w, h), Film::new(w, h), Film::new(w, h)];
    let mut stats = DrawStats::default();
    // Every vertex to camera space once; depth range for shading and dots.
    let cam: Vec<Vec<Vec3>> = meshes
        .iter()
        .map(|m| m.positions.iter().map(|p| camera.to_camera(*p)).collect())
        .collect();
    let depths = cam.iter().flatten().map(|p| -p.z).filter(|d| *d >= NEAR);
    let z_min = depths.clone().fold(f32::INFINITY, f32::min);
    let z_max = depths.fold(0.0, f32::max).max(z_min);
    // Brightness proportional to 1/z, which is linear along a projected edge.
    let shade = |z: f32| {
        let s = (1.0 / z - 1.0 / z_max) / (1.0 / z_min - 1.0 / z_max);
        Vec3::splat(0.15 + 0.85 * if s.is_finite() { s } else { 1.0 })
    };

    for (mesh, pts) in meshes.iter().zip(&cam) {
        let color = wire_color(&materials[mesh.material]);
        for [i, j] in mesh.edges() {
            let Some(e) = project_edge(camera, pts[i as usize], pts[j as usize]) else {
                stats.edges_culled += 1;
                continue;
            };
            if e.clipped {
                stats.edges_clipped += 1;
            } else {
                stats.edges_whole += 1;
            }
            draw::line(&mut films[0], e.a, e.b, color, color);
            draw::line(
                &mut films[1],
                e.a,
                e.b,
                shade(e.depth[0]),
                shade(e.depth[1]),
            );
        }
        // Farther is smaller: a dot's radius falls off as 1/depth.
        for p in pts {
            let raster = project_pinhole(*p).map(|uv| camera.raster_from_image_plane(uv));
            match raster.filter(|_| -p.z >= NEAR) {
                Some(r) => {
                    let radius = (2.5 * z_min / -p.z).clamp(0.6, 2.5);
                    draw::dot(&mut films[0], r, radius, color);
                    draw::dot(&mut films[2], r, radius * 1.4, color.max(Vec3::splat(0.3)));
                    stats.vertices_drawn += 1;
                }
                None => stats.vertices_culled += 1,
            }
        }
    }
    (films, stats)
}
// ANCHOR_END: draw_scene

/// Chapter 1 as a stage.
pub struct Projection;

impl Chapter for Projection {
    fn number(&self) -> u32 {
        1
    }
    fn slug(&self) -> &'static str {
        "projection"
    }
    fn title(&self) -> &'static str {
        "Projection: the pinhole camera"
    }
    fn views(&self) -> &'static [View] {
        VIEWS
    }
    fn start(&self, scene: Arc<Scene>, settings: &Settings) -> Result<Box<dyn Render>> {
        Ok(Box::new(ProjectionRender {
            scene,
            settings: settings.clone(),
            films: Vec::new(),
            stats: DrawStats::default(),
            seconds: 0.0,
        }))
    }
}

struct ProjectionRender {
    scene: Arc<Scene>,
    settings: Settings,
    films: Vec<Film>,
    stats: DrawStats,
    seconds: f64,
}

impl Render for ProjectionRender {
    fn pass(&mut self) -> bool {
        let start = Instant::now();
        let (films, stats) = draw_scene(
            &self.scene.camera,
            &self.scene.meshes,
            &self.scene.materials,
        );
        self.seconds = start.elapsed().as_secs_f64();
        self.films = films;
        self.stats = stats;
        true
    }

    fn progress(&self) -> (u32, u32) {
        (u32::from(!self.films.is_empty()), 1)
    }

    fn view(&self, index: usize) -> Film {
        crate::core::stage::view_of(&self.films, index, &self.scene.camera)
    }

    fn report(&self) -> Report {
        chapter_report(
            &self.scene,
            &self.settings,
            &self.stats,
            self.seconds,
            &self.films,
        )
    }
}

fn chapter_report(
    scene: &Scene,
    settings: &Settings,
    stats: &DrawStats,
    seconds: f64,
    films: &[Film],
) -> Report {
    let cam = &scene.camera;
    let d = &cam.desc;
    let vertices: usize = scene.meshes.iter().map(|m| m.positions.len()).sum();
    let edges: usize = scene.meshes.iter().map(|m| m.edges().len()).sum();
    let nonfinite = films.iter().map(|f| f.clone().scrub_nonfinite()).sum();
    let mut report = Report {
        title: format!("ch1 projection: {}", scene.name),
        facts: vec![
            ("scene".into(), scene.source.clone()),
            (
                "camera".into(),
                format!(
                    "eye {} target {} up {}, vertical fov {}°, {}x{} pixels",
                    fmt3(d.eye), fmt3(d.target), fmt3(d.up), d.fov_degrees, cam.width, cam.height
                ),
            ),
            (
                "drawn".into(),
                format!(
                    "{} meshes, {vertices} vertices, {edges} edges: {} whole, {} clipped at the near plane (z = -{NEAR}), {} behind the camera; {} vertices drawn, {} culled",
                    scene.meshes.len(), stats.edges_whole, stats.edges_clipped, stats.edges_culled,
                    stats.vertices_drawn, stats.vertices_culled
                ),
            ),
            ("render time".into(), crate::core::report::format_seconds(seconds)),
        ],
        nonfinite_caught: nonfinite,
        ..Report::default()
    };

    // What the scene led the stage to build and to leave out.
    report.built.push("look-at camera and viewport".into());
    report
        .built
        .push(format!("wireframes of {} meshes", scene.meshes.len()));
    report
        .left_out
        .push("shading: materials give edge colours only".into());
    report.left_out.push(match scene.lights.len() {
        0 => "lights: the scene has none".into(),
        1 => "1 light: projection needs no light".into(),
        n => format!("{n} lights: projection needs no light"),
    });
    report
        .left_out
        .push("depth buffer, BVH and sampling: one deterministic pass (--spp ignored)".into());
    if settings.spp != 1 {
        report.facts.push((
            "note".into(),
            format!("--spp {} has no effect in chapter 1", settings.spp),
        ));
    }

    report.tables.push(vertex_table(scene));
    report.tables.push(farther_is_smaller(cam));
    let vp = vanishing_points(cam, &scene.meshes);
    if !vp.is_empty() {
        let mut t = Table::new(
            "Parallel lines meet at infinity: vanishing points (pixels)",
            &[
                "world direction",
                "lines",
                "analytic",
                "where the drawn lines meet",
                "rms miss (px)",
            ],
        );
        for v in vp {
            t.row(vec![
                fmt3(v.direction.as_dvec3()),
                v.lines.to_string(),
                fmt2(v.analytic),
                v.measured
                    .map(fmt2)
                    .unwrap_or_else(|| "lines coincide".into()),
                v.measured
                    .map(|_| format_number(v.rms_miss as f64))
                    .unwrap_or_default(),
            ]);
        }
        report.tables.push(t);
    }
    if settings.studies {
        report.error_vs_time = Some(precision_study(cam));
        report.stability = stability_cases(cam);
    }
    report
}

fn fmt3(v: DVec3) -> String {
    format!(
        "({}, {}, {})",
        format_number(v.x),
        format_number(v.y),
        format_number(v.z)
    )
}

fn fmt2(v: Vec2) -> String {
    format!(
        "({}, {})",
        format_number(v.x as f64),
        format_number(v.y as f64)
    )
}

/// Every vertex of the small meshes (at most 8 vertices, like the lecture's
/// tetrahedron) through every step of the projection.
pub fn vertex_table(scene: &Scene) -> Table {
    let mut t = Table::new(
        "Projected vertices (meshes of at most 8 vertices)",
        &[
            "mesh",
            "vertex",
            "world (x, y, z)",
            "camera (x, y, z)",
            "image plane (u, v)",
            "pixel (x, y)",
        ],
    );
    for m in scene
        .meshes
        .iter()
        .filter(|m| m.positions.len() <= 8)
        .take(4)
    {
        for (i, p) in m.positions.iter().enumerate() {
            let c = scene.camera.to_camera(*p);
            let (uv, px) = match project_pinhole(c) {
                Some(uv) => (fmt2(uv), fmt2(scene.camera.raster_from_image_plane(uv))),
                None => ("behind the camera".into(), "-".into()),
            };
            t.row(vec![
                m.name.clone(),
                i.to_string(),
                fmt3(p.as_dvec3()),
                fmt3(c.as_dvec3()),
                uv,
                px,
            ]);
        }
    }
    if t.rows.is_empty() {
        t.title += ": none in this scene";
    }
    t
}

/// The image height of an upright stick 1 unit tall, straight ahead at
/// growing distances: it halves each time the distance doubles.
pub fn farther_is_smaller(cam: &Camera) -> Table {
    let mut t = Table::new(
        "Farther is smaller: a 1-unit upright stick straight ahead",
        &["distance", "height (px)", "height x distance"],
    );
    let d = &cam.desc;
    let forward = (d.target - d.eye).normalize();
    let up = forward.cross(d.up).cross(forward).normalize() * -1.0;
    for k in 0..6 {
        let dist = 2f64.powi(k);
        let centre = d.eye + forward * dist;
        let (a, b) = (
            cam.project((centre - up * 0.5).as_vec3()),
            cam.project((centre + up * 0.5).as_vec3()),
        );
        let h = match (a, b) {
            (Some(a), Some(b)) => a.distance(b) as f64,
            _ => f64::NAN,
        };
        t.row(vec![
            format_number(dist),
            format_number(h),
            format_number(h * dist),
        ]);
    }
    t
}

/// A family of parallel edges and where their images meet.
#[derive(Clone, Debug, PartialEq)]
pub struct VanishingPoint {
    /// Their common direction in world space.
    pub direction: Vec3,
    /// How many edges share it.
    pub lines: usize,
    /// Where the direction itself projects: the point at infinity's image.
    pub analytic: Vec2,
    /// The least-squares meeting point of the drawn edges, if they are not
    /// all one line.
    pub measured: Option<Vec2>,
    /// Root-mean-square distance of the drawn edges from `measured`.
    pub rms_miss: f32,
}

/// The vanishing points of the three largest families of parallel edges
/// that are not parallel to the image plane.
pub fn vanishing_points(cam: &Camera, meshes: &[Mesh]) -> Vec<VanishingPoint> {
    use std::collections::BTreeMap;
    // Quantised direction → (direction, the edges along it).
    type Family = (Vec3, Vec<(Vec3, Vec3)>);
    let mut families: BTreeMap<[i32; 3], Family> = BTreeMap::new();
    for m in meshes {
        for [i, j] in m.edges() {
            let (a, b) = (m.positions[i as usize], m.positions[j as usize]);
            let Some(mut dir) = (b - a).try_normalize() else {
                continue;
            };
            // One sign per direction: the first non-zero component positive.
            let first = dir
                .to_array()
                .into_iter()
                .find(|c| c.abs() > 1e-4)
                .unwrap_or(1.0);
            if first < 0.0 {
                dir = -dir;
            }
            let key = (dir * 1000.0).round().as_ivec3().to_array();
            families
                .entry(key)
                .or_insert((dir, Vec::new()))
                .1
                .push((a, b));
        }
    }
    let mut out: Vec<VanishingPoint> = families
        .into_values()
        .filter(|(_, edges)| edges.len() >= 3)
        .filter_map(|(direction, edges)| {
            let mut dc = cam.camera_from_world.transform_vector3(direction);
            if dc.z.abs() < 0.05 {
                return None; // parallel to the image plane: they meet nowhere
            }
            if dc.z > 0.0 {
                dc = -dc;
            }
            let analytic = cam.raster_from_image_plane(project_pinhole(dc)?);
            // Least squares: the point closest to every drawn line.
            let lines: Vec<(glam::DVec2, glam::DVec2)> = edges
                .iter()
                .filter_map(|(a, b)| {
                    let e = project_edge(cam, cam.to_camera(*a), cam.to_camera(*b))?;
                    let t = (e.b - e.a).as_dvec2().try_normalize()?;
                    Some((e.a.as_dvec2(), t.perp()))
                })
                .collect();
            let (mut a, mut rhs) = (glam::DMat2::ZERO, glam::DVec2::ZERO);
            for (p, n) in &lines {
                let nn = glam::DMat2::from_cols(*n * n.x, *n * n.y);
                a += nn;
                rhs += nn * *p;
            }
            let measured = (a.determinant().abs() > 1e-9 * a.col(0).length_squared().max(1.0))
                .then(|| a.inverse() * rhs);
            let rms_miss = measured
                .map(|x| {
                    let s: f64 = lines.iter().map(|(p, n)| n.dot(x - *p).powi(2)).sum();
                    (s / lines.len().max(1) as f64).sqrt() as f32
                })
                .unwrap_or(0.0);
            Some(VanishingPoint {
                direction,
                lines: edges.len(),
                analytic,
                measured: measured.map(|m| m.as_vec2()),
                rms_miss,
            })
        })
        .collect();
    out.sort_by_key(|v| std::cmp::Reverse(v.lines));
    out.truncate(3);
    out
}

/// Points straight ahead at camera-space depth `depth`, one through each
/// cell of a 32x32 grid of pixels, with the pixel positions they must land
/// on (exact, from the construction).
fn points_at_depth(cam: &Camera, depth: f64) -> Vec<(DVec3, glam::DVec2)> {
    let d = &cam.desc;
    let back = (d.eye - d.target).normalize();
    let right = d.up.cross(back).normalize();
    let up = back.cross(right);
    let t = (d.fov_degrees.to_radians() * 0.5).tan();
    let aspect = d.width as f64 / d.height as f64;
    let mut pts = Vec::with_capacity(1024);
    for j in 0..32 {
        for i in 0..32 {
            let raster = glam::DVec2::new(
                (i as f64 + 0.5) / 32.0 * d.width as f64,
                (j as f64 + 0.5) / 32.0 * d.height as f64,
            );
            let u = (raster.x / d.width as f64 * 2.0 - 1.0) * aspect * t;
            let v = (1.0 - raster.y / d.height as f64 * 2.0) * t;
            let world = d.eye + (right * u + up * v - back) * depth;
            pts.push((world, raster));
        }
    }
    pts
}

/// Requirement 1 for chapter 1: the f32 projection against the exact pixel
/// positions, for points from 1e-3 to 1e7 in front of the camera, with the
/// time per batch of 1024 points next to the f64 reference's.
pub fn precision_study(cam: &Camera) -> ErrorTime {
    let mut et = ErrorTime {
        reference: "exact pixel positions (points built in f64 to land on known pixels)".into(),
        error_name: "max error (px)".into(),
        rows: Vec::new(),
        show_slopes: false,
    };
    for k in -3..=7 {
        let depth = 10f64.powi(k);
        let pts = points_at_depth(cam, depth);
        let world32: Vec<Vec3> = pts.iter().map(|(w, _)| w.as_vec3()).collect();
        let time = |f: &dyn Fn() -> f64| {
            // Best of 5 runs of 20 batches: the least disturbed measurement.
            let mut best = f64::INFINITY;
            let mut err = 0.0;
            for _ in 0..5 {
                let t0 = Instant::now();
                for _ in 0..20 {
                    err = std::hint::black_box(f());
                }
                best = best.min(t0.elapsed().as_secs_f64() / 20.0);
            }
            (best, err)
        };
        let (s32, e32) = time(&|| {
            world32
                .iter()
                .zip(&pts)
                .map(|(w, (_, r))| match cam.project(*w) {
                    Some(p) => (p.as_dvec2() - *r).length(),
                    None => f64::INFINITY,
                })
                .fold(0.0, f64::max)
        });
        let (s64, e64) = time(&|| {
            pts.iter()
                .map(|(w, r)| match cam.project_f64(*w) {
                    Some(p) => (p - *r).length(),
                    None => f64::INFINITY,
                })
                .fold(0.0, f64::max)
        });
        let label = format!("depth 1e{k}");
        et.rows.push(Measurement {
            series: "f32 camera".into(),
            variant: label.clone(),
            seconds: s32,
            samples: pts.len() as u64,
            error: e32,
            notes: String::new(),
        });
        et.rows.push(Measurement {
            series: "f64 reference".into(),
            variant: label,
            seconds: s64,
            samples: pts.len() as u64,
            error: e64,
            notes: String::new(),
        });
    }
    et
}

/// Requirement 2 for chapter 1: the named stiff and extreme cases.
pub fn stability_cases(cam: &Camera) -> Vec<StabilityCase> {
    let mut cases = Vec::new();
    let mut case = |name: &str, expected: &str, measured: String, ok: bool| {
        cases.push(StabilityCase::new(name, expected, measured, ok))
    };
    let shown = |r: Option<Vec2>| r.map(fmt2).unwrap_or_else(|| "culled".into());

    let r = project_pinhole(Vec3::new(0.5, 0.5, 1.0));
    case(
        "point behind the camera (z = +1)",
        "culled",
        shown(r),
        r.is_none(),
    );
    let r = project_pinhole(Vec3::new(0.5, 0.5, 0.0));
    case(
        "point on the camera plane (z = 0)",
        "culled, no division by zero",
        shown(r),
        r.is_none(),
    );
    let r = project_pinhole(Vec3::new(1.0, 1.0, -1e-40));
    case(
        "point 1e-40 in front of the pinhole",
        "culled, no Inf",
        shown(r),
        r.is_none(),
    );
    let r = project_pinhole(Vec3::new(0.0, 0.0, -1e7));
    case(
        "point 1e7 away on the axis",
        "(0, 0)",
        shown(r),
        r == Some(Vec2::ZERO),
    );

    // Edges through the whole pipeline: clip, project, draw.
    let draw_edge = |a: Vec3, b: Vec3| {
        let mut film = Film::new(cam.width, cam.height);
        let e = project_edge(cam, a, b);
        let lit = e.map_or(0, |e| draw::line(&mut film, e.a, e.b, Vec3::ONE, Vec3::ONE));
        (e, lit, film)
    };
    let (a, b) = (Vec3::new(-0.2, -0.1, -2.0), Vec3::new(0.3, -0.1, 2.0));
    let (e, lit, mut film) = draw_edge(a, b);
    let front = cam.raster_from_image_plane(project_pinhole(a).unwrap_or_default());
    let front_lit = film.get(
        (front.x as u32).min(cam.width - 1),
        (front.y as u32).min(cam.height - 1),
    ) != Vec3::ZERO;
    let cut_depth = e.map_or(f32::NAN, |e| e.depth[1]);
    let nan = film.scrub_nonfinite();
    case(
        "edge crossing the camera plane",
        "cut at depth = near; the visible part drawn from its front end",
        format!(
            "cut at depth {cut_depth}, {lit} samples drawn, front end lit: {front_lit}, NaN: {nan}"
        ),
        cut_depth == NEAR && lit > 0 && front_lit && nan == 0,
    );
    let (_, lit, _) = draw_edge(Vec3::new(0.0, 0.0, 1.0), Vec3::new(1.0, 1.0, 3.0));
    case(
        "edge entirely behind the camera",
        "nothing drawn",
        format!("{lit} samples drawn"),
        lit == 0,
    );
    let (_, lit, _) = draw_edge(
        Vec3::new(f32::NAN, 0.0, -1.0),
        Vec3::new(0.0, f32::NAN, f32::NAN),
    );
    case(
        "edge with NaN ends",
        "nothing drawn",
        format!("{lit} samples drawn"),
        lit == 0,
    );

    // Extreme fields of view and far-off coordinates: the f32 camera against
    // exact pixel positions.
    let extreme = |fov: f64, eye: DVec3, depth: f64| -> (f64, bool) {
        let desc = crate::ch1_projection::camera::CameraDesc {
            fov_degrees: fov,
            eye,
            target: eye + DVec3::new(0.0, 0.0, -10.0),
            up: DVec3::Y,
            ..cam.desc
        };
        let Ok(c) = Camera::new(desc) else {
            return (f64::NAN, false);
        };
        let mut worst: f64 = 0.0;
        let mut finite = true;
        for (w, r) in points_at_depth(&c, depth) {
            match c.project(w.as_vec3()) {
                Some(p) if p.is_finite() => worst = worst.max((p.as_dvec2() - r).length()),
                _ => finite = false,
            }
        }
        (worst, finite)
    };
    for fov in [0.01, 179.99] {
        let (e, fin) = extreme(fov, DVec3::ZERO, 10.0);
        case(
            &format!("fov {fov}°"),
            "finite, within 0.5 px",
            format!("max error {} px", format_number(e)),
            fin && e < 0.5,
        );
    }
    let (e, fin) = extreme(cam.desc.fov_degrees, DVec3::splat(1e7), 10.0);
    case(
        "camera and points at coordinates 1e7",
        "finite; f32 spacing there is 1.0, so large error is expected and reported",
        format!("max error {} px", format_number(e)),
        fin,
    );
    cases
}
