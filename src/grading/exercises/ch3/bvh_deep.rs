//! A tree deeper than any fixed-size traversal stack: a chain of inner
//! nodes, each with one leaf and the rest of the chain, drawn for the run
//! (100 to 300 deep). The chain's nearer part comes first, so a
//! front-to-back traversal goes down the chain and leaves every leaf for
//! later; the one triangle the rays hit hangs deep in it. A traversal
//! whose stack drops what it cannot hold (or overflows) misses it.

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::readable_bvh::{Aabb, Node, NodeKind, ReadableBvh};
use crate::exercises::draws::Draws;

/// The drawn chain and rays along it (with what to call each).
pub(super) fn deep_chain() -> (ReadableBvh, Vec<(Ray, String)>) {
    let mut draws = Draws::new(35);
    let n = draws.count(100, 300);
    let hit = draws.count(n / 2, n - 1);
    chain(draws, n, hit)
}

/// A longer chain, 600 to 900 deep, whose hit hangs a quarter to an
/// eighth of the way down: a front-to-back traversal opens 450 leaves or
/// more before it (no count of leaves may stop it).
pub(super) fn long_chain() -> (ReadableBvh, Vec<(Ray, String)>) {
    let mut draws = Draws::new(135);
    let n = draws.count(600, 900);
    let hit = draws.count(n / 8, n / 4);
    chain(draws, n, hit)
}

/// A chain of `n` with the hit at `hit`, the rest drawn from `draws`.
fn chain(mut draws: Draws, n: usize, hit: usize) -> (ReadableBvh, Vec<(Ray, String)>) {
    let spacing = draws.decades(-2.0, 1.0);
    let size = spacing * 0.4;
    let place = draws.place_for(size, 2.0);
    // Triangle i at depth n - i along -z: the deeper in the chain, the
    // nearer. All but one are corners whose boxes the rays enter (so that
    // a traversal keeps every leaf for later) and whose triangles they
    // pass by; the rays hit the one centred on them.
    let tris: Vec<[Vec3; 3]> = (0..n)
        .map(|i| {
            let c = place + Vec3::new(0.0, 0.0, -((n - i) as f32) * spacing);
            let at = |x: f32, y: f32| c + Vec3::new(x, y, 0.0) * size;
            let mirror = if i % 2 == 0 { 1.0 } else { -1.0 };
            if i == hit {
                [at(-1.0, -1.0), at(1.0, -1.0), at(0.0, 1.0)]
            } else {
                [
                    at(-2.0 * mirror, -2.0),
                    at(2.0 * mirror, -2.0),
                    at(2.0 * mirror, 0.5),
                ]
            }
        })
        .collect();
    // Inner node i (0 ≤ i < n - 1) at index i, leaf i at n - 1 + i.
    let leaf = |i: usize| (n - 1 + i) as u32;
    let mut nodes = vec![
        Node {
            bounds: Aabb::EMPTY,
            kind: NodeKind::Leaf { first: 0, count: 0 },
        };
        2 * n - 1
    ];
    for (i, tri) in tris.iter().enumerate() {
        nodes[leaf(i) as usize] = Node {
            bounds: Aabb::around(tri),
            kind: NodeKind::Leaf {
                first: i as u32,
                count: 1,
            },
        };
    }
    for i in (0..n - 1).rev() {
        let right = if i + 1 == n - 1 {
            leaf(n - 1)
        } else {
            (i + 1) as u32
        };
        let bounds = nodes[leaf(i) as usize]
            .bounds
            .union(nodes[right as usize].bounds);
        nodes[i] = Node {
            bounds,
            kind: NodeKind::Inner {
                left: leaf(i),
                right,
            },
        };
    }
    let bvh = ReadableBvh {
        nodes,
        order: (0..n as u32).collect(),
        tris,
    };
    let rays = (0..draws.count(4, 12))
        .filter_map(|_| {
            draws.next_case();
            let at = place + Vec3::new(draws.range(-0.3, 0.3), draws.range(-0.3, 0.2), 0.0) * size;
            let ray = Ray::new(at + Vec3::Z * spacing, -Vec3::Z).ok()?;
            let what = format!(
                "a chain {n} nodes deep whose triangle {hit} (a leaf {} nodes down) is the one hit, \
                 ray from {}",
                hit + 1,
                ray.origin
            );
            Some((ray, what))
        })
        .collect();
    (bvh, rays)
}
