//! The fifth fresh set (2026-11-29): plausible wrong solutions written by
//! two testers from the stubs' contracts before reading the checks, each
//! the course's solution (`tests/project/solutions/`) with one change,
//! mostly a shortcut that holds on the usual inputs only: a cache kept
//! between calls, a threshold or a snap where the contract has none, a
//! sample skipped, a tolerance taken at the wrong point, a cosine's sign
//! dropped. The grader now catches each: it must fail under every seed
//! tried, naming its symptom where the grader names one. The testers'
//! correct alternatives that no other test covers must pass under every
//! seed. Where one copies a long solution body, it is a one-line call of
//! that solution written once with knobs ([`super::knobs`]), its change a
//! knob turned.
//!
//! The mutant that keeps state between calls keeps it in a
//! `thread_local`, as the tester wrote; [`super::under_seeds`] runs the
//! seeds one after another on this thread, so each seed's run starts from
//! the state a fresh process would have (reset in the closure that runs
//! the check), and no seed's run can pass on what an earlier one left
//! behind.

use std::cell::Cell;
use std::f32::consts::{FRAC_1_PI, PI, TAU};

use glam::{Mat3, Mat4, Vec2, Vec3, Vec4};
use raystep::ch1_projection::camera::Camera;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::grading::counted::{intersect_watertight, Hit, NodeKind, ReadableBvh};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::paths::{self, PathScene};
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5, ch6, refraction};

use super::knobs::{
    self, BvhKnobs, Cut, EdgeKnobs, Knobs, LightCos, MarchEps, MarchKnobs, NormalStep, PathKnobs,
    Plane, RasterKnobs, SahKnobs, SceneKnobs, Survival, TMin, Weights,
};
use super::{fails_every, passes_every};

/// The seeds every mutant must fail under (and every alternative pass
/// under): the testers' three and one more.
const SEEDS: [u64; 4] = [7, 8, 9, 0x2026_1131];

/// The path loop's check traces 200,000 paths in a furnace per seed: its
/// mutants and alternatives are tried under the first two seeds only.
const PATH_SEEDS: &[u64] = &[7, 8];

fn fails(what: &str, symptom: Option<&str>, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, symptom, check);
}

fn passes(what: &str, check: impl Fn() -> Check) {
    passes_every(&SEEDS, what, check);
}

// ---- 1.1 project_point -------------------------------------------------------

/// Through the angles: tan(atan2(x, -z)) for x / -z, rounded twice.
fn project_via_angles(p: Vec3) -> Option<Vec2> {
    if p.z.is_nan() || p.z >= 0.0 {
        return None;
    }
    Some(Vec2::new(p.x.atan2(-p.z).tan(), p.y.atan2(-p.z).tan()))
}

/// Correct: homogeneous coordinates (x, y, z, -z), divided by w.
fn project_homogeneous(p: Vec3) -> Option<Vec2> {
    if p.z.is_nan() || p.z >= 0.0 {
        return None;
    }
    let h = Vec4::new(p.x, p.y, p.z, -p.z);
    Some(Vec2::new(h.x / h.w, h.y / h.w))
}

#[test]
fn project_point_mistake_fails() {
    fails("through the angles", None, || {
        ch1::check_project_point(project_via_angles)
    });
    passes("homogeneous, divided by w", || {
        ch1::check_project_point(project_homogeneous)
    });
}

// ---- 1.2 look_at ----------------------------------------------------------------

/// Correct: the camera's frame in world space, inverted.
fn look_at_inverse(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    let z = (eye - target).normalize();
    let x = up.cross(z).normalize();
    let y = z.cross(x);
    Mat4::from_cols(x.extend(0.0), y.extend(0.0), z.extend(0.0), eye.extend(1.0)).inverse()
}

/// Correct: y as up with its part along z taken away, then x = y × z.
fn look_at_gram_schmidt(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    let z = (eye - target).normalize();
    let y = (up - up.dot(z) * z).normalize();
    let x = y.cross(z);
    let rotation = Mat4::from_cols(
        x.extend(0.0),
        y.extend(0.0),
        z.extend(0.0),
        Vec3::ZERO.extend(1.0),
    )
    .transpose();
    rotation * Mat4::from_translation(-eye)
}

