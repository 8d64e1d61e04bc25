//! Exercise 3.4, the closest hit through the readable BVH: every clause
//! of its contract, each failure named.
//!
//! The answers: the exact triangle and t of the reference on a stack of
//! triangles (cut short by t_max, seen from both sides), on every pixel of
//! the Cornell box and on rays from inside it, and nothing for an empty
//! tree. The work: on eight wavy sheets of triangles, where a traversal
//! that prunes opens a few boxes near the first sheet and one that does
//! not opens every sheet, the slab tests and triangle tests it makes
//! (counted by [`Work`]) against the reference's.

use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};

use glam::{Vec2, Vec3};

use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::geometry::Geometry;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::render::{films_from_sums, render_sum};
use crate::ch3_ray_triangle::triangle::{intersect_watertight, Hit};
use crate::core::sampling::random;
use crate::counted::{self, NodeKind, ReadableBvh};
use crate::exercise::{Check, Symptom};
use crate::scene::Scene;
use crate::work::Work;

pub use super::bvh_symptoms::*;

/// A BVH traversal as the exercise asks for it.
pub type TraversalFn = fn(&ReadableBvh, &Ray, f32) -> Option<Hit>;

/// The same t: `got` within 1e-5 of `want`, relative to `want` (the
/// watertight test gives the same t bit for bit for the same triangle and
/// ray; the tolerance only lets a different order of the same arithmetic
/// pass). An infinite or NaN `got` is never the same.
fn same_t(got: f32, want: f32) -> bool {
    (got - want).abs() <= 1e-5 * want.abs().max(1e-3)
}

/// The same barycentric coordinates, for a hit of the same triangle
/// (written so that a NaN differs).
fn same_uv(got: &Hit, want: &Hit) -> bool {
    (got.u - want.u).abs() <= 1e-5 && (got.v - want.v).abs() <= 1e-5
}

/// How `got` differs from the closest hit `want` of `ray` in (0, t_max)
/// through the triangles `tris`: `None` when it agrees, else the symptom
/// (or `Some(None)` for a difference without a name).
fn mismatch(
    got: Option<Hit>,
    want: Option<Hit>,
    tris: &[[Vec3; 3]],
    ray: &Ray,
    t_max: f32,
) -> Option<Option<Symptom>> {
    match (got, want) {
        (None, None) => None,
        (None, Some(_)) => Some(Some(MISSED_HIT)),
        (Some(g), _) if g.t > t_max => Some(Some(IGNORES_T_MAX)),
        (Some(_), None) => Some(None),
        (Some(g), Some(w)) if same_t(g.t, w.t) => {
            // Two triangles hit at the same t (a shared edge, coplanar
            // faces): either is right, if it really is hit there.
            let really_hit = |id: u32| {
                tris.get(id as usize)
                    .and_then(|&tri| intersect_watertight(ray, tri, 0.0, t_max))
                    .is_some_and(|h| same_t(h.t, w.t))
            };
            match g.triangle == w.triangle {
                true => (!same_uv(&g, &w)).then_some(None),
                false => (!really_hit(g.triangle)).then_some(Some(WRONG_TRIANGLE)),
            }
        }
        (Some(g), Some(w)) if g.t > w.t => Some(Some(NOT_CLOSEST)),
        _ => Some(None),
    }
}

/// Whether two closest hits of `ray` through `tris` agree: both miss, or
/// both hit at the same t (1e-5 relative) the same triangle, or two
/// triangles that both really are hit at that t (a shared edge, coplanar
/// faces).
pub fn same_closest_hit(a: Option<Hit>, b: Option<Hit>, tris: &[[Vec3; 3]], ray: &Ray) -> bool {
    mismatch(a, b, tris, ray, f32::INFINITY).is_none()
}

