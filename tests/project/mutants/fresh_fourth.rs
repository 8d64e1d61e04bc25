//! The fourth fresh set (2026-11-29): plausible wrong solutions written by
//! two new testers from the stubs' contracts before reading the checks,
//! each the course's solution (`tests/project/solutions/`) with one
//! change, mostly a shortcut that holds on the usual inputs only: a cache
//! or a counter kept between calls, a threshold where the contract has
//! none, a narrower type, one axis instead of three, an answer before the
//! test. The grader now catches each: it must fail under every seed tried,
//! naming its symptom where the grader names one. The testers' correct
//! alternatives that no other test covers must pass under every seed.
//! Where one copies a long solution body, it is a one-line call of that
//! solution written once with knobs ([`super::knobs`]), its change a knob
//! turned.
//!
//! The mutants that keep state between calls keep it in a `thread_local`,
//! as the testers wrote; [`super::under_seeds`] runs the seeds one after another
//! on this thread, so each seed's run starts from the state a fresh
//! process would have (reset in the closure that runs the check), and no
//! seed's run can pass on what an earlier one left behind.

use std::cell::Cell;
use std::collections::HashMap;
use std::f32::consts::PI;

use glam::{Mat4, Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::paths::{self, PathScene};
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5, ch6};

use super::knobs::{
    self, surface_area, Axes, EdgeKnobs, Knobs, LookKnobs, MarchEps, Measure, MollerKnobs,
    PathKnobs, RasterKnobs, SahKnobs, SceneKnobs, Survival,
};
use super::{fails_every, passes_every};

/// The seeds every mutant must fail under (and every alternative pass
/// under): the testers' three and one more.
const SEEDS: [u64; 4] = [101, 202, 303, 0x2026_1130];

/// The path loop's check traces 200,000 paths in a furnace per seed: its
/// mutant and alternative are tried under the first two seeds only.
const PATH_SEEDS: &[u64] = &[101, 202];

fn fails(what: &str, symptom: Option<&str>, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, symptom, check);
}

fn passes(what: &str, check: impl Fn() -> Check) {
    passes_every(&SEEDS, what, check);
}

// ---- 1.1 project_point -------------------------------------------------------

/// The sign bit for z < 0: z = -0 is in front, and divides by zero.
fn project_sign_bit(p: Vec3) -> Option<Vec2> {
    if !p.z.is_sign_negative() || p.z.is_nan() {
        return None;
    }
    let t = 1.0 / -p.z;
    Some(Vec2::new(p.x * t, p.y * t))
}

#[test]
fn project_point_mistake_fails() {
    fails(
        "the sign bit for z < 0",
        Some("a point with no image got one"),
        || ch1::check_project_point(project_sign_bit),
    );
}

// ---- 1.2 look_at ----------------------------------------------------------------

thread_local! {
    /// The last eye and its matrix, as the tester's cache kept them.
    static LOOK_AT_LAST: Cell<Option<(Vec3, Mat4)>> = const { Cell::new(None) };
}

/// A cache keyed on the eye alone: a new target or up from the same eye
/// gets the last matrix.
fn look_at_cache_eye(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    if let Some((e, m)) = LOOK_AT_LAST.with(|c| c.get()) {
        if e == eye {
            return m;
        }
    }
    let m = knobs::look_at(LookKnobs::default(), eye, target, up);
    LOOK_AT_LAST.with(|c| c.set(Some((eye, m))));
    m
}

#[test]
fn look_at_mistake_fails() {
    fails("a cache keyed on the eye", None, || {
        // Each seed's run starts with an empty cache, as a fresh process.
        LOOK_AT_LAST.with(|c| c.set(None));
        ch1::check_look_at(look_at_cache_eye)
    });
}

// ---- 1.3 draw_edges -------------------------------------------------------------

/// An edge of no length (a == b) drawn as nothing, not as a point.
fn edges_zero_length(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let k = EdgeKnobs::with(|k| k.zero_length_none = true);
    knobs::draw_edges(k, camera, a, b, near)
}

#[test]
fn draw_edges_mistake_fails() {
    fails(
        "an edge of no length drawn as nothing",
        Some("a visible edge dropped"),
        || ch1::check_draw_edges(edges_zero_length),
    );
}

// ---- 2.3 depth_test -------------------------------------------------------------

