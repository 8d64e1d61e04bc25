//! Collapsing chapter 3's binary tree into a wide one, the steps the
//! four-wide tree ([`super::wide_bvh`]) and chapter 6's eight-wide one
//! share: which binary nodes become a wide node's children, and which
//! triangles a leaf holds.

use obvhs::bvh2::Bvh2;

// ANCHOR: open_children
/// The children of a wide node made from binary node `n`: its two binary
/// children, then, while there are fewer than `width`, the one of largest
/// surface area that holds more than `leaf_size` triangles replaced by its
/// own two children.
pub(crate) fn open_children(
    bvh2: &Bvh2,
    counts: &[u32],
    n: usize,
    width: usize,
    leaf_size: usize,
) -> Vec<usize> {
    let first = bvh2.nodes[n].first_index as usize;
    let mut children = vec![first, first + 1];
    while children.len() < width {
        let open = children
            .iter()
            .enumerate()
            .filter(|(_, &c)| counts[c] as usize > leaf_size)
            .max_by(|a, b| {
                let area = |c: usize| bvh2.nodes[c].aabb.half_area();
                area(*a.1).total_cmp(&area(*b.1))
            });
        let Some((i, &c)) = open else { break };
        let first = bvh2.nodes[c].first_index as usize;
        children[i] = first;
        children.push(first + 1);
    }
    children
}
// ANCHOR_END: open_children

/// The triangles (build-list indices) under binary node `n`, left to right.
pub(crate) fn triangles_under(bvh2: &Bvh2, n: usize) -> Vec<u32> {
    let mut ids = Vec::new();
    let mut stack = vec![n];
    while let Some(m) = stack.pop() {
        let node = &bvh2.nodes[m];
        if node.is_leaf() {
            let range = node.first_index..node.first_index + node.prim_count;
            ids.extend(range.map(|k| bvh2.primitive_indices[k as usize]));
        } else {
            stack.extend([node.first_index as usize + 1, node.first_index as usize]);
        }
    }
    ids
}

/// Fills `counts[n]` with the number of triangles under binary node `n`.
pub(crate) fn count_triangles(bvh2: &Bvh2, n: usize, counts: &mut [u32]) -> u32 {
    let node = &bvh2.nodes[n];
    counts[n] = if node.is_leaf() {
        node.prim_count
    } else {
        let first = node.first_index as usize;
        count_triangles(bvh2, first, counts) + count_triangles(bvh2, first + 1, counts)
    };
    counts[n]
}
