//! Chapter 4: implicit surfaces and sphere tracing. A surface is the zero
//! level set of f: ℝ³ → ℝ; when f is a signed distance function
//! (‖∇f‖ = 1, the Eikonal equation) a ray may safely step forward by f.
//!
//! | slide | file |
//! |---|---|
//! | implicit shapes: level sets and signed distance functions | [`distance`] (the scene's description in [`crate::scene::sdf`]) |
//! | the primitive shapes, each an exact SDF | [`primitives`] |
//! | combining shapes (union, intersection, difference, smooth blends) | [`operators`] |
//! | the Eikonal equation ‖∇f‖ = 1, checked by sampling | [`eikonal`], [`bounds`] |
//! | marching a ray until f changes sign: sphere tracing and the fixed step | [`march`] |
//! | the normal is the gradient of f | [`normal`] |
//! | implicit and explicit in one scene: the nearest hit wins | [`hit`] |
//! | one ray per pixel, and the views | [`render`] |
//! | the chapter as a stage | [`stage`] |
//! | what the chapter prints | [`report`] |
//! | error against run time: sphere tracing, over-relaxed, fixed step | [`studies`] |
//! | stiff cases: grazing rays, thin shells, far objects, bounds that are not distances | [`stability`] |

#![forbid(unsafe_code)]

pub mod bounds;
pub mod distance;
pub mod eikonal;
pub mod hit;
pub mod march;
pub mod normal;
pub mod operators;
pub mod primitives;
pub mod render;
pub mod report;
pub mod stability;
pub mod stage;
pub mod studies;
