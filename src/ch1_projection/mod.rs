//! Chapter 1: projection. Where does a point of the world land in the
//! picture? Through a pinhole at the origin onto the image plane z = -1.
//!
//! | slide | file |
//! |---|---|
//! | the pinhole camera: u = x/-z, v = y/-z | [`camera`] ([`camera::project_pinhole`]) |
//! | placing the camera: look-at, field of view, viewport | [`camera`] |
//! | vertices and triangles: the tetrahedron table | [`crate::scene::mesh`] |
//! | drawing edges; what lies behind the camera (near-plane clipping) | [`wireframe`] |
//! | farther is smaller; parallel lines meet at infinity | [`perspective`] |
//! | the chapter as a stage (views, passes) | [`stage`] |
//! | what the chapter prints | [`report`] |
//! | error against run time: f32 projection vs exact pixels | [`studies`] |
//! | stiff cases: behind the camera, fov near 0° and 180°, far coordinates | [`stability`] |

#![forbid(unsafe_code)]

pub mod camera;
pub mod perspective;
pub mod report;
pub mod stability;
pub mod stage;
pub mod studies;
pub mod wireframe;
