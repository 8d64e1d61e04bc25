//! Unit tests of `src/ch3_ray_triangle/readable_bvh.rs`.

use glam::Vec3;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::readable_bvh::*;

#[test]
fn the_slab_test_finds_where_a_ray_enters_a_box() {
    let b = Aabb {
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
    };
    let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), -Vec3::Z).unwrap();
    let t = b.enter(&ray, ray.dir.recip(), f32::INFINITY).unwrap();
    assert!((t - 4.0).abs() < 1e-6, "{t}");
    // Too short to reach it, or pointing away.
    assert_eq!(b.enter(&ray, ray.dir.recip(), 3.0), None);
    let away = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Z).unwrap();
    assert_eq!(b.enter(&away, away.dir.recip(), f32::INFINITY), None);
    // From inside: entered at 0.
    let inside = Ray::new(Vec3::ZERO, Vec3::X).unwrap();
    assert_eq!(b.enter(&inside, inside.dir.recip(), 1.0), Some(0.0));
    // Parallel to a slab and outside it: missed.
    let beside = Ray::new(Vec3::new(0.0, 2.0, 5.0), -Vec3::Z).unwrap();
    assert_eq!(b.enter(&beside, beside.dir.recip(), f32::INFINITY), None);
}

#[test]
fn coincident_centroids_still_split_in_halves() {
    // 1000 triangles, all centred on the origin, turned about z.
    let tris: Vec<[Vec3; 3]> = (0..1000)
        .map(|i| {
            let a = i as f32 * 0.001;
            let (s, c) = a.sin_cos();
            let p = Vec3::new(c, s, 0.0);
            let q = Vec3::new(-s, c, 0.5);
            [p + q, p - q, -2.0 * p]
        })
        .collect();
    let bvh = ReadableBvh::build(&tris);
    assert!(bvh.depth() <= 11, "depth {}", bvh.depth());
    let mut seen = bvh.order.clone();
    seen.sort_unstable();
    assert_eq!(seen, (0..1000).collect::<Vec<u32>>());
}