thread_local! {
    /// The last (index, z's bits) and its answer, as the tester's memo
    /// kept them.
    static DEPTH_LAST: Cell<Option<(usize, u32, bool)>> = const { Cell::new(None) };
}

/// A memo of the last answer: the same test asked twice answers as the
/// first time, though the first stored z.
fn depth_memo(depth: &mut [f32], index: usize, z: f32) -> bool {
    if let Some((i, zb, r)) = DEPTH_LAST.with(|c| c.get()) {
        if i == index && zb == z.to_bits() {
            return r;
        }
    }
    let r = z < depth[index];
    if r {
        depth[index] = z;
    }
    DEPTH_LAST.with(|c| c.set(Some((index, z.to_bits(), r))));
    r
}

#[test]
fn depth_test_mistake_fails() {
    fails("a memo of the last answer", None, || {
        // Each seed's run starts with an empty memo, as a fresh process.
        DEPTH_LAST.with(|c| c.set(None));
        ch2::check_depth_test(depth_memo)
    });
}

// ---- 2.4 rasterize_triangle -----------------------------------------------------

/// An area threshold: a triangle under 1e-3 px² (doubled) draws nothing,
/// though it covers a sample centre.
fn raster_area_eps(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    knobs::rasterize(RasterKnobs::with(|k| k.min_area = 1e-3), v, c, (w, h), d, i);
}

/// Correct: a row stops at the first sample outside after a run inside (a
/// triangle is convex), corners not finite refused as the solution does.
fn raster_row_break(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    let k = RasterKnobs::with(|k| k.row_break = true);
    knobs::rasterize(k, v, c, (w, h), d, i);
}

#[test]
fn rasterize_triangle_mistake_fails() {
    fails("an area threshold of 1e-3", None, || {
        ch2::check_rasterize_triangle(raster_area_eps)
    });
    passes("a row stopped after its run", || {
        ch2::check_rasterize_triangle(raster_row_break)
    });
}

// ---- 2.5 manifold ---------------------------------------------------------------

/// The solution's counts of the triangles `good` (degenerate ones removed).
fn manifold_counts_of(good: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    let mut edges: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
    let mut around: HashMap<u32, Vec<usize>> = HashMap::new();
    for (t, &[a, b, c]) in good.iter().enumerate() {
        for (i, j) in [(a, b), (b, c), (c, a)] {
            let e = edges.entry((i.min(j), i.max(j))).or_default();
            if i < j {
                e.0 += 1;
            } else {
                e.1 += 1;
            }
        }
        for v in [a, b, c] {
            around.entry(v).or_default().push(t);
        }
    }
    let (mut boundary, mut many, mut inconsistent) = (0, 0, 0);
    for &(up, down) in edges.values() {
        match up + down {
            1 => boundary += 1,
            2 if up != 1 => inconsistent += 1,
            2 => {}
            _ => many += 1,
        }
    }
    let mut fans = 0;
    for (&v, tris) in &around {
        let mut parent: Vec<usize> = (0..tris.len()).collect();
        fn root(p: &mut [usize], mut i: usize) -> usize {
            while p[i] != i {
                i = p[i];
            }
            i
        }
        for i in 0..tris.len() {
            for j in i + 1..tris.len() {
                let other = good[tris[i]].iter().filter(|&&u| u != v);
                if other.clone().any(|u| good[tris[j]].contains(u)) {
                    let (a, b) = (root(&mut parent, i), root(&mut parent, j));
                    parent[a] = b;
                }
            }
        }
        let roots = (0..tris.len())
            .filter(|&i| root(&mut parent, i) == i)
            .count();
        if roots > 1 {
            fans += 1;
        }
    }
    (boundary, many, fans, inconsistent)
}

/// u16 indices: vertices whose indices share their low 16 bits are one.
fn manifold_u16(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    let good: Vec<[u32; 3]> = triangles
        .iter()
        .copied()
        .filter(|&[a, b, c]| a != b && b != c && c != a)
        .map(|t| t.map(|i| i as u16 as u32))
        .collect();
    manifold_counts_of(&good)
}