/// `f(bvh, ray, t_max)` and the work it did.
fn counted(f: TraversalFn, bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> (Option<Hit>, Work) {
    let before = Work::now();
    let hit = f(bvh, ray, t_max);
    (hit, Work::now().since(before))
}

/// Eight wavy sheets of 8 x 8 unit squares (two triangles each), one
/// above the other at z = 0 .. 7 and each vertex jittered by up to ±0.2 in
/// z: 1,024 triangles. A ray through them from above or below hits the
/// first sheet, and everything behind it can be skipped.
pub fn sheets() -> Vec<[Vec3; 3]> {
    let vertex = |i: u64, j: u64, k: u64| {
        let jitter = random(35, (k * 9 + j) * 9 + i, 0, 0) * 0.4 - 0.2;
        Vec3::new(i as f32, j as f32, k as f32 + jitter)
    };
    let mut tris = Vec::new();
    for k in 0..8 {
        for j in 0..8 {
            for i in 0..8 {
                let (a, b) = (vertex(i, j, k), vertex(i + 1, j, k));
                let (c, d) = (vertex(i + 1, j + 1, k), vertex(i, j + 1, k));
                tris.push([a, b, c]);
                tris.push([a, c, d]);
            }
        }
    }
    tris
}

/// Rays through [`sheets`]: half from above going down, half from below
/// going up, each from a random point over the sheets to a random point
/// of the middle.
pub fn sheet_rays(n: u64) -> Vec<Ray> {
    (0..n)
        .filter_map(|i| {
            let r = |d| 1.0 + 6.0 * random(36, i, 0, d);
            let z = if i % 2 == 0 { 12.0 } else { -5.0 };
            let from = Vec3::new(r(0), r(1), z);
            Ray::new(from, Vec3::new(r(2), r(3), 3.5) - from).ok()
        })
        .collect()
}

/// The closest hit of `ray` before `t_max` by testing every triangle in
/// turn: the answer a traversal must give, found without any tree (so the
/// grader does not check raystep's own traversal against itself).
fn every_triangle(tris: &[[Vec3; 3]], ray: &Ray, t_max: f32) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    for (id, tri) in tris.iter().enumerate() {
        let t_best = best.map_or(t_max, |h| h.t);
        if let Some(hit) = intersect_watertight(ray, *tri, 0.0, t_best) {
            best = Some(Hit {
                triangle: id as u32,
                ..hit
            });
        }
    }
    best
}

