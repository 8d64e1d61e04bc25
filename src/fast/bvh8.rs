//! The fast engine's BVH: chapter 3's binary tree collapsed to *eight*
//! children per node and up to eight triangles per leaf, stored by
//! coordinate (`[f32; 8]` per axis) so that one pass over the lanes tests
//! all eight boxes or triangles. The queries run the kernels of
//! [`super::kernels`], compiled for the CPU's vectors ([`super::simd`]).
//! This tree also answers them with the plain lane loops of
//! [`super::lanes`], the form the book shows and tests compare the kernels
//! with: the same nodes and leaves in the same order, the same bits.
//!
//! The rare lanes the triangle test hands back (an edge function exactly
//! zero, a t too small to trust) go to the same one-triangle test as the
//! readable engine's.

use glam::Vec3;
use obvhs::aabb::Aabb;
use obvhs::bvh2::Bvh2;
use obvhs::BvhBuildParams;

use crate::ch3_ray_triangle::bvh_robust::build_tree;
use crate::ch3_ray_triangle::obvhs_bvh::padded_boxes;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;
use crate::ch3_ray_triangle::watertight_fast::SoaTriangle;
use crate::ch3_ray_triangle::wide_build::{
    any_checked, closest, count_triangles, nearest_checked, nearest_lane, occluded, open_children,
    triangles_under, AnyHit, ClosestHit, Nearest, WideTree,
};

use super::lanes::{enter, leaf_test, Hits8, Leaf8, Node8, RayData, LEAF, LEAF_SIZE, W};
use super::level::Level;

/// The lanes a narrow node or leaf uses.
const NARROW: usize = 4;

/// The eight-wide tree.
pub struct Bvh8 {
    pub(super) nodes: Vec<Node8>,
    pub(super) leaves: Vec<Leaf8>,
    pub(super) root: u32,
    /// Inner-node levels on the longest root-to-leaf path.
    depth: usize,
    /// The triangles one by one (`tris[8 l + lane]`) for the rare lanes.
    tris: Vec<SoaTriangle>,
    /// `original[8 l + lane]`: the triangle's index in the build list.
    pub(super) original: Vec<u32>,
    /// Per node and per leaf: whether only its first four lanes are used,
    /// so that a four-lane test suffices (half the work where vectors hold
    /// four numbers, as on the portable path).
    narrow_nodes: Vec<bool>,
    narrow_leaves: Vec<bool>,
    /// Which vector instructions the queries use: private, and set only by
    /// [`Bvh8::build`] to a level this CPU has ([`super::simd`]'s
    /// dispatchers rely on it).
    level: Level,
}

// ANCHOR: open_rooms
/// Marks the subtrees of `bvh2` that would make a leaf (at most
/// [`LEAF_SIZE`] triangles, `counts`) but whose box holds more than half
/// of the whole tree's volume as too big for one (`LEAF_SIZE + 1`), so
/// that the tree opens them into their parts. Such a leaf is the walls of
/// a room: nearly every ray starts inside its box, so nearly every query
/// would test its triangles. Opened, its parts are flat boxes along the
/// walls, which the nearest-first order passes by once a nearer hit is
/// found (and which a ray leaving a wall along an axis, moved off it by
/// more than the boxes' padding, does not enter). Larger scenes have
/// no such leaf; a flat scene (no volume) is left as it is.
fn open_rooms(bvh2: &Bvh2, counts: &mut [u32]) {
    let room = room(bvh2);
    for (n, count) in counts.iter_mut().enumerate() {
        if (2..=LEAF_SIZE as u32).contains(count) && volume(&bvh2.nodes[n].aabb) > room {
            *count = LEAF_SIZE as u32 + 1;
        }
    }
}
// ANCHOR_END: open_rooms

/// A leaf whose box holds more than this volume (half the whole tree's)
/// is a room.
fn room(bvh2: &Bvh2) -> f32 {
    0.5 * volume(&bvh2.nodes[0].aabb)
}

/// The volume of `b`.
fn volume(b: &Aabb) -> f32 {
    let d = b.max - b.min;
    d.x * d.y * d.z
}

/// The box around triangles `ids` (their padded boxes).
fn bounds(ids: &[u32], boxes: &[Aabb]) -> Aabb {
    let mut b = Aabb::INVALID;
    for &i in ids {
        b = b.union(&boxes[i as usize]);
    }
    b
}