#[test]
fn look_at_alternatives_pass() {
    passes("the camera's frame inverted", || {
        ch1::check_look_at(look_at_inverse)
    });
    passes("up with its part along z taken away", || {
        ch1::check_look_at(look_at_gram_schmidt)
    });
}

// ---- 1.3 draw_edges -------------------------------------------------------------

/// An end less than 1e-4 behind the near plane kept: it projects from
/// behind the plane, past the image.
fn edges_eps_behind(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    knobs::draw_edges(EdgeKnobs::with(|k| k.behind = 1e-4), camera, a, b, near)
}

/// Correct: the cut by glam's `lerp`, (1 - s) from + s to.
fn edges_lerp(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    knobs::draw_edges(EdgeKnobs::with(|k| k.cut = Cut::Lerp), camera, a, b, near)
}

#[test]
fn draw_edges_mistake_fails() {
    fails(
        "an end 1e-4 behind kept",
        Some("the cut is not on the near plane"),
        || ch1::check_draw_edges(edges_eps_behind),
    );
    passes("the cut by lerp", || ch1::check_draw_edges(edges_lerp));
}

// ---- 2.1 edge_function ----------------------------------------------------------

thread_local! {
    /// The last a and its edge vector b - a, as the tester's cache kept
    /// them.
    static EDGE_LAST: Cell<Option<(Vec2, Vec2)>> = const { Cell::new(None) };
}

/// A cache of the edge vector keyed on a alone: another edge from the
/// same a gets the last one's b - a.
fn edge_cache_a(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    let e = EDGE_LAST.with(|c| match c.get() {
        Some((la, e)) if la == a => e,
        _ => {
            let e = b - a;
            c.set(Some((a, e)));
            e
        }
    });
    e.perp_dot(p - a)
}

/// Correct: (a - p) ⊥· (b - p), the same doubled area seen from p.
fn edge_from_p(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (a - p).perp_dot(b - p)
}

#[test]
fn edge_function_mistake_fails() {
    fails("a cache keyed on a", None, || {
        // Each seed's run starts with an empty cache, as a fresh process.
        EDGE_LAST.with(|c| c.set(None));
        ch2::check_edge_function(edge_cache_a)
    });
    passes("seen from p", || ch2::check_edge_function(edge_from_p));
}

// ---- 2.2 barycentric ------------------------------------------------------------

fn area2(a: Vec2, b: Vec2, c: Vec2) -> f32 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

/// The whole as the sum of the three parts: a p far outside cancels it.
fn barycentric_sum_whole(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    let s = Vec3::new(area2(pj, pk, p), area2(pk, pi, p), area2(pi, pj, p));
    let whole = s.x + s.y + s.z;
    if whole == 0.0 {
        return None;
    }
    Some(s / whole)
}

/// The solution's, renormalised to sum to 1: near the triangle as right
/// as the solution, but for a point far outside the sum of the φ cancels
/// (off by about ε · max|φ|² there; taken for a right alternative until
/// the thirty-fifth fresh set's points 10 to 10⁴ times the triangle's
/// size away, where the contract asks 1e-5 of the largest |φ|).
fn barycentric_renormalised(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    let whole = area2(pi, pj, pk);
    if whole == 0.0 {
        return None;
    }
    let phi = Vec3::new(area2(pj, pk, p), area2(pk, pi, p), area2(pi, pj, p)) / whole;
    Some(phi / (phi.x + phi.y + phi.z))
}

#[test]
fn barycentric_mistake_fails() {
    fails(
        "the whole as the parts' sum",
        Some("coordinates belong to other corners"),
        || ch2::check_barycentric(barycentric_sum_whole),
    );
    fails("renormalised", None, || {
        ch2::check_barycentric(barycentric_renormalised)
    });
}

// ---- 2.3 depth_test -------------------------------------------------------------

