//! What the four-wide tree ([`super::wide_bvh`]) and chapter 6's
//! eight-wide one share: collapsing chapter 3's binary tree into a wide one
//! (which binary nodes become a wide node's children, which triangles a
//! leaf holds), and the steps of a query that do not depend on the width
//! (the order children are visited in, the nearest hit of a leaf, the rare
//! lanes the one-triangle test decides), and the two queries themselves,
//! written once over `WideTree` for every width, instruction set and
//! group of rays.

use obvhs::bvh2::Bvh2;

use crate::ch3_ray_triangle::triangle::Hit;
use crate::ch3_ray_triangle::watertight_fast::{SoaTriangle, WatertightRay};

/// A child reference with this bit set is a leaf (the rest of the bits
/// index the tree's leaves); otherwise it indexes its inner nodes.
pub const LEAF: u32 = 1 << 31;

/// What both queries ask of a wide tree of `N` children per node and `N`
/// triangles per leaf: the four-wide tree ([`super::wide_bvh`]), the fast
/// engine's eight-wide one, that one with its vector kernels, and that one
/// for eight camera rays at once, each with its own slab test.
pub trait WideTree<const N: usize> {
    /// The ray, as this tree's tests take it (computed once per query).
    type Ray<'r>;
    /// The root's reference.
    fn root(&self) -> u32;
    /// The slab test at inner node `node`: the children the ray enters in
    /// (0, t_max) as a bit mask, where it enters each, and the children.
    fn enter(&self, r: &Self::Ray<'_>, node: usize, t_max: f32) -> (u32, [f32; N], &[u32; N]);
}

/// What the closest-hit query asks of a leaf.
pub trait ClosestHit<const N: usize>: WideTree<N> {
    /// The nearest hits found so far: one ray's ([`Nearest`]), or each of
    /// a group of rays'.
    type Found: Found;
    /// Keeps in `found` any hit of leaf `leaf` nearer than what it holds.
    fn leaf_closest(&self, r: &Self::Ray<'_>, leaf: usize, found: &mut Self::Found);
}

/// What the shadow query asks of a leaf.
pub trait AnyHit<const N: usize>: WideTree<N> {
    /// Whether any of leaf `leaf`'s triangles is hit in (0, t_max).
    fn leaf_any(&self, r: &Self::Ray<'_>, leaf: usize, t_max: f32) -> bool;
}

/// The hits a closest-hit query has found so far.
pub trait Found {
    /// How far a box may start and still hold a nearer hit: the nearest
    /// hit's t (for a group of rays, the farthest of theirs).
    fn reach(&self) -> f32;
}

/// One ray's nearest hit so far, and where the search ends.
#[derive(Clone, Copy, Debug)]
pub struct Nearest {
    /// The nearest hit (its triangle indexes the build list).
    pub hit: Option<Hit>,
    /// Its t, or the query's t_max while there is none.
    pub t: f32,
}

impl Nearest {
    /// Nothing found yet, in (0, t_max).
    #[inline(always)]
    pub fn new(t_max: f32) -> Nearest {
        Nearest {
            hit: None,
            t: t_max,
        }
    }

