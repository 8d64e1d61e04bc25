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
//!   so a scene 1e-38 wide, one at +1e12 and one 1 wide split alike;
//! * when every centroid of a node is the same point (copies of one
//!   triangle), the node is split in halves by index;
//! * below depth [`SAH_DEPTH`] (reached only by a chain of lopsided SAH
//!   splits) every split is at the median centroid.
//!
//! So no tree is deeper than [`SAH_DEPTH`] + log₂ n + 1, and the build takes
//! O(n log n) whatever the triangles are.

use glam::Vec3A;
use obvhs::aabb::Aabb;
use obvhs::bvh2::node::Bvh2Node;
use obvhs::bvh2::Bvh2;
use obvhs::BvhBuildParams;

/// Bins per axis for the SAH split.
pub const BINS: usize = 16;
/// Below this depth every split is a median split.
pub const SAH_DEPTH: usize = 40;
/// A binary BVH over `boxes` (non-empty): leaves hold at most
/// `params.max_prims_per_leaf` boxes (at least one; a node that small
/// becomes a leaf unless a split is cheaper by SAH, a node visit costing
/// `params.collapse_traversal_cost` box tests), and `primitive_indices`
/// index `boxes`. Children always come after their parent.
pub fn build_tree(boxes: &[Aabb], params: &BvhBuildParams) -> Bvh2 {
    let max_leaf = (params.max_prims_per_leaf as usize).clamp(1, 255);
    let traversal = params.collapse_traversal_cost as f64;
    // Half of each corner, added: no overflow near f32::MAX.
    let centres: Vec<Vec3A> = boxes.iter().map(|b| b.min * 0.5 + b.max * 0.5).collect();
    let mut order: Vec<u32> = (0..boxes.len() as u32).collect();
    let mut nodes = vec![Bvh2Node::default()];
    let mut deepest = 0;
    // (node, first item, end of items, depth)
    let mut jobs = vec![(0usize, 0usize, boxes.len(), 0usize)];
    while let Some((at, lo, hi, depth)) = jobs.pop() {
        deepest = deepest.max(depth);
        let items = &mut order[lo..hi];
        let mut bounds = Aabb::empty();
        let mut spread = Aabb::empty();
        for &i in items.iter() {
            bounds = bounds.union(&boxes[i as usize]);
            spread.extend(centres[i as usize]);
        }
        nodes[at].aabb = bounds;
        let node = Node {
            traversal,
            boxes,
            centres: &centres,
            bounds: &bounds,
            spread: &spread,
        };
        match node.split(items, depth, max_leaf) {
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
        max_depth: (deepest + 2).max(obvhs::bvh2::DEFAULT_MAX_STACK_DEPTH),
        ..Bvh2::default()
    }
}

/// One node being split: its boxes' bounds and its centroids' bounds.
struct Node<'a> {
    traversal: f64,
    boxes: &'a [Aabb],
    centres: &'a [Vec3A],
    bounds: &'a Aabb,
    spread: &'a Aabb,
}

/// A box's half surface area, in f64 (no underflow at 1e-30, no overflow
/// at 1e30).
fn half_area(b: &Aabb) -> f64 {
    let d = (b.max - b.min).as_dvec3().max(glam::DVec3::ZERO);
    d.x * d.y + d.y * d.z + d.z * d.x
}

impl Node<'_> {
    /// Reorders `items` into a left and a right child and returns how many
    /// go left, or `None` to make a leaf.
    fn split(&self, items: &mut [u32], depth: usize, max_leaf: usize) -> Option<usize> {
        let n = items.len();
        let lo = self.spread.min.as_dvec3();
        let extent = self.spread.max.as_dvec3() - lo;
        let axis = (0..3)
            .max_by(|&a, &b| extent[a].total_cmp(&extent[b]))
            .unwrap_or(0);
        if extent[axis].is_nan() || extent[axis] <= 0.0 {
            // All centroids at one point: halves by index.
            return (n > max_leaf).then_some(n / 2);
        }
        if depth >= SAH_DEPTH {
            let key = |i: &u32| self.centres[*i as usize][axis];
            items.select_nth_unstable_by(n / 2, |a, b| key(a).total_cmp(&key(b)).then(a.cmp(b)));
            return Some(n / 2);
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
            // Right-hand sums, from the last bin down.
            let mut right = [(0.0, 0usize); BINS];
            let (mut b, mut count) = (Aabb::empty(), 0);
            for k in (1..BINS).rev() {
                b = b.union(&bins[k].0);
                count += bins[k].1;
                right[k] = (half_area(&b), count);
            }
            let (mut b, mut count) = (Aabb::empty(), 0);
            for k in 1..BINS {
                b = b.union(&bins[k - 1].0);
                count += bins[k - 1].1;
                let (area_r, count_r) = right[k];
                if count == 0 || count_r == 0 {
                    continue;
                }
                let cost = half_area(&b) * count as f64 + area_r * count_r as f64;
                if best.is_none_or(|(c, _, _)| cost < c) {
                    best = Some((cost, a, k));
                }
            }
        }
        // The lowest and highest centroid on `axis` fall in its first and
        // last bins, so there is always a plane.
        let (cost, a, k) = best?;
        let area = half_area(self.bounds);
        if n <= max_leaf && n as f64 * area <= self.traversal * area + cost {
            return None;
        }
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
