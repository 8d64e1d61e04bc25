//! Building a BVH that stays O(n log n) on hostile input.
//!
//! obvhs builds with PLOC: sort the boxes along a Morton curve, then merge
//! neighbours that are each other's cheapest partner (the smallest union
//! surface area). When many candidate costs are *equal* the merges stall to
//! about one per sweep and the build turns quadratic. Equal costs come from
//! two kinds of input:
//!
//! * geometry so small (or so large) that box areas underflow (or overflow)
//!   in f32: a sphere of radius 1e-30 has every surface area exactly 0;
//! * many triangles in (almost) the same place: N copies of one face, a
//!   polygon fan whose corners repeat, a shape scaled to nothing inside a
//!   normal scene.
//!
//! The guard answers each: boxes are scaled by a power of two (exact in
//! floating point, so the tree is the one the unscaled boxes would give)
//! into a range where areas neither underflow nor overflow; and large groups
//! of triangles that would tie anyway (bit-identical boxes, or boxes in one
//! tiny cell whose areas underflow) are built as *one* box, then split in
//! halves by index (an object split) into a balanced subtree. Scenes with
//! neither problem get obvhs' tree untouched.

use std::time::Duration;

use glam::Vec3A;
use obvhs::aabb::Aabb;
use obvhs::bvh2::builder::build_bvh2;
use obvhs::bvh2::node::Bvh2Node;
use obvhs::bvh2::Bvh2;
use obvhs::BvhBuildParams;

/// Groups of at least this many triangles whose boxes fall in one cell are
/// built as a single box. Smaller ties cost PLOC little.
pub const CLUSTER_MIN: usize = 32;
/// Cells are 2⁻³² of the scene's extent along each axis.
const CELLS_PER_AXIS: f64 = 4_294_967_296.0;
/// Extents in [2⁻²⁰, 2⁶⁰] need no scaling: their areas are far from f32's
/// limits (2⁻¹⁴⁹ and 2¹²⁸).
const SAFE_EXPONENTS: std::ops::RangeInclusive<i32> = -20..=60;
/// Other scenes are scaled to an extent of 2⁴⁰: areas up to 2⁸⁰, with as
/// much room below for small triangles as the unscaled range leaves.
const TARGET_EXPONENT: i32 = 40;
/// A cell group whose (scaled) area is below this is about to underflow:
/// its members' costs tie.
const TINY_AREA: f32 = 1e-30;

/// A binary BVH over `boxes` (non-empty) with obvhs' PLOC builder and
/// `params`, guarded against the inputs that make PLOC quadratic (see the
/// module documentation). Leaves hold at most `params.max_prims_per_leaf`
/// boxes; `primitive_indices` index `boxes`.
pub fn build_guarded(boxes: &[Aabb], params: BvhBuildParams) -> Bvh2 {
    let mut total = Aabb::empty();
    for b in boxes {
        total = total.union(b);
    }
    let scale = power_of_two_scale(&total);
    let clusters = clusters(boxes, &total, scale);
    if scale == 1.0 && clusters.iter().all(|c| c.len() == 1) {
        return build_bvh2(boxes, params, &mut Duration::default());
    }
    // One build box per cluster (a singleton is its own cluster), scaled.
    let build_boxes: Vec<Aabb> = clusters
        .iter()
        .map(|members| {
            let mut b = Aabb::empty();
            for &m in members {
                b = b.union(&boxes[m as usize]);
            }
            Aabb::new(b.min * scale, b.max * scale)
        })
        .collect();
    let coarse = build_bvh2(&build_boxes, params, &mut Duration::default());
    expand(
        &coarse,
        &clusters,
        boxes,
        params.max_prims_per_leaf.max(1) as usize,
    )
}

/// 1 when the extent is in the safe range, else the power of two that
/// scales it to about 2⁴⁰.
fn power_of_two_scale(total: &Aabb) -> f32 {
    let extent = (total.max - total.min).max_element();
    if !(extent.is_finite() && extent > 0.0) {
        return 1.0;
    }
    let exponent = extent.log2().round() as i32;
    if SAFE_EXPONENTS.contains(&exponent) {
        return 1.0;
    }
    // Keep the largest coordinate finite after scaling.
    let largest = total.min.abs().max(total.max.abs()).max_element();
    let mut k = TARGET_EXPONENT - exponent;
    while k > 0 && !(largest * 2f32.powi(k)).is_finite() {
        k -= 1;
    }
    2f32.powi(k)
}

