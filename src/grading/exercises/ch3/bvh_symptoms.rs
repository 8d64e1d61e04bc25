//! What can go wrong in exercise 3.4, each with its hint.

use crate::grading::exercise::Symptom;

/// The section that teaches the traversal.
macro_rules! bvh_book {
    () => {
        "book \"A BVH you can read\""
    };
}

/// Panics (an index out of bounds) on a tree with no nodes.
pub const EMPTY_TREE: Symptom = Symptom {
    name: "misses an empty tree",
    hint: concat!(
        bvh_book!(),
        ": a tree built over no triangles has no nodes at all, not even a root; \
         check bvh.nodes before you read nodes[0], and return None."
    ),
};
/// Returns a hit at or beyond t_max.
pub const IGNORES_T_MAX: Symptom = Symptom {
    name: "ignores t_max",
    hint: concat!(
        bvh_book!(),
        ": the search interval starts as (0, t_max), not (0, ∞); the best t \
         starts at t_max, and a hit beyond it is no hit."
    ),
};
/// The right t, the wrong triangle.
pub const WRONG_TRIANGLE: Symptom = Symptom {
    name: "wrong triangle id",
    hint: concat!(
        bvh_book!(),
        ": intersect_watertight leaves Hit::triangle at 0; set it to the \
         triangle's index in bvh.tris, which is bvh.order[i] for a leaf's \
         slot i, not i itself."
    ),
};
/// Returns a hit behind the closest one.
pub const NOT_CLOSEST: Symptom = Symptom {
    name: "not the closest hit",
    hint: concat!(
        bvh_book!(),
        ": boxes overlap, so the first leaf that hits need not hold the \
         closest triangle; keep going until every box left starts beyond \
         the best t, and skip only those."
    ),
};
/// Returns nothing where a triangle is hit.
pub const MISSED_HIT: Symptom = Symptom {
    name: "misses a hit",
    hint: concat!(
        bvh_book!(),
        ": something that holds the hit was never tested; open both children \
         of an inner node, test all `count` triangles of a leaf \
         (bvh.order[first .. first + count]), and skip a box only when the \
         ray does not enter it before the best t."
    ),
};
/// Calls intersect_watertight on (nearly) every triangle.
pub const EVERY_TRIANGLE: Symptom = Symptom {
    name: "tests every triangle",
    hint: concat!(
        bvh_book!(),
        ": the answer is right, but a loop over every triangle is the naive \
         loop the BVH is there to avoid; walk the tree and test only the \
         triangles of the leaves the ray reaches."
    ),
};
/// Opens boxes beyond the best hit.
pub const NO_PRUNING: Symptom = Symptom {
    name: "no pruning",
    hint: concat!(
        bvh_book!(),
        ": the answer is right, but the traversal opens boxes that start \
         beyond the best hit so far; test child boxes against the best t \
         (not t_max) and skip a stacked node whose entry distance is beyond \
         it."
    ),
};
/// Visits the farther child first.
pub const FAR_FIRST: Symptom = Symptom {
    name: "far child first",
    hint: concat!(
        bvh_book!(),
        ": the answer is right, but it is found back to front (or in a fixed \
         order), each nearer hit replacing a farther one; of two children, \
         visit first the one whose box the ray enters first (on a stack: \
         push the farther one first, so the nearer is popped next)."
    ),
};
/// Finds its hits without the counted building blocks.
pub const BYPASSES_BLOCKS: Symptom = Symptom {
    name: "bypasses the building blocks",
    hint: concat!(
        bvh_book!(),
        ": the grader counts the boxes and triangles a traversal tests \
         through Aabb::enter and intersect_watertight; test them with those \
         two, as the stub imports them."
    ),
};

/// Every symptom [`check_bvh_traversal`](super::check_bvh_traversal) names.
pub const SYMPTOMS: &[Symptom] = &[
    EMPTY_TREE,
    IGNORES_T_MAX,
    WRONG_TRIANGLE,
    NOT_CLOSEST,
    MISSED_HIT,
    EVERY_TRIANGLE,
    NO_PRUNING,
    FAR_FIRST,
    BYPASSES_BLOCKS,
];
