//! Exercise 3.5, solved: a full sweep over the centroids sorted on each
//! axis, the boxes' areas summed from both ends, and the leaf's cost as
//! the price to beat.

use glam::Vec3;

fn area(lo: Vec3, hi: Vec3) -> f64 {
    let d = (hi - lo).max(Vec3::ZERO).as_dvec3();
    2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
}

/// The split of a node with the triangles' `boxes` and `centroids`, or
/// `None` for a leaf.
pub fn sah_split(boxes: &[[Vec3; 2]], centroids: &[Vec3]) -> Option<(usize, f32)> {
    let n = boxes.len();
    let (mut lo, mut hi) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
    for [a, b] in boxes {
        lo = lo.min(*a);
        hi = hi.max(*b);
    }
    let whole = area(lo, hi);
    let mut best = n as f64; // the leaf's cost: a split must beat it
    let mut split = None;
    for axis in 0..3 {
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| centroids[a][axis].total_cmp(&centroids[b][axis]));
        // Areas of the boxes around order[k..], from the right.
        let mut right = vec![0.0; n + 1];
        let (mut rl, mut rh) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        for k in (0..n).rev() {
            rl = rl.min(boxes[order[k]][0]);
            rh = rh.max(boxes[order[k]][1]);
            right[k] = area(rl, rh);
        }
        let (mut ll, mut lh) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        for k in 1..n {
            ll = ll.min(boxes[order[k - 1]][0]);
            lh = lh.max(boxes[order[k - 1]][1]);
            let (a, b) = (centroids[order[k - 1]][axis], centroids[order[k]][axis]);
            if a == b {
                continue; // no plane between equal centroids
            }
            let cost = 1.0 + (area(ll, lh) * k as f64 + right[k] * (n - k) as f64) / whole;
            if cost < best {
                best = cost;
                split = Some((axis, b));
            }
        }
    }
    split
}