    /// Keeps a leaf's nearest hit and its lane (`None`: the leaf has no
    /// nearer one), with `original`, the build-list index of a lane's
    /// triangle.
    #[inline(always)]
    pub fn keep(&mut self, leaf_hit: Option<(Hit, usize)>, original: impl Fn(usize) -> u32) {
        if let Some((hit, lane)) = leaf_hit {
            self.t = hit.t;
            self.hit = Some(Hit {
                triangle: original(lane),
                ..hit
            });
        }
    }
}

impl Found for Nearest {
    #[inline(always)]
    fn reach(&self) -> f32 {
        self.t
    }
}

// ANCHOR: wide_closest
/// The closest hits, into `found`: the entered children nearest first,
/// skipping every subtree whose box starts beyond the nearest hit so far.
/// `stack` holds the subtrees still to visit (deep enough for the tree).
#[inline(always)]
pub fn closest<const N: usize, T: ClosestHit<N>>(
    tree: &T,
    r: &T::Ray<'_>,
    found: &mut T::Found,
    stack: &mut [(u32, f32)],
) {
    let mut depth = 0;
    let mut at = tree.root();
    loop {
        if at & LEAF == 0 {
            let (entered, t_near, child) = tree.enter(r, at as usize, found.reach());
            if entered != 0 {
                at = nearest_child_next(entered, child, &t_near, stack, &mut depth);
                continue;
            }
        } else {
            tree.leaf_closest(r, (at & !LEAF) as usize, found);
        }
        match pop_nearer(stack, &mut depth, found.reach()) {
            Some(next) => at = next,
            None => return,
        }
    }
}
// ANCHOR_END: wide_closest

/// Whether anything is hit in (0, t_max): stops at the first hit, in no
/// particular order.
#[inline(always)]
pub fn occluded<const N: usize, T: AnyHit<N>>(
    tree: &T,
    r: &T::Ray<'_>,
    t_max: f32,
    stack: &mut [(u32, f32)],
) -> bool {
    let mut depth = 0;
    let mut at = tree.root();
    loop {
        if at & LEAF == 0 {
            let (entered, _, child) = tree.enter(r, at as usize, t_max);
            if let Some(next) = push_entered(entered, child, stack, &mut depth) {
                at = next;
                continue;
            }
        } else if tree.leaf_any(r, (at & !LEAF) as usize, t_max) {
            return true;
        }
        if depth == 0 {
            return false;
        }
        depth -= 1;
        at = stack[depth].0;
    }
}

// ANCHOR: open_children
/// The children of a wide node made from binary node `n`: its two binary
/// children, then, while there are fewer than `width`, the one of largest
/// surface area that holds more than `leaf_size` triangles replaced by its
/// own two children.
pub fn open_children(
    bvh2: &Bvh2,
    counts: &[u32],
    n: usize,
    width: usize,
    leaf_size: usize,
) -> Vec<usize> {
    let first = bvh2.nodes[n].first_index as usize;
    let mut children = vec![first, first + 1];
    while children.len() < width {
        let open = children
            .iter()
            .enumerate()
            .filter(|(_, &c)| counts[c] as usize > leaf_size)
            .max_by(|a, b| {
                let area = |c: usize| bvh2.nodes[c].aabb.half_area();
                area(*a.1).total_cmp(&area(*b.1))
            });
        let Some((i, &c)) = open else { break };
        let first = bvh2.nodes[c].first_index as usize;
        children[i] = first;
        children.push(first + 1);
    }
    children
}
// ANCHOR_END: open_children

/// The triangles (build-list indices) under binary node `n`, left to right.
pub fn triangles_under(bvh2: &Bvh2, n: usize) -> Vec<u32> {
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
    ids
}

/// Fills `counts[n]` with the number of triangles under binary node `n`.
pub fn count_triangles(bvh2: &Bvh2, n: usize, counts: &mut [u32]) -> u32 {
    let node = &bvh2.nodes[n];
    counts[n] = if node.is_leaf() {
        node.prim_count
    } else {
        let first = node.first_index as usize;
        count_triangles(bvh2, first, counts) + count_triangles(bvh2, first + 1, counts)
    };
    counts[n]
}

/// Traversal steps the two wide trees share.
///
/// A closest-hit query at a node: `entered` marks the children the ray
/// enters, `t_near` where it enters each. Visit the nearest child next
/// (returned); stack the others farthest first, so they come off nearest
/// first.
#[inline(always)]
pub fn nearest_child_next<const N: usize>(
    mut entered: u32,
    child: &[u32; N],
    t_near: &[f32; N],
    stack: &mut [(u32, f32)],
    depth: &mut usize,
) -> u32 {
    // One or two children entered (most nodes a ray in a room visits):
    // the order the sort below gives, without its buffer. Of two at the
    // same distance the later lane goes first, as there.
    let first = entered.trailing_zeros() as usize;
    let rest = entered & (entered - 1);
    if rest == 0 {
        return child[first];
    }
    if rest & (rest - 1) == 0 {
        let second = rest.trailing_zeros() as usize;
        let (near, far) = match t_near[first] < t_near[second] {
            true => (first, second),
            false => (second, first),
        };
        stack[*depth] = (child[far], t_near[far]);
        *depth += 1;
        return child[near];
    }
    let mut order = [(0u32, 0f32); N];
    let mut count = 0;
    while entered != 0 {
        let lane = entered.trailing_zeros() as usize;
        entered &= entered - 1;
        let item = (child[lane], t_near[lane]);
        let mut i = count;
        while i > 0 && order[i - 1].1 < item.1 {
            order[i] = order[i - 1];
            i -= 1;
        }
        order[i] = item;
        count += 1;
    }
    for &item in &order[..count - 1] {
        stack[*depth] = item;
        *depth += 1;
    }
    order[count - 1].0
}

/// A shadow ray at a node: of the entered children (mask `entered`), the
/// last in lane order is returned, to visit next (`None`: none entered),
/// and the others are pushed on `stack` in lane order. A shadow ray needs
/// any hit, not the nearest, so the order is free. (It is the order of
/// pushing them all and popping one; the one visited next just does not
/// go through memory, where reading it back at once waited on the store.)
#[inline(always)]
pub fn push_entered<const N: usize>(
    entered: u32,
    child: &[u32; N],
    stack: &mut [(u32, f32)],
    depth: &mut usize,
) -> Option<u32> {
    if entered == 0 {
        return None;
    }
    let last = 31 - entered.leading_zeros();
    let mut rest = entered & !(1 << last);
    while rest != 0 {
        let lane = rest.trailing_zeros() as usize;
        rest &= rest - 1;
        stack[*depth] = (child[lane], 0.0);
        *depth += 1;
    }
    Some(child[last as usize])
}

/// Pops `stack` down to the next subtree that can still hold a hit nearer
/// than `t_best` (one whose box the ray enters no farther than that): its
/// node, or `None` when none is left. The readable tree's `closest` spells
/// this loop out; the fast engine's traversals share it.
#[inline(always)]
pub fn pop_nearer(stack: &[(u32, f32)], depth: &mut usize, t_best: f32) -> Option<u32> {
    while *depth > 0 {
        *depth -= 1;
        let (next, t_near) = stack[*depth];
        if t_near <= t_best {
            return Some(next);
        }
    }
    None
}

/// The nearest of a leaf's hit lanes (`hits`, with their t, u and v) and
/// its lane; `Hit::triangle` is left 0. A later lane wins a tie.
#[inline(always)]
pub fn nearest_lane(mut hits: u32, t: &[f32], u: &[f32], v: &[f32]) -> Option<(Hit, usize)> {
    let mut best: Option<(Hit, usize)> = None;
    while hits != 0 {
        let lane = hits.trailing_zeros() as usize;
        hits &= hits - 1;
        if best.is_none_or(|(b, _)| t[lane] <= b.t) {
            let hit = Hit {
                t: t[lane],
                u: u[lane],
                v: v[lane],
                triangle: 0,
            };
            best = Some((hit, lane));
        }
    }
    best
}

/// The rare lanes `check` of a leaf (its triangles one by one in `tris`)
/// that the one-triangle test must decide, against the nearest hit so far.
/// Kept out of line, so the common path's registers are not spent on the
/// f64 tie-breakers.
#[cold]
#[inline(never)]
pub fn nearest_checked(
    wr: &WatertightRay,
    tris: &[SoaTriangle],
    mut check: u32,
    t_max: f32,
    mut best: Option<(Hit, usize)>,
) -> Option<(Hit, usize)> {
    while check != 0 {
        let lane = check.trailing_zeros() as usize;
        check &= check - 1;
        let t_best = best.map_or(t_max, |(b, _)| b.t);
        if let Some(hit) = wr.intersect(&tris[lane], 0.0, t_best) {
            best = Some((hit, lane));
        }
    }
    best
}

/// Whether any of the rare lanes `check` of a leaf (its triangles in
/// `tris`) is hit in (0, t_max), by the one-triangle test (out of line,
/// as above).
#[cold]
#[inline(never)]
pub fn any_checked(wr: &WatertightRay, tris: &[SoaTriangle], mut check: u32, t_max: f32) -> bool {
    while check != 0 {
        let lane = check.trailing_zeros() as usize;
        check &= check - 1;
        if wr.intersect(&tris[lane], 0.0, t_max).is_some() {
            return true;
        }
    }
    false
}
