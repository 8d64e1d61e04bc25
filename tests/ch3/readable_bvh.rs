//! Chapter 3's readable BVH: hit for hit against the naive loop and
//! against obvhs on several meshes, and its exercise's grader.

use glam::Vec3;
use raystep::ch3_ray_triangle::obvhs_bvh::{closest_naive, Bvh, Triangles};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::readable_bvh::{closest_hit, NodeKind, ReadableBvh, MAX_LEAF};
use raystep::ch3_ray_triangle::sah;
use raystep::ch3_ray_triangle::triangle::{Hit, Intersector};
use raystep::core::sampling::random;
use raystep::grading::exercises::ch3::{check_bvh_traversal, same_closest_hit};
use raystep::scene::mesh::Mesh;
use raystep::scene::Scene;

/// `n` random triangles of about 0.2 across in [-1, 1]³.
fn soup(n: u64) -> Vec<[Vec3; 3]> {
    (0..n)
        .map(|i| {
            let r = |d| random(70, i, 0, d) * 2.0 - 1.0;
            let c = Vec3::new(r(0), r(1), r(2));
            [0, 1, 2].map(|k| c + Vec3::new(r(3 + 3 * k), r(4 + 3 * k), r(5 + 3 * k)) * 0.1)
        })
        .collect()
}

/// `n` triangles whose centroids all lie at the origin: (p + q, p - q,
/// -2p) for random p and q.
fn coincident(n: u64) -> Vec<[Vec3; 3]> {
    (0..n)
        .map(|i| {
            let r = |d| random(71, i, 0, d) * 2.0 - 1.0;
            let (p, q) = (Vec3::new(r(0), r(1), r(2)), Vec3::new(r(3), r(4), r(5)));
            [p + q, p - q, -2.0 * p]
        })
        .collect()
}

/// The meshes of the comparison, by name.
fn meshes() -> Vec<(&'static str, Vec<[Vec3; 3]>)> {
    vec![
        (
            "Cornell box",
            Triangles::from_meshes(&Scene::builtin().meshes).tris,
        ),
        ("sphere", Triangles::from_meshes(&[Mesh::icosphere(4)]).tris),
        ("triangle soup", soup(3000)),
        ("coincident centroids", coincident(500)),
        (
            "one triangle",
            vec![[
                Vec3::new(-1.0, -1.0, 0.0),
                Vec3::new(1.0, -1.0, 0.0),
                Vec3::new(0.0, 1.0, 0.0),
            ]],
        ),
        ("empty", Vec::new()),
    ]
}

