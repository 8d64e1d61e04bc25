//! The BVH the shading chapters trace through: chapter 3's hierarchy
//! converted into obvhs' compressed eight-wide form (`CwBvh`), where one
//! node test checks eight child boxes at once with SIMD and the tree is a
//! third as deep. Chapter 3 teaches the binary tree ([`crate::bvh`]); a
//! path tracer casts tens of millions of rays, so it takes the wide one.
//! Both answer the same questions with the same watertight triangle test
//! ([`WatertightRay`]), and a test checks that they agree ray for ray.
//!
//! One detail of obvhs shapes the traversal: its node test ignores boxes
//! that end nearer than t = 10⁻⁴ along the ray (a fixed, absolute
//! "ε"). A path vertex in a corner has walls closer than that, and
//! a scene modelled at millimetre scale has everything closer than that,
//! so dropping those boxes would leak light. The traversal therefore tests
//! boxes with a copy of the ray started [`NODE_SHIFT`] *behind* its real
//! origin, which moves every box 2·10⁻⁴ further along it, while the
//! triangle test uses the real ray and the real distances.

use std::time::Duration;

use glam::Vec3;
use glam34::{UVec2, Vec3A};
use obvhs::cwbvh::builder::build_cwbvh;
use obvhs::cwbvh::CwBvh;
use obvhs::ray::Ray as ORay;
use obvhs::{traverse, BvhBuildParams};

use crate::bvh::padded_boxes;
use crate::ray::Ray;
use crate::triangle::Hit;
use crate::watertight_fast::{SoaTriangle, WatertightRay};

/// How far behind the real origin the box-testing ray starts: twice
/// obvhs' node ε (10⁻⁴), so no box at t ≥ 0 on the real ray is culled.
pub const NODE_SHIFT: f32 = 2e-4;

/// Chapter 3's BVH in obvhs' compressed 8-wide layout.
pub struct WideBvh {
    bvh: CwBvh,
    /// Triangles in the wide BVH's order, as [`SoaTriangle`]s.
    tris: Vec<SoaTriangle>,
    /// `original[k]`: the index of `tris[k]` in the list the BVH was built
    /// from.
    original: Vec<u32>,
}

impl WideBvh {
    /// Builds the wide BVH over `tris` (with chapter 3's padded boxes,
    /// leaves of up to three triangles, children ordered for front-to-back
    /// traversal); `None` for an empty list.
    pub fn build(tris: &[[Vec3; 3]]) -> Option<WideBvh> {
        if tris.is_empty() {
            return None;
        }
        let wide = build_cwbvh(
            &padded_boxes(tris),
            BvhBuildParams::medium_build(),
            &mut Duration::default(),
        );
        // The wide BVH's `primitive_indices` index `tris`; store the
        // triangles in that order so the hot loop needs no indirection.
        let original = wide.primitive_indices.clone();
        Some(WideBvh {
            tris: original
                .iter()
                .map(|&i| SoaTriangle::new(tris[i as usize]))
                .collect(),
            bvh: wide,
            original,
        })
    }

    /// How many 8-wide nodes the hierarchy has.
    pub fn node_count(&self) -> usize {
        self.bvh.nodes.len()
    }

    /// The box-testing ray: [`NODE_SHIFT`] behind `ray`, reaching
    /// `t_max` on the real ray.
    // ANCHOR: node_ray
    #[inline(always)]
    fn node_ray(ray: &Ray, t_max: f32) -> ORay {
        let o = ray.origin - NODE_SHIFT * ray.dir;
        let d = ray.dir;
        ORay::new(
            Vec3A::new(o.x, o.y, o.z),
            Vec3A::new(d.x, d.y, d.z),
            0.0,
            node_t(t_max),
        )
    }
    // ANCHOR_END: node_ray

    /// The closest hit in (0, t_max); `Hit::triangle` indexes the list
    /// chapter 3's BVH was built from.
    pub fn closest(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let wr = WatertightRay::new(ray);
        let mut best: Option<(Hit, usize)> = None;
        let mut t_best = t_max;
        self.walk(ray, t_max, |k, node_ray| {
            if let Some(hit) = wr.intersect(&self.tris[k], 0.0, t_best) {
                t_best = hit.t;
                node_ray.tmax = node_t(hit.t);
                best = Some((hit, k));
            }
            false
        });
        best.map(|(hit, k)| Hit {
            triangle: self.original[k],
            ..hit
        })
    }

    /// Whether anything is hit in (0, t_max): stops at the first hit.
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        let wr = WatertightRay::new(ray);
        let mut hit = false;
        self.walk(ray, t_max, |k, _| {
            hit = wr.intersect(&self.tris[k], 0.0, t_max).is_some();
            hit
        });
        hit
    }

    /// Walks the tree (nearest children first) with the box-testing ray,
    /// calling `visit(k, box_ray)` for each triangle `k` in a leaf it
    /// enters. `visit` may shorten `box_ray.tmax` and returns `true` to
    /// stop.
    #[inline(always)]
    fn walk(&self, ray: &Ray, t_max: f32, mut visit: impl FnMut(usize, &mut ORay) -> bool) {
        let mut node_ray = Self::node_ray(ray, t_max);
        let mut state = self.bvh.new_traversal(node_ray.direction);
        let mut node;
        'search: {
            traverse!(
                self.bvh,
                node,
                state,
                node.intersect_ray(&node_ray, state.oct_inv4),
                {
                    if visit(state.primitive_id as usize, &mut node_ray) {
                        break 'search;
                    }
                }
            );
        }
    }
}

/// The box-testing ray's parameter for distance `t` on the real ray,
/// rounded up a little so a box that ends exactly at `t` is still tested.
#[inline(always)]
fn node_t(t: f32) -> f32 {
    (t + NODE_SHIFT) * (1.0 + 1.0 / 1_048_576.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::Bvh;
    use crate::sampling::random;
    use crate::triangle::Intersector;

    /// A closed box of 12 triangles plus a few inside, scaled by `s`.
    fn box_scene(s: f32) -> Vec<[Vec3; 3]> {
        let mut tris = Vec::new();
        let c = [
            Vec3::new(-1.0, -1.0, -1.0),
            Vec3::new(1.0, -1.0, -1.0),
            Vec3::new(1.0, 1.0, -1.0),
            Vec3::new(-1.0, 1.0, -1.0),
            Vec3::new(-1.0, -1.0, 1.0),
            Vec3::new(1.0, -1.0, 1.0),
            Vec3::new(1.0, 1.0, 1.0),
            Vec3::new(-1.0, 1.0, 1.0),
        ];
        for [a, b, cc, d] in [
            [0, 1, 2, 3],
            [4, 5, 6, 7],
            [0, 1, 5, 4],
            [3, 2, 6, 7],
            [0, 3, 7, 4],
            [1, 2, 6, 5],
        ] {
            tris.push([c[a], c[b], c[cc]]);
            tris.push([c[a], c[cc], c[d]]);
        }
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
                // t far below obvhs' node ε), directions anywhere.
                let u = |d| random(7, i, 0, d);
                let mut o = Vec3::new(u(0), u(1), u(2)) * 1.98 - 0.99;
                if i % 2 == 0 {
                    o.x = -1.0 + 1e-6;
                }
                let dir = Vec3::new(u(3) - 0.5, u(4) - 0.5, u(5) - 0.5);
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
            // The near hits are the case obvhs' own node test would drop
            // (at 1e4, coordinates are too coarse to place an origin so near).
            if scale <= 1.0 {
                assert!(near_hits > 1000, "scale {scale}: {near_hits} near hits");
            }
        }
    }
}
