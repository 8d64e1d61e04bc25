//! Chapter 3's studies: error against run time (anti-aliasing, naive loop
//! against BVH), the leak counts of the three ray-triangle tests on closed
//! meshes, the precision of t, and the stiff and extreme cases.

use std::collections::HashMap;
use std::time::Instant;

use glam::{DVec3, Mat4, Vec3};

use crate::ch1_projection::camera::{Camera, CameraDesc};
use crate::ch3_ray_triangle::bvh::{closest_naive, Bvh, Triangles};
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::spawn::spawn_ray;
use crate::ch3_ray_triangle::stage::{render_views, render_views_naive, Geometry};
use crate::ch3_ray_triangle::triangle::{intersect_f64, Intersector};
use crate::core::report::{
    format_number, format_seconds, ErrorTime, Measurement, Report, StabilityCase, Table,
};
use crate::core::sampling::random;
use crate::core::stage::Settings;
use crate::scene::mesh::Mesh;
use crate::scene::Scene;

/// How big the studies are: the report runs them in full, tests shrink them.
#[derive(Clone, Debug, PartialEq)]
pub struct StudySize {
    /// Rays aimed at edges and vertices per mesh in the leak test.
    pub leak_rays: u64,
    /// Triangle counts of the naive-vs-BVH comparison.
    pub triangle_counts: Vec<usize>,
    /// Largest rays x triangles the naive loop is allowed (else skipped).
    pub naive_budget: f64,
    /// Samples per pixel of the anti-aliasing series.
    pub spp: Vec<u32>,
    /// Samples per pixel of its reference.
    pub reference_spp: u32,
    /// Secondary rays per distance in the self-intersection test.
    pub spawn_rays: u64,
}

impl StudySize {
    /// The size the report uses.
    pub fn full() -> StudySize {
        StudySize {
            leak_rays: 1_000_000,
            triangle_counts: vec![10, 1_000, 100_000, 1_000_000],
            naive_budget: 5e8,
            spp: vec![1, 2, 4, 8, 16, 32, 64],
            reference_spp: 256,
            spawn_rays: 100_000,
        }
    }

    /// A size quick enough for debug-build tests.
    pub fn quick() -> StudySize {
        StudySize {
            leak_rays: 100_000,
            triangle_counts: vec![10, 1_000],
            naive_budget: 1e7,
            spp: vec![1, 4, 16],
            reference_spp: 64,
            spawn_rays: 10_000,
        }
    }
}

/// Adds every study to `report` (full size).
pub fn add_studies(report: &mut Report, scene: &Scene, settings: &Settings) {
    add_studies_sized(report, scene, settings, &StudySize::full());
}

/// Adds every study to `report`, at the given size.
pub fn add_studies_sized(
    report: &mut Report,
    scene: &Scene,
    settings: &Settings,
    size: &StudySize,
) {
    let mut et = anti_aliasing_study(scene, &size.spp, size.reference_spp, settings.seed);
    let (table, rows) = naive_vs_bvh(&size.triangle_counts, size.naive_budget);
    et.rows.extend(rows);
    report.error_vs_time = Some(et);
    report.tables.push(table);
    let leaks = leak_table(size.leak_rays, settings.seed);
    report.tables.push(leaks.0);
    report.tables.push(t_precision_table());
    report.tables.push(intersector_speed(200_000));
    report.stability = stability_cases(size, &leaks.1);
    report.stability.push(agreement_case(scene));
}

/// The stiff case "primary visibility agrees with chapter 2's raster
/// image on this scene": only edge pixels may differ.
pub fn agreement_case(scene: &Scene) -> StabilityCase {
    let geometry = Geometry::new(scene);
    let measured = crate::ch3_ray_triangle::agreement::raster_agreement(scene, &geometry);
    let (measured, ok) = match measured {
        Ok(a) => (
            format!(
                "{} of {} pixels differ ({:.2}%), {} of them off edges",
                a.differ,
                a.pixels,
                100.0 * a.differ as f64 / a.pixels.max(1) as f64,
                a.differ_off_edges
            ),
            a.differ_off_edges == 0,
        ),
        Err(e) => (
            format!("chapter 2 could not rasterize the scene: {e}"),
            false,
        ),
    };
    StabilityCase::new(
        "first hits against chapter 2's raster image (pixel centres)",
        "the same triangle everywhere but on edges",
        measured,
        ok,
    )
}

