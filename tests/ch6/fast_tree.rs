//! The fast engine's eight-wide tree on rays that pass exactly through
//! shared edges and vertices: there the triangle test hands lanes to the
//! one-triangle test, and every SIMD path's kernels must find the same
//! hit, bit for bit, as the plain lane loops the book shows.

use glam::Vec3;

use crate::common;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch5_reflection::world::RayQueries;
use raystep::fast::bvh8::Bvh8;
use raystep::fast::level::Level;

#[test]
fn every_simd_path_finds_the_lane_loops_hits_on_edges_and_vertices() {
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
                portable.closest_by_lane_loops(ray, f32::INFINITY),
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
                    portable.occluded_by_lane_loops(ray, t_max),
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

/// The kernels against the plain lane loops on a soup of triangles of
/// every size and place (leaves and nodes of four lanes or fewer among
/// them, which the portable path tests four wide), from rays in every
/// direction, with every level the CPU has.
#[test]
fn every_simd_path_finds_the_lane_loops_hits_in_a_soup() {
    let mut next = common::unit_stream(0x9e37_79b9_7f4a_7c15);
    for (count, scale) in [(3, 1.0), (7, 1e-3), (150, 1.0), (600, 1e4)] {
        let mut point =
            |spread: f32| Vec3::new(next(), next(), next()) * 2.0 * spread - Vec3::splat(spread);
        let tris: Vec<[Vec3; 3]> = (0..count)
            .map(|i| {
                let centre = point(scale);
                let size = scale * [0.01, 0.2, 1.0][i % 3];
                [
                    centre + point(size),
                    centre + point(size),
                    centre + point(size),
                ]
            })
            .collect();
        let rays: Vec<(Ray, f32)> = (0..3000)
            .filter_map(|i| {
                let origin = point(1.5 * scale);
                let to = point(scale) - origin;
                let t_max = [f32::INFINITY, to.length(), 0.5 * to.length()][i % 3];
                Some((Ray::new(origin, to.try_normalize()?).ok()?, t_max))
            })
            .collect();
        let lanes = Bvh8::build(&tris, Level::Portable).unwrap();
        let want: Vec<_> = rays
            .iter()
            .map(|(ray, t_max)| {
                let hit = lanes.closest_by_lane_loops(ray, *t_max);
                let hit = hit.map(|h| (h.t.to_bits(), h.u.to_bits(), h.v.to_bits(), h.triangle));
                (hit, lanes.occluded_by_lane_loops(ray, *t_max))
            })
            .collect();
        let found = want.iter().filter(|w| w.0.is_some()).count();
        assert!(found > 25, "{count} triangles: {found} hits");
        for level in Level::ALL.into_iter().filter(|l| l.available()) {
            let tree = Bvh8::build(&tris, level).unwrap();
            for ((ray, t_max), want) in rays.iter().zip(&want) {
                let hit = tree.closest(ray, *t_max);
                let hit = hit.map(|h| (h.t.to_bits(), h.u.to_bits(), h.v.to_bits(), h.triangle));
                let got = (hit, tree.occluded(ray, *t_max));
                assert_eq!(
                    &got, want,
                    "{level:?}, {count} triangles, {ray:?} to {t_max}"
                );
            }
        }
    }
}

#[test]
fn no_leaf_of_the_fast_tree_holds_a_room() {
    // A room (the walls of a 2x2x2 box) with a tilted slab inside: the
    // walls' triangles would fit one leaf, whose box is the whole room.
    let mut tris = common::box_faces(Vec3::splat(-1.0), Vec3::splat(1.0));
    tris.extend(
        common::box_faces(Vec3::new(-0.5, -1.0, -0.3), Vec3::new(0.1, 0.2, 0.4))
            .iter()
            .map(|t| t.map(|p| Vec3::new(p.x + 0.2 * p.z, p.y, p.z - 0.2 * p.x))),
    );
    let volume = |lo: Vec3, hi: Vec3| (hi - lo).max(Vec3::ZERO).element_product();
    let tree = Bvh8::build(&tris, Level::Portable).unwrap();
    let leaves = tree.leaf_boxes();
    assert_eq!(leaves.iter().map(|l| l.2).sum::<usize>(), tris.len());
    for (lo, hi, n) in &leaves {
        assert!(
            *n == 1 || volume(*lo, *hi) <= 0.5 * 8.0,
            "a leaf of {n} triangles fills {lo} .. {hi}"
        );
    }
    // And the opened tree finds what testing every triangle finds, from
    // points on the walls and inside the room.
    let brute = |ray: &Ray| {
        tris.iter()
            .filter_map(|t| {
                raystep::ch3_ray_triangle::triangle::intersect_watertight(
                    ray,
                    *t,
                    0.0,
                    f32::INFINITY,
                )
            })
            .map(|h| h.t)
            .fold(f32::INFINITY, f32::min)
    };
    let mut unit = common::unit_stream(0x2545_f491_4f6c_dd1d);
    let mut next = || unit() * 2.0 - 1.0;
    for _ in 0..2000 {
        let o = Vec3::new(next(), next() * 0.999, next() * 0.999);
        let Some(ray) = Ray::new(o, Vec3::new(next(), next(), next())).ok() else {
            continue;
        };
        let got = tree
            .closest(&ray, f32::INFINITY)
            .map_or(f32::INFINITY, |h| h.t);
        let want = brute(&ray);
        assert!(
            got == want || (got - want).abs() <= 1e-5 * want,
            "{ray:?}: {got} against {want}"
        );
    }
}

#[test]
fn shadow_rays_end_outside_the_lights_box_wherever_the_scene_sits() {
    use raystep::ch3_ray_triangle::obvhs_bvh::BOX_PADDING;
    use raystep::ch3_ray_triangle::spawn::{offset_origin, stop_distance};
    // The Cornell box's light (y = 0.99, facing down) seen from its floor
    // (y = -1), with the box where it is, far away, small and large. The
    // trees pad the light's box by BOX_PADDING of its coordinates and the
    // slab test lets a far end reach 4γ(3) of t further; a shadow ray
    // meeting the light at least 0.3 from grazing must end short of all
    // that, or it tests the light's own leaf for nothing.
    let eps = f32::EPSILON / 2.0;
    let stretch = 4.0 * (3.0 * eps) / (1.0 - 3.0 * eps);
    for (shift, scale) in [
        (Vec3::ZERO, 1.0),
        (Vec3::new(1e4, -2e4, 3e4), 1.0),
        (Vec3::ZERO, 1e-3),
        (Vec3::new(-300.0, 0.0, 70.0), 40.0),
    ] {
        let place = |p: Vec3| p * scale + shift;
        let light_y = place(Vec3::new(0.0, 0.99, 0.0)).y;
        let corners = [Vec3::new(-0.23, 0.99, -0.18), Vec3::new(0.23, 0.99, 0.2)].map(place);
        let pad = corners[0].y.abs().max(corners[1].y.abs()) * BOX_PADDING;
        let mut checked = 0;
        for i in 0..9 {
            for j in 0..9 {
                let p = place(Vec3::new(i as f32 * 0.2 - 0.8, -1.0, j as f32 * 0.2 - 0.8));
                for (a, b) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.7)] {
                    let q = corners[0] + (corners[1] - corners[0]) * Vec3::new(a, 0.0, b);
                    let (wi, dist) = ((q - p).normalize(), (q - p).length());
                    if wi.y < 0.3 {
                        continue;
                    }
                    // As `World::unoccluded` aims it.
                    let origin = offset_origin(p, Vec3::Y);
                    let y = p + wi * dist;
                    let to = y - wi * stop_distance(y) - origin;
                    let t_max = to.length();
                    let dir = to / t_max;
                    let reach = origin.y + dir.y * t_max * (1.0 + stretch);
                    assert!(
                        reach < light_y - pad,
                        "{shift} x{scale}: a shadow ray from {p} reaches {reach}, the light's box starts at {}",
                        light_y - pad
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 100, "{checked}");
    }
}

#[test]
fn camera_rays_eight_at_a_time_find_the_one_ray_hits() {
    use raystep::ch1_projection::camera::Camera;
    use raystep::ch3_ray_triangle::triangle::Hit;
    use raystep::fast::{packet, simd, FastEngine};
    use raystep::scene::Scene;
    let bits =
        |h: &Option<Hit>| h.map(|h| (h.t.to_bits(), h.u.to_bits(), h.v.to_bits(), h.triangle));
    // The Cornell box's camera rays, eight jittered samples per pixel (the
    // packets), and the same rays shuffled across the image (eights that
    // mostly differ in direction signs or permutation: one at a time).
    let scene = Scene::builtin().with_resolution(48, 48).unwrap();
    let camera = Camera::of(&scene);
    let mut next = common::unit_stream(0x9e37_79b9_7f4a_7c15);
    let mut rays = Vec::new();
    for y in 0..camera.height {
        for x in 0..camera.width {
            for _ in 0..8 {
                let raster = glam::Vec2::new(x as f32 + next(), y as f32 + next());
                rays.push(camera.ray(raster));
            }
        }
    }
    // Eights from nearby origins too (a lens, or a ray leaving a surface):
    // the group's box test then works with a range of origins.
    let spread: Vec<_> = rays
        .iter()
        .map(|r| raystep::ch3_ray_triangle::ray::Ray {
            origin: r.origin + 0.02 * glam::Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5),
            dir: r.dir,
        })
        .collect();
    let mut shuffled = rays.clone();
    for i in (1..shuffled.len()).rev() {
        let j = (next() * i as f32) as usize;
        shuffled.swap(i, j);
    }
    // And a remainder of three that is not a whole eight.
    shuffled.truncate(shuffled.len() - 5);
    let together = rays.chunks(8).filter(|r| packet::together(r)).count();
    assert!(
        together * 10 >= rays.len() / 8 * 9,
        "{together} of {}",
        rays.len() / 8
    );
    let apart = shuffled
        .chunks_exact(8)
        .filter(|r| !packet::together(r))
        .count();
    assert!(apart * 2 >= shuffled.len() / 8, "{apart}");
    let engine = FastEngine::at(&scene, Level::Portable);
    let portable = engine.tree().unwrap();
    for level in Level::ALL.into_iter().filter(|l| l.available()) {
        let engine = FastEngine::at(&scene, level);
        let tree = engine.tree().unwrap();
        for rays in [&rays, &spread, &shuffled] {
            let (mut want, mut got) = (Vec::new(), Vec::new());
            simd::closest_all(portable, rays, &mut want);
            simd::closest_packets(tree, rays, &mut got);
            assert_eq!(got.len(), rays.len());
            let misses = want.iter().filter(|h| h.is_none()).count();
            assert!(misses * 4 < rays.len(), "most rays see the box: {misses}");
            for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                assert_eq!(bits(g), bits(w), "{level:?} ray {i}: {:?}", rays[i]);
            }
        }
    }
}