// ANCHOR: pack_leaves
/// A better way to put triangles `ids` (more than one leaf's worth, at
/// most a node's) into leaves than the binary tree's, whose leaves have
/// boxes of half-area `area` in all: `None` if there is none.
///
/// A ray tests a leaf when it enters the leaf's box, which happens about
/// in proportion to the box's area, so the best leaves are those whose
/// areas add up to the least. The binary tree splits a box's twelve
/// triangles into two leaves of four sides each, both as big as the box,
/// and a ray that meets the box tests both. Sorted along an axis (by
/// their boxes' centres), the same triangles split into the bottom, the
/// four sides and the top: a ray that meets the box tests the sides and
/// only the flat top or bottom it crosses. This finds, for each axis, the
/// runs of at most [`LEAF_SIZE`] consecutive triangles whose boxes' areas
/// add up to the least (a shortest path over the sorted list), and keeps
/// the best axis if it beats the binary tree's leaves by a tenth. A leaf
/// whose box would hold more than `room` ([`room`]) is not allowed, for
/// the reason [`open_rooms`] gives.
fn pack_leaves(ids: &[u32], boxes: &[Aabb], area: f32, room: f32) -> Option<Vec<Vec<u32>>> {
    let mut best: Option<(f32, Vec<Vec<u32>>)> = None;
    for axis in 0..3 {
        let mut sorted = ids.to_vec();
        let centre = |i: &u32| boxes[*i as usize].center()[axis];
        sorted.sort_by(|a, b| centre(a).total_cmp(&centre(b)));
        // cost[k]: the least area of leaves holding the first k triangles,
        // the last leaf starting at from[k].
        let n = sorted.len();
        let mut cost = vec![f32::INFINITY; n + 1];
        let mut from = vec![0; n + 1];
        cost[0] = 0.0;
        for end in 1..=n {
            // The last leaf grown backwards from `end`, a triangle at a time.
            let mut b = Aabb::INVALID;
            for start in (end.saturating_sub(LEAF_SIZE)..end).rev() {
                b = b.union(&boxes[sorted[start] as usize]);
                if end - start > 1 && volume(&b) > room {
                    break;
                }
                let c = cost[start] + b.half_area();
                if c < cost[end] {
                    (cost[end], from[end]) = (c, start);
                }
            }
        }
        let mut groups = Vec::new();
        let mut end = n;
        while end > 0 {
            groups.push(sorted[from[end]..end].to_vec());
            end = from[end];
        }
        groups.reverse();
        let fits = cost[n].is_finite() && groups.len() <= W;
        if fits && best.as_ref().is_none_or(|(c, _)| cost[n] < *c) {
            best = Some((cost[n], groups));
        }
    }
    best.filter(|(c, _)| *c < 0.9 * area).map(|(_, g)| g)
}
// ANCHOR_END: pack_leaves

impl Bvh8 {
    /// Builds the tree over `tris` (`None` for an empty list): the same
    /// binary tree as the readable engine's, collapsed eight-wide. Its
    /// queries use `level`'s instructions, or the portable path if this
    /// CPU lacks them.
    pub fn build(tris: &[[Vec3; 3]], level: Level) -> Option<Bvh8> {
        if tris.is_empty() {
            return None;
        }
        let params = BvhBuildParams {
            max_prims_per_leaf: 1,
            ..BvhBuildParams::medium_build()
        };
        let boxes = padded_boxes(tris);
        let bvh2 = build_tree(&boxes, &params);
        let mut counts = vec![0u32; bvh2.nodes.len()];
        count_triangles(&bvh2, 0, &mut counts);
        open_rooms(&bvh2, &mut counts);
        let mut b = Bvh8 {
            nodes: Vec::new(),
            leaves: Vec::new(),
            root: 0,
            depth: 0,
            tris: Vec::new(),
            original: Vec::new(),
            narrow_nodes: Vec::new(),
            narrow_leaves: Vec::new(),
            level: level.or_portable(),
        };
        b.root = b.collapse((&bvh2, &counts, &boxes, room(&bvh2)), 0, tris, 1);
        Some(b)
    }

