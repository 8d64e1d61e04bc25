//! Exercise 3.4, solved as a student would: recursively, nearer child
//! first.

use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::readable_bvh::ReadableBvh;
use raystep::ch3_ray_triangle::triangle::Hit;
use raystep::ch3_ray_triangle::{readable_bvh::NodeKind, triangle::intersect_watertight};

/// The closest hit along `ray` before `t_max`, through `bvh`.
pub fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    if bvh.nodes.is_empty() {
        return None;
    }
    let inv_dir = ray.dir.recip();
    let t_root = bvh.nodes[0].bounds.enter(ray, inv_dir, t_max)?;
    let mut best = None;
    let mut t_best = t_max;
    visit(bvh, ray, inv_dir, 0, t_root, &mut t_best, &mut best);
    best
}

fn visit(
    bvh: &ReadableBvh,
    ray: &Ray,
    inv_dir: glam::Vec3,
    node: u32,
    t_enter: f32,
    t_best: &mut f32,
    best: &mut Option<Hit>,
) {
    if t_enter > *t_best {
        return;
    }
    match bvh.nodes[node as usize].kind {
        NodeKind::Leaf { first, count } => {
            for i in first..first + count {
                let id = bvh.order[i as usize];
                if let Some(hit) = intersect_watertight(ray, bvh.tris[id as usize], 0.0, *t_best) {
                    *t_best = hit.t;
                    *best = Some(Hit { triangle: id, ..hit });
                }
            }
        }
        NodeKind::Inner { left, right } => {
            let tl = bvh.nodes[left as usize].bounds.enter(ray, inv_dir, *t_best);
            let tr = bvh.nodes[right as usize].bounds.enter(ray, inv_dir, *t_best);
            let mut kids = [(left, tl), (right, tr)];
            if tr.unwrap_or(f32::INFINITY) < tl.unwrap_or(f32::INFINITY) {
                kids.swap(0, 1);
            }
            for (child, t) in kids {
                if let Some(t) = t {
                    visit(bvh, ray, inv_dir, child, t, t_best, best);
                }
            }
        }
    }
}