/// Rays for `tris`: half aimed at a random point of a random triangle from
/// a random point around the mesh, half from a random point in a random
/// direction; some with a short t_max.
fn rays(tris: &[[Vec3; 3]], n: u64) -> Vec<(Ray, f32)> {
    let (lo, hi) = tris
        .iter()
        .flatten()
        .fold((Vec3::splat(-1.0), Vec3::splat(1.0)), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    let (centre, size) = ((lo + hi) * 0.5, (hi - lo).length());
    (0..n)
        .filter_map(|i| {
            let r = |d| random(72, i, 0, d);
            let origin = centre + (Vec3::new(r(0), r(1), r(2)) - 0.5) * size * 1.5;
            let dir = if i % 2 == 0 && !tris.is_empty() {
                let tri = tris[((r(3) * tris.len() as f32) as usize).min(tris.len() - 1)];
                let (a, b) = (r(4), r(5) * (1.0 - r(4)));
                tri[0] * (1.0 - a - b) + tri[1] * a + tri[2] * b - origin
            } else {
                Vec3::new(r(3), r(4), r(5)) * 2.0 - 1.0
            };
            let t_max = if i % 5 == 0 {
                r(6) * size
            } else {
                f32::INFINITY
            };
            Ray::new(origin, dir).ok().map(|ray| (ray, t_max))
        })
        .collect()
}

#[test]
fn the_readable_bvh_gives_the_naive_loops_and_obvhs_hits() {
    for (name, tris) in meshes() {
        let readable = ReadableBvh::build(&tris);
        let obvhs = Bvh::build(&tris);
        let (mut hits, mut ties) = (0, 0);
        let rays = rays(&tris, 10_000);
        for (ray, t_max) in &rays {
            let ours = readable.closest(ray, *t_max);
            let naive = closest_naive(&tris, ray, *t_max, Intersector::Watertight);
            let fast = obvhs
                .as_ref()
                .and_then(|b| b.closest(ray, *t_max, Intersector::Watertight));
            for (other, what) in [(naive, "naive loop"), (fast, "obvhs")] {
                assert!(
                    same_closest_hit(ours, other, &tris, ray),
                    "{name}: readable {ours:?} vs {what} {other:?} on {ray:?} to {t_max}"
                );
            }
            // The same watertight test on the same triangle: the same t, bit for bit.
            if let (Some(a), Some(b)) = (ours, naive) {
                hits += 1;
                if a.triangle == b.triangle {
                    assert_eq!(a.t.to_bits(), b.t.to_bits(), "{name}: {ray:?}");
                } else {
                    // A tie: coplanar faces (a block standing on the floor)
                    // or a shared edge. Both triangles really are hit there.
                    ties += 1;
                    for h in [a, b] {
                        let again = Intersector::Watertight
                            .intersect(ray, tris[h.triangle as usize], 0.0, f32::INFINITY)
                            .unwrap();
                        assert!((again.t - a.t).abs() <= 1e-6 * a.t, "{name}: {ray:?}");
                    }
                }
            }
        }
        assert!(ties * 50 <= hits, "{name}: {ties} ties in {hits} hits");
        let expect_hits = match name {
            "empty" => 0,
            "one triangle" => 1_000,
            _ => 4_000,
        };
        assert!(
            hits >= expect_hits,
            "{name}: only {hits} hits of {}",
            rays.len()
        );
    }
}

#[test]
fn every_triangle_is_in_exactly_one_leaf_of_bounded_size() {
    for (name, tris) in meshes() {
        let bvh = ReadableBvh::build(&tris);
        let mut seen = vec![0u32; tris.len()];
        for node in &bvh.nodes {
            if let NodeKind::Leaf { first, count } = node.kind {
                assert!(
                    (1..=MAX_LEAF as u32).contains(&count),
                    "{name}: leaf of {count}"
                );
                for &id in &bvh.order[first as usize..(first + count) as usize] {
                    seen[id as usize] += 1;
                    // The leaf's box holds its triangle.
                    for p in tris[id as usize] {
                        assert!(p.cmpge(node.bounds.min).all() && p.cmple(node.bounds.max).all());
                    }
                }
            }
        }
        assert!(seen.iter().all(|&s| s == 1), "{name}");
        // Median splits: about log₂ N deep, coincident centroids included.
        let bound = (tris.len().max(1) as f32).log2().ceil() as usize + 1;
        assert!(
            bvh.depth() <= bound,
            "{name}: depth {} > {bound}",
            bvh.depth()
        );
    }
}

#[test]
fn a_quarter_million_coincident_centroids_build_in_n_log_n() {
    // A quadratic build (splitting off one triangle at a time) would take
    // minutes here; median splits keep the depth at 18.
    let tris = coincident(1 << 18);
    let bvh = ReadableBvh::build(&tris);
    assert_eq!(bvh.depth(), 18);
    let ray = Ray::new(Vec3::new(0.0, 0.0, 10.0), -Vec3::Z).unwrap();
    let naive = closest_naive(&tris, &ray, f32::INFINITY, Intersector::Watertight);
    assert!(same_closest_hit(
        bvh.closest(&ray, f32::INFINITY),
        naive,
        &tris,
        &ray
    ));
    assert!(naive.is_some());
}

#[test]
fn the_traversal_exercise_passes_the_reference_and_fails_wrong_traversals() {
    use raystep::grading::counted::{self, ReadableBvh};
    let check = check_bvh_traversal(counted::closest_hit);
    assert!(check.passed(), "{check:?}");
    // Both depth views come with every verdict (`ch3 --student` shows them).
    assert!(check.images.is_some());
    // Stopping at the first leaf that hits: the nearest box first is not
    // always the nearest triangle.
    fn first_leaf(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
        let inv = ray.dir.recip();
        let mut stack = vec![0u32];
        if bvh.nodes.is_empty() {
            return None;
        }
        while let Some(n) = stack.pop() {
            let node = bvh.nodes[n as usize];
            if node.bounds.enter(ray, inv, t_max).is_none() {
                continue;
            }
            match node.kind {
                NodeKind::Leaf { first, count } => {
                    let mut best = None;
                    for &id in &bvh.order[first as usize..(first + count) as usize] {
                        let t_best = best.map_or(t_max, |h: Hit| h.t);
                        let hit = Intersector::Watertight.intersect(
                            ray,
                            bvh.tris[id as usize],
                            0.0,
                            t_best,
                        );
                        best = hit.map(|h| Hit { triangle: id, ..h }).or(best);
                    }
                    if best.is_some() {
                        return best;
                    }
                }
                NodeKind::Inner { left, right } => stack.extend([right, left]),
            }
        }
        None
    }
    let check = check_bvh_traversal(first_leaf);
    assert!(
        !check.passed() && check.detail.contains("differ"),
        "{check:?}"
    );
    assert!(check.images.is_some());
    // Ignoring t_max.
    let check = check_bvh_traversal(|b, r, _| counted::closest_hit(b, r, f32::INFINITY));
    assert!(
        !check.passed() && check.detail.contains("t_max"),
        "{check:?}"
    );
}

/// The grader measures the work a traversal may do against the book's
/// traversal run over the counted blocks (`grading::counted`): that copy
/// is the lesson's function line for line, and finds the same hits.
#[test]
fn the_counted_traversal_is_the_books_line_for_line() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |f: &str| std::fs::read_to_string(root.join(f)).unwrap();
    let body = |text: &str, from: &str| -> Vec<String> {
        let start = text.find(from).unwrap_or_else(|| panic!("no `{from}`"));
        let rest = &text[start..];
        let end = rest.find("\n}\n").expect("the function's end");
        // Anchor markers (the book shows the function in two parts) are
        // comments that mdBook drops; the code must match line for line.
        rest[..end]
            .lines()
            .map(|l| l.trim().to_string())
            .filter(|l| !l.starts_with("// ANCHOR"))
            .collect()
    };
    let signature = "pub fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {";
    let lesson = body(&read("src/ch3_ray_triangle/readable_bvh.rs"), signature);
    let counted = body(&read("src/grading/counted.rs"), signature);
    assert!(lesson.len() > 30, "{lesson:?}");
    assert_eq!(lesson, counted);
    // And the same hits, with work counted only for the counted blocks.
    use raystep::grading::counted;
    use raystep::grading::work::Work;
    let tris = soup(300);
    let lesson_tree = ReadableBvh::build(&tris);
    let tree = counted::ReadableBvh::of(&lesson_tree);
    for i in 0..500 {
        let r = |d| random(77, i, 0, d) * 2.0 - 1.0;
        let Ok(ray) = Ray::new(
            Vec3::new(r(0), r(1), r(2)) * 2.0,
            Vec3::new(r(3), r(4), r(5)),
        ) else {
            continue;
        };
        let before = Work::now();
        let want = closest_hit(&lesson_tree, &ray, f32::INFINITY);
        assert_eq!(
            Work::now().since(before).box_tests,
            0,
            "the lesson counts nothing"
        );
        let got = counted::closest_hit(&tree, &ray, f32::INFINITY);
        let work = Work::now().since(before);
        assert_eq!(format!("{got:?}"), format!("{want:?}"));
        assert!(work.box_tests > 0);
    }
}

