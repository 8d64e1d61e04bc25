//! Chapter 3: ray-triangle intersection, the BVH, and the stage.

use crate::common;
use std::sync::Arc;

use glam::{DVec3, Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch3_ray_triangle::geometry::Geometry;
use raystep::ch3_ray_triangle::leaks::{bunny, leak_test, self_intersections};
use raystep::ch3_ray_triangle::obvhs_bvh::{closest_naive, occluded_naive, Bvh, Triangles};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::render::{render_views, sample_position};
use raystep::ch3_ray_triangle::stability::stability_cases;
use raystep::ch3_ray_triangle::stage::DEFAULT as RayTriangle;
use raystep::ch3_ray_triangle::studies::{
    naive_vs_bvh, procedural_camera, procedural_mesh, scene_of, StudySize,
};
use raystep::ch3_ray_triangle::triangle::{intersect_f64, Intersector};
use raystep::core::sampling::random;
use raystep::core::stage::{Chapter, Settings};
use raystep::scene::mesh::Mesh;
use raystep::scene::Scene;

/// Seeded rays from random points around `tris` towards random triangles.
fn rays_at(tris: &[[Vec3; 3]], n: u64, seed: u64) -> Vec<Ray> {
    (0..n)
        .filter_map(|i| {
            let r = |d| random(seed, i, 0, d);
            let tri = tris[((r(0) * tris.len() as f32) as usize).min(tris.len() - 1)];
            let (a, b) = (r(1), r(2) * (1.0 - r(1)));
            let target = tri[0] * (1.0 - a - b) + tri[1] * a + tri[2] * b;
            let origin = (Vec3::new(r(3), r(4), r(5)) * 2.0 - 1.0) * 3.0;
            Ray::new(origin, target - origin).ok()
        })
        .collect()
}

#[test]
fn the_three_intersectors_agree_on_ordinary_rays() {
    let mut compared = 0;
    for i in 0..20_000u64 {
        let r = |d| random(42, i, 0, d);
        let tri = [
            Vec3::new(r(0), r(1), r(2)) * 2.0 - 1.0,
            Vec3::new(r(3), r(4), r(5)) * 2.0 - 1.0,
            Vec3::new(r(6), r(7), r(8)) * 2.0 - 1.0,
        ];
        let origin = Vec3::new(r(9), r(10), r(11)) * 6.0 - 3.0;
        let aim = tri[0] * 0.5 + tri[1] * r(12) * 0.5 + tri[2] * (0.5 - r(12) * 0.5);
        let target = aim + (Vec3::new(r(13), r(14), r(15)) - 0.5) * 0.5;
        let ray = Ray::new(origin, target - origin).unwrap();
        let reference = intersect_f64(
            ray.origin.as_dvec3(),
            ray.dir.as_dvec3(),
            tri.map(|p| p.as_dvec3()),
        );
        // Leave out rays within 1e-3 of an edge (by the f64 answer) and
        // triangles seen almost edge-on: there the tests may disagree.
        let n = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalize_or_zero();
        if n.dot(ray.dir).abs() < 0.05 {
            continue;
        }
        let margin = |(_, u, v): (f64, f64, f64)| u.min(v).min(1.0 - u - v);
        if reference.is_some_and(|h| margin(h) < 1e-3) {
            continue;
        }
        let hits = Intersector::ALL.map(|x| x.intersect(&ray, tri, 0.0, f32::INFINITY));
        for (x, h) in Intersector::ALL.iter().zip(hits) {
            match (h, reference) {
                (Some(h), Some((t, u, v))) => {
                    assert!((h.t as f64 - t).abs() <= 1e-5 * t, "{x:?} t {} vs {t}", h.t);
                    assert!((h.u as f64 - u).abs() < 1e-4 && (h.v as f64 - v).abs() < 1e-4);
                }
                (None, None) => {}
                (h, r) => panic!("{x:?} disagrees with f64: {h:?} vs {r:?} on ray {ray:?}"),
            }
        }
        compared += 1;
    }
    assert!(compared > 10_000, "only {compared} rays compared");
}

#[test]
fn bvh_gives_the_same_first_hit_as_the_naive_loop() {
    for mesh in [bunny(), procedural_mesh(2000), Mesh::icosphere(3)] {
        let tris = Triangles::from_meshes(std::slice::from_ref(&mesh)).tris;
        let bvh = Bvh::build(&tris).unwrap();
        let mut hits = 0;
        for ray in rays_at(&tris, 2000, 9) {
            let naive = closest_naive(&tris, &ray, f32::INFINITY, Intersector::Watertight);
            let fast = bvh.closest(&ray, f32::INFINITY, Intersector::Watertight);
            match (naive, fast) {
                (Some(a), Some(b)) => {
                    assert_eq!(a.triangle, b.triangle, "{}: ray {ray:?}", mesh.name);
                    assert!((a.t - b.t).abs() <= 1e-5 * a.t);
                    hits += 1;
                }
                (None, None) => {}
                (a, b) => panic!("{}: naive {a:?} vs BVH {b:?}", mesh.name),
            }
            // Occlusion before a random distance agrees too.
            let t_max = random(3, hits, 0, 0) * 4.0;
            assert_eq!(
                occluded_naive(&tris, &ray, t_max, Intersector::Watertight),
                bvh.occluded(&ray, t_max, Intersector::Watertight)
            );
        }
        assert!(hits > 1000, "{}: only {hits} hits", mesh.name);
    }
}

#[test]
fn watertight_test_does_not_leak_at_edges_and_vertices() {
    for mesh in [Mesh::icosphere(3), bunny()] {
        let counts = leak_test(&mesh, 100_000, 1);
        assert_eq!(counts.len(), 3, "{}: no closed edges found", mesh.name);
        for c in &counts {
            assert_eq!(c.rays, 100_000);
            if c.intersector == Intersector::Watertight {
                assert_eq!(c.leaks, 0, "{}: watertight test leaked", mesh.name);
            }
        }
        // The other two do leak here: that is what the comparison shows.
        assert!(counts.iter().any(|c| c.leaks > 0));
    }
}

#[test]
fn every_stiff_case_comes_out_as_expected() {
    let size = StudySize::quick();
    let leaks = [Mesh::icosphere(3), bunny()]
        .iter()
        .flat_map(|m| leak_test(m, 20_000, 2))
        .collect::<Vec<_>>();
    let cases = stability_cases(&size, &leaks);
    assert!(cases.len() >= 14, "{} cases", cases.len());
    for c in &cases {
        assert!(
            c.ok,
            "{}: expected {}, got {}",
            c.name, c.expected, c.measured
        );
    }
    for name in [
        "parallel",
        "edges and vertices",
        "1e7",
        "tiny",
        "degenerate",
        "grazing",
    ] {
        assert!(
            cases.iter().any(|c| c.name.contains(name)),
            "no case {name}"
        );
    }
}

#[test]
fn spawned_rays_do_not_hit_their_own_surface_far_from_the_origin() {
    let (scaled, fixed) = self_intersections(1e5, 5_000, 1e-4);
    assert_eq!(scaled, 0);
    // A fixed ε of 1e-4 is below the f32 spacing at 1e5 (about 0.008).
    assert!(fixed > 500, "fixed ε self-hits: {fixed}");
}

#[test]
fn degenerate_and_parallel_cases_never_give_nan() {
    let line = [Vec3::ZERO, Vec3::X, Vec3::X * 2.0];
    for i in 0..2000u64 {
        let r = |d| random(8, i, 0, d);
        let origin = Vec3::new(r(0), r(1), r(2)) * 2.0 - 1.0;
        let Ok(ray) = Ray::new(origin, Vec3::new(r(3), 0.0, 0.0) - origin) else {
            continue;
        };
        for x in Intersector::ALL {
            assert_eq!(x.intersect(&ray, line, 0.0, f32::INFINITY), None);
        }
    }
}

#[test]
fn primary_hit_projects_back_onto_its_sample_position() {
    let scene = Scene::builtin().with_resolution(64, 48).unwrap();
    let geometry = Geometry::new(&scene);
    let cam = &Camera::of(&scene);
    let mut checked = 0;
    for y in 0..cam.height {
        for x in 0..cam.width {
            let raster = sample_position(x, y, cam.width, 4, 5, 3);
            let ray = cam.ray(raster);
            let Some(hit) = geometry.closest(&ray) else {
                continue;
            };
            let p = ray.at(hit.t);
            let back = cam.project(p).expect("a hit is in front of the camera");
            assert!((back - raster).length() < 2e-3, "{raster} -> {back}");
            checked += 1;
        }
    }
    assert!(checked > 2000);
}

#[test]
fn same_bytes_on_one_and_two_threads() {
    let scene = Scene::builtin().with_resolution(48, 36).unwrap();
    let geometry = Geometry::new(&scene);
    let render = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| render_views(&Camera::of(&scene), &geometry, 3, 11))
            .iter()
            .map(|f| f.to_srgb8())
            .collect::<Vec<_>>()
    };
    let one = render(1);
    assert_eq!(one, render(2));
    assert!(one[0].iter().any(|b| *b > 0), "the image is not black");
}

