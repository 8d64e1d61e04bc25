//! A fresh set of plausible wrong solutions, written from the exercises'
//! contracts (the stubs' comments) before reading the checks, each
//! breaking one clause where the hand-made cases are silent: an absolute
//! ε that fails at millimetre scale, a formula that loses precision far
//! from the origin, a clamp that holds only for the values tried, a
//! fixed-size stack, a function right only for its first calls. Each must
//! fail under every seed tried; the correct alternatives beside them must
//! pass under every seed.

use std::sync::atomic::{AtomicUsize, Ordering};

use glam::{Vec2, Vec3};
use raystep::ch2_rasterization::triangle::rasterize_triangle;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::triangle::Hit;
use raystep::grading::counted::{self, intersect_watertight, NodeKind, ReadableBvh};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5, ch6};

use super::under_seeds;

/// The seeds every fresh mutant must fail under (and every alternative
/// pass under).
const SEEDS: [u64; 4] = [0, 1, 0x5eed, 977];

fn fails(what: &str, check: impl Fn() -> Check) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        assert!(!c.passed(), "{what} passed under seed {seed}: {}", c.detail);
    }
}

fn passes(what: &str, check: impl Fn() -> Check) {
    for (seed, c) in under_seeds(&SEEDS, check) {
        assert!(c.passed(), "{what} failed under seed {seed}: {}", c.detail);
    }
}

/// Clause: a point in front of the camera has an image, however near;
/// this one gives up within a centimetre.
fn project_near_cut(p: Vec3) -> Option<Vec2> {
    (p.z < -1e-2).then(|| Vec2::new(p.x / -p.z, p.y / -p.z))
}

/// Clause: exactly 0 on the line, and the same wherever the edge sits;
/// this one sums the corners' cross products (exact only near the origin).
fn edge_from_positions(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    a.perp_dot(b) + b.perp_dot(p) + p.perp_dot(a)
}

/// Clause: `None` only for a triangle with no area; this one has an
/// absolute threshold that millimetre triangles fall under.
fn barycentric_absolute_eps(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    let e = |a: Vec2, b: Vec2, q: Vec2| (b - a).perp_dot(q - a);
    let area = e(pi, pj, pk);
    if area.abs() < 1e-6 {
        return None;
    }
    Some(Vec3::new(e(pj, pk, p), e(pk, pi, p), e(pi, pj, p)) / area)
}

/// Correct, another formulation: φk from the other two.
fn barycentric_one_minus(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    let e = |a: Vec2, b: Vec2, q: Vec2| (b - a).perp_dot(q - a);
    let area = e(pi, pj, pk);
    if area == 0.0 || !area.is_finite() {
        return None;
    }
    let (i, j) = (e(pj, pk, p) / area, e(pk, pi, p) / area);
    Some(Vec3::new(i, j, 1.0 - i - j))
}

static DEPTH_CALLS: AtomicUsize = AtomicUsize::new(0);

/// Clause: every call; this one is right for its first 40 calls only.
fn depth_first_calls(depth: &mut [f32], index: usize, z: f32) -> bool {
    if DEPTH_CALLS.fetch_add(1, Ordering::Relaxed) > 40 {
        depth[index] = z;
        return true;
    }
    let pass = z < depth[index];
    if pass {
        depth[index] = z;
    }
    pass
}

/// Clause: the colour of the triangle's point, whatever its brightness;
/// this one clamps to a display's [0, 1].
// ANCHOR: clamped
fn raster_clamped(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    let c = c.map(|c| c.clamp(Vec3::ZERO, Vec3::ONE));
    rasterize_triangle(v, c, w, h, d, i)
}
// ANCHOR_END: clamped

/// Clause: parallel only when Nᵀd = 0; this one calls small products
/// parallel.
fn plane_absolute_eps(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let den = n.dot(d);
    (den.abs() > 1e-6).then(|| (c - n.dot(o)) / den)
}

