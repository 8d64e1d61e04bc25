//! The binary tree every triangle BVH of chapters 3 to 6 starts from:
//! built top-down with binned surface area heuristic (SAH) splits, in
//! O(n log n) time on any input.
//!
//! obvhs' own builder (PLOC) merges neighbours bottom-up and turns
//! quadratic whenever many merge costs tie: coincident, collapsed, fanned or
//! overlapping triangles. A top-down build has no such failure: each level
//! of the tree looks at every triangle a constant number of times, so only
//! the number of levels needs a bound, and it gets three:
//!
//! * split planes are chosen among [`BINS`] bins spanning the centroids'
//!   range, the bin of a centroid computed in f64 *relative* to that range,
//!   so a scene 1e-38 wide, one at +1e12 and one 1 wide split alike (nodes
//!   of at most [`EXACT`] boxes try every cut between sorted centroids);
//! * when every centroid of a node is the same point (copies of one
//!   triangle), the node is split in halves by index;
//! * below depth [`SAH_DEPTH`] (reached only by a chain of lopsided SAH
//!   splits) every split is at the median centroid.
//!
//! So no top-down tree is deeper than [`SAH_DEPTH`] + log₂ n + 1, and it
//! is built in O(n log n) whatever the triangles are. obvhs' reinsertion
//! then moves subtrees where they cost less (on the bunny its closest-hit
//! traversal runs about 9% fewer instructions than over obvhs' own tree),
//! but only on trees whose SAH cost is at most [`REINSERT_COST`] × log₂ n:
//! on wholesale-overlapping boxes its search degenerates towards n² (a
//! million overlapping triangles took 84 s instead of 6).

use glam::Vec3A;
use obvhs::aabb::Aabb;
use obvhs::bvh2::node::Bvh2Node;
use obvhs::bvh2::Bvh2;
use obvhs::BvhBuildParams;

/// Bins per axis for the SAH split.
pub const BINS: usize = 32;
/// Nodes of at most this many boxes try every split between their sorted
/// centroids on each axis (exact SAH) instead of bins.
pub const EXACT: usize = 16;
/// Below this depth every split is a median split.
pub const SAH_DEPTH: usize = 40;
/// A binary BVH over `boxes` (non-empty): built top-down one box per leaf,
/// improved by obvhs' reinsertion where that stays cheap, and collapsed by
/// obvhs into leaves of at most `params.max_prims_per_leaf` boxes where
/// SAH (a node visit costing `params.collapse_traversal_cost` box tests)
/// says so. `primitive_indices` index `boxes`.
pub fn build_tree(boxes: &[Aabb], params: &BvhBuildParams) -> Bvh2 {
    let mut bvh = top_down(boxes);
    // obvhs' reinsertion moves subtrees to where they cost less (a few
    // percent fewer box tests on ordinary meshes than the greedy top-down
    // tree), but its search prunes by area: where boxes overlap wholesale
    // it degenerates towards n². Such trees give themselves away by their
    // SAH cost, which grows like n instead of log n; they keep the
    // top-down tree.
    let n = boxes.len() as f64;
    let optimize = sah_cost(&bvh) <= REINSERT_COST * n.log2().max(1.0);
    let mut optimizer = obvhs::bvh2::reinsertion::ReinsertionOptimizer::default();
    if optimize {
        optimizer.run(&mut bvh, params.reinsertion_batch_ratio, None);
    }
    obvhs::bvh2::leaf_collapser::collapse(
        &mut bvh,
        params.max_prims_per_leaf.clamp(1, 255),
        params.collapse_traversal_cost,
    );
    if optimize {
        let ratio = params.reinsertion_batch_ratio
            * params.post_collapse_reinsertion_batch_ratio_multiplier;
        optimizer.run(&mut bvh, ratio, None);
    }
    // Reinsertion may deepen the tree: size the traversal stack anew.
    bvh.max_depth = (depth(&bvh) + 2).max(obvhs::bvh2::DEFAULT_MAX_STACK_DEPTH);
    bvh
}

