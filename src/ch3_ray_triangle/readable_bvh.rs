//! The lecture's "hierarchical approach" to ray-mesh intersection, written
//! to be read: a binary bounding volume hierarchy built by splitting at the
//! median, and its front-to-back closest-hit traversal.
//!
//! The naive loop ([`closest_naive`](super::obvhs_bvh::closest_naive)) tests every
//! triangle. A BVH puts the triangles in a tree of boxes: every node's box
//! holds all the triangles below it, so a ray that misses a box skips its
//! whole subtree, and a ray that already found a hit at distance t skips
//! every box it would enter beyond t. A ray then visits about log N boxes
//! instead of N triangles.
//!
//! This version is for reading and for the exercise; it gives the same
//! hits as the naive loop and as obvhs (tests check it ray for ray). The
//! renderer uses obvhs' builder ([`super::obvhs_bvh::Bvh`], a better tree from
//! the surface area heuristic) and the four-wide traversal
//! ([`super::wide_bvh::WideBvh`]).

use glam::Vec3;

use super::obvhs_bvh::padded_bounds;
use super::ray::Ray;
use super::triangle::{gamma, intersect_watertight, Hit};

/// An axis-aligned box, by its lowest and highest corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest x, y and z.
    pub min: Vec3,
    /// The corner with the largest x, y and z.
    pub max: Vec3,
}

/// How much a box's far distance is stretched, so rounding in the slab test
/// never culls a box a hit lies in (pbrt stretches by 2γ₃).
const FAR_STRETCH: f32 = 1.0 + 2.0 * gamma(3);

impl Aabb {
    /// The empty box: growing it by anything gives that thing's box.
    pub const EMPTY: Aabb = Aabb {
        min: Vec3::INFINITY,
        max: Vec3::NEG_INFINITY,
    };

    /// The box around a triangle, padded by [`BOX_PADDING`](super::obvhs_bvh::BOX_PADDING) of its
    /// coordinates ([`padded_bounds`], as obvhs' boxes are), so that a ray
    /// aimed exactly at a vertex or an edge, which lie on the box's faces,
    /// is not culled by rounding.
    pub fn around(tri: &[Vec3; 3]) -> Aabb {
        let (min, max) = padded_bounds(tri);
        Aabb { min, max }
    }

    /// The smallest box holding both.
    pub fn union(self, other: Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The smallest box holding this one and the point `p`.
    pub fn grow(self, p: Vec3) -> Aabb {
        Aabb {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The slab test: where the ray enters the box, if it meets the box
    /// somewhere in [0, t_max]. `inv_dir` is 1 / ray.dir, per axis.
    // ANCHOR: slab_test
    pub fn enter(&self, ray: &Ray, inv_dir: Vec3, t_max: f32) -> Option<f32> {
        let mut t_near = 0.0f32;
        let mut t_far = t_max;
        for axis in 0..3 {
            // Where the ray crosses the box's two planes on this axis.
            let t0 = (self.min[axis] - ray.origin[axis]) * inv_dir[axis];
            let t1 = (self.max[axis] - ray.origin[axis]) * inv_dir[axis];
            // The interval inside the slab; f32::min and max ignore a NaN
            // (0 · ∞, a ray in the slab's plane), which keeps the box.
            t_near = t_near.max(t0.min(t1));
            t_far = t_far.min(t0.max(t1) * FAR_STRETCH);
        }
        (t_near <= t_far).then_some(t_near)
    }
    // ANCHOR_END: slab_test
}

/// Triangles per leaf at most: below this a split saves nothing.
pub const MAX_LEAF: usize = 2;

/// A node of the tree: its box, and either two children or some triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    /// Holds every triangle below this node.
    pub bounds: Aabb,
    /// What the node holds.
    pub kind: NodeKind,
}

/// An inner node's children, or a leaf's triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NodeKind {
    /// Two subtrees, by their index in [`ReadableBvh::nodes`].
    Inner {
        /// One half of the triangles.
        left: u32,
        /// The other half.
        right: u32,
    },
    /// Triangles `order[first .. first + count]` of [`ReadableBvh::order`].
    Leaf {
        /// Where the leaf's triangles start in `order`.
        first: u32,
        /// How many triangles (1 to [`MAX_LEAF`]).
        count: u32,
    },
}

/// A binary BVH over a triangle list; the root is `nodes[0]`.
#[derive(Clone, Debug, Default)]
pub struct ReadableBvh {
    /// Every node; children come after their parent.
    pub nodes: Vec<Node>,
    /// Triangle indices, arranged so that each leaf's are contiguous.
    pub order: Vec<u32>,
    /// The triangles the tree was built over (a hit's `triangle` indexes
    /// this list).
    pub tris: Vec<[Vec3; 3]>,
}

impl ReadableBvh {
    /// Builds the tree over `tris` (see `subdivide` below); an empty list
    /// gives an empty tree (no nodes, and every ray misses).
    // ANCHOR: build
    pub fn build(tris: &[[Vec3; 3]]) -> ReadableBvh {
        let boxes: Vec<Aabb> = tris.iter().map(Aabb::around).collect();
        // A triangle's centroid: the mean of its vertices.
        let centroids: Vec<Vec3> = tris.iter().map(|[a, b, c]| (*a + *b + *c) / 3.0).collect();
        let mut order: Vec<u32> = (0..tris.len() as u32).collect();
        let mut nodes = Vec::with_capacity(2 * tris.len());
        if !tris.is_empty() {
            subdivide(&mut nodes, &mut order, 0, &boxes, &centroids);
        }
        ReadableBvh {
            nodes,
            order,
            tris: tris.to_vec(),
        }
    }
    // ANCHOR_END: build

