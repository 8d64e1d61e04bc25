//! Chapter 5: the reflection equation.

pub mod direct;
pub mod light;
pub mod material;
pub mod mis;
pub mod plot;
pub mod radiometry;
pub mod render;
pub mod report;
pub mod stability;
pub mod stage;
pub mod studies;
pub mod warp;
pub mod world;
