//! The eight-wide tree's ray queries written once over a vector type
//! ([`Vector`]): the slab test of a node's boxes and the watertight test
//! of a leaf's triangles, each lane in a register lane, with the
//! operations and order of the plain lane loops of [`super::lanes`] (so
//! every hit is the same bits).
//!
//! Two kinds of vector run them. The portable path (`portable.rs`) uses
//! the `wide` crate's `f32x8` and `f32x4`, which compile to SSE2 on
//! x86-64's baseline and to NEON on aarch64 (with a plain fallback
//! elsewhere); a node or leaf that uses only its first four lanes is
//! tested four wide there. [`super::simd`] runs the same code with AVX2's
//! eight-lane registers.
//!
//! [`Vector::max_over`] and [`Vector::min_over`] keep the old value
//! where the new one is not larger (or smaller): the rule of x86's vector
//! max and min and of the lane loops' `larger` and `smaller`. (NEON's
//! differ only where a lane is NaN, and no NaN reaches them where it
//! would change a hit.)

use std::ops::{Add, BitAnd, BitOr, BitXor, Div, Mul, Sub};

use super::bvh8::Bvh8;
use super::lanes::{Leaf8, Node8, RayData, FAR_STRETCH, W};
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::rounding::{t_error_bound, Lanes};
use crate::ch3_ray_triangle::triangle::Hit;
use crate::ch3_ray_triangle::wide_build::{self, AnyHit, ClosestHit, Nearest, WideTree};

/// A vector of `LANES` f32 lanes (4 or 8) and what the kernels ask of it.
/// A comparison gives a mask of the same type (every bit of a lane set
/// where it holds).
pub trait Vector:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + BitAnd<Output = Self>
    + BitOr<Output = Self>
    + BitXor<Output = Self>
{
    /// How many lanes.
    const LANES: usize;
    /// `x` in every lane.
    fn splat(x: f32) -> Self;
    /// The first `LANES` numbers of `a`.
    fn load(a: &[f32; W]) -> Self;
    /// `self` where it is larger than `old`, else `old`.
    fn max_over(self, old: Self) -> Self;
    /// `self` where it is smaller than `old`, else `old`.
    fn min_over(self, old: Self) -> Self;
    /// Where `self == o` (false where either is NaN, as the other three).
    fn eq(self, o: Self) -> Self;
    /// Where `self < o`.
    fn lt(self, o: Self) -> Self;
    /// Where `self > o`.
    fn gt(self, o: Self) -> Self;
    /// Where `self <= o`.
    fn le(self, o: Self) -> Self;
    /// `self` and not `m`, bit by bit.
    fn and_not(self, m: Self) -> Self;
    /// |x| lane by lane: the sign bit cleared.
    #[inline(always)]
    fn abs(self) -> Self {
        self.and_not(Self::splat(-0.0))
    }
    /// Bit i set where lane i's sign bit is (a mask's lane holds).
    fn mask(self) -> u32;
    /// The lanes, in the first `LANES` places of an eight.
    fn store(self) -> [f32; W];
    /// Lane `j`.
    fn lane(self, j: usize) -> f32;
    /// The lane of `hits` (a mask, at least one bit) with the smallest
    /// number, and of equal ones the last.
    fn smallest(self, hits: u32) -> usize;
}

/// The error bound's lane type over any [`Vector`] (the bound is written
/// once, over chapter 3's [`Lanes`]).
#[derive(Clone, Copy)]
struct Bound<V>(V);

impl<V: Vector> Add for Bound<V> {
    type Output = Bound<V>;
    #[inline(always)]
    fn add(self, o: Bound<V>) -> Bound<V> {
        Bound(self.0 + o.0)
    }
}

impl<V: Vector> Mul for Bound<V> {
    type Output = Bound<V>;
    #[inline(always)]
    fn mul(self, o: Bound<V>) -> Bound<V> {
        Bound(self.0 * o.0)
    }
}

