//! The fast engine's eight-wide tree on rays that pass exactly through
//! shared edges and vertices: there the triangle test hands lanes to the
//! one-triangle test, and every SIMD path must find the same hit, bit for
//! bit, as the portable one.

use glam::Vec3;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch5_reflection::world::RayQueries;
use raystep::ch6_global_illumination::fast::bvh8::Bvh8;
use raystep::ch6_global_illumination::fast::level::Level;

#[test]
fn every_simd_path_finds_the_portable_hits_on_edges_and_vertices() {
    // A 6x6 grid of squares in z = 0, two triangles each (72 triangles,
    // several leaves), and a tilted one above it.
    let mut tris = Vec::new();
    for i in 0..6 {
        for j in 0..6 {
            let p = |di: i32, dj: i32| Vec3::new((i + di) as f32, (j + dj) as f32, 0.0);
            tris.push([p(0, 0), p(1, 0), p(1, 1)]);
            tris.push([p(0, 0), p(1, 1), p(0, 1)]);
        }
    }
    tris.push([
        Vec3::new(1.0, 1.0, 2.0),
        Vec3::new(3.0, 1.0, 3.0),
        Vec3::new(1.0, 3.0, 2.5),
    ]);
    // Straight down onto every vertex, edge midpoint and square centre
    // (where the edge functions are exactly zero), and slanted through them.
    let mut rays = Vec::new();
    for i in 0..=12 {
        for j in 0..=12 {
            let target = Vec3::new(i as f32 * 0.5, j as f32 * 0.5, 0.0);
            for dir in [
                Vec3::new(0.0, 0.0, -1.0),
                Vec3::new(0.25, 0.0, -1.0).normalize(),
                Vec3::new(0.0, -0.5, -1.0).normalize(),
            ] {
                rays.push(Ray::new(target - 4.0 * dir, dir).unwrap());
            }
        }
    }
    let portable = Bvh8::build(&tris, Level::Portable).unwrap();
    let mut hits = 0;
    for level in Level::ALL.into_iter().filter(|l| l.available()) {
        let tree = Bvh8::build(&tris, level).unwrap();
        assert_eq!(tree.level(), level);
        for ray in &rays {
            let (want, got) = (
                portable.closest(ray, f32::INFINITY),
                tree.closest(ray, f32::INFINITY),
            );
            let bits = |h: Option<raystep::ch3_ray_triangle::triangle::Hit>| {
                h.map(|h| (h.t.to_bits(), h.u.to_bits(), h.v.to_bits(), h.triangle))
            };
            assert_eq!(bits(got), bits(want), "{level:?} {ray:?}");
            hits += usize::from(ray.dir == Vec3::NEG_Z && want.is_some());
            for t_max in [1.0, 3.9, 4.0, 4.1] {
                assert_eq!(
                    tree.occluded(ray, t_max),
                    portable.occluded(ray, t_max),
                    "{level:?} {ray:?} {t_max}"
                );
            }
        }
    }
    // Watertight: no ray straight down onto the grid (its coordinates
    // exact) slips through an edge or a vertex. (A slanted ray aimed at the
    // grid's border may start rounded to just outside it.)
    let straight = rays.iter().filter(|r| r.dir == Vec3::NEG_Z).count();
    let levels = Level::ALL.iter().filter(|l| l.available()).count();
    assert_eq!(hits, straight * levels);
}