/// The grader of exercise 3.4. In order, each failing with its symptom:
/// an empty tree (`None`, no panic); the stack of `stack_cases`; the
/// Cornell box at 32 x 32, one ray per pixel centre, and 2,000 rays from
/// random points inside it in random directions; then [`sheet_rays`]
/// through [`sheets`], answers and work. Every answer must be the
/// answer of `every_triangle` (no BVH at all): the same t (1e-5
/// relative) and the same triangle (another only where it too is hit at
/// that t). The work must stay near the reference traversal's (see
/// [`work_verdict`]).
pub fn check_bvh_traversal(f: TraversalFn) -> Check {
    let reference = counted::closest_hit;
    let fail = |error: f64, detail: String, symptom: Option<Symptom>| Check {
        error,
        tolerance: 0.0,
        detail,
        images: None,
        symptom,
    };
    // An empty tree: no nodes at all.
    let progress = |what: &str| crate::progress(format_args!("calling closest_hit on {what}"));
    progress("an empty tree");
    let empty = ReadableBvh::build(&[]);
    let down = Ray::new(Vec3::Z, -Vec3::Z).expect("a ray");
    match catch_unwind(AssertUnwindSafe(|| f(&empty, &down, f32::INFINITY))) {
        Ok(None) => {}
        Ok(Some(hit)) => {
            return fail(
                1.0,
                format!("an empty tree: got {hit:?}, expected None"),
                None,
            )
        }
        Err(payload) => {
            let message = crate::panic_text(&*payload);
            if message.starts_with("not yet implemented") {
                resume_unwind(payload);
            }
            return fail(
                1.0,
                format!(
                    "an empty tree (no nodes, no triangles) panicked: \"{message}\"; \
                     expected None"
                ),
                Some(EMPTY_TREE),
            );
        }
    }
    // Answers, ray by ray.
    let mut rays_checked = 0usize;
    let mut wrong = 0usize;
    let mut first_wrong: Option<(String, Option<Symptom>)> = None;
    let mut triangle_tests = 0;
    let mut compare = |bvh: &ReadableBvh, ray: &Ray, t_max: f32, what: &dyn Fn() -> String| {
        let (got, work) = counted(f, bvh, ray, t_max);
        let want = every_triangle(&bvh.tris, ray, t_max);
        triangle_tests += work.triangle_tests;
        rays_checked += 1;
        if let Some(symptom) = mismatch(got, want, &bvh.tris, ray, t_max) {
            wrong += 1;
            if first_wrong.is_none() {
                let show = |h: Option<Hit>| match h {
                    Some(h) => format!("triangle {} at t = {}", h.triangle, h.t),
                    None => "no hit".to_string(),
                };
                first_wrong = Some((
                    format!(
                        "{} (t_max = {t_max}): got {}, expected {}",
                        what(),
                        show(got),
                        show(want)
                    ),
                    symptom,
                ));
            }
        }
    };
    progress("a stack of 16 triangles");
    let (stack, cases) = super::bvh_cases::stack_cases();
    for (ray, t_max, what) in &cases {
        compare(&stack, ray, *t_max, &|| what.to_string());
    }
    // The same triangles in a tree of one leaf that holds them all (a
    // tree's leaves may hold any number).
    let mut one_leaf = ReadableBvh {
        nodes: stack.nodes[..1].to_vec(),
        order: stack.order.clone(),
        tris: stack.tris.clone(),
    };
    one_leaf.nodes[0].kind = NodeKind::Leaf {
        first: 0,
        count: one_leaf.order.len() as u32,
    };
    for (ray, t_max, what) in &cases {
        compare(&one_leaf, ray, *t_max, &|| {
            format!("{what}, in a tree of one leaf")
        });
    }
    // The Cornell box, primary rays and rays from inside it.
    let scene = Scene::builtin()
        .with_resolution(32, 32)
        .expect("a valid resolution");
    let camera = Camera::of(&scene);
    let geometry = Geometry::new(&scene);
    let bvh = ReadableBvh::build(&geometry.triangles.tris);
    progress("the Cornell box's pixels and rays from inside it");
    let mut rays = super::bvh_cases::cornell_inside_rays(&geometry.triangles.tris);
    for y in 0..camera.height {
        for x in 0..camera.width {
            let ray = camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
            rays.push((ray, format!("the Cornell box, pixel ({x}, {y})")));
        }
    }
    // Each of them whole, then cut short before or just past its hit.
    let hit_t = |ray: &Ray| every_triangle(&bvh.tris, ray, f32::INFINITY).map(|h| h.t);
    let cut = super::bvh_cases::cut_short(&rays, hit_t);
    let whole = rays
        .into_iter()
        .map(|(ray, what)| (ray, f32::INFINITY, what));
    for (ray, t_max, what) in whole.chain(cut) {
        compare(&bvh, &ray, t_max, &|| what.clone());
    }
    // A ray along -z, 10⁻⁶ inside the side x = 10 of a flat triangle's box
    // (its direction's x exactly 0, where 1/d is infinite), from 1,000
    // away: the slab test must keep the box for the hit.
    let wall = ReadableBvh::build(&[[
        Vec3::new(-10.0, -10.0, 0.0),
        Vec3::new(10.0, -10.0, 0.0),
        Vec3::new(10.0, 10.0, 0.0),
    ]]);
    let inside = Ray::new(Vec3::new(10.0 - 1e-6, 0.0, 1000.0), -Vec3::Z).expect("a ray");
    compare(&wall, &inside, f32::INFINITY, &|| {
        "a ray along -z 10⁻⁶ inside its box's side x = 10, the hit 1,000 away".to_string()
    });
    for (ray, what) in super::bvh_cases::side_rays() {
        compare(&wall, &ray, f32::INFINITY, &|| what.clone());
    }
    // A triangle 2·10⁻⁹ across, 1 away, with t_max = 1: its hit is at
    // t_max exactly, and so is the entry to its box (the box's padding is
    // far below the rounding of 1), and (0, t_max] keeps both.
    let speck = ReadableBvh::build(&[[
        Vec3::new(-1e-9, -1e-9, 0.0),
        Vec3::new(1e-9, -1e-9, 0.0),
        Vec3::new(0.0, 1e-9, 0.0),
    ]]);
    let above = Ray::new(Vec3::Z, -Vec3::Z).expect("a ray");
    compare(&speck, &above, 1.0, &|| {
        "a triangle 2·10⁻⁹ across, 1 away, t_max = 1: its hit and the entry to its box both at t_max"
            .to_string()
    });
    let (far, far_rays) = super::bvh_cases::far_triangle();
    for (ray, what) in &far_rays {
        compare(&far, ray, f32::INFINITY, &|| what.clone());
    }
    progress("rays at a flat triangle");
    for far in [false, true] {
        let (flat, flat_rays) = super::bvh_cases::flat_triangle(far);
        for (ray, what) in &flat_rays {
            compare(&flat, ray, f32::INFINITY, &|| what.clone());
        }
    }
    progress("a chain deeper than a fixed stack");
    for (deep, deep_rays) in [super::bvh_deep::deep_chain(), super::bvh_deep::long_chain()] {
        let deep = ReadableBvh::of(&deep);
        for (ray, what) in &deep_rays {
            compare(&deep, ray, f32::INFINITY, &|| what.clone());
        }
    }
    // The sheets: the same answers, and the work.
    progress("rays through eight sheets of triangles");
    let sheets = ReadableBvh::build(&sheets());
    let rays = sheet_rays(200);
    let (mut mine, mut theirs) = (Work::default(), Work::default());
    for (i, ray) in rays.iter().enumerate() {
        let (_, w) = counted(f, &sheets, ray, f32::INFINITY);
        let (_, r) = counted(reference, &sheets, ray, f32::INFINITY);
        for (sum, w) in [(&mut mine, w), (&mut theirs, r)] {
            sum.box_tests += w.box_tests;
            sum.triangle_tests += w.triangle_tests;
            sum.shrinks += w.shrinks;
        }
        compare(&sheets, ray, f32::INFINITY, &|| {
            format!(
                "ray {i} through eight sheets of triangles, from {:.2}",
                ray.origin
            )
        });
    }
    // The depth views of both, for the images of a failed check.
    let film = |t: TraversalFn| {
        let (sums, _) = render_sum(&camera, &geometry, 0..camera.height, 0..1, 1, 0, &|r| {
            t(&bvh, r, f32::INFINITY)
        });
        films_from_sums(&camera, &sums, 1).swap_remove(0)
    };
    // Always: `ch3 --student` shows them whether or not they match.
    let images = Some((film(f), film(reference)));
    if let Some((mut first, mut symptom)) = first_wrong {
        // Another triangle test than the watertight one leaks through
        // edges and vertices: that explains the difference.
        if triangle_tests == 0 {
            first += "; your traversal never called intersect_watertight";
            symptom = Some(BYPASSES_BLOCKS);
        }
        let check = Check {
            images,
            ..fail(
                wrong as f64 / rays_checked as f64,
                format!("{wrong} of {rays_checked} rays differ; first: {first}"),
                None,
            )
        };
        return match symptom {
            Some(s) => check.with_symptom(s),
            None => check,
        };
    }
    let (error, tolerance, detail, symptom) =
        work_verdict(mine, theirs, rays.len() as u64, sheets.tris.len() as u64);
    Check {
        error,
        tolerance,
        detail: format!("all {rays_checked} rays match; {detail}"),
        images,
        symptom,
    }
}