/// Correct: the fans at a vertex found by a breadth-first walk over its
/// triangles sharing a second vertex, the edges counted per direction.
fn manifold_bfs(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize) {
    use std::collections::{BTreeMap, VecDeque};
    let good: Vec<[u32; 3]> = triangles
        .iter()
        .copied()
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .collect();
    let mut dir: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    let mut around: BTreeMap<u32, Vec<usize>> = BTreeMap::new();
    for (t, tri) in good.iter().enumerate() {
        for e in 0..3 {
            *dir.entry((tri[e], tri[(e + 1) % 3])).or_insert(0) += 1;
            around.entry(tri[e]).or_default().push(t);
        }
    }
    let mut undirected: BTreeMap<(u32, u32), (usize, usize)> = BTreeMap::new();
    for (&(i, j), &n) in &dir {
        let e = undirected.entry((i.min(j), i.max(j))).or_insert((0, 0));
        if i < j {
            e.0 += n
        } else {
            e.1 += n
        }
    }
    let (mut b, mut m, mut inc) = (0, 0, 0);
    for &(f, r) in undirected.values() {
        let n = f + r;
        if n == 1 {
            b += 1
        } else if n >= 3 {
            m += 1
        } else if f == 2 || r == 2 {
            inc += 1
        }
    }
    let mut fans = 0;
    for (&v, ts) in &around {
        let mut seen = vec![false; ts.len()];
        let mut comps = 0;
        for s in 0..ts.len() {
            if seen[s] {
                continue;
            }
            comps += 1;
            seen[s] = true;
            let mut q = VecDeque::from([s]);
            while let Some(a) = q.pop_front() {
                for c in 0..ts.len() {
                    if seen[c] {
                        continue;
                    }
                    let share = good[ts[a]]
                        .iter()
                        .any(|&u| u != v && good[ts[c]].contains(&u));
                    if share {
                        seen[c] = true;
                        q.push_back(c);
                    }
                }
            }
        }
        if comps > 1 {
            fans += 1;
        }
    }
    (b, m, fans, inc)
}

#[test]
fn manifold_mistake_fails() {
    fails(
        "u16 indices",
        Some("the boundary edges are miscounted"),
        || ch2::check_manifold(manifold_u16),
    );
    passes("fans by a breadth-first walk", || {
        ch2::check_manifold(manifold_bfs)
    });
}

// ---- 3.1 ray_plane --------------------------------------------------------------

/// Some(0) for an origin on the plane, before the parallel test: a ray
/// inside a parallel plane hits it at 0.
fn plane_in_plane_zero(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    if n.dot(o) == c {
        return Some(0.0);
    }
    let denom = n.dot(d);
    if denom == 0.0 {
        return None;
    }
    Some((c - n.dot(o)) / denom)
}

#[test]
fn ray_plane_mistake_fails() {
    fails(
        "Some(0) before the parallel test",
        Some("parallel ray"),
        || ch3::check_ray_plane(plane_in_plane_zero),
    );
}

// ---- 3.2 barycentric_inside -----------------------------------------------------

/// Projected onto the xy plane: a triangle standing in a plane x = const
/// or y = const is degenerate there.
fn inside_xy_projection(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    let (e1, e2, q) = (tri[1] - tri[0], tri[2] - tri[0], p - tri[0]);
    let det = e1.x * e2.y - e1.y * e2.x;
    if det == 0.0 {
        return None;
    }
    let u = (q.x * e2.y - q.y * e2.x) / det;
    let v = (e1.x * q.y - e1.y * q.x) / det;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0).then_some((u, v))
}

/// Correct: projected onto the plane that drops the normal's largest axis.
fn inside_dominant_axis(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
    let n = e1.cross(e2);
    if n.length_squared() == 0.0 {
        return None;
    }
    let a = n.abs();
    let (i, j) = if a.x >= a.y && a.x >= a.z {
        (1, 2)
    } else if a.y >= a.z {
        (2, 0)
    } else {
        (0, 1)
    };
    let f = |v: Vec3| Vec2::new(v[i], v[j]);
    let (e1, e2, q) = (f(e1), f(e2), f(p - tri[0]));
    let det = e1.perp_dot(e2);
    if det == 0.0 {
        return None;
    }
    let u = q.perp_dot(e2) / det;
    let v = e1.perp_dot(q) / det;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0).then_some((u, v))
}

#[test]
fn barycentric_inside_mistake_fails() {
    fails("an xy projection", None, || {
        ch3::check_barycentric_inside(inside_xy_projection)
    });
    passes("the dominant axis dropped", || {
        ch3::check_barycentric_inside(inside_dominant_axis)
    });
}

