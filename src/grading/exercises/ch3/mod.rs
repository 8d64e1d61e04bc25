//! Chapter 3's exercises and how each is graded.

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::readable_bvh;
use crate::ch3_ray_triangle::triangle::{self, intersect_f64};
use crate::core::sampling::random;
use crate::grading::exercise::{Check, Exercise};

/// Barycentric (u, v).
pub type Uv = (f32, f32);
/// A hit as (t, u, v).
pub type Tuv = (f32, f32, f32);

/// Chapter 3's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 3,
            name: "ray_plane",
            file: "chapters/ch3-ray-triangle/exercises/ray_plane.rs",
            hints: [
                "slide \"ray-plane\": substitute the ray r(t) = o + t d into the plane equation Nᵀx = c and solve for t.",
                "the equation is linear in t; it has no solution when the ray runs parallel to the plane (Nᵀd = 0).",
                "Nᵀ(o + t d) = c gives t = (c - Nᵀo) / (Nᵀd); None when Nᵀd = 0",
            ],
            symptoms: &[],
            reference: || check_ray_plane(triangle::ray_plane),
        },
        Exercise {
            chapter: 3,
            name: "barycentric_inside",
            file: "chapters/ch3-ray-triangle/exercises/barycentric_inside.rs",
            hints: [
                "slide \"ray-triangle\": u and v are area ratios of sub-triangles, measured along the triangle's normal.",
                "with N = e1 × e2 and q = p - p0, project the cross products q × e2 and e1 × q onto N and divide by |N|²; inside when u, v >= 0 and u + v <= 1.",
                "u = Nᵀ(q x e2) / |N|², v = Nᵀ(e1 x q) / |N|² with N = e1 x e2; \
                   inside when u ≥ 0, v ≥ 0 and u + v ≤ 1",
            ],
            symptoms: &[],
            reference: || check_barycentric_inside(triangle::barycentric_inside),
        },
        Exercise {
            chapter: 3,
            name: "moller_trumbore",
            file: "chapters/ch3-ray-triangle/exercises/moller_trumbore.rs",
            hints: [
                "slide \"ray-triangle: solve for u, v, t\": write o + t d = p0 + u e1 + v e2 as a 3×3 linear system and solve it with Cramer's rule.",
                "the determinant is a triple product of d, e1, e2; each unknown is another triple product over it. Reject a zero determinant, u or v outside [0, 1], u + v > 1 and t <= 0.",
                "det = e1 · (d x e2); u = s · (d x e2) / det; with q = s x e1: \
                   v = d · q / det, t = e2 · q / det",
            ],
            symptoms: &[],
            reference: || check_moller_trumbore(reference_moller_trumbore),
        },
        Exercise {
            chapter: 3,
            name: "bvh_traversal",
            file: "chapters/ch3-ray-triangle/exercises/bvh_traversal.rs",
            hints: [
                "slide \"ray-mesh intersection: the bounding volume hierarchy\": visit the boxes the ray enters, nearest first, and skip any box that starts beyond the best hit so far.",
                "keep a stack of (node, t where the ray enters its box); a leaf tests its triangles against the best t and shrinks it; an inner node pushes the children the ray enters, the farther one first so the nearer is popped next.",
                "pop (node, t_enter); skip it if t_enter > best t; a leaf tests its \
                   triangles against the best t and shrinks it; an inner node pushes \
                   the children the ray enters, the farther first",
            ],
            symptoms: &[],
            reference: || check_bvh_traversal(readable_bvh::closest_hit),
        },
    ]
}

/// raystep's Möller–Trumbore in the exercise's signature.
fn reference_moller_trumbore(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let ray = Ray::new(o, d).ok()?;
    // Our Ray normalises d: scale t back to the caller's d.
    let h = triangle::intersect_moller_trumbore(&ray, tri, 0.0, f32::INFINITY)?;
    Some((h.t / d.length(), h.u, h.v))
}

