//! Chapter 6: global illumination. The rendering equation is the
//! reflection equation made recursive: the light arriving at a point is
//! itself light leaving other points. A path tracer estimates it bounce by
//! bounce.
//!
//! | slide | file |
//! |---|---|
//! | the rendering equation, one light path per sample, bounce by bounce | [`integrator`] |
//! | the simplest path tracer on its own: a uniform random walk | [`random_walk`](mod@random_walk) |
//! | how paths are traced: bounce limit, Russian roulette's start and scale | [`settings`] |
//! | where a path's light goes: one layer per bounce count | [`layers`] |
//! | one vertex of a path and the direction it goes on in | [`vertex`] |
//! | where a path's random numbers come from (independent, Sobol) | [`sampler`] |
//! | one path written down vertex by vertex, for a pixel one asks about | [`path_events`], [`path_record`] |
//! | direct, one-bounce, two-bounce … global illumination: the layers | [`accumulate`], [`figures`] |
//! | what traces a pass: the lesson's path loop, or the engine a front end chose | [`engine`] |
//! | the converged answer and the statistical image test | [`reference`](mod@reference), [`annotate`] |
//! | scenes whose answer is known (furnace, Cornell box) | [`scenes`] |
//! | the chapter as a stage | [`stage`] |
//! | what happened at this pixel: one path written down for the inspector | [`inspect`] |
//! | what the chapter prints | [`report`] |
//! | error against run time: every estimator with both samplers | [`studies`] |
//! | stiff cases: a bright furnace, a tiny light, total internal reflection | [`stability`] |

#![forbid(unsafe_code)]

pub mod accumulate;
pub mod annotate;
pub mod engine;
pub mod figures;
pub mod inspect;
pub mod integrator;
pub mod layers;
pub mod path_events;
pub mod path_record;
pub mod random_walk;
pub mod reference;
pub mod report;
pub mod sampler;
pub mod scenes;
pub mod settings;
pub mod stability;
pub mod stage;
pub mod studies;
pub mod vertex;
