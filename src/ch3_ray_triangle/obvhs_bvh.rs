//! Ray-mesh intersection: the lecture's naive loop over every triangle, and
//! a bounding volume hierarchy (BVH) built with the `obvhs` crate (the BVH
//! written to be read is [`super::readable_bvh`]).
//!
//! The naive loop costs O(N) per ray; the BVH skips every box the ray misses
//! and so costs about O(log N). Both answer the same two questions:
//! *closest hit* (which surface does the ray see first) and *occlusion* (is
//! anything in the way before `t_max`).
//!
//! obvhs works with 16-byte `Vec3A`s where raystep uses `Vec3`, so this file
//! is the only one that names obvhs types and converts vectors at the
//! boundary.
//! Two facts about obvhs 0.4 shape the code: hit ids index the BVH's
//! `primitive_indices`, not our triangle list (we store the triangles in BVH
//! order and keep the map back), and we compute barycentrics ourselves.

use std::time::{Duration, Instant};

use glam::Vec3;
use glam::Vec3A;
use obvhs::aabb::Aabb;
use obvhs::bvh2::builder::build_bvh2_from_tris;
use obvhs::bvh2::Bvh2;
use obvhs::ray::{Ray as ORay, RayHit};
use obvhs::triangle::Triangle as OTriangle;
use obvhs::BvhBuildParams;

use crate::ch3_ray_triangle::bvh_robust::build_tree;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::{Hit, Intersector};
use crate::ch3_ray_triangle::watertight_fast::{SoaTriangle, WatertightRay};
use crate::scene::mesh::Mesh;

/// Every triangle of a list of meshes as three vertex positions, with the
/// mesh each came from.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Triangles {
    /// (p0, p1, p2) of each triangle.
    pub tris: Vec<[Vec3; 3]>,
    /// The mesh index of each triangle.
    pub mesh: Vec<u32>,
}

impl Triangles {
    /// Flattens meshes into one triangle list, in mesh order.
    pub fn from_meshes(meshes: &[Mesh]) -> Triangles {
        let mut out = Triangles::default();
        for (m, mesh) in meshes.iter().enumerate() {
            for t in &mesh.triangles {
                out.tris.push(t.map(|i| mesh.positions[i as usize]));
                out.mesh.push(m as u32);
            }
        }
        out
    }
}

/// The naive closest hit: test every triangle, keep the nearest.
// ANCHOR: closest_naive
pub fn closest_naive(tris: &[[Vec3; 3]], ray: &Ray, t_max: f32, x: Intersector) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    let mut t_max = t_max;
    for (i, tri) in tris.iter().enumerate() {
        if let Some(hit) = x.intersect(ray, *tri, 0.0, t_max) {
            // Anything farther than this hit can be skipped from now on.
            t_max = hit.t;
            best = Some(Hit {
                triangle: i as u32,
                ..hit
            });
        }
    }
    best
}
// ANCHOR_END: closest_naive

/// The naive occlusion test: is any triangle hit in (0, t_max)?
pub fn occluded_naive(tris: &[[Vec3; 3]], ray: &Ray, t_max: f32, x: Intersector) -> bool {
    tris.iter()
        .any(|tri| x.intersect(ray, *tri, 0.0, t_max).is_some())
}

/// How much each triangle's box grows, relative to its largest coordinate
/// (2⁻²⁰).
pub const BOX_PADDING: f32 = 1.0 / 1_048_576.0;

/// The corners (min, max) of a triangle's box, padded on every axis by
/// [`BOX_PADDING`] of its largest coordinate: the one padding of every
/// BVH's boxes (obvhs' here, the readable BVH's `Aabb::around`). The slab
/// test's rounding grows with the size of the points it works on, whatever
/// the axis: a fan's sliver from (1, 0) to (-1, 6e-5) needs the y padding
/// of a point at 1, not of one at 6e-5.
pub fn padded_bounds(tri: &[Vec3; 3]) -> (Vec3, Vec3) {
    let lo = tri[0].min(tri[1]).min(tri[2]);
    let hi = tri[0].max(tri[1]).max(tri[2]);
    let pad = lo.abs().max(hi.abs()).max_element() * BOX_PADDING + f32::MIN_POSITIVE;
    (lo - pad, hi + pad)
}

