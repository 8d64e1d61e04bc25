//! Chapter 1: projection.

mod capstone;
mod projection;