/// Relative error of `got` against `want`, infinite when one is missing.
fn rel(got: Option<f32>, want: Option<f32>) -> f64 {
    match (got, want) {
        (Some(g), Some(w)) => ((g - w).abs() / w.abs().max(1.0)) as f64,
        (None, None) => 0.0,
        _ => f64::INFINITY,
    }
}

fn check(cases: impl Iterator<Item = (f64, String)>, tolerance: f64) -> Check {
    let mut worst = (0.0f64, String::from("all cases match"));
    for (err, what) in cases {
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            worst = (err, what);
        }
    }
    Check {
        error: worst.0,
        tolerance,
        detail: worst.1,
        images: None,
        symptom: None,
    }
}

/// Hand-worked planes, a parallel ray, then random cases against the
/// reference.
pub fn check_ray_plane(f: fn(Vec3, Vec3, Vec3, f32) -> Option<f32>) -> Check {
    let mut cases: Vec<(Vec3, Vec3, Vec3, f32, Option<f32>)> = vec![
        // The plane z = -2, a ray down -z from the origin: t = 2.
        (Vec3::ZERO, -Vec3::Z, Vec3::Z, -2.0, Some(2.0)),
        // The plane x + y = 4 (N = (1, 1, 0), c = 4), ray along +x from (1, 1, 0): t = 2.
        (
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::X,
            Vec3::new(1.0, 1.0, 0.0),
            4.0,
            Some(2.0),
        ),
        // Behind the origin: t = -3 (the sign is the caller's business).
        (Vec3::new(0.0, 3.0, 0.0), Vec3::Y, Vec3::Y, 0.0, Some(-3.0)),
        // Parallel: no t.
        (Vec3::ZERO, Vec3::X, Vec3::Y, 1.0, None),
    ];
    for i in 0..200u64 {
        let r = |d| random(31, i, 0, d) * 2.0 - 1.0;
        let (o, d, n) = (
            Vec3::new(r(0), r(1), r(2)) * 3.0,
            Vec3::new(r(3), r(4), r(5)),
            Vec3::new(r(6), r(7), r(8)),
        );
        if n.dot(d).abs() > 0.1 {
            let c = r(9);
            cases.push((o, d, n, c, triangle::ray_plane(o, d, n, c)));
        }
    }
    check(
        cases.into_iter().map(|(o, d, n, c, want)| {
            let got = f(o, d, n, c);
            (
                rel(got, want),
                format!("o {o}, d {d}, N {n}, c {c}: got {got:?}, expected {want:?}"),
            )
        }),
        1e-4,
    )
}

/// Hand-worked points of one triangle, a degenerate triangle, and random
/// points against the reference.
pub fn check_barycentric_inside(f: fn(Vec3, [Vec3; 3]) -> Option<(f32, f32)>) -> Check {
    let tri = [
        Vec3::ZERO,
        Vec3::new(2.0, 0.0, 0.0),
        Vec3::new(0.0, 2.0, 0.0),
    ];
    let mut cases: Vec<(Vec3, [Vec3; 3], Option<Uv>)> = vec![
        (Vec3::new(1.0, 0.5, 0.0), tri, Some((0.5, 0.25))),
        (Vec3::ZERO, tri, Some((0.0, 0.0))),
        (Vec3::new(1.0, 1.0, 0.0), tri, Some((0.5, 0.5))),
        (Vec3::new(1.5, 1.5, 0.0), tri, None),
        (Vec3::new(-0.1, 0.5, 0.0), tri, None),
        (
            Vec3::new(0.5, 0.5, 0.0),
            [Vec3::ZERO, Vec3::X, Vec3::X * 2.0],
            None,
        ),
    ];
    for i in 0..300u64 {
        let r = |d| random(32, i, 0, d) * 2.0 - 1.0;
        let t = [
            Vec3::new(r(0), r(1), r(2)),
            Vec3::new(r(3), r(4), r(5)),
            Vec3::new(r(6), r(7), r(8)),
        ];
        let (u, v) = (r(9) * 0.8 + 0.3, r(10) * 0.8 + 0.3);
        let p = t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
        // Skip points right on an edge, where rounding decides.
        if u.abs().min(v.abs()).min((1.0 - u - v).abs()) > 1e-3 {
            cases.push((p, t, triangle::barycentric_inside(p, t)));
        }
    }
    check(
        cases.into_iter().map(|(p, t, want)| {
            let got = f(p, t);
            let err = match (got, want) {
                (Some(g), Some(w)) => ((g.0 - w.0).abs().max((g.1 - w.1).abs())) as f64,
                (None, None) => 0.0,
                _ => f64::INFINITY,
            };
            (
                err,
                format!("p {p} in {t:?}: got {got:?}, expected {want:?}"),
            )
        }),
        1e-4,
    )
}

