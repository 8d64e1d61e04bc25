//! Chapter 2: rasterization. For each triangle, which pixels are covered?
//!
//! The stage follows the lecture's rasterization pipeline, one file per
//! step:
//!
//! | slide | file |
//! |---|---|
//! | edge functions, the top-left rule, barycentrics | [`edge`] |
//! | near-plane and guard-band clipping | [`clip`] |
//! | triangle setup: transform, clip, project, snap, cull | [`setup`] |
//! | coverage and the parallel band loop | [`coverage`] |
//! | visibility: the depth buffer | [`depth`] |
//! | attribute interpolation, perspective-correct and affine | [`interpolate`] |
//! | texture coordinates on a checkered floor, both ways and ray cast | [`checker`] |
//! | the views | [`views`] |
//! | exact coverage, the anti-aliasing reference | [`exact`] |
//! | one triangle start to finish, readable (exercise 2.4) | [`triangle`] |
//! | the whole pipeline for one frame: setup, coverage, depth, resolve | [`frame`] |
//! | the manifold and boundary checks of a mesh | [`mesh_check`] |
//! | the chapter boundary | [`stage`] |
//! | what the chapter prints | [`report`] |
//! | the report's studies | [`studies`] |
//! | stiff cases: slivers, shared edges, the near plane, z-fighting, huge coordinates | [`stability`] |
//! | the speed benchmark (`ch2 --bench`) | [`bench`](mod@bench) |

#![forbid(unsafe_code)]

pub mod bench;
pub mod checker;
pub mod clip;
pub mod coverage;
pub mod depth;
pub mod edge;
pub mod exact;
pub mod frame;
pub mod interpolate;
pub mod mesh_check;
pub mod report;
pub mod setup;
pub mod stability;
pub mod stage;
pub mod studies;
pub mod triangle;
pub mod views;
