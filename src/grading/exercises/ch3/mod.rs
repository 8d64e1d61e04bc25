//! Chapter 3's exercises and how each is graded.

use crate::ch3_ray_triangle::triangle;
use crate::exercise::Exercise;

mod bvh;
mod bvh_cases;
mod bvh_deep;
mod bvh_symptoms;
mod inside_cases;
mod ray_plane;
pub mod sah;
mod sah_nodes;
mod triangle_checks;
mod triangle_edges;
mod triangle_symptoms;
pub use bvh::*;
pub use ray_plane::check_ray_plane;
pub use sah::{check_sah, SahFn};
pub use triangle_checks::*;
pub use triangle_symptoms::*;

/// Chapter 3's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 3,
            name: "ray_plane",
            file: "chapters/ch3-ray-triangle/exercises/ray_plane.rs",
            symptoms: &[PLANE_SIGN, PARALLEL],
            reference: || check_ray_plane(triangle::ray_plane),
        },
        Exercise {
            chapter: 3,
            name: "barycentric_inside",
            file: "chapters/ch3-ray-triangle/exercises/barycentric_inside.rs",
            symptoms: &[SWAPPED_UV, EDGES_OUTSIDE, DEGENERATE],
            reference: || check_barycentric_inside(triangle::barycentric_inside),
        },
        Exercise {
            chapter: 3,
            name: "moller_trumbore",
            file: "chapters/ch3-ray-triangle/exercises/moller_trumbore.rs",
            symptoms: &[UNIT_T, DEGENERATE, PARALLEL, BEHIND],
            reference: || check_moller_trumbore(reference_moller_trumbore),
        },
        Exercise {
            chapter: 3,
            name: "bvh_traversal",
            file: "chapters/ch3-ray-triangle/exercises/bvh_traversal.rs",
            symptoms: SYMPTOMS,
            reference: || check_bvh_traversal(crate::counted::closest_hit),
        },
        Exercise {
            chapter: 3,
            name: "sah",
            file: "chapters/ch3-ray-triangle/exercises/sah.rs",
            symptoms: &[
                sah::EMPTY_CHILD,
                sah::NEVER_LEAF,
                sah::ONE_AXIS,
                sah::COSTLY,
            ],
            reference: || check_sah(crate::ch3_ray_triangle::sah::sah_split),
        },
    ]
}