// ---- 3.3 moller_trumbore --------------------------------------------------------

/// A far cut at t = 1e4: a short d puts a near triangle past it.
fn moller_far_cut(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    knobs::moller(MollerKnobs::with(|k| k.far = Some(1e4)), o, d, tri)
}
/// Counted right until the twenty-third set: t recomputed as the hit
/// point's projection on d, over |d|² (which leaves f32's range for a
/// very long or very short d).
fn moller_t_projected(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    knobs::moller(MollerKnobs::with(|k| k.t_projected = true), o, d, tri)
}

#[test]
fn moller_trumbore_mistake_fails() {
    fails("a far cut at t = 1e4", None, || {
        ch3::check_moller_trumbore(moller_far_cut)
    });
    // Counted right until the twenty-third set: d · d leaves f32's range
    // for a d 10¹⁹ or 10⁻¹⁹ long, where t does not.
    fails("t projected on d", None, || {
        ch3::check_moller_trumbore(moller_t_projected)
    });
}

// ---- 3.5 sah --------------------------------------------------------------------

/// Only the axis along which the centroids spread furthest is swept.
fn sah_longest_axis(b: &[[Vec3; 2]], c: &[Vec3]) -> Option<(usize, f32)> {
    knobs::sah_sweep(SahKnobs::with(|k| k.axes = Axes::Longest), b, c)
}

/// The half-perimeter dx + dy + dz for the surface area.
fn sah_perimeter(b: &[[Vec3; 2]], c: &[Vec3]) -> Option<(usize, f32)> {
    knobs::sah_sweep(SahKnobs::with(|k| k.measure = Measure::HalfPerimeter), b, c)
}

/// Correct: every plane at a distinct centroid value costed directly,
/// counting the triangles on each side.
fn sah_brute(boxes: &[[Vec3; 2]], centroids: &[Vec3]) -> Option<(usize, f32)> {
    let n = boxes.len();
    let (lo, hi) = knobs::bounds(boxes);
    let whole = surface_area(lo, hi);
    let (mut best, mut split) = (n as f64, None);
    for axis in 0..3 {
        let mut cands: Vec<f32> = centroids.iter().map(|c| c[axis]).collect();
        cands.sort_by(f32::total_cmp);
        cands.dedup();
        for &at in cands.iter().skip(1) {
            let (mut l0, mut l1) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
            let (mut r0, mut r1) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
            let (mut nl, mut nr) = (0usize, 0usize);
            for i in 0..n {
                if centroids[i][axis] < at {
                    (l0, l1, nl) = (l0.min(boxes[i][0]), l1.max(boxes[i][1]), nl + 1);
                } else {
                    (r0, r1, nr) = (r0.min(boxes[i][0]), r1.max(boxes[i][1]), nr + 1);
                }
            }
            let cost =
                1.0 + (surface_area(l0, l1) * nl as f64 + surface_area(r0, r1) * nr as f64) / whole;
            if cost < best {
                (best, split) = (cost, Some((axis, at)));
            }
        }
    }
    split
}

#[test]
fn sah_mistakes_fail() {
    fails(
        "the longest axis only",
        Some("the tree costs more than the SAH's"),
        || ch3::check_sah(sah_longest_axis),
    );
    fails(
        "the half-perimeter for the area",
        Some("the tree costs more than the SAH's"),
        || ch3::check_sah(sah_perimeter),
    );
    passes("every plane costed directly", || ch3::check_sah(sah_brute));
}

// ---- 4.3 gradient_normal --------------------------------------------------------

thread_local! {
    /// The last (p, h) and its normal, as the tester's cache kept them.
    static NORMAL_LAST: Cell<Option<(Vec3, f32, Vec3)>> = const { Cell::new(None) };
}

/// A cache keyed on p and h: another surface asked at the same point gets
/// the last one's normal.
fn normal_cache_p(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    if let Some((lp, lh, ln)) = NORMAL_LAST.with(|c| c.get()) {
        if lp == p && lh == h {
            return ln;
        }
    }
    let partial = |axis: Vec3| (sdf(p + axis * h) - sdf(p - axis * h)) / (2.0 * h);
    let n = Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z)).normalize();
    NORMAL_LAST.with(|c| c.set(Some((p, h, n))));
    n
}