/// `total_cmp`: -0 is nearer than +0, and a NaN z is nearer or farther by
/// its sign bit.
fn depth_total_cmp(depth: &mut [f32], index: usize, z: f32) -> bool {
    let nearer = z.total_cmp(&depth[index]) == std::cmp::Ordering::Less;
    if nearer {
        depth[index] = z;
    }
    nearer
}

/// Only a finite z stored: -∞ passes the test, and the buffer keeps the
/// old depth.
fn depth_finite_store(depth: &mut [f32], index: usize, z: f32) -> bool {
    let nearer = z < depth[index];
    if nearer && z.is_finite() {
        depth[index] = z;
    }
    nearer
}

#[test]
fn depth_test_mistakes_fail() {
    fails("total_cmp", None, || ch2::check_depth_test(depth_total_cmp));
    fails("only a finite z stored", None, || {
        ch2::check_depth_test(depth_finite_store)
    });
}

// ---- 2.4 rasterize_triangle -----------------------------------------------------

/// A near plane of the rasterizer's own: a sample nearer than 0.1 is not
/// drawn.
fn raster_near_skip(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    let k = RasterKnobs::with(|k| k.near = Some(0.1));
    knobs::rasterize(k, v, c, (w, h), d, i);
}

/// The stored depth clamped to 1e3: a farther triangle drawn later wins
/// where it should lose.
fn raster_clamp_depth(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    let k = RasterKnobs::with(|k| k.depth_clamp = Some(1.0e3));
    knobs::rasterize(k, v, c, (w, h), d, i);
}

/// Correct: the barycentric weights first, each then over its z.
fn raster_bary_first(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    let k = RasterKnobs::with(|k| k.weights = Weights::BaryFirst);
    knobs::rasterize(k, v, c, (w, h), d, i);
}

#[test]
fn rasterize_triangle_mistakes_fail() {
    fails(
        "a near plane of 0.1",
        Some("the nearer surface did not win"),
        || ch2::check_rasterize_triangle(raster_near_skip),
    );
    fails(
        "the stored depth clamped to 1e3",
        // (The quad 10¹³ m away shows the clamp first.)
        Some("the wrong depth at a sample"),
        || ch2::check_rasterize_triangle(raster_clamp_depth),
    );
    passes("the barycentric weights first", || {
        ch2::check_rasterize_triangle(raster_bary_first)
    });
}

// ---- 3.1 ray_plane --------------------------------------------------------------

/// None for an origin on the plane: a ray starting on it crosses at 0.
fn plane_start_none(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let denom = n.dot(d);
    if denom == 0.0 {
        return None;
    }
    let num = c - n.dot(o);
    if num == 0.0 {
        return None;
    }
    Some(num / denom)
}

/// |t| under 1e-6 snapped to 0: a short d's small t is lost.
fn plane_snap_zero(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let denom = n.dot(d);
    if denom == 0.0 {
        return None;
    }
    let t = (c - n.dot(o)) / denom;
    Some(if t.abs() < 1e-6 { 0.0 } else { t })
}

/// Correct: along the unit direction, then over |d|.
fn plane_unit_d(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let len = d.length();
    let denom = n.dot(d / len);
    if denom == 0.0 || n.dot(d) == 0.0 {
        return None;
    }
    Some((c - n.dot(o)) / denom / len)
}

#[test]
fn ray_plane_mistakes_fail() {
    fails("None for an origin on the plane", None, || {
        ch3::check_ray_plane(plane_start_none)
    });
    fails("|t| < 1e-6 snapped to 0", None, || {
        ch3::check_ray_plane(plane_snap_zero)
    });
    passes("along the unit direction", || {
        ch3::check_ray_plane(plane_unit_d)
    });
}

// ---- 3.2 barycentric_inside -----------------------------------------------------

