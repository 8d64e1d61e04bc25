//! Chapter 3's BVH diagram: the boxes of a real [`ReadableBvh`] over a
//! dozen triangles in the plane z = 0, the tree they form, and which boxes
//! a ray enters before its closest hit ([`Aabb::enter`]).

use glam::Vec3;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::readable_bvh::{NodeKind, ReadableBvh};
use raystep::core::error::{Error, Result};

use crate::svg::{Anchor, Stroke, Svg, BLUE, FILL_GREEN, GREEN, GREY, INK, ORANGE};
use crate::Diagram;

/// The fourth level's colour.
const VIOLET: &str = "#7a4fb5";

/// The diagram: boxes on the left, the tree on the right.
pub fn diagram() -> Result<Diagram> {
    Ok(Diagram {
        name: "ch3-bvh-diagram",
        what: "the boxes and tree ReadableBvh::build makes over 12 triangles, and the boxes a ray enters before its closest hit (Aabb::enter)",
        svg: bvh()?,
    })
}

/// Twelve triangles standing upright: each has one edge along z, from
/// (a, −1) to (a, 1), and its third corner at (c, 0), so that seen from
/// above (and by a ray in the plane z = 0) it is the segment a–c.
fn triangles() -> Vec<[Vec3; 3]> {
    let walls = [
        ((0.6, 0.6), (1.6, 1.5)),
        ((1.6, 6.0), (2.8, 5.2)),
        ((2.6, 2.0), (3.6, 3.0)),
        ((0.8, 3.2), (1.9, 4.1)),
        ((4.0, 6.4), (4.9, 5.3)),
        ((4.5, 0.6), (5.7, 1.4)),
        ((5.8, 3.0), (6.6, 4.2)),
        ((6.8, 6.4), (7.7, 5.5)),
        ((7.4, 1.0), (8.5, 2.0)),
        ((8.7, 3.6), (9.4, 4.8)),
        ((3.8, 3.4), (4.8, 4.4)),
        ((8.2, 6.7), (9.2, 6.0)),
    ];
    walls
        .iter()
        .map(|&((ax, ay), (cx, cy))| {
            [
                Vec3::new(ax, ay, -1.0),
                Vec3::new(ax, ay, 1.0),
                Vec3::new(cx, cy, 0.0),
            ]
        })
        .collect()
}

fn xy(v: Vec3) -> (f64, f64) {
    (v.x as f64, v.y as f64)
}

/// Depth of every node below the root (root 0), by walking the tree.
fn depths(bvh: &ReadableBvh) -> Vec<usize> {
    let mut depth = vec![0; bvh.nodes.len()];
    for (n, node) in bvh.nodes.iter().enumerate() {
        if let NodeKind::Inner { left, right } = node.kind {
            depth[left as usize] = depth[n] + 1;
            depth[right as usize] = depth[n] + 1;
        }
    }
    depth
}

/// Horizontal slots of the tree's nodes: leaves 0, 1, 2, ... left to
/// right, an inner node half way between its children.
fn slots(bvh: &ReadableBvh, n: u32, next: &mut f64, out: &mut [f64]) -> f64 {
    let x = match bvh.nodes[n as usize].kind {
        NodeKind::Leaf { .. } => {
            *next += 1.0;
            *next - 1.0
        }
        NodeKind::Inner { left, right } => {
            0.5 * (slots(bvh, left, next, out) + slots(bvh, right, next, out))
        }
    };
    out[n as usize] = x;
    x
}

