//! Exercise 3.4: the closest hit through a BVH, front to back.
//!
//! `bvh.nodes[0]` is the root (an empty tree has no nodes at all). An
//! inner node has two children; a leaf holds the triangles
//! `bvh.order[first .. first + count]` (indices into `bvh.tris`). Every
//! node's `bounds` holds everything below it, and
//! `bounds.enter(ray, inv_dir, t)` is the slab test: where the ray enters
//! the box, if it does before t (`inv_dir` is `ray.dir.recip()`).
//!
//! Contract (what the grader checks):
//! * The closest hit along `ray` in (0, t_max], as the naive loop over
//!   every triangle would find it: the same t, the same triangle and its
//!   u and v, with `Hit::triangle` the triangle's index in `bvh.tris`
//!   (where two triangles are hit at exactly the same t, either). `None`
//!   for a miss, for a hit only beyond t_max, and for an empty tree. (The
//!   interval is `intersect_watertight`'s: it keeps a hit exactly at its
//!   t_max.)
//! * Boxes are tested with `bounds.enter` and triangles with
//!   `intersect_watertight`: the grader counts both. On eight stacked
//!   sheets of triangles your traversal may do at most twice the slab
//!   tests and twice the triangle tests of the book's.
//!
//! The idea: a ray that misses a box misses everything in it, and once it
//! hits something at t, every box it enters beyond t can be skipped too.
//! Visiting the nearer of two children first finds close hits early, so
//! that most of the tree is skipped.
//!
//! Grade it with: `cargo grade ch3`

use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::readable_bvh::ReadableBvh;
use raystep::ch3_ray_triangle::triangle::Hit;
// What your traversal needs (until it uses them, they are unused).
#[allow(unused_imports)]
use raystep::ch3_ray_triangle::{readable_bvh::NodeKind, triangle::intersect_watertight};

/// The closest hit along `ray` before `t_max`, through `bvh`.
pub fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    // TODO: your code here (steps: `cargo grade --hint ch3/bvh_traversal`).
    todo!()
}
