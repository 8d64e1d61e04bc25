//! Chapter 2: rasterization.

mod capstone;
mod checker;
mod rasterization;
mod unit;
