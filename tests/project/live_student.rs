//! The TUI's student mode without a terminal: the library function it
//! calls builds the exercises crate as the grader does and renders a
//! chapter's capstone with the student's code. The shipped stub is "not
//! started"; a correct solution, written into the exercise file,
//! matches the reference image; a file that does not compile gives the
//! compiler's file:line; and two builds of different files in one
//! folder each run their own binary. (The builds share the grader tests'
//! lock and their build folder: each is one small rebuild of the
//! exercises crate.)

use std::time::Duration;

use raystep::grading::build::{build_exercises_in, Place};
use raystep::grading::kept::{kept_runner, used_marker};
use raystep::grading::live::{live_student, LiveError, LiveOptions};
use raystep::grading::process::capstone_images;
use raystep::grading::runner::capstone;

use super::grading::{copy_exercises, BUILD};
use crate::common;

#[test]
fn live_student_is_not_started_for_the_stub_and_matches_with_the_reference() {
    let _guard = BUILD.lock().unwrap_or_else(|e| e.into_inner());
    let exercises = copy_exercises(common::temp_dir("live-src"));
    let live_out = common::temp_dir("live-out");
    let opts = LiveOptions {
        exercises: exercises.clone(),
        place: Place::current().unwrap(),
        out: live_out.to_path_buf(),
        timeout: Duration::from_secs(60),
    };
    let file = exercises.join("ch1-projection/exercises/draw_edges.rs");
    let stub = std::fs::read_to_string(&file).unwrap();
    assert!(stub.contains("todo!()"), "the shipped stub");

    // The shipped stub: not started, with the status the TUI shows.
    let err = live_student(1, &opts, None).unwrap_err();
    assert!(matches!(err, LiveError::NotStarted { .. }), "{err:?}");
    assert_eq!(err.status(), "ch1/draw_edges: not started (todo!)");

    // A correct solution in the student's file: the two images match.
    std::fs::copy(
        common::root().join("tests/project/solutions/ch1-projection/exercises/draw_edges.rs"),
        &file,
    )
    .unwrap();
    let render = live_student(1, &opts, None).unwrap();
    assert!(render.matches, "{}", render.detail);
    assert_eq!(render.id, "ch1/draw_edges");
    assert_eq!(render.status(), "student matches reference");
    // Another correct formulation may round one or two anti-aliased pixels
    // differently (the check's tolerance allows it).
    assert!(
        render.differing_pixels() <= 2,
        "{}",
        render.differing_pixels()
    );
    assert_eq!(
        (render.student.width, render.student.height),
        (160, 120),
        "the grader's size"
    );
    assert!(render
        .reference
        .pixels
        .iter()
        .any(|p| p.max_element() > 0.0));

    // A syntax error: the compiler's file:line and message, first line.
    std::fs::write(&file, stub.replace("todo!()", "let x = 3\n    todo!()")).unwrap();
    let err = live_student(1, &opts, None).unwrap_err();
    let status = err.status();
    assert!(
        status.starts_with("compile error: ch1-projection/exercises/draw_edges.rs:"),
        "{status}"
    );
    assert!(status.contains("expected `;`"), "{status}");

    // A chapter without a capstone is said so, before anything is built.
    assert_eq!(
        live_student(9, &opts, None).unwrap_err(),
        LiveError::NoCapstone(9)
    );
}

