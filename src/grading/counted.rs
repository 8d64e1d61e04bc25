//! Exercise 3.4's building blocks as a traversal gets them: chapter 3's
//! tree, its slab test and its watertight triangle test, each call
//! counted on the calling thread ([`work`]). The lesson's
//! own functions count nothing; the student's crate sees these in their
//! place (`src/grading/crates/blocks`), and the grader measures the
//! book's traversal over them ([`closest_hit`], the lesson's lines).

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::readable_bvh as lesson;
use crate::ch3_ray_triangle::triangle as lesson_triangle;

pub use crate::ch3_ray_triangle::readable_bvh::NodeKind;
pub use crate::ch3_ray_triangle::triangle::Hit;

use super::work;

/// A node's box, by its lowest and highest corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest x, y and z.
    pub min: Vec3,
    /// The corner with the largest x, y and z.
    pub max: Vec3,
}

impl Aabb {
    /// The slab test ([`lesson::Aabb::enter`]), counted: where the ray
    /// enters the box, if it does before `t_max`.
    pub fn enter(&self, ray: &Ray, inv_dir: Vec3, t_max: f32) -> Option<f32> {
        work::box_test();
        let b = lesson::Aabb {
            min: self.min,
            max: self.max,
        };
        b.enter(ray, inv_dir, t_max)
    }
}

/// A node of the tree: its box, and either two children or some triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    /// Holds every triangle below this node.
    pub bounds: Aabb,
    /// What the node holds.
    pub kind: NodeKind,
}

/// Chapter 3's binary BVH as exercise 3.4 walks it: `nodes[0]` is the
/// root (an empty tree has no nodes); a leaf holds the triangles
/// `order[first .. first + count]`, indices into `tris`.
#[derive(Clone, Debug, PartialEq)]
pub struct ReadableBvh {
    /// The nodes, the root first.
    pub nodes: Vec<Node>,
    /// The leaves' triangles, as indices into `tris`.
    pub order: Vec<u32>,
    /// The triangles.
    pub tris: Vec<[Vec3; 3]>,
}

impl ReadableBvh {
    /// The tree chapter 3 builds over `tris`.
    pub fn build(tris: &[[Vec3; 3]]) -> ReadableBvh {
        ReadableBvh::of(&lesson::ReadableBvh::build(tris))
    }

    /// The counted blocks of the lesson's tree `tree`.
    pub fn of(tree: &lesson::ReadableBvh) -> ReadableBvh {
        let node = |n: &lesson::Node| Node {
            bounds: Aabb {
                min: n.bounds.min,
                max: n.bounds.max,
            },
            kind: n.kind,
        };
        ReadableBvh {
            nodes: tree.nodes.iter().map(node).collect(),
            order: tree.order.clone(),
            tris: tree.tris.clone(),
        }
    }
}

/// The watertight triangle test ([`lesson_triangle::intersect_watertight`]),
/// counted.
pub fn intersect_watertight(ray: &Ray, tri: [Vec3; 3], t_min: f32, t_max: f32) -> Option<Hit> {
    work::triangle_test(t_max);
    lesson_triangle::intersect_watertight(ray, tri, t_min, t_max)
}

/// The book's traversal ([`lesson::closest_hit`]) over the counted
/// blocks: its lines are the lesson's, word for word (a test compares
/// them), so the work the grader allows is measured on the book's own
/// algorithm.
pub fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    let Some(root) = bvh.nodes.first() else {
        return None; // no triangles, nothing to hit
    };
    let inv_dir = ray.dir.recip();
    let mut best: Option<Hit> = None;
    let mut t_best = t_max;
    // Subtrees still to visit, with where the ray enters their box.
    let mut stack: Vec<(u32, f32)> = Vec::new();
    if let Some(t_enter) = root.bounds.enter(ray, inv_dir, t_best) {
        stack.push((0, t_enter));
    }
    while let Some((index, t_enter)) = stack.pop() {
        // A hit found since this subtree was stacked may lie in front of it.
        if t_enter > t_best {
            continue;
        }
        match bvh.nodes[index as usize].kind {
            NodeKind::Leaf { first, count } => {
                for &id in &bvh.order[first as usize..(first + count) as usize] {
                    let tri = bvh.tris[id as usize];
                    if let Some(hit) = intersect_watertight(ray, tri, 0.0, t_best) {
                        t_best = hit.t; // nothing beyond this hit matters now
                        best = Some(Hit {
                            triangle: id,
                            ..hit
                        });
                    }
                }
            }
            NodeKind::Inner { left, right } => {
                let enter =
                    |child: u32| bvh.nodes[child as usize].bounds.enter(ray, inv_dir, t_best);
                // Push the farther child first, so the nearer one comes
                // off the stack next.
                match (enter(left), enter(right)) {
                    (Some(tl), Some(tr)) if tl <= tr => stack.extend([(right, tr), (left, tl)]),
                    (Some(tl), Some(tr)) => stack.extend([(left, tl), (right, tr)]),
                    (Some(tl), None) => stack.push((left, tl)),
                    (None, Some(tr)) => stack.push((right, tr)),
                    (None, None) => {}
                }
            }
        }
    }
    best
}
