//! Chapter 1: projection. `cargo run --release --bin ch1 -- --help`
//!
//! Renders the wireframe of any scene through the pinhole camera, prints
//! the projected vertices, "farther is smaller" and the vanishing points,
//! and with `--report` the precision study and the stiff cases.

fn main() -> std::process::ExitCode {
    // `--student`: the chapter's capstone rendered with your exercise.
    if std::env::args().any(|a| a == "--student") {
        return raystep::grading::process::student_main(1);
    }
    raystep::core::run::chapter_main(&raystep::ch1_projection::stage::DEFAULT)
}
