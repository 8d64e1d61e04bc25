//! Camera rays eight at a time. The eight samples of a pixel that start a
//! round of paths leave the same eye through the same pixel, so they open
//! the same nodes and leaves of the tree: one traversal for all eight
//! tests a node's boxes once against the range of the eight rays
//! (`enter`), and each triangle once with one ray per lane, where the
//! one-ray `Bvh8::closest_with` does both eight times, and makes its
//! branches once. The traversal is the one closest-hit query
//! (`wide_build::closest`), with the group as its ray: `Group` gives it
//! the group's tests, and `Best` the eight nearest hits so far, its
//! reach the farthest of them.
//!
//! The box test opens every box some ray of the eight enters. At the
//! leaves each lane runs the one-ray test's arithmetic in its order (the
//! watertight test with the ray's own shear, pbrt-v4's error bound), so a
//! ray's hit is the one the one-ray traversal finds: the nearest trusted
//! hit, t, u and v to the bit. Two things send a ray back
//! to the one-ray traversal: eight rays whose largest direction components
//! are not on the same axis (the test's permutation differs) or whose
//! directions differ in sign on some axis (the slab test's near and far
//! sides differ), and a lane the one-ray test would hand to its exact
//! fallback (an edge function exactly zero, or a t too small to trust). A tie (two triangles at
//! exactly the same t, which only coincident surfaces give) may go to
//! another of the tied triangles than the one-ray order picks.

// Lane loops index several arrays by lane, on purpose (vector code).
#![allow(clippy::needless_range_loop)]

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;

use crate::ch3_ray_triangle::wide_build::{closest, ClosestHit, Found, WideTree};

use super::bvh8::Bvh8;
use super::lanes::{
    front_lane, larger, mask, smaller, trust_lane, Fronts, RayData, FAR_STRETCH, W,
};

/// Eight rays' numbers: per axis the smallest and largest origin and
/// 1/direction of the eight (what [`enter`] tests the node's boxes with),
/// and by lane the watertight test's permuted origin and shear; the
/// direction signs and the permutation are the same for all eight.
struct Packet {
    o_range: [(f32, f32); 3],
    inv_range: [(f32, f32); 3],
    negative: [bool; 3],
    k: [usize; 3],
    ko: [[f32; W]; 3],
    s: [[f32; W]; 3],
}

impl Packet {
    /// The numbers of eight rays, as chapter 3's `BoxRay` and
    /// `WatertightRay` compute them for one (the same operations, lane by
    /// lane); `None` where the rays' permutations or direction signs
    /// differ.
    #[inline(always)]
    fn new(rays: &[Ray]) -> Option<Packet> {
        let mut d = [[0.0f32; W]; 3];
        let mut o = [[0.0f32; W]; 3];
        for j in 0..W {
            for a in 0..3 {
                d[a][j] = rays[j].dir[a];
                o[a][j] = rays[j].origin[a];
            }
        }
        // The watertight permutation: z is the largest component.
        let mut kz = [0u32; W];
        for j in 0..W {
            let (x, y, z) = (d[0][j].abs(), d[1][j].abs(), d[2][j].abs());
            let xy = if x > z { 0 } else { 2 };
            let yz = if y > z { 1 } else { 2 };
            kz[j] = if x > y { xy } else { yz };
        }
        let mut sign = [[false; W]; 3];
        for a in 0..3 {
            for j in 0..W {
                sign[a][j] = d[a][j].is_sign_negative();
            }
        }
        let same = |v: &[bool; W]| v.iter().all(|&b| b == v[0]);
        if kz.iter().any(|&k| k != kz[0]) || !(0..3).all(|a| same(&sign[a])) {
            return None;
        }
        const PERMUTATION: [[usize; 3]; 3] = [[1, 2, 0], [2, 0, 1], [0, 1, 2]];
        let k = PERMUTATION[kz[0] as usize];
        let mut inv = [[0.0f32; W]; 3];
        for a in 0..3 {
            for j in 0..W {
                // `BoxRay`: tiny components kept finite.
                let x = d[a][j];
                let safe = if x.abs() < 1e-30 {
                    1e-30f32.copysign(x)
                } else {
                    x
                };
                inv[a][j] = 1.0 / safe;
            }
        }
        let mut p = Packet {
            o_range: o.map(|v| (smallest(v), largest(v))),
            inv_range: inv.map(|v| (smallest(v), largest(v))),
            negative: [sign[0][0], sign[1][0], sign[2][0]],
            k,
            ko: [o[k[0]], o[k[1]], o[k[2]]],
            s: [[0.0; W]; 3],
        };
        for j in 0..W {
            let (dx, dy, dz) = (d[k[0]][j], d[k[1]][j], d[k[2]][j]);
            p.s[0][j] = -dx / dz;
            p.s[1][j] = -dy / dz;
            p.s[2][j] = 1.0 / dz;
        }
        Some(p)
    }
}

