//! The readable BVH built by the surface area heuristic instead of the
//! median: one node's split chosen by a full sweep over its sorted
//! centroids, the tree built top-down with any such choice, and the
//! tree's expected cost.
//!
//! The cost model: a ray that reaches a node with box B enters a child box
//! C with probability A(C)/A(B) (surface areas). Stepping into a node's
//! children costs [`TRAVERSAL_COST`], testing a triangle
//! [`TRIANGLE_COST`]. A leaf of N triangles costs N·C_tri; a split into
//! L and R costs C_trav + (A(L)·N_L + A(R)·N_R)/A(B)·C_tri, and the node
//! splits only where that is cheaper than the leaf.
//!
//! The renderer does not use this tree (it uses [`super::bvh_robust`]'s
//! binned build and obvhs' traversal); it is here to be read, and as the
//! reference of exercise 3.5. Building it changes no rendered image.

use glam::{DVec3, Vec3};

use super::readable_bvh::{Aabb, Node, NodeKind, ReadableBvh};

/// What stepping into a node's two children costs, in triangle tests.
pub const TRAVERSAL_COST: f64 = 1.0;
/// What testing one triangle costs.
pub const TRIANGLE_COST: f64 = 1.0;

/// A node's split: the triangles whose centroid on `axis` (0, 1, 2 for
/// x, y, z) is below the position go left, the others right; `None`
/// makes the node a leaf.
pub type Split = Option<(usize, f32)>;

/// Something that chooses a node's split from its triangles' boxes and
/// centroids (the reference, or a student's).
pub type SplitFn<'a> = dyn FnMut(&[[Vec3; 2]], &[Vec3]) -> Split + 'a;

/// Half a box's surface area, in f64 (xy + yz + zx; the half does not
/// change any ratio of areas).
pub fn half_area(min: Vec3, max: Vec3) -> f64 {
    let d = (max.as_dvec3() - min.as_dvec3()).max(DVec3::ZERO);
    d.x * d.y + d.y * d.z + d.z * d.x
}

/// The cheapest split of a node by SAH: the node's triangles by their
/// boxes (`[min, max]`) and centroids. Every plane between two different
/// neighbouring centroids on each axis is tried; `None` when no plane is
/// cheaper than a leaf (or none separates any centroids).
// ANCHOR: sah_split_sort
pub fn sah_split(boxes: &[[Vec3; 2]], centroids: &[Vec3]) -> Split {
    let n = boxes.len();
    let node = boxes.iter().fold(Aabb::EMPTY, |b, &[lo, hi]| {
        b.union(Aabb { min: lo, max: hi })
    });
    let area = half_area(node.min, node.max);
    let mut best: Option<(f64, usize, f32)> = None;
    for axis in [0, 1, 2] {
        let mut ids: Vec<usize> = (0..n).collect();
        ids.sort_by(|&a, &b| centroids[a][axis].total_cmp(&centroids[b][axis]));
        // right[k]: the area of the box around ids[k..].
        let mut right = vec![0.0; n];
        let mut b = Aabb::EMPTY;
        for k in (1..n).rev() {
            b = b.union(box_of(boxes[ids[k]]));
            right[k] = half_area(b.min, b.max);
        }
        // ANCHOR_END: sah_split_sort
        // ANCHOR: sah_split_planes
        let mut left = Aabb::EMPTY;
        for k in 1..n {
            left = left.union(box_of(boxes[ids[k - 1]]));
            let next = centroids[ids[k]][axis];
            // No plane passes between two equal centroids.
            if centroids[ids[k - 1]][axis] == next {
                continue;
            }
            let (n_left, n_right) = (k as f64, (n - k) as f64);
            let cost = TRAVERSAL_COST
                + (half_area(left.min, left.max) * n_left + right[k] * n_right) / area
                    * TRIANGLE_COST;
            if best.is_none_or(|(c, _, _)| cost < c) {
                // `next` itself is the plane: it is right of `k - 1`.
                best = Some((cost, axis, next));
            }
        }
    }
    let leaf = n as f64 * TRIANGLE_COST;
    best.filter(|&(cost, _, _)| cost < leaf)
        .map(|(_, axis, at)| (axis, at))
}
// ANCHOR_END: sah_split_planes