/// The five-point stencil: it reaches 2h, past an edge the contract's
/// steps of h do not see.
fn normal_five_point(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let partial = |a: Vec3| {
        (-sdf(p + 2.0 * h * a) + 8.0 * sdf(p + h * a) - 8.0 * sdf(p - h * a) + sdf(p - 2.0 * h * a))
            / (12.0 * h)
    };
    Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z)).normalize()
}

/// h floored at 1e-3: a smaller step is widened past an edge.
fn normal_h_floor(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let h = h.max(1e-3);
    let partial = |axis: Vec3| (sdf(p + axis * h) - sdf(p - axis * h)) / (2.0 * h);
    Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z)).normalize()
}

/// Correct: the differences mapped over an array of axes, not divided by
/// 2h, then divided by their length.
fn normal_array(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let g: [f32; 3] = [Vec3::X, Vec3::Y, Vec3::Z].map(|e| sdf(p + h * e) - sdf(p - h * e));
    let g = Vec3::from_array(g);
    g / g.length()
}

#[test]
fn gradient_normal_mistakes_fail() {
    fails("a cache keyed on p and h", None, || {
        // Each seed's run starts with an empty cache, as a fresh process.
        NORMAL_LAST.with(|c| c.set(None));
        ch4::check_gradient_normal(normal_cache_p)
    });
    fails("the five-point stencil", None, || {
        ch4::check_gradient_normal(normal_five_point)
    });
    fails("h floored at 1e-3", None, || {
        ch4::check_gradient_normal(normal_h_floor)
    });
    passes("over an array of axes", || {
        ch4::check_gradient_normal(normal_array)
    });
}

// ---- 4.4 trace_scene ------------------------------------------------------------

/// |p| for the largest coordinate in ε at p: far along a diagonal, the
/// tolerance is √3 times the contract's.
fn scene_eps_length(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    knobs::trace_scene(SceneKnobs::with(|k| k.eps = MarchEps::ByLength), f, o, d, m)
}

#[test]
fn trace_scene_mistake_fails() {
    fails("|p| in ε at p", None, || {
        ch4::check_trace_scene(scene_eps_length)
    });
}

// ---- 5.2 cosine_hemisphere ------------------------------------------------------

/// The tester's generator's first state.
const OWN_RNG_START: u64 = 0x9E37_79B9_7F4A_7C15;

thread_local! {
    /// The state of the tester's own xorshift generator.
    static OWN_RNG: Cell<u64> = const { Cell::new(OWN_RNG_START) };
}

/// Its own random numbers, not the caller's u: a direction the caller
/// cannot choose or repeat.
fn cosine_own_rng(u: Vec2) -> (Vec3, f32) {
    let _ = u;
    let next = || {
        OWN_RNG.with(|s| {
            let mut x = s.get();
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            s.set(x);
            (x >> 40) as f32 / (1u64 << 24) as f32
        })
    };
    let (a, b) = (next(), next());
    let r = a.sqrt();
    let phi = 2.0 * PI * b;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    (Vec3::new(x, y, z), z / PI)
}

/// The pdf floored at 1e-3 / π: a direction in the surface gets a pdf.
fn cosine_pdf_floor(u: Vec2) -> (Vec3, f32) {
    let r = u.x.sqrt();
    let phi = 2.0 * PI * u.y;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    (Vec3::new(x, y, z), z.max(1e-3) / PI)
}

/// Correct: z = √(1 - u.x) directly, not from x and y.
fn cosine_z_direct(u: Vec2) -> (Vec3, f32) {
    let z = (1.0 - u.x).sqrt();
    let r = u.x.sqrt();
    let (s, c) = (2.0 * PI * u.y).sin_cos();
    (Vec3::new(r * c, r * s, z), z * std::f32::consts::FRAC_1_PI)
}

#[test]
fn cosine_hemisphere_mistakes_fail() {
    fails("its own random numbers", None, || {
        // Each seed's run starts the generator afresh, as a fresh process.
        OWN_RNG.with(|s| s.set(OWN_RNG_START));
        ch5::check_cosine_hemisphere(cosine_own_rng)
    });
    fails(
        "a pdf floor of 1e-3 / π",
        Some("the pdf is not cos θ / π"),
        || ch5::check_cosine_hemisphere(cosine_pdf_floor),
    );
    passes("z = √(1 - u.x)", || {
        ch5::check_cosine_hemisphere(cosine_z_direct)
    });
}