/// Whether eight rays go through the tree together in
/// `closest8` (the same permutation and direction signs), rather than
/// one at a time.
pub fn together(rays: &[Ray]) -> bool {
    rays.len() == W && Packet::new(rays).is_some()
}

/// The nearest hits found so far, by lane, and the lanes the one-ray
/// traversal must decide.
struct Best {
    t: [f32; W],
    u: [f32; W],
    v: [f32; W],
    triangle: [u32; W],
    redo: u32,
    /// The farthest of the lanes' `t`: a box that starts beyond it holds
    /// no nearer hit for any lane. (Updated at each leaf, since the
    /// traversal reads it twice at every node.)
    farthest: f32,
}

impl Found for Best {
    #[inline(always)]
    fn reach(&self) -> f32 {
        self.farthest
    }
}

/// The eight-wide tree, traversed by a group of eight rays: the
/// closest-hit query written once ([`closest`]) with the group's slab
/// test ([`enter`]) and leaf test ([`leaf`]).
struct Group<'a> {
    bvh: &'a Bvh8,
}

impl WideTree<W> for Group<'_> {
    type Ray<'r> = Packet;

    #[inline(always)]
    fn root(&self) -> u32 {
        self.bvh.root
    }

    #[inline(always)]
    fn enter(&self, p: &Packet, node: usize, t_far: f32) -> (u32, [f32; W], &[u32; W]) {
        let node = &self.bvh.nodes[node];
        let (entered, nears) = enter(p, t_far, node);
        (entered, nears, &node.child)
    }
}

impl ClosestHit<W> for Group<'_> {
    type Found = Best;

    #[inline(always)]
    fn leaf_closest(&self, p: &Packet, l: usize, best: &mut Best) {
        best.redo |= leaf(p, self.bvh, l, best);
        best.farthest = largest(best.t);
    }
}

/// The closest hits of eight `rays` in (0, ∞), into `out` (eight
/// entries), as `Bvh8::closest_with` finds them; `stack` holds at least
/// [`Bvh8::stack_size`] entries.
#[inline(always)]
pub(super) fn closest8(
    bvh: &Bvh8,
    rays: &[Ray],
    out: &mut [Option<Hit>],
    stack: &mut [(u32, f32)],
) {
    let Some(p) = Packet::new(rays) else {
        return one_by_one(bvh, rays, out, 0xff, stack);
    };
    let mut best = Best {
        t: [f32::INFINITY; W],
        u: [0.0; W],
        v: [0.0; W],
        triangle: [u32::MAX; W],
        redo: 0,
        farthest: f32::INFINITY,
    };
    closest(&Group { bvh }, &p, &mut best, stack);
    for j in 0..W {
        out[j] = (best.triangle[j] != u32::MAX).then(|| Hit {
            t: best.t[j],
            u: best.u[j],
            v: best.v[j],
            triangle: best.triangle[j],
        });
    }
    if best.redo != 0 {
        one_by_one(bvh, rays, out, best.redo, stack);
    }
}

/// The one-ray traversal for the rays of `lanes` (a bit per ray).
fn one_by_one(
    bvh: &Bvh8,
    rays: &[Ray],
    out: &mut [Option<Hit>],
    lanes: u32,
    stack: &mut [(u32, f32)],
) {
    for (j, ray) in rays.iter().enumerate().filter(|(j, _)| lanes >> j & 1 != 0) {
        out[j] = bvh.closest_with(&RayData::new(ray), f32::INFINITY, stack);
    }
}