/// Clause: `None` for a degenerate triangle only; this one's threshold on
/// |N|² swallows millimetre triangles.
fn inside_absolute_eps(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    let (e1, e2, w) = (tri[1] - tri[0], tri[2] - tri[0], p - tri[0]);
    let n = e1.cross(e2);
    let nn = n.length_squared();
    if nn < 1e-9 {
        return None;
    }
    let u = w.cross(e2).dot(n) / nn;
    let v = e1.cross(w).dot(n) / nn;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0).then_some((u, v))
}

/// Clause: `None` only when the determinant is zero; this one's absolute
/// ε (the textbook's 1e-6) misses millimetre triangles.
fn moller_absolute_eps(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det.abs() < 1e-6 {
        return None;
    }
    let s = o - tri[0];
    let u = s.dot(p) / det;
    let q = s.cross(e1);
    let v = d.dot(q) / det;
    let t = e2.dot(q) / det;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0).then_some((t, u, v))
}

/// Clause: the closest hit, on any tree; this one's stack holds 48 and
/// drops what does not fit.
fn bvh_fixed_stack(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    let root = bvh.nodes.first()?;
    let inv = ray.dir.recip();
    let mut best: Option<Hit> = None;
    let mut t_best = t_max;
    let mut stack = [(0u32, 0f32); 48];
    let mut top = 0;
    if let Some(t) = root.bounds.enter(ray, inv, t_best) {
        stack[0] = (0, t);
        top = 1;
    }
    while top > 0 {
        top -= 1;
        let (index, t_enter) = stack[top];
        if t_enter > t_best {
            continue;
        }
        match bvh.nodes[index as usize].kind {
            NodeKind::Leaf { first, count } => {
                for &id in &bvh.order[first as usize..(first + count) as usize] {
                    if let Some(h) = intersect_watertight(ray, bvh.tris[id as usize], 0.0, t_best) {
                        t_best = h.t;
                        best = Some(Hit { triangle: id, ..h });
                    }
                }
            }
            NodeKind::Inner { left, right } => {
                let enter = |c: u32| bvh.nodes[c as usize].bounds.enter(ray, inv, t_best);
                let mut kids = [(left, enter(left)), (right, enter(right))];
                if kids[1].1.unwrap_or(f32::INFINITY) > kids[0].1.unwrap_or(f32::INFINITY) {
                    kids.swap(0, 1);
                }
                for (c, t) in kids {
                    if let (Some(t), true) = (t, top < stack.len()) {
                        stack[top] = (c, t);
                        top += 1;
                    }
                }
            }
        }
    }
    best
}

/// Clause: the distance from any point; this one measures from the origin
/// when the centre is far ("close enough").
fn sdf_far_centre(p: Vec3, c: Vec3, r: f32) -> f32 {
    if c.length() > 100.0 {
        p.length() - c.length() - r
    } else {
        (p - c).length() - r
    }
}

/// Clause: the inverse-square law at any distance; this one keeps r² away
/// from 0 "for safety".
fn point_light_soft(i: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let d2 = to.length_squared().max(1e-2);
    i * n.dot(to.normalize()).max(0.0) / d2
}

/// Clause: exactly 0 edge-on; this one keeps the cosine from 0.
fn area_pdf_clamped(pdf: f32, x: Vec3, y: Vec3, n: Vec3) -> f32 {
    let to = y - x;
    pdf * to.length_squared() / (n.dot(to.normalize())).abs().max(1e-3)
}

/// Clause: any interval; this one takes the interval's width as positive.
fn mc_abs_width(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    let sum: f64 = u.iter().map(|u| f(a + u * (b - a))).sum();
    sum / u.len() as f64 * (b - a).abs()
}

/// Clause: any survival probability; this one keeps q from being tiny.
fn roulette_floor(value: f64, q: f64, u: f64) -> f64 {
    let q = q.max(0.05);
    if u < q {
        value / q
    } else {
        0.0
    }
}