#[test]
fn a_scene_without_meshes_is_refused_and_one_with_meshes_builds_a_bvh() {
    let mut empty = Scene::builtin().with_resolution(16, 12).unwrap();
    empty.meshes.clear();
    let full = Scene::builtin().with_resolution(16, 12).unwrap();
    // Nothing to trace: the stage says so when it starts, instead of a
    // black picture without a word.
    let why = RayTriangle
        .start(Arc::new(empty), &Settings::default())
        .err()
        .expect("refused")
        .to_string();
    assert_eq!(
        why,
        "chapter 3 draws triangle meshes; cornell-box has none (it is empty)"
    );
    let mut r = RayTriangle
        .start(Arc::new(full), &Settings::default())
        .unwrap();
    while !r.pass().complete {}
    let r = r.report();
    let bvh = r
        .built
        .iter()
        .find(|s| s.starts_with("BVH"))
        .expect("a BVH");
    assert!(bvh.contains("nodes"), "{bvh}");
    assert!(!r.left_out.iter().any(|s| s.starts_with("BVH")));
}

#[test]
fn naive_and_bvh_images_are_identical() {
    let (table, rows) = naive_vs_bvh(&[10, 1000], 1e9);
    assert_eq!(table.rows.len(), 2);
    for row in 0..table.rows.len() {
        assert_eq!(common::cell(&table, row, "same image"), "yes", "{table:?}");
    }
    assert!(rows.iter().all(|m| m.error == 0.0));
}