// ---- 5.3 point_light ------------------------------------------------------------

/// A cut-off at cos 1e-3: light at grazing incidence is dropped.
fn point_light_cos_cut(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let r2 = to.length_squared();
    let cos = n.dot(to / r2.sqrt());
    if cos < 1e-3 {
        return Vec3::ZERO;
    }
    intensity * cos / r2
}

#[test]
fn point_light_mistake_fails() {
    fails("a cut-off at cos 1e-3", None, || {
        ch5::check_point_light(point_light_cos_cut)
    });
}

// ---- 6.1 mc_integral ------------------------------------------------------------

/// A pair of numbers per sample, the second unused: half the numbers.
fn mc_half_u(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    let m = u.len() / 2;
    if m == 0 {
        return 0.0;
    }
    let w = b - a;
    let s: f64 = (0..m).map(|i| f(a + u[2 * i] * w) * w).sum();
    s / m as f64
}

/// Correct: the numbers rotated by 1/2 (Cranley-Patterson), still uniform.
fn mc_cp_shift(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.is_empty() {
        return 0.0;
    }
    let w = b - a;
    let mut s = 0.0;
    for &v in u {
        s += f(a + (v + 0.5).fract() * w);
    }
    w * s / u.len() as f64
}

#[test]
fn mc_integral_mistake_fails() {
    fails("a pair of numbers per sample", None, || {
        ch6::check_mc_integral(mc_half_u)
    });
    passes("rotated by 1/2", || ch6::check_mc_integral(mc_cp_shift));
}

// ---- 6.2 russian_roulette -------------------------------------------------------

thread_local! {
    /// The tester's running sum of q.
    static ROULETTE_SUM: Cell<f64> = const { Cell::new(0.0) };
}

/// A counter for u: every 1/q-th call survives, whatever u is.
fn roulette_counter(value: f64, q: f64, u: f64) -> f64 {
    let _ = u;
    ROULETTE_SUM.with(|a| {
        let x = a.get() + q;
        if x >= 1.0 {
            a.set(x - 1.0);
            value / q
        } else {
            a.set(x);
            0.0
        }
    })
}

/// A tiny q killed: below 0.01 the path ends, whatever u is.
fn roulette_tiny_q_killed(value: f64, q: f64, u: f64) -> f64 {
    if q < 0.01 {
        return 0.0;
    }
    if u < q {
        value / q
    } else {
        0.0
    }
}

/// Correct: value times q's reciprocal.
fn roulette_mul_inverse(value: f64, q: f64, u: f64) -> f64 {
    let survive = u < q;
    if !survive {
        return 0.0;
    }
    value * q.recip()
}

#[test]
fn russian_roulette_mistakes_fail() {
    fails("a counter for u", None, || {
        // Each seed's run starts the sum at 0, as a fresh process.
        ROULETTE_SUM.with(|a| a.set(0.0));
        ch6::check_russian_roulette(roulette_counter)
    });
    // Named "the wrong fraction of paths ends" under three seeds and
    // "roulette changes the mean" under the fourth: no one name asserted.
    fails("a tiny q killed", None, || {
        ch6::check_russian_roulette(roulette_tiny_q_killed)
    });
    passes("times q's reciprocal", || {
        ch6::check_russian_roulette(roulette_mul_inverse)
    });
}

// ---- 6.4 path_radiance ----------------------------------------------------------

/// q from β's smallest channel: a coloured path dies on its dimmest.
fn path_q_min(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    let k = PathKnobs::with(|k| k.q = Survival::Smallest);
    knobs::path(k, scene, o, d, rng)
}

/// Correct: the roulette from the first bounce on.
fn path_roulette_first(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    knobs::path(PathKnobs::with(|k| k.roulette_after = 0), scene, o, d, rng)
}

#[test]
fn path_radiance_q_min_fails() {
    fails_every(
        PATH_SEEDS,
        "q from β's smallest channel",
        Some("survival not taken from the throughput"),
        || paths::check_path_radiance(path_q_min),
    );
}

#[test]
fn path_radiance_roulette_first_passes() {
    passes_every(PATH_SEEDS, "the roulette from the first bounce", || {
        paths::check_path_radiance(path_roulette_first)
    });
}
