//! Chapter 1: projection.

#[path = "../common/mod.rs"]
mod common;

mod capstone;
mod projection;