#[test]
fn anti_aliasing_error_falls_with_samples() {
    let scene = scene_of(procedural_mesh(200), procedural_camera(32, 24));
    let et = raystep::ch3_ray_triangle::studies::error_against_time(&scene, &[1, 16], 128, 0);
    assert_eq!(et.rows.len(), 2);
    assert!(et.rows[1].error < et.rows[0].error * 0.6, "{:?}", et.rows);
}

#[test]
fn relative_error_of_t_stays_small_far_away() {
    let reference = |d: f64| {
        let o = DVec3::ZERO;
        intersect_f64(
            o,
            DVec3::new(0.0, 0.0, -1.0),
            [
                DVec3::new(-d, -d, -d),
                DVec3::new(d, -d, -d),
                DVec3::new(0.0, d, -d),
            ],
        )
    };
    assert_eq!(reference(1e6).map(|h| h.0), Some(1e6));
    for k in 0..=7 {
        let (err, misses) = raystep::ch3_ray_triangle::leaks::t_relative_error(
            10f64.powi(k),
            100,
            Intersector::Watertight,
        );
        assert_eq!(misses, 0);
        assert!(err < 1e-5, "1e{k}: {err}");
    }
    // The camera's pixel positions are exact at the centre.
    assert_eq!(sample_position(3, 4, 10, 1, 0, 0), Vec2::new(3.5, 4.5));
}

#[test]
fn ch3_exercise_references_pass() {
    let exercises: Vec<_> = raystep::grading::all()
        .into_iter()
        .filter(|e| e.chapter == 3)
        .collect();
    assert_eq!(exercises.len(), 5);
    for ex in &exercises {
        let outcome = raystep::grading::run(ex);
        assert!(
            outcome.is_pass(),
            "{}: reference does not pass: {outcome:?}",
            ex.id()
        );
    }
}

#[test]
fn intersector_table_counts_agreement_with_f64() {
    let t = raystep::ch3_ray_triangle::studies::intersector_speed(5_000);
    assert_eq!(t.rows.len(), 3);
    for row in 0..t.rows.len() {
        let hits: usize = common::cell(&t, row, "hits").parse().unwrap();
        assert!(hits > 500, "{:?}", t.rows[row]);
        let agree = common::cell(&t, row, "agree with f64 on hit/miss");
        let agree: usize = agree.split(' ').next().unwrap().parse().unwrap();
        assert!(agree >= 4_990, "{:?}", t.rows[row]);
    }
}

#[test]
fn snapshot_of_the_tetrahedron_views() {
    use raystep::core::preview::{preview, PreviewStyle};
    let scene = Scene::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/tetrahedron.toml"
    )))
    .unwrap()
    .with_resolution(48, 36)
    .unwrap();
    let geometry = Geometry::new(&scene);
    let films = render_views(&Camera::of(&scene), &geometry, 1, 0);
    let mut text = String::new();
    for (view, film) in raystep::ch3_ray_triangle::stage::VIEWS.iter().zip(&films) {
        text += &format!("{}:\n{}", view.name, preview(film, 48, PreviewStyle::Ascii));
    }
    insta::assert_snapshot!(text);
}