impl<V: Vector> Lanes for Bound<V> {
    #[inline(always)]
    fn splat(x: f32) -> Bound<V> {
        Bound(V::splat(x))
    }
    #[inline(always)]
    fn abs(self) -> Bound<V> {
        Bound(self.0.abs())
    }
}

/// A ray's numbers as the tests use them, each in every lane: made once
/// per query, so the loop reads them from registers.
struct Splat<V> {
    /// Origin and 1/direction per axis, and whether the direction is
    /// negative (the slab test).
    o: [V; 3],
    inv: [V; 3],
    negative: [bool; 3],
    /// The watertight permutation, the permuted origin and the shear.
    k: [usize; 3],
    ko: [V; 3],
    s: [V; 3],
}

impl<V: Vector> Splat<V> {
    #[inline(always)]
    fn new(r: &RayData) -> Splat<V> {
        let three = |a: [f32; 3]| [V::splat(a[0]), V::splat(a[1]), V::splat(a[2])];
        Splat {
            o: three(r.o),
            inv: three(r.inv),
            negative: r.negative,
            k: r.k,
            ko: three(r.ko),
            s: three(r.s),
        }
    }
}

/// The slab test of a node's boxes against (0, t_max): the mask of
/// children entered and where the ray enters each.
// ANCHOR: enter
#[inline(always)]
fn enter<V: Vector>(r: &Splat<V>, node: &Node8, t_max: f32) -> (u32, [f32; W]) {
    let mut t_near = V::splat(0.0);
    let mut t_far = V::splat(t_max);
    for axis in 0..3 {
        let (near, far) = match r.negative[axis] {
            true => (&node.max[axis], &node.min[axis]),
            false => (&node.min[axis], &node.max[axis]),
        };
        let (o, inv) = (r.o[axis], r.inv[axis]);
        t_near = ((V::load(near) - o) * inv).max_over(t_near);
        t_far = ((V::load(far) - o) * inv).min_over(t_far);
    }
    let entered = t_near.le(t_far * V::splat(FAR_STRETCH));
    (entered.mask(), t_near.store())
}
// ANCHOR_END: enter

/// The first half of the leaf test: each triangle's corners in the ray's
/// frame (x, y and the sheared z), the edge functions, det and the scaled
/// t, and the masks of the lanes that can hit and of those with an edge
/// function exactly zero.
struct Front<V> {
    x: [V; 3],
    y: [V; 3],
    zs: [V; 3],
    e: [V; 3],
    det: V,
    ts: V,
    candidates: u32,
    zeros: u32,
}

#[inline(always)]
fn front<V: Vector>(r: &Splat<V>, leaf: &Leaf8, t_max: f32) -> Front<V> {
    let (px, py, pz) = (&leaf.p[r.k[0]], &leaf.p[r.k[1]], &leaf.p[r.k[2]]);
    let [ox, oy, oz] = r.ko;
    let [sx, sy, sz] = r.s;
    let zero = V::splat(0.0);
    let zj = |j: usize| V::load(&pz[j]) - oz;
    let z = [zj(0), zj(1), zj(2)];
    let xj = |j: usize| (V::load(&px[j]) - ox) + sx * z[j];
    let yj = |j: usize| (V::load(&py[j]) - oy) + sy * z[j];
    let (x, y) = ([xj(0), xj(1), xj(2)], [yj(0), yj(1), yj(2)]);
    let e0 = x[1] * y[2] - y[1] * x[2];
    let e1 = x[2] * y[0] - y[2] * x[0];
    let e2 = x[0] * y[1] - y[0] * x[1];
    let any_zero = e0.eq(zero) | e1.eq(zero) | e2.eq(zero);
    // Edge functions of both signs: no hit. Where one is not finite, det
    // is not either and `finite` below rejects the lane, so the minimum
    // and maximum answer as the lane loops' six comparisons do.
    let lowest = e0.min_over(e1).min_over(e2);
    let highest = e0.max_over(e1).max_over(e2);
    let mixed = lowest.lt(zero) & highest.gt(zero);
    let det = (e0 + e1) + e2;
    let zs = [z[0] * sz, z[1] * sz, z[2] * sz];
    let ts = (e0 * zs[0] + e1 * zs[1]) + e2 * zs[2];
    // The lane loops' two cases (det < 0 and det > 0) as one: with det's
    // sign taken off det and ts (exact), 0 < ts <= t_max det.
    let sign = det & V::splat(-0.0);
    let (abs_det, ts_pos) = (det ^ sign, ts ^ sign);
    let inside = (abs_det.gt(zero) & ts_pos.gt(zero)) & ts_pos.le(V::splat(t_max) * abs_det);
    let finite = abs_det.lt(V::splat(f32::INFINITY));
    let candidate = (finite & inside).and_not(mixed);
    Front {
        x,
        y,
        zs,
        e: [e0, e1, e2],
        det,
        ts,
        candidates: candidate.mask(),
        zeros: any_zero.mask(),
    }
}