/// Correct: inside when p is on the inner side of all three edges, then
/// the solution's (u, v).
fn inside_same_side(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    let (e1, e2, q) = (tri[1] - tri[0], tri[2] - tri[0], p - tri[0]);
    let n = e1.cross(e2);
    let nn = n.dot(n);
    if nn == 0.0 {
        return None;
    }
    let sides = [
        n.dot(e1.cross(p - tri[0])),
        n.dot((tri[2] - tri[1]).cross(p - tri[1])),
        n.dot((tri[0] - tri[2]).cross(p - tri[2])),
    ];
    if sides.iter().any(|&s| s < 0.0) {
        return None;
    }
    Some((n.dot(q.cross(e2)) / nn, n.dot(e1.cross(q)) / nn))
}

#[test]
fn barycentric_inside_alternative_passes() {
    passes("on the inner side of each edge", || {
        ch3::check_barycentric_inside(inside_same_side)
    });
}

// ---- 3.3 moller_trumbore --------------------------------------------------------

/// Correct: (u, v, t) as the inverse of the matrix (e1, e2, -d) times s.
fn moller_inverse(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let (e1, e2, s) = (tri[1] - tri[0], tri[2] - tri[0], o - tri[0]);
    if e1.dot(e2.cross(-d)) == 0.0 {
        return None;
    }
    let x = Mat3::from_cols(e1, e2, -d).inverse() * s;
    let (u, v, t) = (x.x, x.y, x.z);
    if u < 0.0 || v < 0.0 || u + v > 1.0 || t <= 0.0 {
        return None;
    }
    Some((t, u, v))
}

#[test]
fn moller_trumbore_alternative_passes() {
    passes("the matrix inverted", || {
        ch3::check_moller_trumbore(moller_inverse)
    });
}

// ---- 3.4 bvh_traversal ----------------------------------------------------------

/// The box's entry t as the leaf's t_min: a triangle poking out of its box
/// in front is missed.
fn bvh_t_min_enter(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    let k = BvhKnobs::with(|k| k.t_min = TMin::BoxEntry);
    knobs::closest_hit(k, bvh, ray, t_max)
}

/// Correct: recursive, each box entered as it is visited, the nearer child
/// by its box's centre along the ray.
fn bvh_visit_box(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    fn visit(bvh: &ReadableBvh, ray: &Ray, inv: Vec3, node: u32, best: &mut (f32, Option<Hit>)) {
        let Some(t_enter) = bvh.nodes[node as usize].bounds.enter(ray, inv, best.0) else {
            return;
        };
        if t_enter > best.0 {
            return;
        }
        match bvh.nodes[node as usize].kind {
            NodeKind::Leaf { first, count } => {
                for &id in &bvh.order[first as usize..(first + count) as usize] {
                    if let Some(hit) = intersect_watertight(ray, bvh.tris[id as usize], 0.0, best.0)
                    {
                        *best = (
                            hit.t,
                            Some(Hit {
                                triangle: id,
                                ..hit
                            }),
                        );
                    }
                }
            }
            NodeKind::Inner { left, right } => {
                let centre = |k: u32| {
                    let b = bvh.nodes[k as usize].bounds;
                    ((b.min + b.max) * 0.5 - ray.origin).dot(ray.dir)
                };
                let kids = if centre(right) < centre(left) {
                    [right, left]
                } else {
                    [left, right]
                };
                for child in kids {
                    visit(bvh, ray, inv, child, best);
                }
            }
        }
    }
    let inv = ray.dir.recip();
    bvh.nodes.first()?.bounds.enter(ray, inv, t_max)?;
    let mut best = (t_max, None);
    visit(bvh, ray, inv, 0, &mut best);
    best.1
}

#[test]
fn bvh_traversal_mistake_fails() {
    fails("the box's entry as t_min", Some("misses a hit"), || {
        ch3::check_bvh_traversal(bvh_t_min_enter)
    });
    passes("each box entered as visited", || {
        ch3::check_bvh_traversal(bvh_visit_box)
    });
}

// ---- 3.5 sah --------------------------------------------------------------------

