//! The tests of single library files, one file here per file in `src/`
//! (they live outside the library so that `cargo test` compiles it once).

mod core_draw;
mod core_film;
mod core_format;
mod core_plot;
mod core_preview;
mod core_report;
mod core_sampling;
mod core_strip;
mod core_table;
mod core_text;
mod core_zview;
mod grading_child;
mod grading_live;
mod scene_mesh;
mod scene_obj;
