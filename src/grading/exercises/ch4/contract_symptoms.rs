//! The symptoms the clauses of [`contract`](super::contract) name.

use crate::exercise::Symptom;

/// Evaluates the distance function past the budget.
pub const NO_BUDGET: Symptom = Symptom {
    name: "no step budget",
};
/// One evaluation too many or too few.
pub const BUDGET_OFF_BY_ONE: Symptom = Symptom {
    name: "budget off by one",
};
/// Marches on past max_distance.
pub const IGNORES_MAX_DISTANCE: Symptom = Symptom {
    name: "ignores max_distance",
};
/// Compares |f| with march.epsilon, not with march.epsilon_at(p).
pub const FIXED_EPSILON: Symptom = Symptom { name: "fixed ε" };
/// A normal that is not unit length.
pub const NOT_UNIT: Symptom = Symptom {
    name: "normal not unit length",
};
/// A normal pointing away from the viewer.
pub const NOT_FACING: Symptom = Symptom {
    name: "normal faces away",
};
/// NaN where the gradient is zero.
pub const ZERO_GRADIENT: Symptom = Symptom {
    name: "zero gradient",
};
/// A point inside the surface (f ≤ -ε) taken for a hit: f < ε, not |f| < ε.
pub const INSIDE_HIT: Symptom = Symptom {
    name: "inside taken for a hit",
};
