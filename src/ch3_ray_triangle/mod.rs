//! Chapter 3: ray-triangle intersection and a BVH. Rasterization asks, for
//! each triangle, which pixels it covers; ray tracing turns the question
//! round: for each pixel, which triangle is seen first along its ray?
//!
//! | slide | file |
//! |---|---|
//! | the ray equation r(t) = o + t d | [`ray`] |
//! | ray-plane, then ray-triangle: solve for u, v, t (Möller-Trumbore), and the watertight test | [`triangle`] |
//! | the same watertight test, rearranged for speed | [`watertight_fast`] |
//! | the watertight test's bound on the rounding error of t, once for every lane width | [`rounding`] |
//! | ray-mesh intersection: the naive loop over every triangle, and the bounding volume hierarchy of the `obvhs` crate | [`obvhs_bvh`] |
//! | the hierarchical approach, written to be read: a median-split BVH and its front-to-back traversal | [`readable_bvh`] |
//! | building the binary BVH top-down by SAH, O(n log n) on any triangles | [`bvh_robust`] |
//! | the surface area heuristic, written to be read: one node's split by a full sweep, and the readable tree built with it | [`sah`] |
//! | the BVH in the four-wide layout the shading chapters trace, and the collapse it shares with chapter 6's eight-wide one | [`wide_bvh`], [`wide_build`] |
//! | what is traced and what a first hit shows (depth, normal, barycentrics) | [`geometry`], [`render`] |
//! | leaving a surface without hitting it again | [`spawn`] |
//! | rays aimed at edges and vertices: do they slip through? | [`leaks`] |
//! | "which triangle is seen?" answered by rasterization and by rays alike | [`agreement`] |
//! | the chapter as a stage (views, passes) | [`stage`] |
//! | what the chapter prints | [`report`] |
//! | error against run time: anti-aliasing, naive loop against the BVH | [`studies`] |
//! | stiff cases: parallel rays, edges and vertices, far and tiny triangles | [`stability`] |
//! | the speed benchmark (`ch3 --bench`) | [`bench`](mod@bench) |
//! | tree builds on hostile geometry (`ch3 --bench hostile`) | [`hostile`] |

#![forbid(unsafe_code)]

pub mod agreement;
pub mod bench;
pub mod bvh_robust;
pub mod geometry;
pub mod hostile;
pub mod leaks;
pub mod obvhs_bvh;
pub mod ray;
pub mod readable_bvh;
pub mod render;
pub mod report;
pub mod rounding;
pub mod sah;
pub mod spawn;
pub mod stability;
pub mod stage;
pub mod studies;
pub mod triangle;
pub mod watertight_fast;
pub mod wide_build;
pub mod wide_bvh;
