//! The BVH the shading chapters trace through: chapter 3's binary
//! hierarchy collapsed into a *four-wide* one, the layout CPU ray tracers
//! such as Embree use. Each node holds the boxes of up to four children
//! side by side, so one SIMD slab test checks all four at once; each leaf
//! holds up to four triangles side by side, so one SIMD watertight test
//! ([`WatertightRay::intersect4`]) checks all of them. The tree is half as
//! deep as the binary one and a query takes few branches.
//!
//! Chapter 3 builds the binary tree with obvhs ([`crate::ch3_ray_triangle::obvhs_bvh`]); a path tracer casts
//! tens of millions of rays, so it takes this one. Both answer the same
//! questions with the same watertight arithmetic, and a test checks that
//! they agree ray for ray.

use glam::{Vec3, Vec3A, Vec4};
use obvhs::bvh2::Bvh2;
use obvhs::BvhBuildParams;

use crate::ch3_ray_triangle::bvh_robust::build_tree;
use crate::ch3_ray_triangle::obvhs_bvh::padded_boxes;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::{gamma, Hit};
use crate::ch3_ray_triangle::watertight_fast::{SoaTriangle, Tri4, WatertightRay};
use crate::ch3_ray_triangle::wide_build::{
    any_checked, closest, count_triangles, nearest_checked, nearest_lane, occluded, open_children,
    triangles_under, AnyHit, ClosestHit, Nearest, WideTree, LEAF,
};

/// Triangles per leaf, one per SIMD lane.
const LANES: usize = 4;

/// Up to four children's boxes, by axis, one child per lane. An unused
/// slot has an empty box (min +∞, max -∞) that no ray enters.
#[derive(Clone, Copy, Debug)]
struct Node4 {
    /// Box minima: x of the four children, then y, then z.
    min: [Vec4; 3],
    /// Box maxima, laid out the same way.
    max: [Vec4; 3],
    /// Child references (see [`LEAF`]).
    child: [u32; 4],
}

/// Chapter 3's BVH collapsed to four children per node and four
/// triangles per leaf.
pub struct WideBvh {
    /// Inner nodes; the root is `root` (a leaf when the scene has at most
    /// four triangles).
    nodes: Vec<Node4>,
    root: u32,
    /// Inner-node levels on the longest root-to-leaf path; a query's stack
    /// never holds more than 3 per level, plus one.
    depth: usize,
    /// Leaves: four triangles each, in SIMD lanes. Unused lanes and
    /// zero-area triangles hold NaN vertices, which the test rejects.
    leaves: Vec<Tri4>,
    /// The same triangles one by one (`tris[4 l + lane]`), for the rare
    /// lanes the four-wide test hands back to the one-triangle test.
    tris: Vec<SoaTriangle>,
    /// `original[4 l + lane]`: the index of that triangle in the list the
    /// BVH was built from (`u32::MAX` for an unused lane).
    original: Vec<u32>,
}

/// How much a box's far distance is stretched, so rounding in the slab
/// test never culls a box a hit lies in (pbrt stretches by 2γ₃ ≈ 4e-7).
pub const FAR_STRETCH: f32 = 1.0 + 4.0 * gamma(3);

/// The part of the slab test that depends only on the ray (chapter 6's
/// eight-wide tree uses it too).
pub struct BoxRay {
    /// The origin, one splat per axis.
    pub o: [Vec4; 3],
    /// 1 / direction per axis (zero components replaced by a tiny number
    /// of the same sign, so no 0 · ∞ can make a NaN).
    pub inv: [Vec4; 3],
    /// Per axis, whether the ray runs towards -∞ (then a box's max is met
    /// first).
    pub negative: [bool; 3],
}

impl BoxRay {
    /// The slab test's per-ray part for `ray`.
    #[inline(always)]
    pub fn new(ray: &Ray) -> BoxRay {
        let d = Vec3A::from(ray.dir);
        let tiny = d.abs().cmplt(Vec3A::splat(1e-30));
        let safe = Vec3A::select(tiny, Vec3A::splat(1e-30).copysign(d), d);
        let inv = (Vec3A::ONE / safe).to_array();
        BoxRay {
            o: ray.origin.to_array().map(Vec4::splat),
            inv: inv.map(Vec4::splat),
            negative: d.to_array().map(|x| x.is_sign_negative()),
        }
    }

