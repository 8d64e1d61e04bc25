//! Every test of the project, in one test binary: one folder per chapter,
//! then the project as a whole and the terminal UI.
//!
//! One binary, not one per folder: each test binary links the whole library
//! and its dependencies again, and the test harness only runs the tests of
//! one binary at a time. Together they build and run in about half the
//! time. `cargo test ch3::` runs one chapter's tests; `cargo test
//! ch3::unit::` the tests of single library files (they live here, not
//! beside the code, so that `cargo test` compiles the library only once).

mod common;

mod ch1;
mod ch2;
mod ch3;
mod ch4;
mod ch5;
mod ch6;
mod project;
#[cfg(feature = "tui")]
mod tui;