/// Each triangle's box, padded ([`padded_bounds`]).
pub fn padded_boxes(tris: &[[Vec3; 3]]) -> Vec<Aabb> {
    tris.iter()
        .map(|tri| {
            let (lo, hi) = padded_bounds(tri);
            Aabb::new(Vec3A::from(lo), Vec3A::from(hi))
        })
        .collect()
}

/// A BVH over a triangle list (obvhs' `Bvh2`).
pub struct Bvh {
    bvh: Bvh2,
    /// The triangles in the BVH's order, stored by coordinate for the
    /// fast watertight test: `tris[k]` is triangle `original[k]` of the
    /// list it was built from (zero-area ones collapsed to a point).
    tris: Vec<SoaTriangle>,
    original: Vec<u32>,
    /// Wall-clock seconds the build took (including our reordering).
    pub build_seconds: f64,
}

impl Bvh {
    /// Builds a BVH over `tris`; `None` for an empty list (nothing to build).
    // ANCHOR: bvh_build
    pub fn build(tris: &[[Vec3; 3]]) -> Option<Bvh> {
        if tris.is_empty() {
            return None;
        }
        let start = Instant::now();
        // Boxes padded by about 1e-6 of their coordinates' magnitude: obvhs'
        // slab test rounds, and a ray aimed exactly at a vertex or an edge
        // (which lie on the faces of their triangles' boxes) could otherwise
        // be culled a box too early, undoing the watertight test.
        // The tree is built top-down by SAH in O(n log n) on any triangles
        // (see `bvh_robust`); obvhs traverses it.
        let boxes = padded_boxes(tris);
        let bvh = build_tree(&boxes, &BvhBuildParams::medium_build());
        // obvhs reports hits as positions in `primitive_indices`: store the
        // triangles in that order so the hot loop needs no indirection.
        let original = bvh.primitive_indices.clone();
        let tris = original
            .iter()
            .map(|&i| SoaTriangle::new(tris[i as usize]))
            .collect();
        Some(Bvh {
            bvh,
            tris,
            original,
            build_seconds: start.elapsed().as_secs_f64(),
        })
    }
    // ANCHOR_END: bvh_build

    /// How many nodes the hierarchy has.
    pub fn node_count(&self) -> usize {
        self.bvh.nodes.len()
    }

    /// How many levels the binary tree has below its root (0 for a root
    /// that is a leaf).
    pub fn depth(&self) -> usize {
        crate::ch3_ray_triangle::bvh_robust::depth(&self.bvh)
    }

    /// How many triangles it holds.
    pub fn triangle_count(&self) -> usize {
        self.tris.len()
    }

    fn oray(ray: &Ray, t_max: f32) -> ORay {
        ORay::new(Vec3A::from(ray.origin), Vec3A::from(ray.dir), 0.0, t_max)
    }

    /// The closest hit in (0, t_max); `Hit::triangle` indexes the list the
    /// BVH was built from. The watertight test runs in its fast form
    /// ([`WatertightRay`]: same hits, bit for bit); the other two through
    /// [`Bvh::closest_with`].
    // ANCHOR: bvh_closest
    pub fn closest(&self, ray: &Ray, t_max: f32, x: Intersector) -> Option<Hit> {
        if x != Intersector::Watertight {
            return self.closest_with(ray, t_max, |r, tri, t0, t1| x.intersect(r, tri, t0, t1));
        }
        // The ray's permutation and shear, once for all its triangles, and
        // only if it reaches a triangle at all (most primary rays do not).
        let mut wr: Option<WatertightRay> = None;
        let mut best: Option<(Hit, usize)> = None;
        let mut record = RayHit::none();
        self.bvh
            .ray_traverse(Self::oray(ray, t_max), &mut record, |r, k| {
                let wr = wr.get_or_insert_with(|| WatertightRay::new(ray));
                // r.tmax shrinks to the closest hit so far.
                match wr.intersect(&self.tris[k], 0.0, r.tmax) {
                    Some(hit) => {
                        best = Some((hit, k));
                        hit.t
                    }
                    None => f32::INFINITY,
                }
            });
        best.map(|(hit, k)| Hit {
            triangle: self.original[k],
            ..hit
        })
    }
    // ANCHOR_END: bvh_closest