fn box_of([min, max]: [Vec3; 2]) -> Aabb {
    Aabb { min, max }
}

/// The tree over `tris` built with the split [`sah_split`] chooses.
pub fn build(tris: &[[Vec3; 3]]) -> ReadableBvh {
    // The reference split always leaves both children non-empty.
    build_with(tris, &mut |b, c| sah_split(b, c)).unwrap_or_default()
}

/// The tree over `tris` built top-down with `split` choosing each split
/// of a node of two or more triangles (a node of one is a leaf); an error
/// when a split names no axis, is not a number, or leaves a side empty.
pub fn build_with(tris: &[[Vec3; 3]], split: &mut SplitFn) -> Result<ReadableBvh, String> {
    let boxes: Vec<Aabb> = tris.iter().map(Aabb::around).collect();
    let centroids: Vec<Vec3> = tris.iter().map(|[a, b, c]| (*a + *b + *c) / 3.0).collect();
    let mut order: Vec<u32> = (0..tris.len() as u32).collect();
    let leaf = |first: usize, count: usize| NodeKind::Leaf {
        first: first as u32,
        count: count as u32,
    };
    let root = Node {
        bounds: Aabb::EMPTY,
        kind: leaf(0, 0),
    };
    let mut nodes = vec![root; usize::from(!tris.is_empty())];
    // (node, its first triangle in `order`, one past its last)
    let mut jobs = vec![(0usize, 0usize, tris.len()); nodes.len()];
    while let Some((at, lo, hi)) = jobs.pop() {
        let ids = &mut order[lo..hi];
        nodes[at].bounds = ids
            .iter()
            .fold(Aabb::EMPTY, |b, &i| b.union(boxes[i as usize]));
        nodes[at].kind = leaf(lo, ids.len());
        if ids.len() < 2 {
            continue;
        }
        let node_boxes: Vec<[Vec3; 2]> = ids
            .iter()
            .map(|&i| [boxes[i as usize].min, boxes[i as usize].max])
            .collect();
        let node_centroids: Vec<Vec3> = ids.iter().map(|&i| centroids[i as usize]).collect();
        let Some((axis, at_plane)) = split(&node_boxes, &node_centroids) else {
            continue;
        };
        if axis > 2 || at_plane.is_nan() {
            return Err(format!(
                "the split ({axis}, {at_plane}) names no axis and plane"
            ));
        }
        let is_left = |i: &u32| centroids[*i as usize][axis] < at_plane;
        let mut sorted: Vec<u32> = ids.iter().copied().filter(is_left).collect();
        let n_left = sorted.len();
        sorted.extend(ids.iter().copied().filter(|i| !is_left(i)));
        if n_left == 0 || n_left == ids.len() {
            return Err(format!(
                "the split at {at_plane} on axis {axis} leaves a child of {} triangles empty",
                ids.len()
            ));
        }
        ids.copy_from_slice(&sorted);
        let c = nodes.len();
        nodes.extend([nodes[at]; 2]);
        nodes[at].kind = NodeKind::Inner {
            left: c as u32,
            right: c as u32 + 1,
        };
        jobs.push((c + 1, lo + n_left, hi));
        jobs.push((c, lo, lo + n_left));
    }
    Ok(ReadableBvh {
        nodes,
        order,
        tris: tris.to_vec(),
    })
}

/// The tree's expected cost for a ray that enters its root, by the cost
/// model above: every inner node C_trav, every leaf its triangles'
/// C_tri, each weighted by its area over the root's (0 for an empty tree).
pub fn tree_cost(bvh: &ReadableBvh) -> f64 {
    let Some(root) = bvh.nodes.first() else {
        return 0.0;
    };
    let whole = half_area(root.bounds.min, root.bounds.max);
    bvh.nodes
        .iter()
        .map(|n| {
            let own = match n.kind {
                NodeKind::Inner { .. } => TRAVERSAL_COST,
                NodeKind::Leaf { count, .. } => count as f64 * TRIANGLE_COST,
            };
            own * half_area(n.bounds.min, n.bounds.max) / whole
        })
        .sum()
}
