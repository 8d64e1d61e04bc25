//! Chapter 3's exercises and how each is graded.

use crate::ch3_ray_triangle::triangle;
use crate::grading::exercise::Exercise;

mod bvh;
mod bvh_deep;
mod bvh_symptoms;
mod triangle_checks;
pub use bvh::*;
pub use triangle_checks::*;

/// Chapter 3's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 3,
            name: "ray_plane",
            file: "chapters/ch3-ray-triangle/exercises/ray_plane.rs",
            hints: [
                "slide \"Geometry Ray-plane intersection\": the points of the ray are \
                 o + t d; the one on the plane is the one that satisfies the plane's \
                 equation.",
                "substitute r(t) = o + t d into Nᵀx = c: Nᵀo + t Nᵀd = c is linear in \
                 t, solve it; when Nᵀd = 0 the ray runs parallel to the plane and there \
                 is no single t: return None.",
                "t = (c - Nᵀo) / (Nᵀd); None when Nᵀd = 0",
            ],
            symptoms: &[PLANE_SIGN, PARALLEL],
            reference: || check_ray_plane(triangle::ray_plane),
        },
        Exercise {
            chapter: 3,
            name: "barycentric_inside",
            file: "chapters/ch3-ray-triangle/exercises/barycentric_inside.rs",
            hints: [
                "slide \"Geometry Ray-triangle intersection\": p - p0 = u e1 + v e2 is \
                 two unknowns in a plane; a cross product removes one of them.",
                "with e1 = p1 - p0, e2 = p2 - p0, q = p - p0 and N = e1 × e2: crossing \
                 q = u e1 + v e2 with e2 leaves q × e2 = u (e1 × e2) = u N, and e1 × q = \
                 v N; project both on N to get numbers. Return None for N = 0 (no area) \
                 and for a point outside.",
                "u = Nᵀ(q × e2) / |N|², v = Nᵀ(e1 × q) / |N|²; inside when u ≥ 0, \
                 v ≥ 0 and u + v ≤ 1",
            ],
            symptoms: &[SWAPPED_UV, EDGES_OUTSIDE, DEGENERATE],
            reference: || check_barycentric_inside(triangle::barycentric_inside),
        },
        Exercise {
            chapter: 3,
            name: "moller_trumbore",
            file: "chapters/ch3-ray-triangle/exercises/moller_trumbore.rs",
            hints: [
                "slide \"Geometry Ray-triangle intersection\": the slide's 3x3 system \
                 [p1 - p0, p2 - p0, -d](u, v, t)ᵀ = o - p0 solves for all three at \
                 once; Cramer's rule solves it with determinants.",
                "det[a, b, c] = a · (b × c). Compute det = det[e1, e2, -d]; reject 0. \
                 Replace one column at a time by s = o - p0 and divide by det to get u, \
                 v and t. Reject u or v < 0, u + v > 1 and t ≤ 0.",
                "det = e1 · (d × e2); u = s · (d × e2) / det; with q = s × e1: \
                 v = d · q / det, t = e2 · q / det",
            ],
            symptoms: &[UNIT_T, DEGENERATE, PARALLEL, BEHIND],
            reference: || check_moller_trumbore(reference_moller_trumbore),
        },
        Exercise {
            chapter: 3,
            name: "bvh_traversal",
            file: "chapters/ch3-ray-triangle/exercises/bvh_traversal.rs",
            hints: [
                "book \"A BVH you can read\": a ray that misses a box misses everything \
                 in it, and one that already hit at t can skip every box it enters \
                 beyond t; visiting the nearer box first makes that skip most of the \
                 tree.",
                "no nodes: None. inv_dir = 1 / ray.dir; best t = t_max. Keep a stack of \
                 (node, t where the ray enters its box), the root first if the ray \
                 enters it. Pop; skip the node if its entry t is beyond the best t. A \
                 leaf: test bvh.tris[bvh.order[i]] for i in first .. first + count with \
                 intersect_watertight(ray, tri, 0.0, best t), keep a hit with triangle \
                 = bvh.order[i] and shrink the best t to it. An inner node: enter both \
                 children against the best t and push those the ray enters, the \
                 farther first, so the nearer is popped next.",
                "pop (node, t_enter); if t_enter > t_best continue; Leaf: for id in \
                 order[first..first+count]: if let Some(h) = intersect_watertight(ray, \
                 tris[id], 0, t_best) { t_best = h.t; best = Hit { triangle: id, ..h } }; \
                 Inner: tl, tr = enter(left, t_best), enter(right, t_best); push far, \
                 then near",
            ],
            symptoms: SYMPTOMS,
            reference: || check_bvh_traversal(crate::grading::counted::closest_hit),
        },
    ]
}