/// A wavy height field over [-1, 1]² facing +z with exactly `n` triangles
/// (`n` rounded up to even): the procedural mesh of the speed studies.
pub fn procedural_mesh(n: usize) -> Mesh {
    let quads = n.div_ceil(2).max(1);
    // The most square grid rows x cols = quads.
    let rows = (1..=quads)
        .take_while(|r| r * r <= quads)
        .filter(|r| quads.is_multiple_of(*r))
        .last()
        .unwrap_or(1);
    let cols = quads / rows;
    let mut positions = Vec::with_capacity((rows + 1) * (cols + 1));
    for j in 0..=rows {
        for i in 0..=cols {
            let x = i as f32 / cols as f32 * 2.0 - 1.0;
            let y = j as f32 / rows as f32 * 2.0 - 1.0;
            let z = 0.15 * (3.0 * x).sin() * (2.0 * y).cos();
            positions.push(Vec3::new(x, y, z));
        }
    }
    let mut triangles = Vec::with_capacity(quads * 2);
    let at = |i: usize, j: usize| (j * (cols + 1) + i) as u32;
    for j in 0..rows {
        for i in 0..cols {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    Mesh::new("wavy grid", positions, triangles)
}

/// The camera the speed studies look at [`procedural_mesh`] with.
pub fn procedural_camera(width: u32, height: u32) -> Camera {
    Camera::new(CameraDesc {
        eye: DVec3::new(0.0, -1.2, 2.2),
        target: DVec3::ZERO,
        up: DVec3::Y,
        fov_degrees: 50.0,
        width,
        height,
    })
    .expect("a valid camera")
}

/// A scene holding one mesh, seen by `camera`.
pub fn scene_of(mesh: Mesh, camera: Camera) -> Scene {
    let mut scene = Scene::builtin();
    scene.name = mesh.name.clone();
    scene.source = "<procedural>".into();
    scene.camera = camera;
    scene.meshes = vec![mesh];
    scene.lights.clear();
    scene
}

/// Anti-aliasing: the depth view at 1..64 samples per pixel against a
/// high-sample reference of the same image (another seed).
pub fn anti_aliasing_study(scene: &Scene, spp: &[u32], reference_spp: u32, seed: u64) -> ErrorTime {
    let geometry = Geometry::new(scene);
    let reference = &render_views(&scene.camera, &geometry, reference_spp, seed ^ 0x5eed)[0];
    let mut et = ErrorTime {
        reference: format!("the depth view at {reference_spp} spp, another seed"),
        error_name: "RMSE".into(),
        rows: Vec::new(),
        show_slopes: true,
    };
    for &n in spp {
        let t0 = Instant::now();
        let films = render_views(&scene.camera, &geometry, n, seed);
        let seconds = t0.elapsed().as_secs_f64();
        et.rows.push(Measurement {
            series: "anti-aliasing (BVH)".into(),
            variant: format!("{n} spp"),
            seconds,
            samples: n as u64 * films[0].pixels.len() as u64,
            error: films[0].rmse(reference),
            notes: String::new(),
        });
    }
    et
}

/// Naive loop against BVH on [`procedural_mesh`]es: time for the same
/// 64x48 depth image, and whether the two images are identical. The naive
/// loop is skipped when rays x triangles exceeds `naive_budget`.
pub fn naive_vs_bvh(counts: &[usize], naive_budget: f64) -> (Table, Vec<Measurement>) {
    let camera = procedural_camera(64, 48);
    let rays = (camera.width * camera.height) as f64;
    let mut t = Table::new(
        "Naive loop against BVH (64x48 depth image of a wavy grid, 1 spp)",
        &[
            "triangles",
            "naive",
            "BVH build",
            "BVH trace",
            "BVH total",
            "speed-up",
            "same image",
        ],
    );
    let mut rows = Vec::new();
    let mut crossover = None;
    for &n in counts {
        let scene = scene_of(procedural_mesh(n), camera.clone());
        let geometry = Geometry::new(&scene);
        let build = geometry.bvh.as_ref().map_or(0.0, |b| b.build_seconds);
        let t0 = Instant::now();
        let bvh_films = render_views(&camera, &geometry, 1, 0);
        let trace = t0.elapsed().as_secs_f64();
        let tris = geometry.triangles.tris.len();
        let naive = (rays * tris as f64 <= naive_budget).then(|| {
            let t0 = Instant::now();
            let films = render_views_naive(&camera, &geometry, 1, 0);
            (t0.elapsed().as_secs_f64(), films)
        });
        let (naive_cell, speedup, same) = match &naive {
            Some((s, films)) => {
                if crossover.is_none() && build + trace < *s {
                    crossover = Some(tris);
                }
                rows.push(Measurement {
                    series: "naive loop".into(),
                    variant: format!("{tris} triangles"),
                    seconds: *s,
                    samples: rays as u64,
                    error: films[0].rmse(&bvh_films[0]),
                    notes: "error: RMSE against the BVH image".into(),
                });
                (
                    format_seconds(*s),
                    format!("{}x", format_number(s / trace.max(1e-9))),
                    if films == &bvh_films { "yes" } else { "NO" }.to_string(),
                )
            }
            None => (
                format!("skipped (~{} tests)", format_number(rays * tris as f64)),
                "-".into(),
                "-".into(),
            ),
        };
        rows.push(Measurement {
            series: "BVH".into(),
            variant: format!("{tris} triangles"),
            seconds: trace,
            samples: rays as u64,
            error: 0.0,
            notes: format!("build {}", format_seconds(build)),
        });
        t.row(vec![
            tris.to_string(),
            naive_cell,
            format_seconds(build),
            format_seconds(trace),
            format_seconds(build + trace),
            speedup,
            same,
        ]);
    }
    t.title += &match crossover {
        Some(n) => format!("; the BVH (build included) pays off from {n} triangles"),
        None => "; the BVH did not pay off at these sizes".into(),
    };
    (t, rows)
}

/// Leaks of one intersector on one mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct LeakCount {
    /// The mesh.
    pub mesh: String,
    /// The test.
    pub intersector: Intersector,
    /// Rays aimed at edges and vertices.
    pub rays: u64,
    /// Rays that none of the triangles around their target hit.
    pub leaks: u64,
}

/// The Stanford bunny of `scenes/meshes/bunny.obj` (compiled in).
pub fn bunny() -> Mesh {
    crate::scene::obj::parse_obj(include_str!("../../scenes/meshes/bunny.obj"), "bunny.obj")
        .expect("the bundled bunny parses")
}

/// Aims `rays` rays from near the mesh's centre at its vertices and at
/// points on its edges, and counts for each test the rays that hit none of
/// the triangles around the target. A watertight test never leaks.
// ANCHOR: leak_test
pub fn leak_test(mesh: &Mesh, rays: u64, seed: u64) -> Vec<LeakCount> {
    // Weld vertices by exact position: OBJ files may repeat a vertex, and a
    // neighbour across an edge must count as a neighbour.
    let mut first: HashMap<[u32; 3], u32> = HashMap::new();
    let weld: Vec<u32> = (0..mesh.positions.len())
        .map(|i| {
            let key = mesh.positions[i].to_array().map(f32::to_bits);
            *first.entry(key).or_insert(i as u32)
        })
        .collect();
    let mut by_vertex: HashMap<u32, Vec<u32>> = HashMap::new();
    let mut by_edge: HashMap<[u32; 2], Vec<u32>> = HashMap::new();
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let tri = tri.map(|i| weld[i as usize]);
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            by_vertex.entry(a).or_default().push(t as u32);
            by_edge
                .entry([a.min(b), a.max(b)])
                .or_default()
                .push(t as u32);
        }
    }
    // Aim only where the surface is closed: edges shared by two triangles,
    // and vertices all of whose edges are such edges.
    let mut edges: Vec<[u32; 2]> = by_edge
        .iter()
        .filter(|(_, t)| t.len() == 2)
        .map(|(e, _)| *e)
        .collect();
    edges.sort_unstable();
    let mut open: Vec<u32> = by_edge
        .iter()
        .filter(|(_, t)| t.len() != 2)
        .flat_map(|(e, _)| *e)
        .collect();
    open.sort_unstable();
    let mut vertices: Vec<u32> = by_vertex
        .keys()
        .copied()
        .filter(|v| open.binary_search(v).is_err())
        .collect();
    vertices.sort_unstable();
    if edges.is_empty() || vertices.is_empty() {
        return Vec::new();
    }
    let centre = mesh.positions.iter().sum::<Vec3>() / mesh.positions.len().max(1) as f32;
    let tri = |t: u32| mesh.triangles[t as usize].map(|i| mesh.positions[i as usize]);
    // Seen from `o`, is the surface folded at edge (a, b), i.e. do its two
    // triangles lie on the same side of the plane through o, a and b? Then a
    // ray grazing the edge may rightly miss both: such targets are skipped.
    let third = |t: u32, e: [u32; 2]| {
        let w = mesh.triangles[t as usize]
            .iter()
            .map(|&i| weld[i as usize])
            .find(|i| !e.contains(i))
            .unwrap_or(e[0]);
        mesh.positions[w as usize].as_dvec3()
    };
    let folded = |o: Vec3, e: [u32; 2]| {
        let o = o.as_dvec3();
        let (a, b) = (
            mesh.positions[e[0] as usize].as_dvec3() - o,
            mesh.positions[e[1] as usize].as_dvec3() - o,
        );
        let n = a.cross(b);
        let t = &by_edge[&e];
        // Sine of the angle between each triangle and the plane (o, a, b);
        // within 1e-5 of grazing counts as folded, since the f32 ray itself
        // is only that close to the exact line from o through the target.
        let side = |c: DVec3| n.dot(c - o) / (n.length() * (c - o).length()).max(1e-300);
        let (s0, s1) = (side(third(t[0], e)), side(third(t[1], e)));
        s0 * s1 >= 0.0 || s0.abs() < 1e-5 || s1.abs() < 1e-5
    };
    let mut leaks = [0u64; 3];
    let (mut tested, mut attempt) = (0u64, 0u64);
    while tested < rays && attempt < rays * 8 {
        let r = attempt;
        attempt += 1;
        let rnd = |d: u64| random(seed, r, 0, d);
        // Start near the centre, jittered so no two rays are alike.
        let jitter = Vec3::new(rnd(0), rnd(1), rnd(2)) - 0.5;
        let origin = centre + jitter * 0.02;
        // Even rays at a vertex, odd ones at a point on an edge.
        let (target, around, fold) = if r % 2 == 0 {
            let k = ((rnd(3) as f64 * vertices.len() as f64) as usize).min(vertices.len() - 1);
            let v = vertices[k];
            let around = &by_vertex[&v];
            let fold = around.iter().any(|&t| {
                let tri = mesh.triangles[t as usize].map(|i| weld[i as usize]);
                (0..3).any(|k| {
                    let (a, b) = (tri[k], tri[(k + 1) % 3]);
                    (a == v || b == v) && folded(origin, [a.min(b), a.max(b)])
                })
            });
            (mesh.positions[v as usize], around, fold)
        } else {
            let e = edges[((rnd(3) as f64 * edges.len() as f64) as usize).min(edges.len() - 1)];
            let (a, b) = (mesh.positions[e[0] as usize], mesh.positions[e[1] as usize]);
            // Keep 1% away from the ends: a point rounded past an end is
            // no longer on this edge (vertices get their own rays).
            (
                a.lerp(b, 0.01 + 0.98 * rnd(4)),
                &by_edge[&e],
                folded(origin, e),
            )
        };
        if fold {
            continue;
        }
        let Ok(ray) = Ray::new(origin, target - origin) else {
            continue;
        };
        tested += 1;
        for (k, x) in Intersector::ALL.iter().enumerate() {
            let hit = around
                .iter()
                .any(|&t| x.intersect(&ray, tri(t), 0.0, f32::INFINITY).is_some());
            leaks[k] += u64::from(!hit);
        }
    }
    let rays = tested;
    Intersector::ALL
        .iter()
        .zip(leaks)
        .map(|(x, leaks)| LeakCount {
            mesh: mesh.name.clone(),
            intersector: *x,
            rays,
            leaks,
        })
        .collect()
}
// ANCHOR_END: leak_test

