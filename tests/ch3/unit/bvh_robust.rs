//! The binary tree builder (`bvh_robust::build_tree`): every box in one
//! leaf, node boxes that hold their children, a depth within the bound
//! that makes the build O(n log n), and the same tree at any scale.

use glam::Vec3A;
use obvhs::aabb::Aabb;
use obvhs::bvh2::Bvh2;
use obvhs::BvhBuildParams;
use raystep::ch3_ray_triangle::bvh_robust::{build_tree, SAH_DEPTH};

fn boxes_of(points: &[[f32; 3]], size: f32) -> Vec<Aabb> {
    points
        .iter()
        .map(|p| {
            let p = Vec3A::from_array(*p);
            Aabb::new(p - size, p + size)
        })
        .collect()
}

/// Every box reaches exactly one leaf, every node's box holds its
/// children's, and the depth is within the documented bound.
fn check(boxes: &[Aabb], max_leaf: usize) -> Bvh2 {
    let params = BvhBuildParams {
        max_prims_per_leaf: max_leaf as u32,
        ..BvhBuildParams::medium_build()
    };
    let t = build_tree(boxes, &params);
    let mut seen = vec![0; boxes.len()];
    let mut stack = vec![(0usize, 0usize)];
    let mut deepest = 0;
    while let Some((n, d)) = stack.pop() {
        deepest = deepest.max(d);
        let node = t.nodes[n];
        if node.prim_count > 0 {
            assert!(node.prim_count as usize <= max_leaf.max(1));
            for k in node.first_index..node.first_index + node.prim_count {
                let i = t.primitive_indices[k as usize] as usize;
                seen[i] += 1;
                let b = boxes[i];
                assert!(node.aabb.min.cmple(b.min).all() && node.aabb.max.cmpge(b.max).all());
            }
        } else {
            let c = node.first_index as usize;
            for child in [c, c + 1] {
                let b = t.nodes[child].aabb;
                assert!(node.aabb.min.cmple(b.min).all() && node.aabb.max.cmpge(b.max).all());
                stack.push((child, d + 1));
            }
        }
    }
    assert!(seen.iter().all(|&s| s == 1), "every box in one leaf");
    let bound = SAH_DEPTH + (boxes.len() as f64).log2().ceil() as usize + 1;
    assert!(deepest <= bound, "depth {deepest} > {bound}");
    t
}

#[test]
fn one_box_is_a_leaf() {
    let t = check(&boxes_of(&[[1.0, 2.0, 3.0]], 0.5), 1);
    assert_eq!(t.nodes.len(), 1);
}

#[test]
fn copies_of_one_box_split_in_halves() {
    let t = check(&boxes_of(&[[0.0; 3]; 1000], 1.0), 1);
    assert_eq!(t.nodes.len(), 1999);
    assert!(t.max_depth <= obvhs::bvh2::DEFAULT_MAX_STACK_DEPTH.max(12));
}

/// Centroids at 2^-k along x: every SAH split peels off one box, so
/// the tree would be n deep without the median below `SAH_DEPTH`.
#[test]
fn a_geometric_row_stays_shallow() {
    let points: Vec<[f32; 3]> = (0..2000).map(|k| [0.5f32.powi(k / 20), 0.0, 0.0]).collect();
    check(&boxes_of(&points, 1e-9), 1);
}

#[test]
fn scale_and_place_give_the_same_tree() {
    let points: Vec<[f32; 3]> = (0..500)
        .map(|k| {
            let a = k as f32 * 0.37;
            [a.sin(), a.cos() * 0.5, (k % 7) as f32 * 0.1]
        })
        .collect();
    let shape = |t: &Bvh2| -> Vec<(u32, u32)> {
        t.nodes
            .iter()
            .map(|n| (n.prim_count, n.first_index))
            .collect()
    };
    let unit = check(&boxes_of(&points, 0.01), 2);
    // Powers of two: exact in floating point.
    for s in [2f32.powi(-100), 2f32.powi(60)] {
        let scaled: Vec<[f32; 3]> = points.iter().map(|p| p.map(|c| c * s)).collect();
        let t = check(&boxes_of(&scaled, 0.01 * s), 2);
        assert_eq!(shape(&t), shape(&unit), "scaled by {s:e}");
        assert_eq!(t.primitive_indices, unit.primitive_indices);
    }
}
