//! Unit tests of `src/ch3_ray_triangle/wide_bvh.rs`.

use glam::Vec3;
use raystep::ch3_ray_triangle::obvhs_bvh::Bvh;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::triangle::Intersector;
use raystep::ch3_ray_triangle::wide_bvh::*;
use raystep::core::sampling::random;

/// A closed box of 12 triangles plus a few inside, scaled by `s`.
fn box_scene(s: f32) -> Vec<[Vec3; 3]> {
    let mut tris = crate::common::box_faces(Vec3::splat(-1.0), Vec3::splat(1.0));
    for i in 0..40 {
        let p = Vec3::new(
            random(1, i, 0, 0) * 1.6 - 0.8,
            random(1, i, 0, 1) * 1.6 - 0.8,
            random(1, i, 0, 2) * 1.6 - 0.8,
        );
        let q = Vec3::new(random(1, i, 1, 0), random(1, i, 1, 1), random(1, i, 1, 2)) * 0.2;
        tris.push([
            p,
            p + Vec3::new(q.x, 0.0, 0.0),
            p + Vec3::new(0.0, q.y, q.z),
        ]);
    }
    tris.iter().map(|t| t.map(|p| p * s)).collect()
}

#[test]
fn wide_and_binary_bvh_agree_ray_for_ray_at_every_scale() {
    for scale in [1e-4f32, 1.0, 1e4] {
        let tris = box_scene(scale);
        let bvh = Bvh::build(&tris).unwrap();
        let wide = WideBvh::build(&tris).unwrap();
        let mut near_hits = 0;
        for i in 0..20_000u64 {
            // Origins anywhere inside, some a hair off a wall (hits at
            // t far below any fixed ε), directions anywhere, some along
            // an axis or in an axis plane (zero components: 1/0).
            let u = |d| random(7, i, 0, d);
            let mut o = Vec3::new(u(0), u(1), u(2)) * 1.98 - 0.99;
            if i % 2 == 0 {
                o.x = -1.0 + 1e-6;
            }
            let mut dir = Vec3::new(u(3) - 0.5, u(4) - 0.5, u(5) - 0.5);
            match i % 7 {
                1 => dir.x = 0.0,
                2 => dir = Vec3::new(0.0, 0.0, dir.z),
                3 => dir = Vec3::new(-0.0, dir.y, 0.0),
                _ => {}
            }
            let Ok(ray) = Ray::new(o * scale, dir) else {
                continue;
            };
            let t_max = if i % 3 == 0 {
                u(6) * scale
            } else {
                f32::INFINITY
            };
            let a = bvh.closest(&ray, t_max, Intersector::Watertight);
            let b = wide.closest(&ray, t_max);
            assert_eq!(a, b, "scale {scale}, ray {i}: {ray:?}");
            if a.is_some_and(|h| h.t < 1e-4) {
                near_hits += 1;
            }
            assert_eq!(
                bvh.occluded(&ray, t_max, Intersector::Watertight),
                wide.occluded(&ray, t_max),
                "scale {scale}, ray {i}"
            );
        }
        // The near hits are the ones a box test with a fixed ε would
        // drop (at 1e4, coordinates are too coarse to place an origin
        // so near).
        if scale <= 1.0 {
            assert!(near_hits > 1000, "scale {scale}: {near_hits} near hits");
        }
    }
}

#[test]
fn a_root_that_is_a_leaf_agrees() {
    // One to four triangles: the whole tree is one leaf, no node.
    for n in 1..=4 {
        let tris = &box_scene(1.0)[..n];
        let bvh = Bvh::build(tris).unwrap();
        let wide = WideBvh::build(tris).unwrap();
        assert_eq!((wide.node_count(), wide.leaf_count()), (0, 1));
        let mut hits = 0;
        for i in 0..2_000u64 {
            let u = |d| random(13, i, 0, d);
            let o = Vec3::new(u(0), u(1), u(2)) * 1.98 - 0.99;
            let Ok(ray) = Ray::new(o, Vec3::new(u(3), u(4), u(5)) - 0.5) else {
                continue;
            };
            let a = bvh.closest(&ray, f32::INFINITY, Intersector::Watertight);
            assert_eq!(
                a,
                wide.closest(&ray, f32::INFINITY),
                "{n} triangles, ray {i}"
            );
            assert_eq!(
                bvh.occluded(&ray, f32::INFINITY, Intersector::Watertight),
                wide.occluded(&ray, f32::INFINITY)
            );
            hits += a.is_some() as u32;
        }
        assert!(hits > 100, "{n} triangles: {hits} hits");
    }
}

#[test]
fn a_tree_too_deep_for_the_fixed_stack_still_agrees() {
    // Triangles at exponentially growing distances make a lopsided
    // tree, far deeper than the on-stack traversal stack allows, so
    // queries take the heap-stack path.
    let tris: Vec<[Vec3; 3]> = (0..300)
        .map(|k| {
            let x = 1.2f32.powi(k);
            let s = 0.1 * x;
            [
                Vec3::new(x, -s, -s),
                Vec3::new(x, s, -s),
                Vec3::new(x, 0.0, s),
            ]
        })
        .collect();
    let bvh = Bvh::build(&tris).unwrap();
    let wide = WideBvh::build(&tris).unwrap();
    assert!(3 * wide.depth() + 1 > 46, "only {} levels", wide.depth());
    let mut hits = 0;
    for i in 0..2_000u64 {
        let u = |d| random(11, i, 0, d);
        let o = Vec3::new(u(0) * 1e3, u(1) - 0.5, u(2) - 0.5);
        let dir = Vec3::new(u(3) - 0.3, (u(4) - 0.5) * 0.01, (u(5) - 0.5) * 0.01);
        let Ok(ray) = Ray::new(o, dir) else {
            continue;
        };
        let a = bvh.closest(&ray, f32::INFINITY, Intersector::Watertight);
        assert_eq!(a, wide.closest(&ray, f32::INFINITY), "ray {i}");
        hits += a.is_some() as u32;
        assert_eq!(
            bvh.occluded(&ray, f32::INFINITY, Intersector::Watertight),
            wide.occluded(&ray, f32::INFINITY)
        );
    }
    assert!(hits > 500, "{hits} hits");
}