/// Rays from inside a closed mesh that the BVH (watertight test) lets out:
/// every one must hit something.
pub fn bvh_escapes(mesh: &Mesh, rays: u64, seed: u64) -> u64 {
    let tris = Triangles::from_meshes(std::slice::from_ref(mesh));
    let Some(bvh) = Bvh::build(&tris.tris) else {
        return rays;
    };
    let edges = mesh.edges();
    (0..rays)
        .filter(|&r| {
            let rnd = |d: u64| random(seed, r, 1, d);
            let origin = (Vec3::new(rnd(0), rnd(1), rnd(2)) - 0.5) * 0.02;
            let e = edges[((rnd(3) as f64 * edges.len() as f64) as usize).min(edges.len() - 1)];
            let (a, b) = (mesh.positions[e[0] as usize], mesh.positions[e[1] as usize]);
            let target = if r % 2 == 0 { a } else { a.lerp(b, rnd(4)) };
            Ray::new(origin, target - origin)
                .map(|ray| {
                    bvh.closest(&ray, f32::INFINITY, Intersector::Watertight)
                        .is_none()
                })
                .unwrap_or(false)
        })
        .count() as u64
}

/// The leak table: the three tests on an icosphere and on the bunny.
pub fn leak_table(rays: u64, seed: u64) -> (Table, Vec<LeakCount>) {
    let mut t = Table::new(
        "Leaks: rays from inside aimed exactly at vertices and edges of a closed mesh",
        &["mesh", "triangles", "test", "rays", "leaks"],
    );
    let mut all = Vec::new();
    for mesh in [Mesh::icosphere(4), bunny()] {
        for c in leak_test(&mesh, rays, seed) {
            t.row(vec![
                mesh.name.clone(),
                mesh.triangles.len().to_string(),
                c.intersector.name().into(),
                c.rays.to_string(),
                c.leaks.to_string(),
            ]);
            all.push(c);
        }
    }
    (t, all)
}