fn bvh() -> Result<Svg> {
    let tris = triangles();
    let bvh = ReadableBvh::build(&tris);
    let ray = Ray::new(Vec3::new(0.2, 6.9, 0.0), Vec3::new(1.0, -0.72, 0.0))?;
    let hit = bvh
        .closest(&ray, f32::INFINITY)
        .ok_or_else(|| Error::Usage("bvh diagram: the ray hits nothing".into()))?;
    let inv = ray.dir.recip();
    // A box the ray enters before its hit must be opened; any other box
    // is skipped with everything below it.
    let opened: Vec<bool> = bvh
        .nodes
        .iter()
        .map(|node| node.bounds.enter(&ray, inv, hit.t).is_some())
        .collect();
    let depth = depths(&bvh);
    let deepest = depth.iter().copied().max().unwrap_or(0);
    let colours = [INK, BLUE, ORANGE, VIOLET, GREY];
    let mut s = Svg::new(680.0, [-0.5, 17.6, -1.0, 8.3]);
    let title = |s: &mut Svg, at: (f64, f64), text: &str| {
        s.text(at, (0.0, 4.0), text, 14.0, Anchor::Middle, INK, false);
    };
    title(&mut s, (5.0, 8.0), "boxes, seen from above");
    title(&mut s, (14.1, 8.0), "the tree");
    // Boxes, outermost first; each level is drawn a little larger than the
    // level below it, so nested boxes that share a side stay apart.
    let pad = 0.09;
    for (n, node) in bvh.nodes.iter().enumerate() {
        let grow = pad * (deepest - depth[n]) as f64;
        let (lo, hi) = (xy(node.bounds.min), xy(node.bounds.max));
        let (lo, hi) = ((lo.0 - grow, lo.1 - grow), (hi.0 + grow, hi.1 + grow));
        let colour = colours[depth[n].min(colours.len() - 1)];
        let stroke = if opened[n] {
            Stroke::solid(colour, 2.0)
        } else {
            Stroke::dashed(colour, 1.0)
        };
        s.polyline(&[lo, (hi.0, lo.1), hi, (lo.0, hi.1)], stroke, Some("none"));
    }
    for (k, tri) in tris.iter().enumerate() {
        let colour = if k as u32 == hit.triangle { GREEN } else { INK };
        s.line(xy(tri[0]), xy(tri[2]), Stroke::solid(colour, 3.6));
        let label = format!("{k}");
        let (a, c) = (tri[0], tri[2]);
        let beyond = xy(c + (c - a).normalize() * 0.28);
        s.text(
            beyond,
            (0.0, 4.0),
            &label,
            12.0,
            Anchor::Middle,
            colour,
            false,
        );
    }
    s.arrow(xy(ray.origin), xy(ray.at(hit.t)), Stroke::solid(GREEN, 2.4));
    s.line(
        xy(ray.at(hit.t)),
        xy(ray.at(hit.t + 3.0)),
        Stroke::dashed(GREY, 1.4),
    );
    s.dot(xy(ray.at(hit.t)), 5.0, GREEN);
    // The tree: one row per level, leaves listing their triangles.
    let mut x = vec![0.0; bvh.nodes.len()];
    let leaves = slots(&bvh, 0, &mut 0.0, &mut x);
    let _ = leaves;
    let leaf_count = bvh
        .nodes
        .iter()
        .filter(|n| matches!(n.kind, NodeKind::Leaf { .. }))
        .count();
    let (tx0, tx1, ty0, ty1) = (10.9, 17.3, 0.4, 7.1);
    let step = (tx1 - tx0) / (leaf_count.max(2) - 1) as f64;
    let at = |n: usize| {
        let level = (ty1 - ty0) / deepest.max(1) as f64;
        (tx0 + x[n] * step, ty1 - depth[n] as f64 * level)
    };
    for (n, node) in bvh.nodes.iter().enumerate() {
        if let NodeKind::Inner { left, right } = node.kind {
            for child in [left, right] {
                let c = child as usize;
                let stroke = if opened[c] {
                    Stroke::solid(INK, 1.6)
                } else {
                    Stroke::dashed(GREY, 1.0)
                };
                s.line(at(n), at(c), stroke);
            }
        }
    }
    for (n, node) in bvh.nodes.iter().enumerate() {
        let colour = colours[depth[n].min(colours.len() - 1)];
        let fill = if opened[n] { FILL_GREEN } else { "#ffffff" };
        s.circle(at(n), 0.2, Stroke::solid(colour, 1.8), Some(fill));
        if let NodeKind::Leaf { first, count } = node.kind {
            let ids: Vec<String> = bvh.order[first as usize..(first + count) as usize]
                .iter()
                .map(|id| id.to_string())
                .collect();
            let label = ids.join(",");
            s.text(at(n), (0.0, 24.0), &label, 12.0, Anchor::Middle, INK, false);
        }
    }
    let opened_count = opened.iter().filter(|&&o| o).count();
    s.caption(&format!(
                "solid: the {opened_count} boxes (of {}) the ray enters before it hits {} at t = {:.2}; dashed: skipped",
        bvh.nodes.len(),
        hit.triangle,
        hit.t
    ));
    Ok(s)
}