/// The warp view's student routine: the stub is "not started"; the
/// solution's draws pass the χ² test against cos θ / π; Malley's method
/// without its square root is rejected; a panic is reported, not a crash.
#[test]
fn live_warp_tests_the_students_cosine_hemisphere() {
    use raystep::ch5_reflection::warp_test::ROUTINES;
    use raystep::grading::live::live_warp;
    let _guard = BUILD.lock().unwrap_or_else(|e| e.into_inner());
    let exercises = copy_exercises(common::temp_dir("warp-src"));
    let warp_out = common::temp_dir("warp-out");
    let opts = LiveOptions {
        exercises: exercises.clone(),
        place: Place::current().unwrap(),
        out: warp_out.to_path_buf(),
        timeout: Duration::from_secs(60),
    };
    let id = "ch5/cosine_hemisphere";
    let file = exercises.join("ch5-reflection/exercises/cosine_hemisphere.rs");
    let err = live_warp(id, 10_000, 1, &opts, None).unwrap_err();
    assert!(matches!(err, LiveError::NotStarted { .. }), "{err:?}");

    let solution = std::fs::read_to_string(
        common::root()
            .join("tests/project/solutions/ch5-reflection/exercises/cosine_hemisphere.rs"),
    )
    .unwrap();
    std::fs::write(&file, &solution).unwrap();
    let cosine_pdf = ROUTINES[1].pdf;
    let drawn = live_warp(id, 100_000, 1, &opts, None).unwrap();
    assert_eq!(drawn.draws, 100_000);
    let test = drawn.test("yours", &cosine_pdf);
    assert!(test.passes(), "{}", test.verdict());

    // r = u instead of √u: too many directions near the pole.
    let no_root = solution.replace("u.x.sqrt()", "u.x");
    assert_ne!(no_root, solution, "the solution takes a square root");
    std::fs::write(&file, no_root).unwrap();
    let test = live_warp(id, 100_000, 1, &opts, None)
        .unwrap()
        .test("no root", &cosine_pdf);
    assert!(!test.passes() && test.bad == 0, "{}", test.verdict());

    std::fs::write(
        &file,
        "use glam::{Vec2, Vec3};\npub fn cosine_hemisphere(u: Vec2) -> (Vec3, f32) {\n    panic!(\"on purpose\")\n}\n",
    )
    .unwrap();
    let err = live_warp(id, 1000, 1, &opts, None).unwrap_err();
    assert!(
        matches!(&err, LiveError::Panicked { message, .. } if message.contains("on purpose")),
        "{err:?}"
    );
}

/// Two builds of different exercise files in one target folder (the TUI's
/// student mode and `cargo grade` at once): each gives its own binary, and
/// the first still runs the first's code after the second was built. (One
/// binary for both would hand a grader that is still starting it the other
/// one's exercises.)
#[test]
fn a_later_build_never_replaces_an_earlier_builds_binary() {
    let _guard = BUILD.lock().unwrap_or_else(|e| e.into_inner());
    let place = Place::current().unwrap();
    let stubs = copy_exercises(common::temp_dir("keep-stubs"));
    let solved = copy_exercises(common::temp_dir("keep-solved"));
    let file = "ch1-projection/exercises/draw_edges.rs";
    std::fs::copy(
        common::root().join("tests/project/solutions").join(file),
        solved.join(file),
    )
    .unwrap();
    let first = build_exercises_in(&solved, &place, None).unwrap();
    let second = build_exercises_in(&stubs, &place, None).unwrap();
    assert_ne!(first.runner, second.runner);
    let ex = capstone(1).unwrap();
    let out = common::temp_dir("keep-out");
    let limit = Duration::from_secs(60);
    let (solved_outcome, _) = capstone_images(&first.runner, &ex, &out, limit, None);
    assert!(solved_outcome.is_pass(), "{solved_outcome:?}");
    let (stub_outcome, _) = capstone_images(&second.runner, &ex, &out, limit, None);
    assert!(!stub_outcome.is_pass(), "{stub_outcome:?}");
}

/// A build removes the binaries of builds no grader has used for an hour,
/// and keeps the ones used since (so a student who edits all term does not
/// fill the disk with them).
#[test]
fn builds_unused_for_an_hour_are_removed() {
    let _guard = BUILD.lock().unwrap_or_else(|e| e.into_inner());
    let place = Place::current().unwrap();
    let folder = |name: &str| place.target.join("raystep-grade").join(name);
    let (old, recent) = (folder("test-unused-2h"), folder("test-used-10min"));
    for (dir, age) in [(&old, 7200), (&recent, 600)] {
        std::fs::create_dir_all(dir).unwrap();
        std::fs::write(kept_runner(dir, place.profile()), b"not a program").unwrap();
        let used = used_marker(dir, place.profile());
        std::fs::write(&used, b"").unwrap();
        let when = std::time::SystemTime::now() - Duration::from_secs(age);
        let file = std::fs::File::options().write(true).open(&used).unwrap();
        file.set_modified(when).unwrap();
    }
    let stubs = copy_exercises(common::temp_dir("prune-stubs"));
    let built = build_exercises_in(&stubs, &place, None).unwrap();
    assert!(built.runner.is_file());
    let kept = |dir: &std::path::Path| kept_runner(dir, place.profile());
    assert!(!kept(&old).exists(), "unused for two hours: removed");
    assert!(kept(&recent).is_file(), "used ten minutes ago: kept");
    let _ = std::fs::remove_dir_all(old);
    let _ = std::fs::remove_dir_all(recent);
}
