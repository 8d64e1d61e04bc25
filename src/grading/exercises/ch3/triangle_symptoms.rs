//! What the checks of exercises 3.1 to 3.3 (the ray and the plane, the
//! point in the triangle, Möller–Trumbore) name when a candidate fails.

use crate::exercise::Symptom;

/// t = (Nᵀo - c) / Nᵀd: the right size, the wrong sign.
pub const PLANE_SIGN: Symptom = Symptom {
    name: "t with the wrong sign",
};
/// A hit reported for a ray parallel to the plane or triangle.
pub const PARALLEL: Symptom = Symptom {
    name: "parallel ray",
};
/// (v, u) for (u, v).
pub const SWAPPED_UV: Symptom = Symptom {
    name: "u and v swapped",
};
/// A point on an edge or a vertex counted as outside.
pub const EDGES_OUTSIDE: Symptom = Symptom {
    name: "edges left out",
};
/// Something returned for a triangle with no area.
pub const DEGENERATE: Symptom = Symptom {
    name: "degenerate triangle",
};
/// A hit at t ≤ 0.
pub const BEHIND: Symptom = Symptom {
    name: "hit behind the origin",
};
/// t for the unit direction, not for the d given.
pub const UNIT_T: Symptom = Symptom {
    name: "t for a unit direction",
};