/// The relative error of t in f32 against the f64 solution, for rays from
/// the origin to triangles of size D/10 at distance D.
pub fn t_relative_error(distance: f64, rays: u64, x: Intersector) -> (f64, u64) {
    let mut worst: f64 = 0.0;
    let mut misses = 0;
    for r in 0..rays {
        let rnd = |d: u64| random(7, r, distance.to_bits(), d) as f64;
        // A triangle around the point at distance D in a random direction.
        let dir = DVec3::new(rnd(0) - 0.5, rnd(1) - 0.5, -1.0).normalize();
        let centre = dir * distance;
        let s = distance * 0.1;
        let tri64 = [
            centre + DVec3::new(-s, -s, rnd(2) * s),
            centre + DVec3::new(s, -s, 0.0),
            centre + DVec3::new(0.0, s, -rnd(3) * s),
        ];
        let tri32 = tri64.map(|p| p.as_vec3());
        // The ray aims at a point inside; the reference uses the same f32
        // inputs, so only the arithmetic differs.
        let aim = (tri32[0] + tri32[1] + tri32[2]) / 3.0;
        let Ok(ray) = Ray::new(Vec3::ZERO, aim) else {
            continue;
        };
        let reference = intersect_f64(
            ray.origin.as_dvec3(),
            ray.dir.as_dvec3(),
            tri32.map(|p| p.as_dvec3()),
        );
        match (x.intersect(&ray, tri32, 0.0, f32::INFINITY), reference) {
            (Some(h), Some((t, _, _))) => worst = worst.max((h.t as f64 - t).abs() / t),
            _ => misses += 1,
        }
    }
    (worst, misses)
}

