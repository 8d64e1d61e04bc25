//! Chapter 2: rasterization.

mod rasterization;