/// `n` small triangles in four tight clusters far apart, most in one.
fn clusters(n: u64) -> Vec<[Vec3; 3]> {
    let centres = [
        Vec3::ZERO,
        Vec3::new(9.0, 0.0, 0.0),
        Vec3::new(0.0, 7.0, 1.0),
        Vec3::new(3.0, 3.0, 8.0),
    ];
    (0..n)
        .map(|i| {
            let r = |d| random(73, i, 0, d) * 2.0 - 1.0;
            let c = centres[if i % 8 < 5 { 0 } else { (i % 8 - 4) as usize }];
            let c = c + Vec3::new(r(0), r(1), r(2)) * 0.3;
            [0, 1, 2].map(|k| c + Vec3::new(r(3 + 3 * k), r(4 + 3 * k), r(5 + 3 * k)) * 0.02)
        })
        .collect()
}

#[test]
fn the_sah_tree_holds_every_triangle_once_and_finds_the_naive_hits() {
    let mut all = meshes();
    all.push(("clusters", clusters(2000)));
    for (name, tris) in all {
        let bvh = sah::build(&tris);
        let mut seen = vec![0u32; tris.len()];
        for node in &bvh.nodes {
            match node.kind {
                NodeKind::Leaf { first, count } => {
                    for &id in &bvh.order[first as usize..(first + count) as usize] {
                        seen[id as usize] += 1;
                        for p in tris[id as usize] {
                            assert!(
                                p.cmpge(node.bounds.min).all() && p.cmple(node.bounds.max).all()
                            );
                        }
                    }
                }
                NodeKind::Inner { left, right } => {
                    // Children after their parent, inside its box.
                    for c in [left, right] {
                        let child = bvh.nodes[c as usize].bounds;
                        assert!(c as usize > 0 && child.min.cmpge(node.bounds.min).all());
                        assert!(child.max.cmple(node.bounds.max).all(), "{name}");
                    }
                }
            }
        }
        assert!(seen.iter().all(|&s| s == 1), "{name}");
        for (ray, t_max) in rays(&tris, 2_000) {
            let ours = bvh.closest(&ray, t_max);
            let naive = closest_naive(&tris, &ray, t_max, Intersector::Watertight);
            assert!(
                same_closest_hit(ours, naive, &tris, &ray),
                "{name}: SAH tree {ours:?} vs naive {naive:?} on {ray:?} to {t_max}"
            );
        }
    }
}

#[test]
fn the_sah_tree_costs_less_than_the_median_tree() {
    let mut all = meshes();
    all.push(("clusters", clusters(2000)));
    for (name, tris) in all {
        let (ours, median) = (
            sah::tree_cost(&sah::build(&tris)),
            sah::tree_cost(&ReadableBvh::build(&tris)),
        );
        // A plane cannot separate one centroid: those stay one leaf.
        if name != "coincident centroids" {
            assert!(ours <= median * 1.000_001, "{name}: {ours} > {median}");
        }
        // Where the triangles cluster, the median cuts through clusters.
        if name == "clusters" {
            assert!(median >= 1.5 * ours, "{name}: {median} against {ours}");
        }
    }
    // Copies sharing one centroid: nothing to split, one leaf.
    let one = sah::build(&coincident(50));
    assert_eq!(one.nodes.len(), 1);
    // The split of a node whose boxes are all one cube: a leaf.
    let cube = [Vec3::ZERO, Vec3::ONE];
    let centroids = [0.2, 0.4, 0.6, 0.8].map(|x| Vec3::new(x, 0.5, 0.5));
    assert_eq!(sah::sah_split(&[cube; 4], &centroids), None);
}