    /// The closest hit in (0, t_max), visiting the tree front to back; see
    /// [`closest_hit`].
    pub fn closest(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        closest_hit(self, ray, t_max)
    }

    /// How deep the tree is (a lone leaf is 1; an empty tree 0).
    pub fn depth(&self) -> usize {
        fn depth_of(bvh: &ReadableBvh, n: u32) -> usize {
            match bvh.nodes[n as usize].kind {
                NodeKind::Leaf { .. } => 1,
                NodeKind::Inner { left, right } => {
                    1 + depth_of(bvh, left).max(depth_of(bvh, right))
                }
            }
        }
        if self.nodes.is_empty() {
            0
        } else {
            depth_of(self, 0)
        }
    }
}

/// Makes a node for the triangles `ids` (which start at `first` in the
/// tree's `order`), appends it and everything below it to `nodes`, and
/// returns its index. Above [`MAX_LEAF`] triangles, the node splits them
/// at the median centroid along the axis where the centroids spread most:
/// half go left, half right, whatever the geometry. The tree is therefore
/// about log₂ N deep, and each level costs O(N) (`select_nth_unstable_by`
/// finds a median in linear time), so building takes O(N log N) even when
/// many centroids coincide (ties are split by count like any others).
// ANCHOR: subdivide
// ANCHOR: subdivide_leaf
fn subdivide(
    nodes: &mut Vec<Node>,
    ids: &mut [u32],
    first: usize,
    boxes: &[Aabb],
    centroids: &[Vec3],
) -> u32 {
    let bounds = ids
        .iter()
        .fold(Aabb::EMPTY, |b, &i| b.union(boxes[i as usize]));
    let index = nodes.len();
    nodes.push(Node {
        bounds,
        kind: NodeKind::Leaf {
            first: first as u32,
            count: ids.len() as u32,
        },
    });
    if ids.len() <= MAX_LEAF {
        return index as u32;
    }
    // ANCHOR_END: subdivide_leaf
    // ANCHOR: subdivide_split
    // The axis along which the centroids spread most...
    let spread = ids
        .iter()
        .fold(Aabb::EMPTY, |b, &i| b.grow(centroids[i as usize]));
    let extent = spread.max - spread.min;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    // ... and the median along it: afterwards no id left of `mid` has a
    // larger centroid than any id right of it.
    let mid = ids.len() / 2;
    ids.select_nth_unstable_by(mid, |&a, &b| {
        centroids[a as usize][axis].total_cmp(&centroids[b as usize][axis])
    });
    let (left_ids, right_ids) = ids.split_at_mut(mid);
    let left = subdivide(nodes, left_ids, first, boxes, centroids);
    let right = subdivide(nodes, right_ids, first + mid, boxes, centroids);
    // Now that both children exist, the leaf becomes an inner node.
    nodes[index].kind = NodeKind::Inner { left, right };
    index as u32
}
// ANCHOR_END: subdivide_split
// ANCHOR_END: subdivide

/// The closest hit along `ray` in (0, t_max) through `bvh`, with the
/// watertight triangle test. `Hit::triangle` indexes `bvh.tris`.
///
/// Front to back: of two children, the one the ray enters first is
/// visited first, and the other waits on a stack with its entry distance.
/// Once a hit at t is found, every box entered beyond t is skipped, both
/// when it is tested and when it comes off the stack.
// ANCHOR: closest_hit
// ANCHOR: closest_hit_stack
pub fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    let Some(root) = bvh.nodes.first() else {
        return None; // no triangles, nothing to hit
    };
    let inv_dir = ray.dir.recip();
    let mut best: Option<Hit> = None;
    let mut t_best = t_max;
    // Subtrees still to visit, with where the ray enters their box.
    let mut stack: Vec<(u32, f32)> = Vec::new();
    if let Some(t_enter) = root.bounds.enter(ray, inv_dir, t_best) {
        stack.push((0, t_enter));
    }
    while let Some((index, t_enter)) = stack.pop() {
        // A hit found since this subtree was stacked may lie in front of it.
        if t_enter > t_best {
            continue;
        }
        // ANCHOR_END: closest_hit_stack
        // ANCHOR: closest_hit_nodes
        match bvh.nodes[index as usize].kind {
            NodeKind::Leaf { first, count } => {
                for &id in &bvh.order[first as usize..(first + count) as usize] {
                    let tri = bvh.tris[id as usize];
                    if let Some(hit) = intersect_watertight(ray, tri, 0.0, t_best) {
                        t_best = hit.t; // nothing beyond this hit matters now
                        best = Some(Hit {
                            triangle: id,
                            ..hit
                        });
                    }
                }
            }
            NodeKind::Inner { left, right } => {
                let enter =
                    |child: u32| bvh.nodes[child as usize].bounds.enter(ray, inv_dir, t_best);
                // Push the farther child first, so the nearer one comes
                // off the stack next.
                match (enter(left), enter(right)) {
                    (Some(tl), Some(tr)) if tl <= tr => stack.extend([(right, tr), (left, tl)]),
                    (Some(tl), Some(tr)) => stack.extend([(left, tl), (right, tr)]),
                    (Some(tl), None) => stack.push((left, tl)),
                    (None, Some(tr)) => stack.push((right, tr)),
                    (None, None) => {}
                }
            }
        }
    }
    best
}
// ANCHOR_END: closest_hit_nodes
// ANCHOR_END: closest_hit
