//! Chapter 2: rasterization.

mod capstone;
mod rasterization;