    /// The boxes of its leaves, each as (min, max) corners, with the number
    /// of triangles in the leaf.
    pub fn leaf_boxes(&self) -> Vec<(Vec3, Vec3, usize)> {
        self.leaves
            .iter()
            .enumerate()
            .map(|(l, leaf)| {
                let (mut lo, mut hi, mut n) = (Vec3::INFINITY, Vec3::NEG_INFINITY, 0);
                for lane in (0..W).filter(|&lane| self.original[l * W + lane] != u32::MAX) {
                    n += 1;
                    for corner in 0..3 {
                        let p = Vec3::from_array(std::array::from_fn(|a| leaf.p[a][corner][lane]));
                        if p.is_finite() {
                            (lo, hi) = (lo.min(p), hi.max(p));
                        }
                    }
                }
                (lo, hi, n)
            })
            .collect()
    }

    /// Inner-node levels on the longest path.
    pub fn depth(&self) -> usize {
        self.depth
    }

    /// The vector instructions its queries use.
    pub fn level(&self) -> Level {
        self.level
    }

    /// Entries a traversal stack needs.
    pub fn stack_size(&self) -> usize {
        (W - 1) * self.depth + 1
    }

    fn collapse(
        &mut self,
        (bvh2, counts, boxes, room): (&Bvh2, &[u32], &[Aabb], f32),
        n: usize,
        tris: &[[Vec3; 3]],
        level: usize,
    ) -> u32 {
        if counts[n] as usize <= LEAF_SIZE {
            return self.leaf(&triangles_under(bvh2, n), tris);
        }
        self.depth = self.depth.max(level);
        let children = open_children(bvh2, counts, n, W, LEAF_SIZE);
        let index = self.nodes.len();
        self.narrow_nodes.push(children.len() <= NARROW);
        self.nodes.push(Node8 {
            min: [[f32::INFINITY; W]; 3],
            max: [[f32::NEG_INFINITY; W]; 3],
            child: [u32::MAX; W],
        });
        let set = |b: &mut Self, lane: usize, child: u32, aabb: Aabb| {
            let node = &mut b.nodes[index];
            node.child[lane] = child;
            for axis in 0..3 {
                node.min[axis][lane] = aabb.min[axis];
                node.max[axis][lane] = aabb.max[axis];
            }
        };
        let leaves_only = children.iter().all(|&c| counts[c] as usize <= LEAF_SIZE);
        if leaves_only {
            let area: f32 = children
                .iter()
                .map(|&c| bvh2.nodes[c].aabb.half_area())
                .sum();
            let ids = triangles_under(bvh2, n);
            if let Some(groups) = pack_leaves(&ids, boxes, area, room) {
                self.narrow_nodes[index] = groups.len() <= NARROW;
                for (lane, group) in groups.iter().enumerate() {
                    let child = self.leaf(group, tris);
                    set(self, lane, child, bounds(group, boxes));
                }
                return index as u32;
            }
        }
        for (lane, &c) in children.iter().enumerate() {
            let child = self.collapse((bvh2, counts, boxes, room), c, tris, level + 1);
            set(self, lane, child, bvh2.nodes[c].aabb);
        }
        index as u32
    }

    fn leaf(&mut self, ids: &[u32], tris: &[[Vec3; 3]]) -> u32 {
        let mut leaf = Leaf8 {
            p: [[[f32::NAN; W]; 3]; 3],
        };
        for lane in 0..W {
            let id = ids.get(lane).copied();
            let tri = id.map(|i| SoaTriangle::new(tris[i as usize]));
            self.tris.push(tri.unwrap_or(SoaTriangle {
                rows: [glam::Vec3A::NAN; 3],
            }));
            self.original.push(id.unwrap_or(u32::MAX));
            let Some(tri) = tri else { continue };
            if tri.rows.iter().all(|r| r.x == r.y && r.y == r.z) {
                continue; // zero area: stays NaN
            }
            for (axis, row) in tri.rows.iter().enumerate() {
                for (vertex, x) in row.to_array().into_iter().enumerate() {
                    leaf.p[axis][vertex][lane] = x;
                }
            }
        }
        self.leaves.push(leaf);
        self.narrow_leaves.push(ids.len() <= NARROW);
        (self.leaves.len() - 1) as u32 | LEAF
    }

    /// The closest hit in (0, t_max), `stack` holding at least
    /// [`Bvh8::stack_size`] entries ([`closest`], with the plain lane
    /// loops).
    #[inline(always)]
    pub(super) fn closest_with(
        &self,
        r: &RayData,
        t_max: f32,
        stack: &mut [(u32, f32)],
    ) -> Option<Hit> {
        let mut found = Nearest::new(t_max);
        closest(self, r, &mut found, stack);
        found.hit
    }

