//! Watertightness and precision of the three ray-triangle tests: how many
//! rays aimed exactly at edges and vertices of a closed mesh slip through
//! (leak), how precise the distance t is far from the origin, and how often
//! a ray spawned from a surface hits that surface again.

use std::collections::HashMap;

use glam::{DVec3, Mat4, Vec3};

use crate::ch3_ray_triangle::obvhs_bvh::{Bvh, Triangles};
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::spawn::spawn_ray;
use crate::ch3_ray_triangle::triangle::{intersect_f64, Intersector};
use crate::core::format::format_number;
use crate::core::report::Table;
use crate::core::sampling::random;
use crate::scene::mesh::Mesh;

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
    // ANCHOR: leak_fold
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
    // ANCHOR_END: leak_fold
    let mut leaks = [0u64; 3];
    let (mut tested, mut attempt) = (0u64, 0u64);
    while tested < rays && attempt < rays * 8 {
        let r = attempt;
        attempt += 1;
        let rnd = |d: u64| random(seed, r, 0, d);
        // ANCHOR: leak_aim
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
        // ANCHOR_END: leak_aim
        // ANCHOR: leak_count
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
        // ANCHOR_END: leak_count
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
