//! The grader: every shipped stub fails cleanly, every reference solution
//! passes, wrong answers fail with a measured error (and images for image
//! checks), and the `grade` command reports all of it.

use crate::common;
use glam::{Mat4, Vec2};
use raystep::grading::exercises::ch1;
use raystep::grading::{self, grade_report, write_failure_images, Outcome, Solution};

#[test]
fn every_reference_solution_passes() {
    let all = grading::all();
    assert!(!all.is_empty());
    for ex in &all {
        let outcome = grading::run(ex, Solution::Reference);
        assert!(outcome.is_pass(), "{}: {outcome:?}", ex.id());
    }
}

#[test]
fn every_shipped_stub_fails_cleanly() {
    for ex in grading::all() {
        let source = std::fs::read_to_string(common::root().join(ex.file)).unwrap();
        let outcome = grading::run(&ex, Solution::Student);
        if source.contains("todo!()") {
            assert!(
                matches!(outcome, Outcome::NotImplemented),
                "{}: {outcome:?}",
                ex.id()
            );
        } else {
            // A student has filled it in: grading still ends in a verdict.
            assert!(
                matches!(outcome, Outcome::Passed(_) | Outcome::Failed(_)),
                "{}: {outcome:?}",
                ex.id()
            );
        }
    }
}

#[test]
fn a_wrong_projection_fails_with_its_worst_case() {
    // Forgetting the minus sign turns the image upside down.
    let check = ch1::check_project_point(|p| (p.z < 0.0).then(|| Vec2::new(p.x / p.z, p.y / p.z)));
    assert!(!check.passed());
    assert!(check.error > 0.5, "{check:?}");
    assert!(check.detail.contains("expected"), "{}", check.detail);
    // Projecting points behind the camera is also wrong.
    let check = ch1::check_project_point(|p| Some(Vec2::new(p.x / -p.z, p.y / -p.z)));
    assert!(check.error.is_infinite());
}

#[test]
fn a_wrong_look_at_fails_and_writes_images() {
    // Returning world_from_camera instead of its inverse.
    let check = ch1::check_look_at(|e, t, u| {
        raystep::ch1_projection::camera::camera_from_world_look_at(e, t, u)
            .unwrap()
            .inverse()
    });
    assert!(!check.passed());
    let (candidate, reference) = check.images.as_ref().unwrap();
    assert!(candidate.rmse(reference) > 0.01);
    let dir = common::temp_dir("grade-images");
    let ex = grading::all()
        .into_iter()
        .find(|e| e.name == "look_at")
        .unwrap();
    let files = write_failure_images(&ex, &check, &dir).unwrap();
    assert_eq!(files.len(), 3);
    for f in files {
        assert!(f.exists(), "{}", f.display());
    }
    // The TUI's `g` reads the pair back: the student's image and the
    // reference, as written (8-bit sRGB).
    let pair = grading::latest_failure_images(&dir).unwrap().unwrap();
    assert_eq!(pair.stem, "ch1-look_at");
    assert_eq!(pair.student.to_srgb8(), candidate.to_srgb8());
    assert_eq!(pair.reference.to_srgb8(), reference.to_srgb8());
    // The printed report points to it when it has written images.
    let wrong = grading::Exercise {
        grade: |_| {
            ch1::check_look_at(|e, t, u| {
                raystep::ch1_projection::camera::camera_from_world_look_at(e, t, u)
                    .unwrap()
                    .inverse()
            })
        },
        ..ex
    };
    let (text, passed) = grade_report(&[wrong], Solution::Student, &dir);
    assert_eq!(passed, 0);
    assert!(text.contains("images: "), "{text}");
    assert!(text.contains("press `g`"), "{text}");
    let (text, _) = grade_report(&[ex], Solution::Reference, &dir);
    assert!(!text.contains("press `g`"), "{text}");
    // The identity is not a camera either.
    assert!(!ch1::check_look_at(|_, _, _| Mat4::IDENTITY).passed());
}

#[test]
fn a_panicking_solution_is_reported_not_fatal() {
    let ex = grading::Exercise {
        chapter: 0,
        name: "boom",
        file: "none.rs",
        hint: "do not divide by zero",
        grade: |_| ch1::check_project_point(|_| panic!("index out of bounds")),
    };
    match grading::run(&ex, Solution::Student) {
        Outcome::Panicked(m) => assert!(m.contains("index out of bounds")),
        other => panic!("{other:?}"),
    }
    let (text, passed) = grade_report(&[ex], Solution::Student, &common::temp_dir("boom"));
    assert_eq!(passed, 0);
    assert!(
        text.contains("FAIL  panicked: index out of bounds"),
        "{text}"
    );
    assert!(text.contains("hint: do not divide by zero"), "{text}");
}

#[test]
fn the_grade_command_reports_pass_and_fail() {
    let dir = common::temp_dir("grade-cmd");
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_grade"))
            .args(args)
            .args(["--out", dir.to_str().unwrap()])
            .current_dir(common::root())
            .output()
            .unwrap()
    };
    let out = run(&["--reference"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    let n = grading::all().len();
    assert!(text.contains(&format!("{n} of {n} passed")), "{text}");

    let out = run(&["ch1"]);
    let text = String::from_utf8_lossy(&out.stdout);
    let stubs = ["project_point", "look_at"].iter().filter(|f| {
        std::fs::read_to_string(
            common::root().join(format!("chapters/ch1-projection/exercises/{f}.rs")),
        )
        .unwrap()
        .contains("todo!()")
    });
    if stubs.count() > 0 {
        assert_eq!(out.status.code(), Some(1), "{text}");
        assert!(text.contains("not implemented yet"), "{text}");
        assert!(text.contains("hint:"), "{text}");
    }
    let out = run(&["chapter-one"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("is not a chapter"));
}