/// Correct: the solution's sweep, the plane midway between the two
/// centroids (at the upper one where the midpoint rounds down to the
/// lower).
fn sah_midway(b: &[[Vec3; 2]], c: &[Vec3]) -> Option<(usize, f32)> {
    knobs::sah_sweep(SahKnobs::with(|k| k.plane = Plane::MidwaySafe), b, c)
}

#[test]
fn sah_alternative_passes() {
    passes("the plane midway", || ch3::check_sah(sah_midway));
}

// ---- 4.1 sphere_sdf -------------------------------------------------------------

/// |d| under 1e-4 snapped to 0: a point near the surface is on it.
fn sdf_snap_surface(p: Vec3, center: Vec3, radius: f32) -> f32 {
    let d = (p - center).length() - radius;
    if d.abs() < 1e-4 {
        0.0
    } else {
        d
    }
}

/// Correct: the length by two `hypot`s.
fn sdf_hypot(p: Vec3, center: Vec3, radius: f32) -> f32 {
    let v = p - center;
    v.x.hypot(v.y).hypot(v.z) - radius
}

#[test]
fn sphere_sdf_mistake_fails() {
    fails("|d| < 1e-4 snapped to 0", None, || {
        ch4::check_sphere_sdf(sdf_snap_surface)
    });
    passes("by hypot", || ch4::check_sphere_sdf(sdf_hypot));
}

// ---- 4.2 sphere_trace -----------------------------------------------------------

/// Correct: t summed in f64, each step's point from t rounded to f32.
fn trace_f64_t(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, e: f32, n: u32, m: f32) -> Option<f32> {
    knobs::sphere_trace(MarchKnobs::with(|k| k.t_f64 = true), f, (o, d), e, n, m)
}

#[test]
fn sphere_trace_alternative_passes() {
    passes("t in f64", || ch4::check_sphere_trace(trace_f64_t));
}

// ---- 4.3 gradient_normal --------------------------------------------------------

/// Correct: the differences times 0.5 / h, +z where they vanish.
fn normal_fallback_z(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let partial = |axis: Vec3| sdf(p + axis * h) - sdf(p - axis * h);
    let g = Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z)) * (0.5 / h);
    g.try_normalize().unwrap_or(Vec3::Z)
}

#[test]
fn gradient_normal_alternative_passes() {
    passes("+z where the gradient vanishes", || {
        ch4::check_gradient_normal(normal_fallback_z)
    });
}

// ---- 4.4 trace_scene ------------------------------------------------------------

/// The normal's step ε at the origin: far from the origin the step is
/// the origin's tiny ε, and the gradient rounds away.
fn scene_h_at_origin(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    knobs::trace_scene(SceneKnobs::with(|k| k.h = NormalStep::AtOrigin), f, o, d, m)
}

/// The ε of the point before the step: a far hit is judged with a nearer
/// point's tighter ε.
fn scene_eps_before(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    let k = SceneKnobs::with(|k| k.eps = MarchEps::AtPointBefore);
    knobs::trace_scene(k, f, o, d, m)
}

/// Correct: d where the gradient vanishes, then turned to face the ray as
/// every normal is (so -d).
fn scene_fallback_dir(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    knobs::trace_scene(SceneKnobs::with(|k| k.fallback_along = true), f, o, d, m)
}

#[test]
fn trace_scene_mistakes_fail() {
    fails("the normal's step ε at the origin", None, || {
        ch4::check_trace_scene(scene_h_at_origin)
    });
    fails(
        "the ε of the point before the step",
        Some("fixed ε"),
        || ch4::check_trace_scene(scene_eps_before),
    );
    passes("d where the gradient vanishes, turned", || {
        ch4::check_trace_scene(scene_fallback_dir)
    });
}

// ---- 5.2 cosine_hemisphere ------------------------------------------------------

/// The square pushed radially onto the disk: the corners crowd the rim,
/// the density is not uniform on the disk.
fn cosine_radial_square(u: Vec2) -> (Vec3, f32) {
    let v = 2.0 * u - Vec2::ONE;
    let r = v.x.abs().max(v.y.abs());
    let d = if v.length_squared() > 0.0 {
        v.normalize() * r
    } else {
        Vec2::ZERO
    };
    let z = (1.0 - d.length_squared()).max(0.0).sqrt();
    (Vec3::new(d.x, d.y, z), z / PI)
}