/// Levels below the root of a binary tree (0 for a root that is a leaf).
pub fn depth(t: &Bvh2) -> usize {
    let mut deepest = 0;
    let mut stack = vec![(0usize, 0usize)];
    while let Some((n, d)) = stack.pop() {
        deepest = deepest.max(d);
        let node = &t.nodes[n];
        if node.prim_count == 0 {
            let c = node.first_index as usize;
            stack.extend([(c, d + 1), (c + 1, d + 1)]);
        }
    }
    deepest
}

/// Trees whose SAH cost (in box tests per ray, [`sah_cost`]) is at most
/// this many times log₂ n are optimized by reinsertion.
pub const REINSERT_COST: f64 = 4.0;

/// The expected box and primitive tests of a ray that hits the root: each
/// node's area over the root's, times its primitives for a leaf.
pub fn sah_cost(t: &Bvh2) -> f64 {
    let root = half_area(&t.nodes[0].aabb);
    if root.is_nan() || root <= 0.0 {
        return 0.0;
    }
    t.nodes
        .iter()
        .map(|n| half_area(&n.aabb) / root * n.prim_count.max(1) as f64)
        .sum()
}

/// The top-down tree, one box per leaf.
fn top_down(boxes: &[Aabb]) -> Bvh2 {
    // Half of each corner, added: no overflow near f32::MAX.
    let centres: Vec<Vec3A> = boxes.iter().map(|b| b.min * 0.5 + b.max * 0.5).collect();
    let mut order: Vec<u32> = (0..boxes.len() as u32).collect();
    let mut nodes = vec![Bvh2Node::default()];
    // (node, first item, end of items, depth)
    let mut jobs = vec![(0usize, 0usize, boxes.len(), 0usize)];
    while let Some((at, lo, hi, depth)) = jobs.pop() {
        let items = &mut order[lo..hi];
        let mut bounds = Aabb::empty();
        let mut spread = Aabb::empty();
        for &i in items.iter() {
            bounds = bounds.union(&boxes[i as usize]);
            spread.extend(centres[i as usize]);
        }
        nodes[at].aabb = bounds;
        let node = Node {
            boxes,
            centres: &centres,
            spread: &spread,
        };
        match node.split(items, depth) {
            None => {
                nodes[at].first_index = lo as u32;
                nodes[at].prim_count = items.len() as u32;
            }
            Some(left) => {
                let c = nodes.len();
                nodes.extend([Bvh2Node::default(); 2]);
                nodes[at].first_index = c as u32;
                nodes[at].prim_count = 0;
                jobs.push((c + 1, lo + left, hi, depth + 1));
                jobs.push((c, lo, lo + left, depth + 1));
            }
        }
    }
    Bvh2 {
        nodes,
        primitive_indices: order,
        children_are_ordered_after_parents: true,
        // `build_tree` sizes the traversal stack once the tree is final.
        ..Bvh2::default()
    }
}

/// One node being split: the boxes, their centres, and the bounds of the
/// node's centres.
struct Node<'a> {
    boxes: &'a [Aabb],
    centres: &'a [Vec3A],
    spread: &'a Aabb,
}

/// The cheapest cut of a row of groups (their box and how many boxes they
/// hold) by SAH: its cost and how many groups lie left of it; cuts with
/// nothing on one side are skipped.
fn cheapest_cut(groups: &[(Aabb, usize)]) -> Option<(f64, usize)> {
    let m = groups.len();
    // Right-hand sums, from the last group down.
    let mut right = vec![(0.0, 0usize); m];
    let (mut b, mut count) = (Aabb::empty(), 0);
    for k in (1..m).rev() {
        b = b.union(&groups[k].0);
        count += groups[k].1;
        right[k] = (half_area(&b), count);
    }
    let mut best: Option<(f64, usize)> = None;
    let (mut b, mut count) = (Aabb::empty(), 0);
    for k in 1..m {
        b = b.union(&groups[k - 1].0);
        count += groups[k - 1].1;
        let (area_r, count_r) = right[k];
        if count == 0 || count_r == 0 {
            continue;
        }
        let cost = half_area(&b) * count as f64 + area_r * count_r as f64;
        if best.is_none_or(|(c, _)| cost < c) {
            best = Some((cost, k));
        }
    }
    best
}