/// The boxes grouped into clusters: every run of at least [`CLUSTER_MIN`]
/// bit-identical boxes, and every group of at least [`CLUSTER_MIN`] boxes
/// whose corners fall in one cell (2⁻³² of the scene per axis) and whose
/// union's area, scaled, is below [`TINY_AREA`]. Every other box is a
/// cluster of its own. Clusters come in the boxes' order (by first
/// member), so the result is deterministic.
fn clusters(boxes: &[Aabb], total: &Aabb, scale: f32) -> Vec<Vec<u32>> {
    let mut in_cluster = vec![u32::MAX; boxes.len()];
    let mut big: Vec<Vec<u32>> = Vec::new();
    let mut take = |run: &[u32], in_cluster: &mut Vec<u32>| {
        for &i in run {
            in_cluster[i as usize] = big.len() as u32;
        }
        let mut members = run.to_vec();
        members.sort_unstable();
        big.push(members);
    };
    // Exact duplicates.
    let bits = |b: &Aabb| {
        let (lo, hi) = (b.min.to_array(), b.max.to_array());
        [lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]].map(f32::to_bits)
    };
    let mut order: Vec<u32> = (0..boxes.len() as u32).collect();
    order.sort_by_key(|&i| (bits(&boxes[i as usize]), i));
    for run in order.chunk_by(|a, b| bits(&boxes[*a as usize]) == bits(&boxes[*b as usize])) {
        if run.len() >= CLUSTER_MIN {
            take(run, &mut in_cluster);
        }
    }
    // Tiny cells.
    let lo = total.min.as_dvec3();
    let size = (total.max.as_dvec3() - lo).max(glam::DVec3::splat(f64::MIN_POSITIVE));
    let cell = |p: Vec3A| -> [u64; 3] {
        let q = (p.as_dvec3() - lo) / size * CELLS_PER_AXIS;
        q.to_array().map(|c| c.clamp(0.0, CELLS_PER_AXIS) as u64)
    };
    let key = |i: u32| {
        let b = &boxes[i as usize];
        (cell(b.min), cell(b.max))
    };
    let mut rest: Vec<u32> = order
        .into_iter()
        .filter(|&i| in_cluster[i as usize] == u32::MAX)
        .collect();
    rest.sort_by_key(|&i| (key(i), i));
    for run in rest.chunk_by(|a, b| key(*a) == key(*b)) {
        if run.len() < CLUSTER_MIN {
            continue;
        }
        let mut union = Aabb::empty();
        for &i in run {
            union = union.union(&boxes[i as usize]);
        }
        let area = Aabb::new(union.min * scale, union.max * scale).half_area();
        if area < TINY_AREA {
            take(run, &mut in_cluster);
        }
    }
    let mut out = Vec::new();
    let mut emitted = vec![false; big.len()];
    for (i, &c) in in_cluster.iter().enumerate() {
        if c == u32::MAX {
            out.push(vec![i as u32]);
        } else if !emitted[c as usize] {
            emitted[c as usize] = true;
            out.push(std::mem::take(&mut big[c as usize]));
        }
    }
    out
}

/// What still has to be written into a node of the new tree.
enum Job {
    /// A node of the coarse tree.
    Coarse(usize),
    /// A list of original boxes, split in halves until each leaf is small.
    List(Vec<u32>),
}

/// The coarse tree (over clusters) rewritten over the original boxes:
/// every leaf with more than `max_leaf` boxes becomes a balanced subtree
/// (halves by index), and every node box is recomputed from the original,
/// unscaled boxes.
fn expand(coarse: &Bvh2, clusters: &[Vec<u32>], boxes: &[Aabb], max_leaf: usize) -> Bvh2 {
    let mut nodes = vec![Bvh2Node::default()];
    let mut prims: Vec<u32> = Vec::with_capacity(boxes.len());
    let mut depth_max = 0;
    let mut jobs = vec![(Job::Coarse(0), 0usize, 0usize)];
    while let Some((job, at, depth)) = jobs.pop() {
        depth_max = depth_max.max(depth);
        let list = match job {
            Job::Coarse(n) => {
                let node = &coarse.nodes[n];
                if node.is_leaf() {
                    let range = node.first_index..node.first_index + node.prim_count;
                    range
                        .flat_map(|k| {
                            clusters[coarse.primitive_indices[k as usize] as usize].iter()
                        })
                        .copied()
                        .collect()
                } else {
                    let c = nodes.len();
                    nodes.extend([Bvh2Node::default(); 2]);
                    nodes[at].first_index = c as u32;
                    nodes[at].prim_count = 0;
                    let first = node.first_index as usize;
                    jobs.push((Job::Coarse(first + 1), c + 1, depth + 1));
                    jobs.push((Job::Coarse(first), c, depth + 1));
                    continue;
                }
            }
            Job::List(list) => list,
        };
        if list.len() <= max_leaf {
            nodes[at].first_index = prims.len() as u32;
            nodes[at].prim_count = list.len() as u32;
            prims.extend(list);
        } else {
            let c = nodes.len();
            nodes.extend([Bvh2Node::default(); 2]);
            nodes[at].first_index = c as u32;
            nodes[at].prim_count = 0;
            let (left, right) = list.split_at(list.len() / 2);
            jobs.push((Job::List(right.to_vec()), c + 1, depth + 1));
            jobs.push((Job::List(left.to_vec()), c, depth + 1));
        }
    }
    // Children always come after their parent: fit boxes bottom-up.
    for n in (0..nodes.len()).rev() {
        let node = nodes[n];
        let mut b = Aabb::empty();
        if node.prim_count > 0 {
            for k in node.first_index..node.first_index + node.prim_count {
                b = b.union(&boxes[prims[k as usize] as usize]);
            }
        } else {
            let c = node.first_index as usize;
            b = nodes[c].aabb.union(&nodes[c + 1].aabb);
        }
        nodes[n].aabb = b;
    }
    Bvh2 {
        nodes,
        primitive_indices: prims,
        children_are_ordered_after_parents: true,
        max_depth: (depth_max + 2).max(obvhs::bvh2::DEFAULT_MAX_STACK_DEPTH),
        ..Bvh2::default()
    }
}