/// The concentric map's radius with the square's own angle atan2(b, a):
/// the same radial crowding.
fn cosine_concentric_atan2(u: Vec2) -> (Vec3, f32) {
    let (a, b) = (2.0 * u.x - 1.0, 2.0 * u.y - 1.0);
    let r = if a == 0.0 && b == 0.0 {
        0.0
    } else if a.abs() > b.abs() {
        a
    } else {
        b
    };
    let phi = b.atan2(a);
    let (x, y) = (r.abs() * phi.cos(), r.abs() * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    (Vec3::new(x, y, z), z / PI)
}

/// Correct: the radius from 1 - u.x, z from u.x, φ from 1 - u.y.
fn cosine_one_minus(u: Vec2) -> (Vec3, f32) {
    let r = (1.0 - u.x).sqrt();
    let phi = TAU * (1.0 - u.y);
    let z = u.x.sqrt();
    (Vec3::new(r * phi.cos(), r * phi.sin(), z), z * FRAC_1_PI)
}

#[test]
fn cosine_hemisphere_mistakes_fail() {
    fails(
        "the square pushed radially",
        Some("directions not distributed as cos θ"),
        || ch5::check_cosine_hemisphere(cosine_radial_square),
    );
    fails(
        "the concentric radius, the square's angle",
        Some("directions not distributed as cos θ"),
        || ch5::check_cosine_hemisphere(cosine_concentric_atan2),
    );
    passes("from 1 - u", || {
        ch5::check_cosine_hemisphere(cosine_one_minus)
    });
}

// ---- 5.4 area_pdf ---------------------------------------------------------------

/// A guard at d² < 1e-6: a light point very near gets pdf 0.
fn area_pdf_d2_guard(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    let to = x - y;
    let d2 = to.length_squared();
    if d2 < 1e-6 {
        return 0.0;
    }
    let cos = n_light.dot(to / d2.sqrt()).abs();
    if cos == 0.0 {
        0.0
    } else {
        pdf_area * d2 / cos
    }
}

/// Correct: the signed cosine, the absolute value taken of the quotient.
fn area_pdf_abs_after(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    let to = y - x;
    let d = to.length();
    let c = n_light.dot(to) / d;
    if c == 0.0 {
        return 0.0;
    }
    (pdf_area * d * d / c).abs()
}

#[test]
fn area_pdf_mistake_fails() {
    fails("a guard at d² < 1e-6", None, || {
        ch5::check_area_pdf(area_pdf_d2_guard)
    });
    passes("the absolute value after", || {
        ch5::check_area_pdf(area_pdf_abs_after)
    });
}

// ---- 5.5 direct_light -----------------------------------------------------------

/// Correct: the light's area pdf turned into a solid-angle pdf, the
/// estimate ρ/π Le cos / pdf_ω.
#[allow(clippy::too_many_arguments)]
fn direct_solid_angle(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: &dyn Fn(Vec3, Vec3) -> bool,
) -> Vec3 {
    let to = y - p;
    let d = to.length();
    let wi = to / d;
    let (cos, cos_light) = (n.dot(wi), -n_light.dot(wi));
    if cos.is_nan() || cos <= 0.0 || cos_light.is_nan() || cos_light <= 0.0 || !visible(p, y) {
        return Vec3::ZERO;
    }
    let pdf = (1.0 / area) * d * d / cos_light;
    rho * le * (cos / (PI * pdf))
}

#[test]
fn direct_light_alternative_passes() {
    passes("by the solid-angle pdf", || {
        ch5::check_direct_light(direct_solid_angle)
    });
}

// ---- 5.6 solid_angle ------------------------------------------------------------

/// Correct: the signed triple product, the absolute value of the angle.
fn solid_abs_result(p: Vec3, tri: [Vec3; 3]) -> f32 {
    let (a, b, c) = (tri[0] - p, tri[1] - p, tri[2] - p);
    let numerator = a.dot((tri[1] - tri[0]).cross(tri[2] - tri[0]));
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    (2.0 * numerator.atan2(denominator)).abs()
}

#[test]
fn solid_angle_alternative_passes() {
    passes("the absolute value after", || {
        ch5::check_solid_angle(solid_abs_result)
    });
}

// ---- 5.7 spot -------------------------------------------------------------------

/// Correct: the band's cos θi - cos θo as 2 sin((θo + θi)/2) sin((θo -
/// θi)/2).
fn spot_product_of_sines(intensity: Vec3, inner: f32, outer: f32) -> Vec3 {
    let one_minus_cos_inner = 2.0 * (inner / 2.0).sin().powi(2);
    let band = 2.0 * ((outer + inner) / 2.0).sin() * ((outer - inner) / 2.0).sin();
    intensity * (2.0 * PI * (one_minus_cos_inner + 0.5 * band))
}

#[test]
fn spot_alternative_passes() {
    passes("the band as a product of sines", || {
        ch5::check_spot(spot_product_of_sines)
    });
}

// ---- 6.1 mc_integral ------------------------------------------------------------

/// Zeros skipped: the mean is over the samples where f is not 0.
fn mc_skip_zeros(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    let (mut sum, mut n) = (0.0, 0usize);
    for &v in u {
        let y = f(a + v * (b - a));
        if y == 0.0 {
            continue;
        }
        sum += y;
        n += 1;
    }
    if n == 0 {
        return 0.0;
    }
    sum / n as f64 * (b - a)
}

/// Values not finite or over 1e6 skipped: a large integrand's mean is
/// taken over what is left.
fn mc_skip_large(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    let (mut sum, mut n) = (0.0, 0usize);
    for &v in u {
        let y = f(a + v * (b - a));
        if !y.is_finite() || y.abs() > 1e6 {
            continue;
        }
        sum += y;
        n += 1;
    }
    if n == 0 {
        0.0
    } else {
        (b - a) * sum / n as f64
    }
}

/// Correct: a running mean, times the width.
fn mc_running_mean(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.is_empty() {
        return 0.0;
    }
    let mut mean = 0.0;
    for (i, &v) in u.iter().enumerate() {
        mean += (f(a + v * (b - a)) - mean) / (i as f64 + 1.0);
    }
    mean * (b - a)
}

#[test]
fn mc_integral_mistakes_fail() {
    fails("zeros skipped", None, || {
        ch6::check_mc_integral(mc_skip_zeros)
    });
    fails("values over 1e6 skipped", None, || {
        ch6::check_mc_integral(mc_skip_large)
    });
    passes("a running mean", || ch6::check_mc_integral(mc_running_mean));
}

// ---- 6.2 russian_roulette -------------------------------------------------------

/// A value ≤ 0 returned as 0: a negative contribution is dropped.
fn roulette_nonpositive_zero(value: f64, q: f64, u: f64) -> f64 {
    if value <= 0.0 {
        return 0.0;
    }
    if u < q {
        value / q
    } else {
        0.0
    }
}

/// Correct: q ≥ 1 kept as it is, otherwise times q's reciprocal.
fn roulette_q_one(value: f64, q: f64, u: f64) -> f64 {
    if q >= 1.0 {
        value
    } else if u >= q {
        0.0
    } else {
        value * (1.0 / q)
    }
}

#[test]
fn russian_roulette_mistake_fails() {
    fails(
        "a value ≤ 0 dropped",
        Some("the wrong fraction of paths ends"),
        || ch6::check_russian_roulette(roulette_nonpositive_zero),
    );
    passes("q ≥ 1 kept as it is", || {
        ch6::check_russian_roulette(roulette_q_one)
    });
}

// ---- 6.3 mis_weight -------------------------------------------------------------

/// Correct: the power heuristic as the logistic of 2 ln(pdf_f / pdf_g).
fn mis_logistic(pdf_f: f64, pdf_g: f64) -> f64 {
    if pdf_f.is_nan() || pdf_f <= 0.0 {
        return 0.0;
    }
    let x = 2.0 * (pdf_f.ln() - pdf_g.ln());
    1.0 / (1.0 + (-x).exp())
}

#[test]
fn mis_weight_alternative_passes() {
    passes("the logistic of the log ratio", || {
        ch6::check_mis_weight(mis_logistic)
    });
}

// ---- 6.4 path_radiance ----------------------------------------------------------

/// |cos| for the light sample: light behind the surface lights it.
fn path_abs_cos(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    let k = PathKnobs::with(|k| k.light_cos = LightCos::Abs);
    knobs::path(k, scene, o, d, rng)
}

/// Half the light sample plus half the emission found, with no MIS
/// weights: the halves are not of one estimate.
fn path_half_half(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    let k = PathKnobs::with(|k| (k.light_weight, k.found_emission) = (0.5, Some(0.5)));
    knobs::path(k, scene, o, d, rng)
}

/// Correct: the roulette at the top of the loop, before the light sample.
fn path_roulette_top(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    let k = PathKnobs::with(|k| k.roulette_at_top = true);
    knobs::path(k, scene, o, d, rng)
}

/// Correct: q from β before this bounce's factor.
fn path_roulette_stale(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    let k = PathKnobs::with(|k| k.q = Survival::LargestBefore);
    knobs::path(k, scene, o, d, rng)
}

#[test]
fn path_radiance_abs_cos_fails() {
    fails_every(
        PATH_SEEDS,
        "|cos| for the light sample",
        Some("a light sample from behind the surface counted"),
        || paths::check_path_radiance(path_abs_cos),
    );
}

#[test]
fn path_radiance_half_half_fails() {
    fails_every(
        PATH_SEEDS,
        "half and half, unweighted",
        Some("emission a bounce finds added"),
        || paths::check_path_radiance(path_half_half),
    );
}

#[test]
fn path_radiance_roulette_top_passes() {
    passes_every(PATH_SEEDS, "the roulette at the loop's top", || {
        paths::check_path_radiance(path_roulette_top)
    });
}

#[test]
fn path_radiance_roulette_stale_passes() {
    passes_every(PATH_SEEDS, "q from β before the bounce", || {
        paths::check_path_radiance(path_roulette_stale)
    });
}

// ---- 6.5 refraction -------------------------------------------------------------

/// Correct: equal indices pass straight through; the direction as the
/// tangential part scaled by η less cos θt along m, not normalised.
fn refract_equal_shortcut(d: Vec3, n: Vec3, eta_o: f32, eta_in: f32) -> Option<(Vec3, f32)> {
    let (m, eta_i, eta_t) = if d.dot(n) < 0.0 {
        (n, eta_o, eta_in)
    } else {
        (-n, eta_in, eta_o)
    };
    if eta_i == eta_t {
        return Some((d, 0.0));
    }
    let cos_i = -d.dot(m);
    let eta = eta_i / eta_t;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let t = eta * (d + cos_i * m) - cos_t * m;
    let r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    let r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    Some((t, 0.5 * (r_p * r_p + r_s * r_s)))
}

/// Correct: the Fresnel terms divided through by η_t, in η alone.
fn refract_eta_ratio(d: Vec3, n: Vec3, eta_o: f32, eta_in: f32) -> Option<(Vec3, f32)> {
    let (m, eta_i, eta_t) = if d.dot(n) < 0.0 {
        (n, eta_o, eta_in)
    } else {
        (-n, eta_in, eta_o)
    };
    let cos_i = -d.dot(m);
    let eta = eta_i / eta_t;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let t = (eta * d + (eta * cos_i - cos_t) * m).normalize();
    let r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    Some((t, 0.5 * (r_s * r_s + r_p * r_p)))
}

#[test]
fn refraction_alternatives_pass() {
    passes("equal indices straight through", || {
        refraction::check_refraction(refract_equal_shortcut)
    });
    passes("Fresnel in η alone", || {
        refraction::check_refraction(refract_eta_ratio)
    });
}