    /// The nearest of `best` (the leaf's hits so far) and leaf `l`'s rare
    /// lanes `check` hit in (0, t_max), by the one-triangle test.
    pub(super) fn leaf_checked(
        &self,
        r: &RayData,
        l: usize,
        check: u32,
        t_max: f32,
        best: Option<(Hit, usize)>,
    ) -> Option<(Hit, usize)> {
        nearest_checked(&r.wt, self.leaf_tris(l), check, t_max, best)
    }

    /// Whether any of leaf `l`'s rare lanes `check` is hit in (0, t_max).
    pub(super) fn leaf_any_checked(&self, r: &RayData, l: usize, check: u32, t_max: f32) -> bool {
        any_checked(&r.wt, self.leaf_tris(l), check, t_max)
    }

    /// The lane test of leaf `l`'s triangles, four lanes wide where it
    /// holds at most four.
    #[inline(always)]
    fn leaf_test(&self, r: &RayData, l: usize, t_max: f32) -> Hits8 {
        match self.narrow_leaves[l] {
            true => leaf_test::<NARROW>(r, &self.leaves[l], t_max),
            false => leaf_test::<W>(r, &self.leaves[l], t_max),
        }
    }

    /// Whether inner node `node` uses only its first four lanes.
    #[inline(always)]
    pub(super) fn narrow_node(&self, node: usize) -> bool {
        self.narrow_nodes[node]
    }

    /// Whether leaf `l` holds at most four triangles.
    #[inline(always)]
    pub(super) fn narrow_leaf(&self, l: usize) -> bool {
        self.narrow_leaves[l]
    }

    /// Leaf `l`'s triangles one by one, for the rare lanes.
    fn leaf_tris(&self, l: usize) -> &[SoaTriangle] {
        &self.tris[l * W..(l + 1) * W]
    }

    /// The closest hit of `ray` in (0, t_max) by the plain lane loops of
    /// [`super::lanes`], whatever the tree's level: what the kernels must
    /// find, bit for bit (the tests' reference).
    pub fn closest_by_lane_loops(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let stack = &mut vec![(0, 0.0); self.stack_size()];
        self.closest_with(&RayData::new(ray), t_max, stack)
    }

    /// Whether anything is hit in (0, t_max), by the plain lane loops
    /// ([`occluded`] over this tree).
    pub fn occluded_by_lane_loops(&self, ray: &Ray, t_max: f32) -> bool {
        let stack = &mut vec![(0, 0.0); self.stack_size()];
        occluded(self, &RayData::new(ray), t_max, stack)
    }
}

/// The eight-wide tree's plain lane loops for the queries written once
/// ([`closest`], [`occluded`]); the kernels ([`super::kernels`]) are the
/// same tests over a vector type.
impl WideTree<W> for Bvh8 {
    type Ray<'r> = RayData<'r>;

    #[inline(always)]
    fn root(&self) -> u32 {
        self.root
    }

    #[inline(always)]
    fn enter(&self, r: &RayData, node: usize, t_max: f32) -> (u32, [f32; W], &[u32; W]) {
        let narrow = self.narrow_nodes[node];
        let node = &self.nodes[node];
        let (entered, t_near) = match narrow {
            true => enter::<NARROW>(r, node, t_max),
            false => enter::<W>(r, node, t_max),
        };
        (entered, t_near, &node.child)
    }
}

impl ClosestHit<W> for Bvh8 {
    type Found = Nearest;

    #[inline(always)]
    fn leaf_closest(&self, r: &RayData, leaf: usize, found: &mut Nearest) {
        let h = self.leaf_test(r, leaf, found.t);
        let best = nearest_lane(h.hit, &h.t, &h.u, &h.v);
        let best = match h.check {
            0 => best,
            check => self.leaf_checked(r, leaf, check, found.t, best),
        };
        found.keep(best, |lane| self.original[leaf * W + lane]);
    }
}

impl AnyHit<W> for Bvh8 {
    #[inline(always)]
    fn leaf_any(&self, r: &RayData, leaf: usize, t_max: f32) -> bool {
        let h = self.leaf_test(r, leaf, t_max);
        h.hit != 0 || (h.check != 0 && self.leaf_any_checked(r, leaf, h.check, t_max))
    }
}
