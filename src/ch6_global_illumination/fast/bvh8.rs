//! The fast engine's BVH: chapter 3's binary tree collapsed to *eight*
//! children per node and eight triangles per leaf, stored by coordinate
//! (`[f32; 8]` per axis), so that one pass over the lanes tests all eight
//! boxes or triangles. The lane loops are plain Rust over arrays; the
//! compiler turns each into a few vector instructions, as wide as the CPU
//! the code was compiled for ([`super::simd`] compiles the whole row loop
//! three times, for AVX-512, AVX2 and the portable baseline, and picks one
//! at run time).
//!
//! The arithmetic of each lane is chapter 3's watertight test in the order
//! [`WatertightRay::intersect4`] uses, so every hit (t, u, v) is bit for
//! bit what the readable engine's four-wide tree finds, and the images
//! of the two engines are the same bytes. The rare lanes that test hands
//! back (an edge function exactly zero, a t too small to trust) go to the
//! same one-triangle test.

use glam::Vec3;
use obvhs::bvh2::Bvh2;
use obvhs::BvhBuildParams;

use crate::ch3_ray_triangle::bvh_robust::build_guarded;
use crate::ch3_ray_triangle::obvhs_bvh::padded_boxes;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::{gamma, Hit};
use crate::ch3_ray_triangle::watertight_fast::{SoaTriangle, WatertightRay};
use crate::ch5_reflection::world::RayQueries;

use super::simd::{self, Level};

/// Children per node and triangles per leaf.
pub const W: usize = 8;
/// Most triangles in a leaf.
const LEAF_SIZE: usize = 8;
/// A child reference with this bit set is a leaf.
const LEAF: u32 = 1 << 31;
/// How much a box's far distance is stretched (as the readable tree).
pub(super) const FAR_STRETCH: f32 = 1.0 + 4.0 * gamma(3);

/// Eight children's boxes by axis; an unused slot has an empty box.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
pub(super) struct Node8 {
    pub(super) min: [[f32; W]; 3],
    pub(super) max: [[f32; W]; 3],
    child: [u32; W],
}

/// Eight triangles: `p[axis][vertex][lane]`. Unused lanes and zero-area
/// triangles hold NaN, which every test rejects.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
pub(super) struct Leaf8 {
    pub(super) p: [[[f32; W]; 3]; 3],
}

/// The two lane tests a traversal needs, as one instruction set computes
/// them: [`Lanes`] in plain Rust, or [`super::simd`]'s AVX2 code. Every
/// implementation gives the same bits.
pub(super) trait Kernel {
    /// [`enter`]: the children a ray enters and where.
    fn enter(r: &RayData, node: &Node8, t_max: f32) -> (u32, [f32; W]);
    /// [`leaf_test`]: the leaf's hits and the lanes left to check.
    fn leaf(r: &RayData, leaf: &Leaf8, t_max: f32) -> Hits8;
}

/// The portable kernel: the lane loops above.
pub(super) struct Lanes;

impl Kernel for Lanes {
    #[inline(always)]
    fn enter(r: &RayData, node: &Node8, t_max: f32) -> (u32, [f32; W]) {
        enter(r, node, t_max)
    }
    #[inline(always)]
    fn leaf(r: &RayData, leaf: &Leaf8, t_max: f32) -> Hits8 {
        leaf_test(r, leaf, t_max)
    }
}

/// The eight-wide tree.
pub struct Bvh8 {
    nodes: Vec<Node8>,
    leaves: Vec<Leaf8>,
    root: u32,
    /// Inner-node levels on the longest root-to-leaf path.
    levels: usize,
    /// The triangles one by one (`tris[8 l + lane]`) for the rare lanes.
    tris: Vec<SoaTriangle>,
    /// `original[8 l + lane]`: the triangle's index in the build list.
    original: Vec<u32>,
    /// Which vector instructions the queries use.
    level: Level,
}

/// What the box and triangle tests need of a ray, computed once per ray.
pub struct RayData<'a> {
    wt: WatertightRay<'a>,
    /// Origin, 1/direction (tiny components kept finite), and per axis
    /// whether the direction is negative.
    pub(super) o: [f32; 3],
    pub(super) inv: [f32; 3],
    pub(super) negative: [bool; 3],
    /// Watertight permutation and shear.
    pub(super) k: [usize; 3],
    pub(super) ko: [f32; 3],
    pub(super) s: [f32; 3],
}