/// The table of t's relative error across distances.
pub fn t_precision_table() -> Table {
    let mut t = Table::new(
        "Relative error of t in f32 against f64 (rays from the origin, triangles of size D/10 at distance D)",
        &["distance D", "plane + inside", "Möller–Trumbore", "watertight"],
    );
    for k in 0..=7 {
        let d = 10f64.powi(k);
        let mut row = vec![format!("1e{k}")];
        for x in Intersector::ALL {
            let (e, misses) = t_relative_error(d, 1000, x);
            row.push(if misses == 0 {
                format_number(e)
            } else {
                format!("{} ({misses} missed)", format_number(e))
            });
        }
        t.row(row);
    }
    t
}

/// Secondary rays leaving hit points on an icosphere placed `distance`
/// from the origin, into the outside hemisphere: how many hit the sphere
/// again, with the origin offset by [`spawn_ray`] and with a fixed ε.
pub fn self_intersections(distance: f32, rays: u64, fixed_epsilon: f32) -> (u64, u64) {
    let mut mesh = Mesh::icosphere(3);
    mesh.transform(&Mat4::from_translation(Vec3::splat(distance)));
    let tris = Triangles::from_meshes(std::slice::from_ref(&mesh));
    let bvh = Bvh::build(&tris.tris).expect("a sphere has triangles");
    let centre = Vec3::splat(distance);
    let (mut scaled, mut fixed) = (0, 0);
    for r in 0..rays {
        let rnd = |d: u64| random(11, r, 0, d);
        // A primary ray from outside towards a random point of the sphere.
        let aim = Vec3::new(rnd(0), rnd(1), rnd(2)) * 2.0 - 1.0;
        let from = centre + aim.normalize_or(Vec3::Z) * 4.0;
        let Ok(primary) = Ray::new(from, centre + aim * 0.3 - from) else {
            continue;
        };
        let Some(hit) = bvh.closest(&primary, f32::INFINITY, Intersector::Watertight) else {
            continue;
        };
        let tri = tris.tris[hit.triangle as usize];
        let p = hit.point(tri);
        let n = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize();
        // A direction in the outer hemisphere, down to grazing angles.
        let w = Vec3::new(rnd(3), rnd(4), rnd(5)) * 2.0 - 1.0;
        let dir = if w.dot(n) < 0.0 {
            w - 2.0 * w.dot(n) * n
        } else {
            w
        };
        if let Some(ray) = spawn_ray(p, n, dir) {
            scaled += u64::from(bvh.occluded(&ray, f32::INFINITY, Intersector::Watertight));
        }
        if let Ok(ray) = Ray::new(p + n * fixed_epsilon, dir) {
            fixed += u64::from(bvh.occluded(&ray, f32::INFINITY, Intersector::Watertight));
        }
    }
    (scaled, fixed)
}