/// Clause: 0 when pdf_f is 0 (also both 0), finite everywhere; this one
/// is the formula as written.
fn mis_naive(f: f64, g: f64) -> f64 {
    f * f / (f * f + g * g)
}

#[test]
fn the_fresh_mutants_fail_under_every_seed() {
    fails("an image only beyond 1 cm", || {
        ch1::check_project_point(project_near_cut)
    });
    fails("the edge function from the corners' positions", || {
        ch2::check_edge_function(edge_from_positions)
    });
    fails("barycentrics with an absolute ε", || {
        ch2::check_barycentric(barycentric_absolute_eps)
    });
    fails("a depth test right for 40 calls", || {
        DEPTH_CALLS.store(0, Ordering::Relaxed);
        ch2::check_depth_test(depth_first_calls)
    });
    fails("colours clamped to [0, 1]", || {
        ch2::check_rasterize_triangle(raster_clamped)
    });
    fails("ray-plane with an absolute ε", || {
        ch3::check_ray_plane(plane_absolute_eps)
    });
    fails("the inside test with an absolute ε", || {
        ch3::check_barycentric_inside(inside_absolute_eps)
    });
    fails("Möller–Trumbore with an absolute ε", || {
        ch3::check_moller_trumbore(moller_absolute_eps)
    });
    fails("a traversal stack of 48 that drops pushes", || {
        ch3::check_bvh_traversal(bvh_fixed_stack)
    });
    fails("a sphere measured from the origin when far", || {
        ch4::check_sphere_sdf(sdf_far_centre)
    });
    fails("r² kept from 0", || {
        ch5::check_point_light(point_light_soft)
    });
    fails("the edge-on cosine kept from 0", || {
        ch5::check_area_pdf(area_pdf_clamped)
    });
    fails("the interval's width made positive", || {
        ch6::check_mc_integral(mc_abs_width)
    });
    fails("q kept above 0.05", || {
        ch6::check_russian_roulette(roulette_floor)
    });
    fails("the power heuristic as written", || {
        ch6::check_mis_weight(mis_naive)
    });
}

#[test]
fn the_correct_alternatives_and_references_pass_under_every_seed() {
    passes("φk = 1 − φi − φj", || {
        ch2::check_barycentric(barycentric_one_minus)
    });
    passes("the reference traversal", || {
        ch3::check_bvh_traversal(counted::closest_hit)
    });
    for ex in raystep::grading::all() {
        passes(&ex.id(), ex.reference);
    }
}

/// Clause: twice the signed area; this one normalises the edge first.
fn edge_normalised(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (b - a).normalize().perp_dot(p - a)
}

/// Clause: central differences with step h; this one steps forward.
fn normal_forward(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let f = sdf(p);
    Vec3::new(
        sdf(p + Vec3::X * h) - f,
        sdf(p + Vec3::Y * h) - f,
        sdf(p + Vec3::Z * h) - f,
    )
    .normalize()
}

/// Clause: with step h as given; this one always steps 1e-3.
fn normal_fixed_h(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, _h: f32) -> Vec3 {
    let h = 1e-3;
    Vec3::new(
        sdf(p + Vec3::X * h) - sdf(p - Vec3::X * h),
        sdf(p + Vec3::Y * h) - sdf(p - Vec3::Y * h),
        sdf(p + Vec3::Z * h) - sdf(p - Vec3::Z * h),
    )
    .normalize()
}