#[test]
fn a_boxs_twelve_triangles_go_into_its_sides_and_two_flat_faces() {
    // A unit cube, two triangles per face. The binary tree splits it into
    // leaves as big as the cube; packed along an axis it becomes two flat
    // faces and one leaf of the other four, so that a ray meeting the cube
    // tests one leaf, plus a flat face only where it crosses that face.
    let c = |x: f32, y: f32, z: f32| Vec3::new(x, y, z);
    let mut tris = Vec::new();
    for axis in 0..3 {
        for side in [0.0, 1.0] {
            let p = |u: f32, v: f32| {
                let mut q = [0.0; 3];
                q[axis] = side;
                q[(axis + 1) % 3] = u;
                q[(axis + 2) % 3] = v;
                c(q[0], q[1], q[2])
            };
            tris.push([p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)]);
            tris.push([p(0.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)]);
        }
    }
    // On a floor much larger than the cube (alone, the cube would be a
    // room, opened into its six faces).
    tris.push([c(-9.0, -1.0, -9.0), c(9.0, -1.0, -9.0), c(9.0, -1.0, 9.0)]);
    tris.push([c(-9.0, -1.0, -9.0), c(9.0, -1.0, 9.0), c(-9.0, -1.0, 9.0)]);
    let tree = Bvh8::build(&tris, Level::Portable).unwrap();
    let mut leaves = tree.leaf_boxes();
    leaves.sort_by_key(|l| l.2);
    let counts: Vec<usize> = leaves.iter().map(|l| l.2).collect();
    assert_eq!(counts, [2, 2, 2, 8], "{leaves:?}");
    for (lo, hi, _) in &leaves[..3] {
        assert_eq!((*hi - *lo).min_element(), 0.0, "a flat face: {lo} {hi}");
    }
    let (lo, hi, _) = leaves[3];
    assert_eq!((lo, hi), (Vec3::ZERO, Vec3::ONE));
    // And the hits are the one-triangle test's: rays from inside and
    // outside the cube, through faces, edges and corners.
    let reference = raystep::ch3_ray_triangle::wide_bvh::WideBvh::build(&tris).unwrap();
    use raystep::ch3_ray_triangle::triangle::Hit;
    let bits =
        |h: Option<Hit>| h.map(|h| (h.t.to_bits(), h.u.to_bits(), h.v.to_bits(), h.triangle));
    let (mut hits, mut edges) = (0, 0);
    for i in 0..=8 {
        for j in 0..=8 {
            let target = c(i as f32 / 8.0, j as f32 / 8.0, 1.0);
            for origin in [
                c(0.5, 0.5, 0.5),
                c(0.3, 0.6, 0.2),
                c(-1.0, 0.5, 3.0),
                c(2.0, -1.0, 0.5),
            ] {
                let Ok(ray) = Ray::new(origin, (target - origin).normalize()) else {
                    continue;
                };
                let want = reference.closest(&ray, f32::INFINITY);
                // Where two faces meet (an edge or a corner), triangles of
                // different leaves are hit at the same point, and which
                // one is reported depends on the order leaves are visited
                // in. Their t may differ in the last place, and the
                // one-triangle test, which compares t_scaled with
                // t_max * det before it divides (pbrt's order), can let
                // the later leaf's hit through one unit beyond t_max: there
                // t must agree to one unit in the last place.
                let on_edge = want.is_some_and(|h| {
                    let p = ray.at(h.t).to_array();
                    let near = |x: f32| x.abs() < 1e-5 || (x - 1.0).abs() < 1e-5;
                    p.into_iter().filter(|x| near(*x)).count() >= 2
                });
                for level in Level::ALL.into_iter().filter(|l| l.available()) {
                    let got = Bvh8::build(&tris, level)
                        .unwrap()
                        .closest(&ray, f32::INFINITY);
                    match on_edge {
                        true => {
                            let t = |h: Option<Hit>| h.map_or(-1, |h| h.t.to_bits() as i64);
                            assert!((t(got) - t(want)).abs() <= 1, "{level:?} {ray:?}");
                        }
                        false => assert_eq!(bits(got), bits(want), "{level:?} {ray:?}"),
                    }
                }
                edges += usize::from(on_edge);
                hits += usize::from(want.is_some());
            }
        }
    }
    assert!(
        hits > 300 && edges < hits / 2,
        "{hits} hits, {edges} on edges"
    );
}