/// Requirement 2 for chapter 3: the named stiff and extreme cases.
pub fn stability_cases(size: &StudySize, leaks: &[LeakCount]) -> Vec<StabilityCase> {
    let mut cases = Vec::new();
    let mut case = |name: &str, expected: &str, measured: String, ok: bool| {
        cases.push(StabilityCase::new(name, expected, measured, ok))
    };
    let all = |ray: &Ray, tri: [Vec3; 3]| {
        Intersector::ALL.map(|x| x.intersect(ray, tri, 0.0, f32::INFINITY))
    };
    let shown = |h: &[Option<crate::ch3_ray_triangle::triangle::Hit>; 3]| {
        h.iter()
            .map(|h| match h {
                Some(h) => format!("t = {}", format_number(h.t as f64)),
                None => "miss".into(),
            })
            .collect::<Vec<_>>()
            .join(" / ")
    };
    let finite = |h: &[Option<crate::ch3_ray_triangle::triangle::Hit>; 3]| {
        h.iter()
            .flatten()
            .all(|h| h.t.is_finite() && h.u.is_finite() && h.v.is_finite())
    };
    let unit = [
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
    ];

    // Rays parallel to the triangle's plane: in it, and above it.
    for (name, origin) in [
        (
            "ray parallel to the triangle, in its plane",
            Vec3::new(-5.0, 0.0, 0.0),
        ),
        (
            "ray parallel to the triangle, above it",
            Vec3::new(-5.0, 0.0, 1e-3),
        ),
    ] {
        let h = all(&Ray::new(origin, Vec3::X).expect("valid"), unit);
        case(
            name,
            "miss with all three tests, no NaN",
            shown(&h),
            h.iter().all(Option::is_none),
        );
    }

    // Leaks.
    for mesh in ["sphere", "bunny.obj"] {
        let of = |x: Intersector| leaks.iter().find(|c| c.mesh == mesh && c.intersector == x);
        if let (Some(w), Some(p), Some(m)) = (
            of(Intersector::Watertight),
            of(Intersector::PlaneInside),
            of(Intersector::MollerTrumbore),
        ) {
            case(
                &format!(
                    "{} rays at edges and vertices of the {mesh} from inside",
                    w.rays
                ),
                "0 leaks with the watertight test (the others are reported)",
                format!(
                    "watertight {}, plane + inside {}, Möller–Trumbore {}",
                    w.leaks, p.leaks, m.leaks
                ),
                w.leaks == 0,
            );
        }
    }
    let n = (size.leak_rays / 10).max(1000);
    let escapes = bvh_escapes(&Mesh::icosphere(4), n, 3);
    case(
        &format!("{n} rays from inside the icosphere through the BVH"),
        "every ray hits the sphere",
        format!("{escapes} escaped"),
        escapes == 0,
    );

    // Far from the origin: camera and triangle both at coordinates D.
    for k in [5, 6, 7] {
        let d = 10f32.powi(k);
        let base = Vec3::splat(d);
        let tri = unit.map(|p| base + p * 10.0 + Vec3::new(0.0, 0.0, -10.0));
        let ray = Ray::new(base, Vec3::new(0.05, 0.1, -1.0)).expect("valid");
        let h = all(&ray, tri);
        let reference = intersect_f64(
            ray.origin.as_dvec3(),
            ray.dir.as_dvec3(),
            tri.map(|p| p.as_dvec3()),
        );
        let err = match (h[2], reference) {
            (Some(h), Some((t, _, _))) => (h.t as f64 - t).abs() / t,
            _ => f64::INFINITY,
        };
        case(
            &format!("ray and triangle at coordinates 1e{k}"),
            "all three hit; watertight t within 1e-5 relative of f64",
            format!(
                "{}; watertight rel. error {}",
                shown(&h),
                format_number(err)
            ),
            h.iter().all(Option::is_some) && finite(&h) && err < 1e-5,
        );
    }

    // A tiny triangle, edge 1e-6, 1 unit away.
    let tiny = unit.map(|p| p * 0.5e-6 + Vec3::new(0.3, 0.2, -1.0));
    let aim = (tiny[0] + tiny[1] + tiny[2]) / 3.0;
    let h = all(&Ray::new(Vec3::ZERO, aim).expect("valid"), tiny);
    let u_ok = h.iter().flatten().all(|h| (h.u - 1.0 / 3.0).abs() < 0.05);
    case(
        "tiny triangle (edge 1e-6) hit at its centroid",
        "all three hit, u and v near 1/3",
        shown(&h),
        h.iter().all(Option::is_some) && finite(&h) && u_ok,
    );

    // Degenerate triangles: no area, many rays.
    let degenerate = [
        [Vec3::ZERO, Vec3::X, Vec3::X * 2.0],
        [Vec3::ONE, Vec3::ONE, Vec3::new(1.0, 2.0, 1.0)],
        [Vec3::splat(0.5); 3],
    ];
    let mut hits = 0;
    let mut nan = 0;
    for (i, tri) in degenerate.iter().enumerate() {
        for r in 0..1000u64 {
            let rnd = |d: u64| random(5, r, i as u64, d);
            let target = tri[0].lerp(tri[2], rnd(0)) + (tri[1] - tri[0]) * rnd(1);
            let origin = Vec3::new(rnd(2), rnd(3), rnd(4)) * 4.0 - 2.0;
            if let Ok(ray) = Ray::new(origin, target - origin) {
                let h = all(&ray, *tri);
                hits += h.iter().flatten().count();
                nan += usize::from(!finite(&h));
            }
        }
    }
    case(
        "degenerate triangles (collinear, repeated vertices, a point), 3000 rays",
        "no hit, no NaN",
        format!("{hits} hits, {nan} NaN"),
        hits == 0 && nan == 0,
    );

    // Grazing rays: angle θ to the plane, hitting inside at t = 3.
    let big = unit.map(|p| p * 10.0);
    let mut worst: f64 = 0.0;
    let mut missed = 0;
    for k in 1..=5 {
        let theta = 10f64.powi(-k);
        let o = DVec3::new(0.0, 0.0, 3.0 * theta.sin());
        let d = DVec3::new(theta.cos(), 0.0, -theta.sin());
        let ray = Ray::new(o.as_vec3(), d.as_vec3()).expect("valid");
        let reference = intersect_f64(
            ray.origin.as_dvec3(),
            ray.dir.as_dvec3(),
            big.map(|p| p.as_dvec3()),
        );
        for h in all(&ray, big) {
            match (h, reference) {
                (Some(h), Some((t, _, _))) => worst = worst.max((h.t as f64 - t).abs() / t),
                _ => missed += 1,
            }
        }
    }
    case(
        "grazing rays, 1e-1 to 1e-5 rad to the plane",
        "all hit; t within 1e-4 relative of f64",
        format!("{missed} missed, worst rel. error {}", format_number(worst)),
        missed == 0 && worst < 1e-4,
    );

    // Bad directions are refused where the ray is built.
    let zero = Ray::new(Vec3::ZERO, Vec3::ZERO);
    let nan_dir = Ray::new(Vec3::ZERO, Vec3::new(f32::NAN, 1.0, 0.0));
    case(
        "ray with a zero or NaN direction",
        "refused by Ray::new with an error",
        format!(
            "zero: {}; NaN: {}",
            zero.err().map_or("accepted".into(), |e| e.to_string()),
            nan_dir.err().map_or("accepted".into(), |e| e.to_string())
        ),
        Ray::new(Vec3::ZERO, Vec3::ZERO).is_err() && Ray::new(Vec3::ZERO, Vec3::NAN).is_err(),
    );

    // Self-intersection far from the origin.
    for d in [1e5f32, 1e6] {
        let (scaled, fixed) = self_intersections(d, size.spawn_rays, 1e-4);
        case(
            &format!(
                "{} secondary rays leaving a sphere at 1e{}",
                size.spawn_rays,
                d.log10()
            ),
            "0 self-hits with the scaled offset (a fixed ε = 1e-4 is reported)",
            format!("scaled offset: {scaled}; fixed ε: {fixed}"),
            scaled == 0,
        );
    }

    // Precision of t across distances.
    let worst = (0..=7)
        .map(|k| t_relative_error(10f64.powi(k), 200, Intersector::Watertight))
        .fold((0.0f64, 0u64), |a, b| (a.0.max(b.0), a.1 + b.1));
    case(
        "relative error of t, distances 1 to 1e7 (watertight)",
        "below 1e-5 at every distance, no miss",
        format!("worst {}, {} missed", format_number(worst.0), worst.1),
        worst.0 < 1e-5 && worst.1 == 0,
    );
    cases
}

