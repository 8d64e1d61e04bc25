//! Chapter 5: the reflection equation. How much light leaves a surface
//! point towards the eye? The integral over incoming directions of
//! incident radiance × BRDF × cos θ, estimated by Monte Carlo.
//!
//! | slide | file |
//! |---|---|
//! | radiometry: flux, irradiance, Lambert's law, solid angle, radiance | [`radiometry`] |
//! | types of light: directional, point, spot, area | [`light`] |
//! | the BRDF: ideal diffuse, glossy, perfect mirror | [`material`] |
//! | turning uniform numbers into directions, with their densities | [`warp`], checked by [`warp_test`] |
//! | the reflection equation, estimated at one point (uniform, BSDF and light sampling, MIS) | [`direct`] |
//! | what the estimator tells a listener: its counts and each term it adds | [`shading_events`] |
//! | several strategies at once: multiple importance sampling | [`mis`] |
//! | the scene the shading chapters see: one intersect, one shadow ray | [`world`] |
//! | one image: camera rays, each shaded by the reflection equation | [`render`] |
//! | what the scene decides first: can anything cast a shadow? | [`shadowing`] |
//! | one pixel's sample, light by light, heard through the estimator's notes (the inspect mode's story) | [`light_terms`] |
//! | the chapter as a stage | [`stage`] |
//! | names of surfaces and lights for tables and panels | [`names`] |
//! | what the chapter prints | [`report`] |
//! | error against run time for the four strategies | [`studies`], drawn by [`crate::core::plot`] |
//! | stiff cases: grazing light, tiny bright lights, mirror-like lobes | [`stability`], [`stiff_scenes`] |

#![forbid(unsafe_code)]

pub mod direct;
pub mod light;
pub mod light_terms;
pub mod material;
pub mod mis;
pub mod names;
pub mod radiometry;
pub mod render;
pub mod report;
pub mod shading_events;
pub mod shadowing;
pub mod stability;
pub mod stage;
pub mod stiff_scenes;
pub mod studies;
pub mod warp;
pub mod warp_test;
pub mod world;
