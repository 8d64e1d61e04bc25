//! Exercise 3.4: the closest hit through a BVH, front to back.
//!
//! `bvh.nodes[0]` is the root. An inner node has two children, a leaf
//! holds the triangles `bvh.order[first .. first + count]` (indices into
//! `bvh.tris`). Every node's `bounds` holds everything below it, and
//! `bounds.enter(ray, inv_dir, t)` is the slab test: where the ray enters
//! the box, if it does before t.
//!
//! Return the closest hit along `ray` in (0, t_max), with `Hit::triangle`
//! the triangle's index in `bvh.tris`, or `None` (also for an empty tree).
//! Visit the nearer child first and skip every box that starts beyond the
//! best hit so far: the answer must equal the naive loop's.
//!
//! Grade it with: `cargo run --release --bin grade -- ch3`

use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::readable_bvh::ReadableBvh;
use raystep::ch3_ray_triangle::triangle::Hit;
// What your traversal needs (until it uses them, they are unused).
#[allow(unused_imports)]
use raystep::ch3_ray_triangle::{readable_bvh::NodeKind, triangle::intersect_watertight};

/// The closest hit along `ray` before `t_max`, through `bvh`.
pub fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    // TODO: return None for an empty tree; compute inv_dir = ray.dir.recip().
    // TODO: keep the best hit and its t (start at t_max), and a stack of
    //       (node index, entry distance); push the root if the ray enters it.
    // TODO: pop a node; skip it if its entry distance is beyond the best t.
    // TODO: a leaf (NodeKind::Leaf): test each of its triangles with
    //       intersect_watertight(ray, bvh.tris[id], 0.0, best t); keep a hit
    //       (with triangle: id) and shrink the best t to it.
    // TODO: an inner node (NodeKind::Inner): slab-test both children against
    //       the best t; push the farther one first, so the nearer comes off
    //       the stack next.
    todo!()
}