/// The second half, for a leaf with candidates: t, 1/det, the candidates
/// pbrt-v4's error bound trusts (hits), and the lanes the one-triangle
/// test decides: `(t, inv_det, hit, check)`.
#[inline(always)]
fn trust<V: Vector>(f: &Front<V>) -> (V, V, u32, u32) {
    let max3 = |v: [V; 3]| Bound(v[2].abs().max_over(v[1].abs().max_over(v[0].abs())));
    let inv_det = V::splat(1.0) / f.det;
    let t = f.ts * inv_det;
    let Bound(delta_t) = t_error_bound(max3(f.x), max3(f.y), max3(f.zs), max3(f.e), Bound(inv_det));
    let trusted = t.gt(delta_t).mask();
    let (candidates, zeros) = (f.candidates, f.zeros);
    (
        t,
        inv_det,
        candidates & trusted & !zeros,
        zeros | (candidates & !trusted),
    )
}

/// The nearest of the lanes `hit` (at least one) and its lane.
#[inline(always)]
fn nearest<V: Vector>(t: V, inv_det: V, f: &Front<V>, hit: u32) -> (Hit, usize) {
    let lane = t.smallest(hit);
    let hit = Hit {
        t: t.lane(lane),
        u: (f.e[1] * inv_det).lane(lane),
        v: (f.e[2] * inv_det).lane(lane),
        triangle: 0,
    };
    (hit, lane)
}

/// The eight-wide tree with the kernels in vectors `V`, and `N` for nodes
/// and leaves that use only their first four lanes (where `N` is
/// narrower), for the queries written once ([`wide_build::closest`],
/// [`wide_build::occluded`]).
pub(super) struct Kernels<'a, V, N> {
    bvh: &'a Bvh8,
    _lanes: std::marker::PhantomData<(V, N)>,
}

/// A ray for [`Kernels`]: splatted for both widths, and as given, for the
/// rare lanes the one-triangle test decides.
pub(super) struct KernelRay<'r, V, N> {
    wide: Splat<V>,
    narrow: Splat<N>,
    ray: &'r Ray,
}

impl<'a, V: Vector, N: Vector> Kernels<'a, V, N> {
    #[inline(always)]
    fn new(bvh: &'a Bvh8) -> Self {
        Kernels {
            bvh,
            _lanes: std::marker::PhantomData,
        }
    }

    /// Whether `narrow` (a node's or leaf's flag) picks the narrow vectors.
    #[inline(always)]
    fn narrow(narrow: bool) -> bool {
        N::LANES < V::LANES && narrow
    }