    /// The closest hit in (0, t_max) with any triangle test `test(ray,
    /// [p0, p1, p2], t_min, t_max)`, e.g. the readable
    /// [`intersect_watertight`](crate::ch3_ray_triangle::triangle::intersect_watertight).
    pub fn closest_with(
        &self,
        ray: &Ray,
        t_max: f32,
        test: impl Fn(&Ray, [Vec3; 3], f32, f32) -> Option<Hit>,
    ) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut record = RayHit::none();
        self.bvh
            .ray_traverse(Self::oray(ray, t_max), &mut record, |r, k| {
                match test(ray, self.tris[k].vertices(), 0.0, r.tmax) {
                    Some(hit) => {
                        best = Some(Hit {
                            triangle: self.original[k],
                            ..hit
                        });
                        hit.t
                    }
                    None => f32::INFINITY,
                }
            });
        best
    }

    /// Whether anything is hit in (0, t_max): stops at the first hit found.
    pub fn occluded(&self, ray: &Ray, t_max: f32, x: Intersector) -> bool {
        if x != Intersector::Watertight {
            return self.occluded_with(ray, t_max, |r, tri, t0, t1| x.intersect(r, tri, t0, t1));
        }
        let mut wr: Option<WatertightRay> = None;
        !self.bvh.ray_traverse_miss(Self::oray(ray, t_max), |r, k| {
            let wr = wr.get_or_insert_with(|| WatertightRay::new(ray));
            match wr.intersect(&self.tris[k], 0.0, r.tmax) {
                Some(hit) => hit.t,
                None => f32::INFINITY,
            }
        })
    }

    /// [`Bvh::occluded`] with any triangle test, as in [`Bvh::closest_with`].
    pub fn occluded_with(
        &self,
        ray: &Ray,
        t_max: f32,
        test: impl Fn(&Ray, [Vec3; 3], f32, f32) -> Option<Hit>,
    ) -> bool {
        !self.bvh.ray_traverse_miss(Self::oray(ray, t_max), |r, k| {
            match test(ray, self.tris[k].vertices(), 0.0, r.tmax) {
                Some(hit) => hit.t,
                None => f32::INFINITY,
            }
        })
    }
}

/// obvhs on its own, with its own triangle test, for the benchmark: how
/// fast the library is without raystep's wrapper.
pub struct ObvhsAlone {
    bvh: Bvh2,
    tris: Vec<OTriangle>,
}

impl ObvhsAlone {
    /// Builds obvhs' BVH with the same parameters as [`Bvh::build`].
    pub fn build(tris: &[[Vec3; 3]]) -> ObvhsAlone {
        let tris: Vec<OTriangle> = tris
            .iter()
            .map(|[a, b, c]| OTriangle {
                v0: Vec3A::from(*a),
                v1: Vec3A::from(*b),
                v2: Vec3A::from(*c),
            })
            .collect();
        let bvh = build_bvh2_from_tris(
            &tris,
            BvhBuildParams::medium_build(),
            &mut Duration::default(),
        );
        ObvhsAlone { bvh, tris }
    }

    /// Closest hit distance, the way obvhs' own example does it.
    pub fn closest_t(&self, ray: &Ray) -> f32 {
        let mut hit = RayHit::none();
        self.bvh.ray_traverse(
            ORay::new_inf(Vec3A::from(ray.origin), Vec3A::from(ray.dir)),
            &mut hit,
            |r, id| self.tris[self.bvh.primitive_indices[id] as usize].intersect(r),
        );
        hit.t
    }

    /// Whether anything is hit before `t_max`.
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        !self.bvh.ray_traverse_miss(Bvh::oray(ray, t_max), |r, id| {
            self.tris[self.bvh.primitive_indices[id] as usize].intersect(r)
        })
    }
}