/// The SIMD queries take the instructions from the tree, never from their
/// caller, and a tree is built only for instructions the CPU has: one
/// asked for AVX2 or AVX-512 on a CPU without them (pretended here) is
/// built for the portable path, and answers as the one built for this
/// CPU's best.
#[test]
fn a_tree_asked_for_instructions_the_cpu_lacks_is_built_for_the_portable_ones() {
    use raystep::fast::simd;
    let tris: Vec<[Vec3; 3]> = (0..40)
        .map(|i| {
            let x = i as f32 * 0.25;
            [
                Vec3::new(x, 0.0, 1.0 + x),
                Vec3::new(x + 1.0, 0.0, 1.0),
                Vec3::new(x, 1.0, 1.5),
            ]
        })
        .collect();
    let rays: Vec<Ray> = (0..200)
        .filter_map(|i| {
            let d = Vec3::new((i % 20) as f32 * 0.03 + 0.1, (i / 20) as f32 * 0.05, 1.0);
            Ray::new(Vec3::new(0.0, 0.3, -1.0), d.normalize()).ok()
        })
        .collect();
    let best = Bvh8::build(&tris, simd::best()).expect("a tree");
    let (mut want, mut got) = (Vec::new(), Vec::new());
    simd::closest_all(&best, &rays, &mut want);
    assert!(want.iter().filter(|h| h.is_some()).count() > 50);
    for level in Level::ALL {
        let lacking = [Level::Avx2, Level::Avx512];
        let tree = Level::pretend_lacking(&lacking, || Bvh8::build(&tris, level)).expect("a tree");
        assert_eq!(tree.level(), Level::Portable, "asked for {level:?}");
        simd::closest_all(&tree, &rays, &mut got);
        assert_eq!(format!("{got:?}"), format!("{want:?}"));
        // Without pretending, each tree is built for `level` if the CPU
        // has it, else for the portable path: never for a level it lacks.
        let tree = Bvh8::build(&tris, level).expect("a tree");
        assert!(tree.level().available());
        assert_eq!(tree.level() == level, level.available());
    }
    // The pretence ends with the closure.
    assert_eq!(
        Bvh8::build(&tris, simd::best()).expect("a tree").level(),
        simd::best()
    );
}