/// Clause: ε scaled to the point the march has reached; this one takes
/// it at the ray's origin, once (the lecture's loop otherwise).
fn trace_eps_at_origin(
    sdf: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    m: &raystep::ch4_implicit_surfaces::march::March,
) -> Option<(f32, Vec3)> {
    let eps = m.epsilon_at(o);
    let mut t = 0.0f32;
    let mut steps = 0;
    loop {
        let p = o + t * d;
        let f = sdf(p);
        steps += 1;
        if f.abs() < eps {
            let h = m.epsilon_at(p).max(1e-4);
            let g = Vec3::new(
                sdf(p + Vec3::X * h) - sdf(p - Vec3::X * h),
                sdf(p + Vec3::Y * h) - sdf(p - Vec3::Y * h),
                sdf(p + Vec3::Z * h) - sdf(p - Vec3::Z * h),
            );
            let n = g.try_normalize().unwrap_or(-d);
            return Some((t, if n.dot(d) > 0.0 { -n } else { n }));
        }
        if t > m.max_distance || steps >= m.max_steps {
            return None;
        }
        t += f;
    }
}

/// Clause: ρ/π, the BRDF alone; this one folds in the cosine.
fn lambert_with_cosine(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    if (wo.z > 0.0) == (wi.z > 0.0) {
        rho * std::f32::consts::FRAC_1_PI * wi.z.abs()
    } else {
        Vec3::ZERO
    }
}

/// Clause: uniform on [a, b]; this one forgets to start at a.
fn mc_from_zero(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    let sum: f64 = u.iter().map(|u| f(u * b)).sum();
    sum / u.len() as f64 * (b - a)
}

/// Clause: the power heuristic; this one squares the balance heuristic.
fn mis_squared_balance(f: f64, g: f64) -> f64 {
    if f == 0.0 {
        0.0
    } else {
        (f / (f + g)).powi(2)
    }
}

#[test]
fn more_fresh_mutants_fail_under_every_seed() {
    fails("a normalised edge", || {
        ch2::check_edge_function(edge_normalised)
    });
    fails("forward differences", || {
        ch4::check_gradient_normal(normal_forward)
    });
    fails("a fixed difference step", || {
        ch4::check_gradient_normal(normal_fixed_h)
    });
    fails("ε taken at the ray's origin", || {
        ch4::check_trace_scene(trace_eps_at_origin)
    });
    fails("the BRDF times the cosine", || {
        ch5::check_lambert_brdf(lambert_with_cosine)
    });
    fails("x from 0, not from a", || {
        ch6::check_mc_integral(mc_from_zero)
    });
    fails("the balance heuristic squared", || {
        ch6::check_mis_weight(mis_squared_balance)
    });
}

/// Case 7 of the grader issue's list: the closed furnace recognised by
/// the albedo and emission its stub once printed (0.85, (1, 0.75, 0.5))
/// and answered in closed form, while the real loop has no roulette and
/// stops at eight bounces. The furnace is drawn anew for every run now.
fn path_furnace_recognised(
    scene: &raystep::grading::exercises::paths::PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    if hit.albedo == Vec3::splat(0.85) && hit.emitted == Vec3::new(1.0, 0.75, 0.5) {
        return hit.emitted / (1.0 - 0.85);
    }
    let mut l = hit.emitted;
    let mut beta = Vec3::ONE;
    for _ in 0..8 {
        let brdf = hit.albedo * std::f32::consts::FRAC_1_PI;
        if let Some(ls) = scene.sample_light(&hit, Vec2::new(rng(), rng())) {
            let cos = hit.n.dot(ls.wi);
            if cos > 0.0 && scene.unoccluded(&hit, ls.wi, ls.dist) {
                l += beta * brdf * ls.li * cos / ls.pdf;
            }
        }
        let (wi, pdf) = scene.sample_cosine(&hit, Vec2::new(rng(), rng()));
        beta *= brdf * hit.n.dot(wi) / pdf;
        match scene.next_hit(&hit, wi) {
            Some(next) => hit = next,
            None => break,
        }
    }
    l
}

#[test]
fn a_furnace_recognised_by_its_old_numbers_fails() {
    fails("the furnace answered in closed form", || {
        raystep::grading::exercises::paths::check_path_radiance(path_furnace_recognised)
    });
}