/// The slab test of a node's eight boxes for the eight rays at once, each
/// box against (0, `t_far`) (`t_far` the farthest of the rays' nearest
/// hits so far): the mask of children some ray may enter, and a distance
/// no ray enters each before. Rather than each ray, the test takes the
/// range of the eight origins and of the eight 1/directions per axis: a
/// ray's distance to a plane, (plane - o) / d, lies between the smallest
/// and the largest of the four products the ranges' ends give (rounding
/// keeps that order, as it never reverses a comparison), so a box no
/// product lets in is missed by every ray. The eight rays of a pixel's
/// samples are nearly one ray, and this one test does the work of eight.
// ANCHOR: packet_enter
#[inline(always)]
fn enter(p: &Packet, t_far: f32, node: &super::lanes::Node8) -> (u32, [f32; W]) {
    let mut t_near = [0.0f32; W];
    let mut t_far = [t_far; W];
    for axis in 0..3 {
        let (lo, hi) = (&node.min[axis], &node.max[axis]);
        let (near, far) = if p.negative[axis] { (hi, lo) } else { (lo, hi) };
        let ((o0, o1), (i0, i1)) = (p.o_range[axis], p.inv_range[axis]);
        for c in 0..W {
            // The four ends of (plane - o) · inv for the near plane and
            // the far plane; the smallest and the largest, as selects.
            let (a0, a1) = (near[c] - o1, near[c] - o0);
            let (b0, b1) = (far[c] - o1, far[c] - o0);
            let [p0, p1, p2, p3] = [a0 * i0, a0 * i1, a1 * i0, a1 * i1];
            let [q0, q1, q2, q3] = [b0 * i0, b0 * i1, b1 * i0, b1 * i1];
            let enters = smaller(smaller(p0, p1), smaller(p2, p3));
            let leaves = larger(larger(q0, q1), larger(q2, q3));
            t_near[c] = larger(t_near[c], enters);
            t_far[c] = smaller(t_far[c], leaves);
        }
    }
    let mut entered = [false; W];
    for c in 0..W {
        entered[c] = node.child[c] != u32::MAX && t_near[c] <= t_far[c] * FAR_STRETCH;
    }
    (mask(entered), t_near)
}
// ANCHOR_END: packet_enter

/// The smallest of the lanes, pairwise (three vector steps, not a chain
/// of eight scalar ones; the lanes are never NaN).
#[inline(always)]
fn smallest(v: [f32; W]) -> f32 {
    let a: [f32; 4] = std::array::from_fn(|j| smaller(v[j], v[j + 4]));
    smaller(smaller(a[0], a[2]), smaller(a[1], a[3]))
}

/// The largest of the lanes, likewise.
#[inline(always)]
fn largest(v: [f32; W]) -> f32 {
    let a: [f32; 4] = std::array::from_fn(|j| larger(v[j], v[j + 4]));
    larger(larger(a[0], a[2]), larger(a[1], a[3]))
}

/// Leaf `l`'s triangles, one at a time, against the eight lanes (each in
/// (0, its nearest hit so far)), in lane order with a later triangle
/// winning a tie, as the one-ray leaf test picks: updates `best`, and
/// returns the lanes that the one-ray test's exact fallback must decide.
/// Each lane runs the one-ray test's halves ([`front_lane`],
/// [`trust_lane`]) with triangle i and its own ray.
#[inline(always)]
fn leaf(p: &Packet, bvh: &Bvh8, l: usize, best: &mut Best) -> u32 {
    let leaf = &bvh.leaves[l];
    let (px, py, pz) = (&leaf.p[p.k[0]], &leaf.p[p.k[1]], &leaf.p[p.k[2]]);
    let mut check = [false; W];
    for i in 0..W {
        let triangle = bvh.original[l * W + i];
        if triangle == u32::MAX {
            continue;
        }
        let tri = (
            [px[0][i], px[1][i], px[2][i]],
            [py[0][i], py[1][i], py[2][i]],
            [pz[0][i], pz[1][i], pz[2][i]],
        );
        let mut f = Fronts::default();
        for j in 0..W {
            let ray = (
                [p.ko[0][j], p.ko[1][j], p.ko[2][j]],
                [p.s[0][j], p.s[1][j], p.s[2][j]],
            );
            f.set(j, &front_lane(tri, ray, best.t[j]));
            check[j] |= f.zero[j];
        }
        if !f.candidate.iter().any(|&c| c) {
            continue;
        }
        // The second half, where a ray can hit.
        for j in 0..W {
            let (t, inv_det, trusted) = trust_lane(&f.get(j));
            let candidate = f.candidate[j];
            let hit = candidate & trusted & !f.zero[j];
            check[j] |= candidate & !trusted;
            let take = hit & (t <= best.t[j]);
            best.t[j] = if take { t } else { best.t[j] };
            best.u[j] = if take { f.e[1][j] * inv_det } else { best.u[j] };
            best.v[j] = if take { f.e[2][j] * inv_det } else { best.v[j] };
            best.triangle[j] = if take { triangle } else { best.triangle[j] };
        }
    }
    mask(check)
}