    /// The slab test on a node's four boxes against (0, t_max): a bit
    /// mask of the children entered, and where the ray enters each box.
    // ANCHOR: slab4
    #[inline(always)]
    fn enter(&self, node: &Node4, t_max: f32) -> (u32, Vec4) {
        let mut t_near = Vec4::ZERO;
        let mut t_far = Vec4::splat(t_max);
        for axis in 0..3 {
            let (near, far) = if self.negative[axis] {
                (node.max[axis], node.min[axis])
            } else {
                (node.min[axis], node.max[axis])
            };
            t_near = t_near.max((near - self.o[axis]) * self.inv[axis]);
            t_far = t_far.min((far - self.o[axis]) * self.inv[axis]);
        }
        let entered = t_near.cmple(t_far * FAR_STRETCH);
        (entered.bitmask(), t_near)
    }
    // ANCHOR_END: slab4
}

impl WideBvh {
    /// Builds the four-wide BVH over `tris`: chapter 3's binary tree (with
    /// its padded boxes, one triangle per leaf), then collapsed from the
    /// root down; `None` for an empty list.
    pub fn build(tris: &[[Vec3; 3]]) -> Option<WideBvh> {
        if tris.is_empty() {
            return None;
        }
        let params = BvhBuildParams {
            max_prims_per_leaf: 1,
            ..BvhBuildParams::medium_build()
        };
        let bvh2 = build_tree(&padded_boxes(tris), &params);
        let mut counts = vec![0u32; bvh2.nodes.len()];
        count_triangles(&bvh2, 0, &mut counts);
        let mut wide = WideBvh {
            nodes: Vec::new(),
            root: 0,
            leaves: Vec::new(),
            tris: Vec::new(),
            original: Vec::new(),
            depth: 0,
        };
        wide.root = wide.collapse(&bvh2, &counts, 0, tris, 1);
        Some(wide)
    }

    /// How many four-wide inner nodes the hierarchy has.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// How many leaves (of up to four triangles) it has.
    pub fn leaf_count(&self) -> usize {
        self.leaves.len()
    }

    /// How many levels of inner nodes the deepest leaf sits below.
    pub fn depth(&self) -> usize {
        self.depth
    }

    /// Makes binary node `n` into a child reference: a leaf if its
    /// subtree has at most four triangles, else a four-wide node whose
    /// children are found by opening the largest binary child (by surface
    /// area) until there are four.
    // ANCHOR: collapse
    fn collapse(
        &mut self,
        bvh2: &Bvh2,
        counts: &[u32],
        n: usize,
        tris: &[[Vec3; 3]],
        level: usize,
    ) -> u32 {
        if counts[n] as usize <= LANES {
            return self.leaf(bvh2, n, tris);
        }
        self.depth = self.depth.max(level);
        let children = open_children(bvh2, counts, n, 4, LANES);
        let index = self.nodes.len();
        self.nodes.push(Node4 {
            min: [Vec4::INFINITY; 3],
            max: [Vec4::NEG_INFINITY; 3],
            child: [u32::MAX; 4],
        });
        for (lane, &c) in children.iter().enumerate() {
            let b = bvh2.nodes[c].aabb;
            let child = self.collapse(bvh2, counts, c, tris, level + 1);
            let node = &mut self.nodes[index];
            node.child[lane] = child;
            for axis in 0..3 {
                node.min[axis][lane] = b.min[axis];
                node.max[axis][lane] = b.max[axis];
            }
        }
        index as u32
    }
    // ANCHOR_END: collapse

    /// A leaf holding every triangle under binary node `n` (at most four).
    fn leaf(&mut self, bvh2: &Bvh2, n: usize, tris: &[[Vec3; 3]]) -> u32 {
        let ids = triangles_under(bvh2, n);
        let nan = SoaTriangle {
            rows: [glam::Vec3A::NAN; 3],
        };
        let lanes = std::array::from_fn(|lane| {
            let id = ids.get(lane).copied().unwrap_or(u32::MAX);
            let tri = match ids.get(lane) {
                Some(&i) => SoaTriangle::new(tris[i as usize]),
                None => nan,
            };
            self.tris.push(tri);
            self.original.push(id);
            // Zero-area triangles (collapsed to a point) can never be hit:
            // NaN keeps them out of the rare-path checks as well.
            let collapsed = tri.rows.iter().all(|r| r.x == r.y && r.y == r.z);
            if collapsed {
                nan
            } else {
                tri
            }
        });
        self.leaves.push(Tri4::new(lanes));
        (self.leaves.len() - 1) as u32 | LEAF
    }

