//! Unit tests of `src/grading/live.rs`.

use raystep::grading::live::*;

#[test]
fn the_first_compiler_line_names_the_file_from_the_chapter_folder() {
    let m = "error[E0308]: mismatched types\n  --> C:\\s\\chapters\\ch2-rasterization\\exercises\\depth_test.rs:9:5\n   |\n";
    assert_eq!(
        first_compiler_line(m),
        "ch2-rasterization/exercises/depth_test.rs:9:5: mismatched types"
    );
    let m = "the signature of your function does not match the one shipped\nerror[E0308]: …\n --> chapters/lib.rs:40:9\n";
    assert_eq!(
        first_compiler_line(m),
        "the signature changed: keep the shipped one"
    );
    assert_eq!(
        first_compiler_line("error: linking failed\n"),
        "linking failed"
    );
}