#[test]
fn first_hits_agree_with_chapter_2_except_on_edges() {
    use raystep::ch3_ray_triangle::agreement::raster_agreement;
    for name in [
        "tetrahedron",
        "bunny",
        "cornell-box",
        "interpenetrating",
        "railroad",
    ] {
        let s = crate::common::shipped_scene(name, 160, 120);
        let geometry = raystep::ch3_ray_triangle::geometry::Geometry::new(&s);
        let a = raster_agreement(&s, &geometry).unwrap();
        assert_eq!(a.pixels, 160 * 120);
        assert_eq!(a.differ_off_edges, 0, "{name}: {a:?}");
        assert!(
            a.differ * 50 < a.pixels,
            "{name}: more than 2% differ: {a:?}"
        );
    }
    // The check can fail: geometry shifted by about 6 pixels disagrees
    // with the rasterizer across whole faces, not only on edges.
    let s = crate::common::shipped_scene("cornell-box", 160, 120);
    let mut moved = s.clone();
    for m in &mut moved.meshes {
        m.transform(&glam::Mat4::from_translation(glam::Vec3::new(
            0.15, 0.0, 0.0,
        )));
    }
    let a = raster_agreement(
        &s,
        &raystep::ch3_ray_triangle::geometry::Geometry::new(&moved),
    )
    .unwrap();
    assert!(a.differ_off_edges > 0, "{a:?}");
}

#[test]
fn fast_watertight_test_gives_the_readable_ones_hits_bit_for_bit() {
    use raystep::ch3_ray_triangle::triangle::intersect_watertight;
    use raystep::ch3_ray_triangle::watertight_fast::{SoaTriangle, WatertightRay};
    let mut hits = 0;
    for i in 0..50_000u64 {
        let r = |d| random(77, i, 0, d);
        // Ordinary, far-away (1e5), tiny (1e-6) and zero-area triangles.
        let (scale, offset) = match i % 4 {
            0 => (2.0, Vec3::ZERO),
            1 => (2.0, Vec3::splat(1e5)),
            2 => (1e-6, Vec3::ZERO),
            _ => (2.0, Vec3::ZERO),
        };
        let p = |k: u64| offset + (Vec3::new(r(k), r(k + 1), r(k + 2)) - 0.5) * scale;
        let mut tri = [p(0), p(3), p(6)];
        if i % 4 == 3 && i % 8 == 7 {
            tri[2] = tri[0] * 2.0 - tri[1]; // collinear
        }
        let origin = offset + (Vec3::new(r(9), r(10), r(11)) - 0.5) * 6.0;
        // Aim at a vertex, an edge or the inside.
        let (a, b) = match i % 3 {
            0 => (0.0, 0.0),
            1 => (r(12), 0.0),
            _ => (r(12) * 0.5, r(13) * 0.5),
        };
        let target = tri[0] * (1.0 - a - b) + tri[1] * a + tri[2] * b;
        let Ok(ray) = Ray::new(origin, target - origin) else {
            continue;
        };
        let t_max = if i % 5 == 0 {
            r(14) * 4.0
        } else {
            f32::INFINITY
        };
        let readable = intersect_watertight(&ray, tri, 0.0, t_max);
        let fast = WatertightRay::new(&ray).intersect(&SoaTriangle::new(tri), 0.0, t_max);
        let bits = |h: Option<raystep::ch3_ray_triangle::triangle::Hit>| {
            h.map(|h| [h.t, h.u, h.v].map(f32::to_bits))
        };
        assert_eq!(bits(readable), bits(fast), "{tri:?} {ray:?}");
        hits += u32::from(fast.is_some());
    }
    assert!(hits > 20_000, "only {hits} hits");
}

#[test]
fn bvh_with_the_readable_tests_matches_the_naive_loop() {
    let mesh = Mesh::icosphere(2);
    let tris = Triangles::from_meshes(std::slice::from_ref(&mesh)).tris;
    let bvh = Bvh::build(&tris).unwrap();
    for ray in rays_at(&tris, 500, 4) {
        for x in Intersector::ALL {
            let naive = closest_naive(&tris, &ray, f32::INFINITY, x).map(|h| h.triangle);
            let fast = bvh.closest(&ray, f32::INFINITY, x).map(|h| h.triangle);
            assert_eq!(naive, fast, "{x:?} {ray:?}");
            assert_eq!(
                occluded_naive(&tris, &ray, 1.0, x),
                bvh.occluded(&ray, 1.0, x),
                "{x:?} {ray:?}"
            );
        }
    }
}