    /// The closest hit in (0, t_max); `Hit::triangle` indexes the list
    /// chapter 3's BVH was built from.
    pub fn closest(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let r = (WatertightRay::new(ray), BoxRay::new(ray));
        let mut found = Nearest::new(t_max);
        self.with_stack(|stack| closest(self, &r, &mut found, stack));
        found.hit
    }

    /// Whether anything is hit in (0, t_max): stops at the first hit, in
    /// no particular order.
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        let r = (WatertightRay::new(ray), BoxRay::new(ray));
        self.with_stack(|stack| occluded(self, &r, t_max, stack))
    }

    /// Leaf `leaf`'s triangles one by one, for the rare lanes.
    fn leaf_tris(&self, leaf: usize) -> &[SoaTriangle] {
        &self.tris[leaf * LANES..(leaf + 1) * LANES]
    }

    /// Runs `query` with a traversal stack deep enough for this tree: this
    /// thread's stack of [`ON_STACK`] entries, which trees of up to 15
    /// levels fit in (the 6,404 triangles of `scenes/brdf-row.toml` make
    /// 8), or a fresh one on the heap for a deeper tree. (A stack made
    /// anew for every query would have to be zeroed every time.)
    #[inline(always)]
    fn with_stack<R>(&self, query: impl FnOnce(&mut [(u32, f32)]) -> R) -> R {
        let needed = 3 * self.depth + 1;
        if needed <= ON_STACK {
            STACK.with_borrow_mut(|stack| query(stack))
        } else {
            query(&mut vec![(0, 0.0); needed])
        }
    }
}

/// Entries in each thread's traversal stack.
const ON_STACK: usize = 46;

thread_local! {
    /// Each thread's traversal stack (a query does not call another, so
    /// one per thread is enough).
    static STACK: std::cell::RefCell<[(u32, f32); ON_STACK]> =
        const { std::cell::RefCell::new([(0, 0.0); ON_STACK]) };
}

/// The four-wide tree's tests for the queries written once
/// ([`super::wide_build::closest`], [`super::wide_build::occluded`]).
impl WideTree<LANES> for WideBvh {
    type Ray<'r> = (WatertightRay<'r>, BoxRay);

    #[inline(always)]
    fn root(&self) -> u32 {
        self.root
    }

    #[inline(always)]
    fn enter(
        &self,
        r: &Self::Ray<'_>,
        node: usize,
        t_max: f32,
    ) -> (u32, [f32; LANES], &[u32; LANES]) {
        let node = &self.nodes[node];
        let (entered, t_near) = r.1.enter(node, t_max);
        (entered, t_near.to_array(), &node.child)
    }
}

impl ClosestHit<LANES> for WideBvh {
    type Found = Nearest;

    #[inline(always)]
    fn leaf_closest(&self, r: &Self::Ray<'_>, leaf: usize, found: &mut Nearest) {
        let h = r.0.intersect4(&self.leaves[leaf], 0.0, found.t);
        let (t, u, v) = (h.t.to_array(), h.u.to_array(), h.v.to_array());
        let best = nearest_lane(h.hit, &t, &u, &v);
        let best = match h.check {
            0 => best,
            check => nearest_checked(&r.0, self.leaf_tris(leaf), check, found.t, best),
        };
        found.keep(best, |lane| self.original[leaf * LANES + lane]);
    }
}

impl AnyHit<LANES> for WideBvh {
    #[inline(always)]
    fn leaf_any(&self, r: &Self::Ray<'_>, leaf: usize, t_max: f32) -> bool {
        let h = r.0.intersect4(&self.leaves[leaf], 0.0, t_max);
        h.hit != 0 || (h.check != 0 && any_checked(&r.0, self.leaf_tris(leaf), h.check, t_max))
    }
}