/// Hand-worked rays, parallel and degenerate cases, and random rays against
/// an f64 solution of the same 3x3 system.
pub fn check_moller_trumbore(f: fn(Vec3, Vec3, [Vec3; 3]) -> Option<Tuv>) -> Check {
    let tri = [
        Vec3::new(0.0, 0.0, -2.0),
        Vec3::new(2.0, 0.0, -2.0),
        Vec3::new(0.0, 2.0, -2.0),
    ];
    let mut cases: Vec<(Vec3, Vec3, [Vec3; 3], Option<Tuv>)> = vec![
        // Straight down -z onto (1, 0.5, -2): t = 2, u = 0.5, v = 0.25.
        (
            Vec3::new(1.0, 0.5, 0.0),
            -Vec3::Z,
            tri,
            Some((2.0, 0.5, 0.25)),
        ),
        // The same with an unnormalised direction: t halves.
        (
            Vec3::new(1.0, 0.5, 0.0),
            -Vec3::Z * 2.0,
            tri,
            Some((1.0, 0.5, 0.25)),
        ),
        // Behind the origin, outside, parallel, degenerate: no hit.
        (Vec3::new(1.0, 0.5, 0.0), Vec3::Z, tri, None),
        (Vec3::new(3.0, 3.0, 0.0), -Vec3::Z, tri, None),
        (Vec3::new(0.0, 0.0, -2.0), Vec3::X, tri, None),
        (
            Vec3::ZERO,
            -Vec3::Z,
            [Vec3::ZERO, Vec3::X, Vec3::X * 2.0],
            None,
        ),
    ];
    for i in 0..300u64 {
        let r = |d| random(33, i, 0, d) * 2.0 - 1.0;
        let t = [
            Vec3::new(r(0), r(1), r(2) - 3.0),
            Vec3::new(r(3), r(4), r(5) - 3.0),
            Vec3::new(r(6), r(7), r(8) - 3.0),
        ];
        let (o, d) = (
            Vec3::new(r(9), r(10), r(11)) * 0.5,
            Vec3::new(r(12), r(13), -2.0),
        );
        let want = intersect_f64(o.as_dvec3(), d.as_dvec3(), t.map(|p| p.as_dvec3()));
        let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
        let clear = match want {
            Some((_, u, v)) => u.min(v).min(1.0 - u - v) > 1e-3,
            None => true,
        };
        if clear && n.dot(d.normalize()).abs() > 0.05 {
            cases.push((
                o,
                d,
                t,
                want.map(|(t, u, v)| (t as f32, u as f32, v as f32)),
            ));
        }
    }
    check(
        cases.into_iter().map(|(o, d, t, want)| {
            let got = f(o, d, t);
            let err = match (got, want) {
                (Some(g), Some(w)) => ((g.0 - w.0).abs() / w.0.abs().max(1.0))
                    .max((g.1 - w.1).abs())
                    .max((g.2 - w.2).abs()) as f64,
                (None, None) => 0.0,
                _ => f64::INFINITY,
            };
            (
                err,
                format!("o {o}, d {d}, {t:?}: got {got:?}, expected {want:?}"),
            )
        }),
        1e-4,
    )
}

mod bvh;
pub use bvh::*;
