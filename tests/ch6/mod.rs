//! Chapter 6: global illumination, its exercises, and its terminal preview.

mod bench;
mod caught;
mod exercises;
mod fast;
mod fast_tree;
mod global_illumination;
mod ladder;
mod path_record;
mod placement;
mod reference_match;
mod roulette_glass;
#[cfg(feature = "tui")]
mod tui;
mod unit;