impl<'a> RayData<'a> {
    /// The per-ray data of `ray`.
    #[inline(always)]
    pub fn new(ray: &'a Ray) -> RayData<'a> {
        let d = ray.dir.to_array();
        let o = ray.origin.to_array();
        let inv = d.map(|x| {
            let safe = if x.abs() < 1e-30 {
                1e-30f32.copysign(x)
            } else {
                x
            };
            1.0 / safe
        });
        let a = ray.dir.abs();
        let kz = if a.x > a.y {
            if a.x > a.z {
                0
            } else {
                2
            }
        } else if a.y > a.z {
            1
        } else {
            2
        };
        const PERMUTATION: [[usize; 3]; 3] = [[1, 2, 0], [2, 0, 1], [0, 1, 2]];
        let k = PERMUTATION[kz];
        let dz = d[k[2]];
        RayData {
            wt: WatertightRay::new(ray),
            o,
            inv,
            negative: d.map(|x| x.is_sign_negative()),
            k,
            ko: k.map(|i| o[i]),
            s: [-d[k[0]] / dz, -d[k[1]] / dz, 1.0 / dz],
        }
    }
}

/// Bit i set where lane i is true.
#[inline(always)]
fn mask(b: [bool; W]) -> u32 {
    let mut bits = [0u32; W];
    for i in 0..W {
        bits[i] = (b[i] as u32) << i;
    }
    bits.iter().fold(0, |m, x| m | x)
}

/// The slab test of a node's eight boxes against (0, t_max): the mask of
/// children entered and where the ray enters each.
// ANCHOR: slab8
#[inline(always)]
pub(super) fn enter(r: &RayData, node: &Node8, t_max: f32) -> (u32, [f32; W]) {
    let mut t_near = [0.0f32; W];
    let mut t_far = [t_max; W];
    for axis in 0..3 {
        let (near, far) = match r.negative[axis] {
            true => (&node.max[axis], &node.min[axis]),
            false => (&node.min[axis], &node.max[axis]),
        };
        for i in 0..W {
            t_near[i] = t_near[i].max((near[i] - r.o[axis]) * r.inv[axis]);
            t_far[i] = t_far[i].min((far[i] - r.o[axis]) * r.inv[axis]);
        }
    }
    let mut entered = [false; W];
    for i in 0..W {
        entered[i] = t_near[i] <= t_far[i] * FAR_STRETCH;
    }
    (mask(entered), t_near)
}
// ANCHOR_END: slab8

/// What [`leaf_test`] found: hit and check masks, and t, u, v per lane.
pub(super) struct Hits8 {
    pub(super) hit: u32,
    pub(super) check: u32,
    pub(super) t: [f32; W],
    pub(super) u: [f32; W],
    pub(super) v: [f32; W],
}

/// The watertight test on a leaf's eight triangles in (0, t_max), lane
/// by lane in the order of the four-wide test. One loop without branches
/// (bitwise `&` and `|` on the comparisons, no early exit), which the
/// compiler turns into vector instructions.
// ANCHOR: leaf8
#[inline(always)]
pub(super) fn leaf_test(r: &RayData, leaf: &Leaf8, t_max: f32) -> Hits8 {
    let (px, py, pz) = (&leaf.p[r.k[0]], &leaf.p[r.k[1]], &leaf.p[r.k[2]]);
    let [ox, oy, oz] = r.ko;
    let [sx, sy, sz] = r.s;
    let mut h = Hits8 {
        hit: 0,
        check: 0,
        t: [0.0; W],
        u: [0.0; W],
        v: [0.0; W],
    };
    // First the edge functions and which lanes can hit at all; the
    // division and the error bound only when one can (most leaves a ray
    // enters hold no hit).
    let mut e = [[0.0f32; W]; 3];
    let (mut xs, mut ys, mut zs) = ([[0.0f32; W]; 3], [[0.0f32; W]; 3], [[0.0f32; W]; 3]);
    let (mut det, mut ts) = ([0.0f32; W], [0.0f32; W]);
    let (mut candidate, mut any_zero) = ([false; W], [false; W]);
    for i in 0..W {
        // Translate, permute and shear each vertex (a, b, c).
        let (z0, z1, z2) = (pz[0][i] - oz, pz[1][i] - oz, pz[2][i] - oz);
        let (x0, x1, x2) = (
            (px[0][i] - ox) + sx * z0,
            (px[1][i] - ox) + sx * z1,
            (px[2][i] - ox) + sx * z2,
        );
        let (y0, y1, y2) = (
            (py[0][i] - oy) + sy * z0,
            (py[1][i] - oy) + sy * z1,
            (py[2][i] - oy) + sy * z2,
        );
        // The edge functions.
        let e0 = x1 * y2 - y1 * x2;
        let e1 = x2 * y0 - y2 * x0;
        let e2 = x0 * y1 - y0 * x1;
        any_zero[i] = (e0 == 0.0) | (e1 == 0.0) | (e2 == 0.0);
        let neg = (e0 < 0.0) | (e1 < 0.0) | (e2 < 0.0);
        let pos = (e0 > 0.0) | (e1 > 0.0) | (e2 > 0.0);
        let d = e0 + e1 + e2;
        let (z0, z1, z2) = (z0 * sz, z1 * sz, z2 * sz);
        let t_scaled = e0 * z0 + e1 * z1 + e2 * z2;
        let (lo, hi) = (0.0 * d, t_max * d);
        let in_neg = (d < 0.0) & (t_scaled < lo) & (t_scaled >= hi);
        let in_pos = (d > 0.0) & (t_scaled > lo) & (t_scaled <= hi);
        let finite = d.abs() < f32::INFINITY;
        candidate[i] = !(neg & pos) & finite & (in_neg | in_pos);
        (e[0][i], e[1][i], e[2][i]) = (e0, e1, e2);
        (xs[0][i], xs[1][i], xs[2][i]) = (x0, x1, x2);
        (ys[0][i], ys[1][i], ys[2][i]) = (y0, y1, y2);
        (zs[0][i], zs[1][i], zs[2][i]) = (z0, z1, z2);
        (det[i], ts[i]) = (d, t_scaled);
    }
    let (candidates, zeros) = (mask(candidate), mask(any_zero));
    if candidates == 0 {
        h.check = zeros;
        return h;
    }
    let g = gamma;
    let mut trusted = [false; W];
    let max3 = |v: &[[f32; W]; 3], i: usize| v[0][i].abs().max(v[1][i].abs()).max(v[2][i].abs());
    for i in 0..W {
        let inv_det = 1.0 / det[i];
        let t = ts[i] * inv_det;
        // pbrt-v4's bound on the rounding error of t.
        let (max_zt, max_xt, max_yt) = (max3(&zs, i), max3(&xs, i), max3(&ys, i));
        let delta_z = g(3) * max_zt;
        let delta_x = g(5) * (max_xt + max_zt);
        let delta_y = g(5) * (max_yt + max_zt);
        let delta_e = 2.0 * (g(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
        let max_e = max3(&e, i);
        let delta_t =
            3.0 * (g(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * inv_det.abs();
        trusted[i] = t > delta_t;
        h.t[i] = t;
        h.u[i] = e[1][i] * inv_det;
        h.v[i] = e[2][i] * inv_det;
    }
    let trusted = mask(trusted);
    h.hit = candidates & trusted & !zeros;
    h.check = zeros | (candidates & !trusted);
    h
}
// ANCHOR_END: leaf8

impl Bvh8 {
    /// Builds the tree over `tris` (`None` for an empty list): the same
    /// binary tree as the readable engine's, collapsed eight-wide. Its
    /// queries use `level`'s instructions, or the portable path if this
    /// CPU lacks them.
    pub fn build(tris: &[[Vec3; 3]], level: Level) -> Option<Bvh8> {
        if tris.is_empty() {
            return None;
        }
        let params = BvhBuildParams {
            max_prims_per_leaf: 1,
            ..BvhBuildParams::medium_build()
        };
        let bvh2 = build_guarded(&padded_boxes(tris), params);
        let mut counts = vec![0u32; bvh2.nodes.len()];
        count(&bvh2, 0, &mut counts);
        let mut b = Bvh8 {
            nodes: Vec::new(),
            leaves: Vec::new(),
            root: 0,
            levels: 0,
            tris: Vec::new(),
            original: Vec::new(),
            level: if level.available() {
                level
            } else {
                Level::Portable
            },
        };
        b.root = b.collapse(&bvh2, &counts, 0, tris, 1);
        Some(b)
    }

    /// Inner-node levels on the longest path.
    pub fn levels(&self) -> usize {
        self.levels
    }

    /// The vector instructions its queries use.
    pub fn level(&self) -> Level {
        self.level
    }

    /// Entries a traversal stack needs.
    pub fn stack_size(&self) -> usize {
        (W - 1) * self.levels + 1
    }

    fn collapse(
        &mut self,
        bvh2: &Bvh2,
        counts: &[u32],
        n: usize,
        tris: &[[Vec3; 3]],
        level: usize,
    ) -> u32 {
        if counts[n] as usize <= LEAF_SIZE {
            return self.leaf(bvh2, n, tris);
        }
        self.levels = self.levels.max(level);
        let first = bvh2.nodes[n].first_index as usize;
        let mut children = vec![first, first + 1];
        while children.len() < W {
            let open = children
                .iter()
                .enumerate()
                .filter(|(_, &c)| counts[c] as usize > LEAF_SIZE)
                .max_by(|a, b| {
                    let area = |c: usize| bvh2.nodes[c].aabb.half_area();
                    area(*a.1).total_cmp(&area(*b.1))
                });
            let Some((i, &c)) = open else { break };
            let first = bvh2.nodes[c].first_index as usize;
            children[i] = first;
            children.push(first + 1);
        }
        let index = self.nodes.len();
        self.nodes.push(Node8 {
            min: [[f32::INFINITY; W]; 3],
            max: [[f32::NEG_INFINITY; W]; 3],
            child: [u32::MAX; W],
        });
        for (lane, &c) in children.iter().enumerate() {
            let b = bvh2.nodes[c].aabb;
            let child = self.collapse(bvh2, counts, c, tris, level + 1);
            let node = &mut self.nodes[index];
            node.child[lane] = child;
            for axis in 0..3 {
                node.min[axis][lane] = b.min[axis];
                node.max[axis][lane] = b.max[axis];
            }
        }
        index as u32
    }

    fn leaf(&mut self, bvh2: &Bvh2, n: usize, tris: &[[Vec3; 3]]) -> u32 {
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
        let mut leaf = Leaf8 {
            p: [[[f32::NAN; W]; 3]; 3],
        };
        for lane in 0..W {
            let id = ids.get(lane).copied();
            let tri = id.map(|i| SoaTriangle::new(tris[i as usize]));
            self.tris.push(tri.unwrap_or(SoaTriangle {
                rows: [glam::Vec3A::NAN; 3],
            }));
            self.original.push(id.unwrap_or(u32::MAX));
            let Some(tri) = tri else { continue };
            if tri.rows.iter().all(|r| r.x == r.y && r.y == r.z) {
                continue; // zero area: stays NaN
            }
            for axis in 0..3 {
                let r = tri.rows[axis].to_array();
                for vertex in 0..3 {
                    leaf.p[axis][vertex][lane] = r[vertex];
                }
            }
        }
        self.leaves.push(leaf);
        (self.leaves.len() - 1) as u32 | LEAF
    }

    /// The closest hit in (0, t_max), `stack` holding at least
    /// [`Bvh8::stack_size`] entries.
    #[inline(always)]
    pub(super) fn closest_with<K: Kernel>(
        &self,
        r: &RayData,
        t_max: f32,
        stack: &mut [(u32, f32)],
    ) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut t_best = t_max;
        let mut depth = 0;
        let mut at = self.root;
        loop {
            if at & LEAF == 0 {
                let node = &self.nodes[at as usize];
                let (mut entered, t_near) = K::enter(r, node, t_best);
                if entered != 0 {
                    let mut order = [(0u32, 0f32); W];
                    let mut count = 0;
                    while entered != 0 {
                        let lane = entered.trailing_zeros() as usize;
                        entered &= entered - 1;
                        let item = (node.child[lane], t_near[lane]);
                        let mut i = count;
                        while i > 0 && order[i - 1].1 < item.1 {
                            order[i] = order[i - 1];
                            i -= 1;
                        }
                        order[i] = item;
                        count += 1;
                    }
                    for &item in &order[..count - 1] {
                        stack[depth] = item;
                        depth += 1;
                    }
                    at = order[count - 1].0;
                    continue;
                }
            } else {
                let l = (at & !LEAF) as usize;
                if let Some((hit, lane)) = self.leaf_closest::<K>(r, l, t_best) {
                    t_best = hit.t;
                    best = Some(Hit {
                        triangle: self.original[l * W + lane],
                        ..hit
                    });
                }
            }
            loop {
                if depth == 0 {
                    return best;
                }
                depth -= 1;
                let (next, t_near) = stack[depth];
                if t_near <= t_best {
                    at = next;
                    break;
                }
            }
        }
    }

    #[inline(always)]
    fn leaf_closest<K: Kernel>(&self, r: &RayData, l: usize, t_max: f32) -> Option<(Hit, usize)> {
        let h = K::leaf(r, &self.leaves[l], t_max);
        let mut best: Option<(Hit, usize)> = None;
        let mut hits = h.hit;
        while hits != 0 {
            let lane = hits.trailing_zeros() as usize;
            hits &= hits - 1;
            if best.is_none_or(|(b, _)| h.t[lane] <= b.t) {
                let hit = Hit {
                    t: h.t[lane],
                    u: h.u[lane],
                    v: h.v[lane],
                    triangle: 0,
                };
                best = Some((hit, lane));
            }
        }
        if h.check != 0 {
            best = self.closest_checked(r, l, h.check, t_max, best);
        }
        best
    }

    #[cold]
    #[inline(never)]
    fn closest_checked(
        &self,
        r: &RayData,
        l: usize,
        mut check: u32,
        t_max: f32,
        mut best: Option<(Hit, usize)>,
    ) -> Option<(Hit, usize)> {
        while check != 0 {
            let lane = check.trailing_zeros() as usize;
            check &= check - 1;
            let t_best = best.map_or(t_max, |(b, _)| b.t);
            if let Some(hit) = r.wt.intersect(&self.tris[l * W + lane], 0.0, t_best) {
                best = Some((hit, lane));
            }
        }
        best
    }

    /// Whether anything is hit in (0, t_max).
    #[inline(always)]
    pub(super) fn occluded_with<K: Kernel>(
        &self,
        r: &RayData,
        t_max: f32,
        stack: &mut [(u32, f32)],
    ) -> bool {
        let mut depth = 0;
        let mut at = self.root;
        loop {
            if at & LEAF == 0 {
                let node = &self.nodes[at as usize];
                let (mut entered, _) = K::enter(r, node, t_max);
                while entered != 0 {
                    let lane = entered.trailing_zeros() as usize;
                    entered &= entered - 1;
                    stack[depth] = (node.child[lane], 0.0);
                    depth += 1;
                }
            } else {
                let l = (at & !LEAF) as usize;
                let h = K::leaf(r, &self.leaves[l], t_max);
                if h.hit != 0 || (h.check != 0 && self.any_checked(r, l, h.check, t_max)) {
                    return true;
                }
            }
            if depth == 0 {
                return false;
            }
            depth -= 1;
            at = stack[depth].0;
        }
    }

    #[cold]
    #[inline(never)]
    fn any_checked(&self, r: &RayData, l: usize, mut check: u32, t_max: f32) -> bool {
        while check != 0 {
            let lane = check.trailing_zeros() as usize;
            check &= check - 1;
            if r.wt
                .intersect(&self.tris[l * W + lane], 0.0, t_max)
                .is_some()
            {
                return true;
            }
        }
        false
    }
}

impl RayQueries for Bvh8 {
    fn closest(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        simd::closest(self.level, self, ray, t_max)
    }
    fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        simd::occluded(self.level, self, ray, t_max)
    }
    fn describe(&self) -> String {
        format!(
            "the fast engine's BVH, 8 wide ({} nodes, {} leaves; {} instructions)",
            self.nodes.len(),
            self.leaves.len(),
            self.level.name()
        )
    }
}

/// Fills `counts[n]` with the number of triangles under binary node `n`.
fn count(bvh2: &Bvh2, n: usize, counts: &mut [u32]) -> u32 {
    let node = &bvh2.nodes[n];
    counts[n] = if node.is_leaf() {
        node.prim_count
    } else {
        let first = node.first_index as usize;
        count(bvh2, first, counts) + count(bvh2, first + 1, counts)
    };
    counts[n]
}