/// Closest hits of the naive loop for a batch of rays (used by tests).
pub fn naive_hits(
    tris: &[[Vec3; 3]],
    rays: &[Ray],
    x: Intersector,
) -> Vec<Option<crate::ch3_ray_triangle::triangle::Hit>> {
    rays.iter()
        .map(|r| closest_naive(tris, r, f32::INFINITY, x))
        .collect()
}

/// The three tests side by side on `n` random ray-triangle pairs (about
/// half of them hits): time per test (best of 3) and how often each agrees
/// with the f64 solution of the 3x3 system on hit or miss.
pub fn intersector_speed(n: u64) -> Table {
    let pairs: Vec<(Ray, [Vec3; 3])> = (0..n)
        .filter_map(|i| {
            let r = |d| random(21, i, 0, d);
            let tri = [
                Vec3::new(r(0), r(1), r(2)) * 2.0 - 1.0,
                Vec3::new(r(3), r(4), r(5)) * 2.0 - 1.0,
                Vec3::new(r(6), r(7), r(8)) * 2.0 - 1.0,
            ];
            let origin = Vec3::new(r(9), r(10), r(11)) * 8.0 - 4.0;
            let target = Vec3::new(r(12), r(13), r(14)) - 0.5;
            Ray::new(origin, target - origin).ok().map(|ray| (ray, tri))
        })
        .collect();
    let reference: Vec<bool> = pairs
        .iter()
        .map(|(ray, tri)| {
            intersect_f64(
                ray.origin.as_dvec3(),
                ray.dir.as_dvec3(),
                tri.map(|p| p.as_dvec3()),
            )
            .is_some()
        })
        .collect();
    let mut t = Table::new(
        &format!(
            "The three ray-triangle tests on {} random rays (one thread)",
            pairs.len()
        ),
        &["test", "ns per test", "hits", "agree with f64 on hit/miss"],
    );
    for x in Intersector::ALL {
        let mut best = f64::INFINITY;
        let mut hits = Vec::new();
        for _ in 0..3 {
            let t0 = Instant::now();
            hits = pairs
                .iter()
                .map(|(ray, tri)| x.intersect(ray, *tri, 0.0, f32::INFINITY).is_some())
                .collect();
            best = best.min(t0.elapsed().as_secs_f64());
        }
        let agree = hits.iter().zip(&reference).filter(|(a, b)| a == b).count();
        t.row(vec![
            x.name().into(),
            format_number(best / pairs.len().max(1) as f64 * 1e9),
            hits.iter().filter(|h| **h).count().to_string(),
            format!("{agree} of {}", pairs.len()),
        ]);
    }
    t
}