/// A box's half surface area, in f64 (no underflow at 1e-30, no overflow
/// at 1e30).
fn half_area(b: &Aabb) -> f64 {
    let d = (b.max - b.min).as_dvec3().max(glam::DVec3::ZERO);
    d.x * d.y + d.y * d.z + d.z * d.x
}

impl Node<'_> {
    /// Orders boxes by their centre on `axis`, index breaking ties.
    fn by_centre(&self, axis: usize) -> impl Fn(&u32, &u32) -> std::cmp::Ordering + '_ {
        move |x, y| {
            let key = |i: &u32| self.centres[*i as usize][axis];
            key(x).total_cmp(&key(y)).then(x.cmp(y))
        }
    }

    /// The exact SAH split of a small node: on each axis with extent, the
    /// boxes sorted by centroid, and the cheapest cut between two of them.
    fn exact_split(&self, items: &mut [u32], extent: &glam::DVec3) -> Option<usize> {
        let mut best: Option<(f64, usize, usize)> = None;
        for a in (0..3).filter(|&a| extent[a] > 0.0) {
            items.sort_unstable_by(self.by_centre(a));
            let groups: Vec<(Aabb, usize)> =
                items.iter().map(|&i| (self.boxes[i as usize], 1)).collect();
            if let Some((cost, k)) = cheapest_cut(&groups) {
                if best.is_none_or(|(c, _, _)| cost < c) {
                    best = Some((cost, a, k));
                }
            }
        }
        let (_, a, k) = best?;
        items.sort_unstable_by(self.by_centre(a));
        Some(k)
    }

    /// Reorders `items` into a left and a right child and returns how many
    /// go left, or `None` for a leaf (one box).
    fn split(&self, items: &mut [u32], depth: usize) -> Option<usize> {
        let n = items.len();
        let lo = self.spread.min.as_dvec3();
        let extent = self.spread.max.as_dvec3() - lo;
        let axis = (0..3)
            .max_by(|&a, &b| extent[a].total_cmp(&extent[b]))
            .unwrap_or(0);
        if extent[axis].is_nan() || extent[axis] <= 0.0 {
            // All centroids at one point: halves by index.
            return (n > 1).then_some(n / 2);
        }
        if depth >= SAH_DEPTH {
            items.select_nth_unstable_by(n / 2, self.by_centre(axis));
            return Some(n / 2);
        }
        if n <= EXACT {
            return self.exact_split(items, &extent);
        }
        let bin = |i: u32, axis: usize| -> usize {
            let c = self.centres[i as usize][axis] as f64;
            let k = (c - lo[axis]) / extent[axis] * BINS as f64;
            (k as usize).min(BINS - 1)
        };
        // The cheapest plane over all axes: (cost, axis, bins left of it).
        let mut best: Option<(f64, usize, usize)> = None;
        for a in (0..3).filter(|&a| extent[a] > 0.0) {
            let mut bins = [(Aabb::empty(), 0usize); BINS];
            for &i in items.iter() {
                let k = bin(i, a);
                bins[k].0 = bins[k].0.union(&self.boxes[i as usize]);
                bins[k].1 += 1;
            }
            if let Some((cost, k)) = cheapest_cut(&bins) {
                if best.is_none_or(|(c, _, _)| cost < c) {
                    best = Some((cost, a, k));
                }
            }
        }
        // The lowest and highest centroid on `axis` fall in its first and
        // last bins, so there is always a plane.
        let (_, a, k) = best?;
        // Partition in place: bins below k to the front.
        let mut left = 0;
        for j in 0..n {
            if bin(items[j], a) < k {
                items.swap(left, j);
                left += 1;
            }
        }
        Some(left)
    }
}