/// Judges a traversal's work on [`sheet_rays`] through [`sheets`]
/// against the reference's: (error, tolerance, what was measured, the
/// symptom of a failure).
///
/// Measured on the 200 rays (slab tests, triangle tests, shrinks of the
/// best t; `tests/project/mutants/ch3.rs` asserts these ranges):
///
/// | traversal | slab tests | triangle tests | shrinks |
/// |---|---|---|---|
/// | the reference (stack, nearer child first) | 3,854 | 412 | 91 |
/// | recursive, the far box tested again after the near subtree | 4,458 | 412 | 91 |
/// | nearer child by box centre along the ray | 3,854 | 412 | 91 |
/// | boxes skipped when entered, never when popped | 4,788 | 666 | 159 |
/// | always the left child first | 7,198 | 1,638 | 645 |
/// | farther child first | 11,826 | 3,482 | 1,450 |
/// | no pruning (boxes against t_max, no skip) | 11,826 | 3,482 | 200 |
/// | the naive loop | 0 | 204,800 | 885 |
///
/// Right traversals stay within 1.62 times the reference's work (the
/// less pruned one; the others within 1.16); the wrong ones make at least
/// 1.87 times its slab tests and 3.98 times its triangle tests. The limit,
/// [`WORK_LIMIT`] = 2, sits between. Back to
/// front shows in the shrinks (7 to 16 times the reference's, against 2.2
/// without pruning): above [`SHRINK_LIMIT`] = 4 the symptom is the order.
pub fn work_verdict(
    mine: Work,
    reference: Work,
    rays: u64,
    triangles: u64,
) -> (f64, f64, String, Option<Symptom>) {
    let ratio = |a: u64, b: u64| a as f64 / b.max(1) as f64;
    let measured = format!(
        "on {rays} rays through eight sheets ({triangles} triangles) your traversal made \
         {} slab tests and {} triangle tests (the reference: {} and {})",
        mine.box_tests, mine.triangle_tests, reference.box_tests, reference.triangle_tests
    );
    let tri = ratio(mine.triangle_tests, reference.triangle_tests);
    let boxes = ratio(mine.box_tests, reference.box_tests);
    let limit = WORK_LIMIT;
    if mine.triangle_tests == 0 || mine.box_tests == 0 {
        if mine.triangle_tests >= rays * triangles / 2 {
            return (tri, limit, measured, Some(EVERY_TRIANGLE));
        }
        let which = if mine.triangle_tests == 0 {
            "intersect_watertight"
        } else {
            "Aabb::enter"
        };
        return (
            f64::INFINITY,
            limit,
            format!("{measured}: the right hits, but never through {which}"),
            Some(BYPASSES_BLOCKS),
        );
    }
    if mine.triangle_tests >= rays * triangles / 2 {
        return (tri, limit, measured, Some(EVERY_TRIANGLE));
    }
    let worst = tri.max(boxes);
    if worst > limit {
        let shrinks = ratio(mine.shrinks, reference.shrinks);
        let symptom = if shrinks > SHRINK_LIMIT {
            FAR_FIRST
        } else {
            NO_PRUNING
        };
        return (
            worst,
            limit,
            format!(
                "{measured}: {worst:.1} times the reference's work, over the {limit} allowed; \
                 the best t shrank {} times (the reference: {})",
                mine.shrinks, reference.shrinks
            ),
            Some(symptom),
        );
    }
    (worst, limit, measured, None)
}

/// The most work allowed (slab tests or triangle tests), as a multiple of
/// the reference's: see [`work_verdict`].
pub const WORK_LIMIT: f64 = 2.0;
/// Shrinks of the best t above this multiple of the reference's say the
/// traversal goes back to front: see [`work_verdict`].
pub const SHRINK_LIMIT: f64 = 4.0;