    #[inline(always)]
    fn ray<'r>(ray: &'r Ray) -> KernelRay<'r, V, N> {
        let data = RayData::new(ray);
        KernelRay {
            wide: Splat::new(&data),
            narrow: Splat::new(&data),
            ray,
        }
    }

    /// Leaf `l`'s test in vectors `U`, for the closest hit.
    #[inline(always)]
    fn leaf_closest_in<U: Vector>(
        &self,
        s: &Splat<U>,
        ray: &Ray,
        l: usize,
        t: f32,
    ) -> Option<(Hit, usize)> {
        let f = front(s, &self.bvh.leaves[l], t);
        if f.candidates == 0 && f.zeros == 0 {
            return None;
        }
        let (t_hit, inv_det, hit, check) = trust(&f);
        let best = (hit != 0).then(|| nearest(t_hit, inv_det, &f, hit));
        match check {
            0 => best,
            // The rare lanes, by the one-triangle test.
            _ => self.bvh.leaf_checked(&RayData::new(ray), l, check, t, best),
        }
    }

    /// Leaf `l`'s test in vectors `U`, for the shadow query.
    #[inline(always)]
    fn leaf_any_in<U: Vector>(&self, s: &Splat<U>, ray: &Ray, l: usize, t_max: f32) -> bool {
        let f = front(s, &self.bvh.leaves[l], t_max);
        if f.candidates == 0 && f.zeros == 0 {
            return false;
        }
        let (_, _, hit, check) = trust(&f);
        hit != 0
            || (check != 0
                && self
                    .bvh
                    .leaf_any_checked(&RayData::new(ray), l, check, t_max))
    }
}

impl<V: Vector, N: Vector> WideTree<W> for Kernels<'_, V, N> {
    type Ray<'r> = KernelRay<'r, V, N>;

    #[inline(always)]
    fn root(&self) -> u32 {
        self.bvh.root
    }

    #[inline(always)]
    fn enter(&self, r: &KernelRay<V, N>, node: usize, t_max: f32) -> (u32, [f32; W], &[u32; W]) {
        let narrow = Self::narrow(self.bvh.narrow_node(node));
        let node = &self.bvh.nodes[node];
        let (entered, t_near) = match narrow {
            true => enter(&r.narrow, node, t_max),
            false => enter(&r.wide, node, t_max),
        };
        (entered, t_near, &node.child)
    }
}

impl<V: Vector, N: Vector> ClosestHit<W> for Kernels<'_, V, N> {
    type Found = Nearest;

    #[inline(always)]
    fn leaf_closest(&self, r: &KernelRay<V, N>, l: usize, found: &mut Nearest) {
        let leaf_hit = match Self::narrow(self.bvh.narrow_leaf(l)) {
            true => self.leaf_closest_in(&r.narrow, r.ray, l, found.t),
            false => self.leaf_closest_in(&r.wide, r.ray, l, found.t),
        };
        found.keep(leaf_hit, |lane| self.bvh.original[l * W + lane]);
    }
}

impl<V: Vector, N: Vector> AnyHit<W> for Kernels<'_, V, N> {
    #[inline(always)]
    fn leaf_any(&self, r: &KernelRay<V, N>, l: usize, t_max: f32) -> bool {
        match Self::narrow(self.bvh.narrow_leaf(l)) {
            true => self.leaf_any_in(&r.narrow, r.ray, l, t_max),
            false => self.leaf_any_in(&r.wide, r.ray, l, t_max),
        }
    }
}

/// The closest hit of `ray` in (0, t_max) with vectors `V` (and `N`),
/// `stack` holding at least [`Bvh8::stack_size`] entries.
#[inline(always)]
pub(super) fn closest<V: Vector, N: Vector>(
    bvh: &Bvh8,
    ray: &Ray,
    t_max: f32,
    stack: &mut [(u32, f32)],
) -> Option<Hit> {
    let mut found = Nearest::new(t_max);
    let r = Kernels::<V, N>::ray(ray);
    wide_build::closest(&Kernels::<V, N>::new(bvh), &r, &mut found, stack);
    found.hit
}

/// Whether anything is hit in (0, t_max), likewise.
#[inline(always)]
pub(super) fn occluded<V: Vector, N: Vector>(
    bvh: &Bvh8,
    ray: &Ray,
    t_max: f32,
    stack: &mut [(u32, f32)],
) -> bool {
    let r = Kernels::<V, N>::ray(ray);
    wide_build::occluded(&Kernels::<V, N>::new(bvh), &r, t_max, stack)
}
