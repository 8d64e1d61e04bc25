//! What can go wrong in exercise 3.4 (the hints are in chapters/hints.toml).

use crate::exercise::Symptom;

/// Panics (an index out of bounds) on a tree with no nodes.
pub const EMPTY_TREE: Symptom = Symptom {
    name: "misses an empty tree",
};
/// Returns a hit at or beyond t_max.
pub const IGNORES_T_MAX: Symptom = Symptom {
    name: "ignores t_max",
};
/// The right t, the wrong triangle.
pub const WRONG_TRIANGLE: Symptom = Symptom {
    name: "wrong triangle id",
};
/// Returns a hit behind the closest one.
pub const NOT_CLOSEST: Symptom = Symptom {
    name: "not the closest hit",
};
/// Returns nothing where a triangle is hit.
pub const MISSED_HIT: Symptom = Symptom {
    name: "misses a hit",
};
/// Calls intersect_watertight on (nearly) every triangle.
pub const EVERY_TRIANGLE: Symptom = Symptom {
    name: "tests every triangle",
};
/// Opens boxes beyond the best hit.
pub const NO_PRUNING: Symptom = Symptom { name: "no pruning" };
/// Visits the farther child first.
pub const FAR_FIRST: Symptom = Symptom {
    name: "far child first",
};
/// Finds its hits without the counted building blocks.
pub const BYPASSES_BLOCKS: Symptom = Symptom {
    name: "bypasses the building blocks",
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
