//! The grader: every reference solution passes, every shipped stub is "not
//! started" (through the real `grade` command, which builds the exercises
//! crate), wrong answers fail with a measured error (and images for image
//! checks), a loop that never ends is stopped, an exercise that does not
//! compile is reported and leaves the others graded, hints come in tiers,
//! and `--json` writes Gradescope's results.json.

use std::path::Path;
use std::process::Output;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use crate::common;
use glam::{Mat4, Vec2};
use raystep::grading::driver::{describe, grade_stream};
use raystep::grading::exercises::ch1;
use raystep::grading::{self, write_failure_images, Outcome};

/// One `grade` that builds the exercises crate at a time (two builds
/// would wait for each other on the grader's build lock anyway).
pub(crate) static BUILD: Mutex<()> = Mutex::new(());

/// Runs the `grade` command with `args`; images and hints go to `out`.
pub(crate) fn grade(args: &[&str], out: &Path) -> (Output, String, Duration) {
    let _guard = BUILD.lock().unwrap_or_else(|e| e.into_inner());
    let start = Instant::now();
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_grade"))
        .args(args)
        .arg("--out")
        .arg(out)
        .current_dir(common::root())
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&output.stdout).into_owned();
    (output, text, start.elapsed())
}

/// A fresh copy of every chapter's exercise folder under `dir`, as
/// shipped (from the stubs embedded in the library, never from the files a
/// student edits under `chapters/`).
pub(crate) fn copy_exercises(dir: common::TempDir) -> common::TempDir {
    raystep::grading::shipped::write_all(&dir).unwrap();
    dir
}

/// The line `grade` printed for exercise `id` (`ch3/ray_plane`).
pub(crate) fn line<'a>(text: &'a str, id: &str) -> &'a str {
    text.lines()
        .find(|l| l.trim_start().starts_with(&format!("{id} ")))
        .unwrap_or_else(|| panic!("{id} not graded:\n{text}"))
}

#[test]
fn every_reference_solution_passes() {
    let all = grading::all();
    assert!(all.len() >= 18);
    for ex in &all {
        let outcome = grading::run(ex);
        assert!(outcome.is_pass(), "{}: {outcome:?}", ex.id());
        assert!(grading::shipped::find(&ex.id()).is_some(), "{}", ex.file);
        // Three tiers, each saying something.
        assert!(ex.hints().iter().all(|h| h.len() > 20), "{}", ex.id());
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
    let wrong = || {
        ch1::check_look_at(|e, t, u| {
            raystep::ch1_projection::camera::camera_from_world_look_at(e, t, u)
                .unwrap()
                .inverse()
        })
    };
    let check = wrong();
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
    for f in &files {
        assert!(f.exists(), "{}", f.display());
    }
    // The TUI's `g` reads the pair back: the student's image and the
    // reference, as written (8-bit sRGB).
    let pair = grading::latest_failure_images(&dir).unwrap().unwrap();
    assert_eq!(pair.stem, "ch1-look_at");
    assert_eq!(pair.student.to_srgb8(), candidate.to_srgb8());
    assert_eq!(pair.reference.to_srgb8(), reference.to_srgb8());
    // The printed result names the images and gives the first hint only.
    let text = describe(&ex, &grading::run_check(wrong), 12, &files);
    assert!(text.contains("FAIL") && text.contains("images: "), "{text}");
    // The check names the mistake: its hint stands in for the first tier.
    assert!(text.contains(ex.symptom_hint(&ch1::INVERSE)), "{text}");
    assert!(
        !text.contains(ex.hints()[2]),
        "the formula is the last tier: {text}"
    );
    assert!(text.contains("grade --hint ch1/look_at"), "{text}");
    // The identity is not a camera either.
    assert!(!ch1::check_look_at(|_, _, _| Mat4::IDENTITY).passed());
}

#[test]
fn a_panicking_solution_is_reported_not_fatal() {
    // Exercise 1.1 with a solution that panics.
    let ex = grading::Exercise {
        reference: || ch1::check_project_point(|_| panic!("index out of bounds")),
        ..grading::all()[0]
    };
    assert_eq!(ex.id(), "ch1/project_point");
    match grading::run(&ex) {
        Outcome::Panicked(m) => assert!(m.contains("index out of bounds")),
        other => panic!("{other:?}"),
    }
    let mut printed = Vec::new();
    let results = grade_stream(
        &[ex],
        &mut |e| (grading::run(e), Vec::new()),
        &mut printed,
        false,
    );
    let text = String::from_utf8(printed).unwrap();
    assert!(!results[0].1.is_pass());
    assert!(
        text.contains("FAIL  panicked: index out of bounds"),
        "{text}"
    );
    // The first tier of its hints, from the hints file.
    let first = ex.hints()[0];
    assert!(first.starts_with("slide \""), "{first}");
    assert!(text.contains(&format!("hint: {first}")), "{text}");
}

#[test]
fn the_grade_command_grades_references_and_rejects_bad_arguments() {
    let dir = common::temp_dir("grade-ref");
    let (out, text, _) = grade(&["--reference"], &dir);
    assert!(out.status.success(), "{text}");
    let n = grading::all().len();
    assert!(text.contains(&format!("{n} of {n} passed")), "{text}");
    let (out, _, _) = grade(&["chapter-one"], &dir);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("is not a chapter"));
    let (out, _, _) = grade(&["--hint", "ch9/nothing"], &dir);
    assert_eq!(out.status.code(), Some(2));
    // A time limit that is not a number of seconds in range (a NaN panicked).
    for t in ["nan", "-5", "1e9"] {
        let (out, _, _) = grade(&["--reference", &format!("--timeout={t}")], &dir);
        assert_eq!(out.status.code(), Some(2), "--timeout {t}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("expected seconds"));
    }
}

#[test]
fn every_shipped_stub_is_not_started_and_gives_no_hint() {
    let dir = common::temp_dir("grade-stubs");
    let exercises = copy_exercises(common::temp_dir("grade-stubs-src"));
    let (out, text, _) = grade(&["--exercises", exercises.to_str().unwrap()], &dir);
    assert_eq!(out.status.code(), Some(1), "{text}");
    for ex in grading::all() {
        let line = line(&text, &ex.id());
        assert!(line.contains("not started"), "{line}");
    }
    assert!(!text.contains("hint:"), "{text}");
    assert!(text.contains("0 of "), "{text}");
    // The course so far, and where to start.
    let n = grading::all().len();
    assert!(text.contains("course: ch1 0/3, ch2 0/"), "{text}");
    assert!(text.contains(&format!("; 0 of {n} passed\n")), "{text}");
    assert!(
        text.contains(
            "next: start ch1/project_point in chapters/ch1-projection/exercises/project_point.rs"
        ),
        "{text}"
    );
    // Exercise 1.1 solved and chapter 1 graded again: the other chapters
    // are remembered, and the next is 1.2.
    let solution =
        common::root().join("tests/project/solutions/ch1-projection/exercises/project_point.rs");
    put(
        &exercises,
        "ch1-projection",
        "project_point",
        &std::fs::read_to_string(solution).unwrap(),
    );
    let (_, text, _) = grade(&["ch1", "--exercises", exercises.to_str().unwrap()], &dir);
    assert!(text.contains("course: ch1 1/3, ch2 0/"), "{text}");
    assert!(text.contains(&format!("; 1 of {n} passed\n")), "{text}");
    assert!(text.contains("next: start ch1/look_at in"), "{text}");
}

/// Writes `text` as exercise `name` of the chapter folder `chapter`.
fn put(dir: &Path, chapter: &str, name: &str, text: &str) {
    std::fs::write(
        dir.join(chapter)
            .join("exercises")
            .join(format!("{name}.rs")),
        text,
    )
    .unwrap();
}

#[test]
fn a_broken_exercise_is_isolated_and_a_loop_that_never_ends_is_stopped() {
    let dir = common::temp_dir("grade-broken");
    let ex = copy_exercises(common::temp_dir("grade-broken-src"));
    // A syntax error in one exercise, a changed signature in another.
    put(
        &ex,
        "ch1-projection",
        "look_at",
        "use glam::{Mat4, Vec3};\npub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {\n    let x = 3\n    Mat4::IDENTITY\n}\n",
    );
    put(
        &ex,
        "ch4-sphere-tracing",
        "sphere_sdf",
        "use glam::Vec3;\npub fn sphere_sdf(p: Vec3, center: Vec3, radius: f32) -> f64 { 1.0 }\n",
    );
    // A right answer next to them still passes.
    put(
        &ex,
        "ch1-projection",
        "project_point",
        "use glam::{Vec2, Vec3};\npub fn project_point(p: Vec3) -> Option<Vec2> {\n    (p.z < 0.0).then(|| Vec2::new(p.x / -p.z, p.y / -p.z))\n}\n",
    );
    // A tracer that ignores its step budget and never ends on a miss.
    put(
        &ex,
        "ch4-sphere-tracing",
        "sphere_trace",
        "use glam::Vec3;\npub fn sphere_trace(sdf: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, eps: f32, steps: u32, max: f32) -> Option<f32> {\n    let mut t = 0.0;\n    loop {\n        let h = sdf(o + t * d);\n        if h < eps { return Some(t); }\n        t += h;\n    }\n}\n",
    );
    // The capstone with a march that forgets to step (and has no budget).
    put(
        &ex,
        "ch4-sphere-tracing",
        "trace_scene",
        "use glam::Vec3;\nuse raystep::ch4_implicit_surfaces::march::March;\npub fn trace_scene(sdf: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {\n    let t = 0.0;\n    loop {\n        let h = sdf(o + t * d);\n        if h < m.epsilon { return Some((t, -d)); }\n    }\n}\n",
    );
    // A wrong answer: the sign of the edge function flipped.
    put(
        &ex,
        "ch2-rasterization",
        "edge_function",
        "use glam::Vec2;\npub fn edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32 {\n    let (e, q) = (b - a, p - a);\n    e.y * q.x - e.x * q.y\n}\n",
    );
    let json = dir.join("results.json");
    let (out, text, took) = grade(
        &[
            "ch1",
            "ch2/edge_function",
            "ch4",
            "--timeout",
            "2",
            "--exercises",
            ex.to_str().unwrap(),
            "--json",
            json.to_str().unwrap(),
        ],
        &dir,
    );
    assert_eq!(out.status.code(), Some(1), "{text}");
    let line = |id: &str| line(&text, id);
    assert!(line("ch1/project_point").contains("PASS"), "{text}");
    assert!(line("ch1/look_at").contains("does not compile"), "{text}");
    assert!(
        text.contains("look_at.rs:3:"),
        "the compiler's file:line: {text}"
    );
    assert!(
        line("ch4/sphere_sdf").contains("does not compile"),
        "{text}"
    );
    assert!(text.contains("signature"), "{text}");
    let timed = line("ch4/sphere_trace");
    assert!(timed.contains("timed out after 2 s"), "{text}");
    assert!(timed.contains("while "), "names what was running: {timed}");
    let timed = line("ch4/trace_scene");
    assert!(timed.contains("timed out after 2 s"), "{text}");
    assert!(
        timed.contains("while calling trace_scene"),
        "names what was running: {timed}"
    );
    assert!(line("ch2/edge_function").contains("FAIL  error"), "{text}");
    assert!(text.contains("expected"), "{text}");
    assert!(
        line("ch4/gradient_normal").contains("not started"),
        "{text}"
    );
    // Two timeouts of 2 s, a build of the small crate, the rest quick.
    assert!(took < Duration::from_secs(120), "{took:?}");
    // Gradescope's shape: a test per exercise with name, score, max_score
    // and output.
    let json = std::fs::read_to_string(&json).unwrap();
    assert!(json.contains("\"tests\": ["), "{json}");
    assert!(
        json.contains("\"name\": \"ch1/project_point\", \"score\": 1, \"max_score\": 1"),
        "{json}"
    );
    assert!(
        json.contains("\"name\": \"ch4/sphere_trace\", \"score\": 0, \"max_score\": 1"),
        "{json}"
    );
    assert!(json.contains("\"output\": \""), "{json}");
    let tests = json.matches("\"max_score\": 1,").count();
    let graded = grading::all()
        .iter()
        .filter(|e| e.chapter == 1 || e.chapter == 4)
        .count()
        + 1;
    assert_eq!(tests, graded, "{json}");
}

#[test]
fn hints_come_in_tiers_and_the_formula_last() {
    let dir = common::temp_dir("grade-hints");
    let ex = grading::all()
        .into_iter()
        .find(|e| e.id() == "ch3/moller_trumbore")
        .unwrap();
    let mut shown = Vec::new();
    for _ in 0..3 {
        let (out, text, _) = grade(&["--hint", "ch3/moller_trumbore"], &dir);
        assert!(out.status.success(), "{text}");
        shown.push(text);
    }
    assert!(
        shown[0].contains("hint 2 of 3") && shown[0].contains(ex.hints()[1]),
        "{}",
        shown[0]
    );
    assert!(!shown[0].contains(ex.hints()[2]), "{}", shown[0]);
    assert!(
        shown[1].contains("hint 3 of 3") && shown[1].contains(ex.hints()[2]),
        "{}",
        shown[1]
    );
    assert!(shown[1].contains("last hint"), "{}", shown[1]);
    assert!(shown[2].contains("hint 3 of 3"), "{}", shown[2]);
}

#[test]
fn a_chapter_binary_renders_the_students_capstone() {
    let _guard = BUILD.lock().unwrap_or_else(|e| e.into_inner());
    let dir = common::temp_dir("student-render");
    let exercises = copy_exercises(common::temp_dir("student-render-src"));
    let run = || {
        std::process::Command::new(env!("CARGO_BIN_EXE_ch4"))
            .arg("--student")
            .env("RAYSTEP_EXERCISES_DIR", &exercises)
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    // The shipped stub: not started.
    let out = run();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("not started"), "{text}");
    // A solution: the student's picture beside the reference.
    let solution =
        common::root().join("tests/project/solutions/ch4-sphere-tracing/exercises/trace_scene.rs");
    std::fs::copy(
        solution,
        exercises.join("ch4-sphere-tracing/exercises/trace_scene.rs"),
    )
    .unwrap();
    let out = run();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(text.contains("wrote "), "{text}");
    assert!(dir
        .join("out/student/ch4-trace_scene-student.png")
        .is_file());
}

/// The reference pictures the capstones are graded against, summarised
/// (size, mean colour, share of lit pixels) in an insta snapshot: when a
/// chapter's renderer changes what a capstone expects, `cargo insta
/// review` shows the instructor the change before students see it.
#[test]
fn the_capstones_reference_pictures_are_reviewed_snapshots() {
    let mut table = String::from("capstone | size | mean RGB | lit pixels\n");
    for (chapter, name) in raystep::grading::runner::CAPSTONES {
        let ex = grading::all()
            .into_iter()
            .find(|e| e.chapter == chapter && e.name == name)
            .unwrap();
        let Outcome::Passed(check) = grading::run(&ex) else {
            panic!("{} does not pass", ex.id());
        };
        let (_, reference) = check.images.expect("a capstone renders");
        let n = reference.pixels.len() as f32;
        let mean = reference.pixels.iter().copied().sum::<glam::Vec3>() / n;
        let lit = reference
            .pixels
            .iter()
            .filter(|p| p.max_element() > 0.0)
            .count();
        table += &format!(
            "{} | {}x{} | {:.4} {:.4} {:.4} | {:.1}%\n",
            ex.id(),
            reference.width,
            reference.height,
            mean.x,
            mean.y,
            mean.z,
            100.0 * lit as f32 / n
        );
    }
    insta::assert_snapshot!(table);
}

/// What `cargo grade` says about the course from the states it remembers:
/// a chapter never graded, one failed exercise as the next to try, all
/// passed; and the states of exercises not graded this time are kept.
#[test]
fn the_course_progress_names_what_to_try_next() {
    use raystep::grading::course::{load, summary, update, State};
    let dir = common::temp_dir("grade-progress");
    let all = grading::all();
    let n = all.len();
    let check = || grading::Check {
        error: 0.0,
        tolerance: 1.0,
        detail: String::new(),
        images: None,
        symptom: None,
    };
    let result = |i: usize, outcome: Outcome| (all[i], outcome, String::new());
    // Nothing remembered: every chapter ungraded, the first exercise next.
    let none = load(&dir);
    let text = summary(&all, &none);
    assert!(text.starts_with("course: ch1 -/3, ch2 -/"), "{text}");
    assert!(text.contains(&format!("; 0 of {n} passed\n")), "{text}");
    assert!(text.contains("(-: a chapter not graded yet)"), "{text}");
    assert!(
        text.contains("next: ch1/project_point has not been graded: `cargo grade ch1`"),
        "{text}"
    );
    // 1.1 passed, 1.2 failed: 1.2 is next, with its hint command.
    let passed = Outcome::Passed(check());
    let failed = Outcome::Panicked("boom".into());
    update(&dir, &[result(0, passed), result(1, failed)]);
    let states = load(&dir);
    assert_eq!(states.get("ch1/project_point"), Some(&State::Passed));
    let text = summary(&all, &states);
    assert!(text.starts_with("course: ch1 1/3, ch2 -/"), "{text}");
    assert!(
        text.contains("next: ch1/look_at failed: `cargo grade --hint ch1/look_at`"),
        "{text}"
    );
    // Grading 1.2 alone keeps 1.1's state.
    let states = update(&dir, &[result(1, Outcome::NotImplemented)]);
    assert_eq!(states.get("ch1/project_point"), Some(&State::Passed));
    assert!(summary(&all, &states).contains("next: start ch1/look_at in"));
    // Everything passed.
    let every: Vec<_> = (0..n)
        .map(|i| result(i, Outcome::Passed(check())))
        .collect();
    let text = summary(&all, &update(&dir, &every));
    assert!(text.contains(&format!("; {n} of {n} passed\n")), "{text}");
    assert!(!text.contains("not graded yet"), "{text}");
    assert!(text.contains("all passed"), "{text}");
}

/// `cargo grade --solution` shows an exercise's solution, with the idea
/// behind it, only once the exercise has passed; every exercise has one.
#[test]
fn a_solution_opens_only_after_a_pass() {
    use raystep::grading::solutions::{find, show};
    let dir = common::temp_dir("grade-solution");
    let all = grading::all();
    for ex in &all {
        assert!(find(&ex.id()).is_some(), "{} has no solution", ex.id());
    }
    let ex = *all.iter().find(|e| e.id() == "ch3/ray_plane").unwrap();
    let why = show(&ex, &dir).unwrap_err();
    assert!(
        why.contains("has not passed yet") && why.contains("--hint ch3/ray_plane"),
        "{why}"
    );
    let (out, _, _) = grade(&["--solution", "ch3/ray_plane"], &dir);
    assert_eq!(out.status.code(), Some(1));
    let passed = grading::Check {
        error: 0.0,
        tolerance: 1.0,
        detail: String::new(),
        images: None,
        symptom: None,
    };
    raystep::grading::course::update(&dir, &[(ex, Outcome::Passed(passed), String::new())]);
    let text = show(&ex, &dir).unwrap();
    assert!(text.contains(find("ch3/ray_plane").unwrap().text), "{text}");
    assert!(
        text.contains(&format!("the idea: {}", ex.hints()[1])),
        "{text}"
    );
    let (out, text, _) = grade(&["--solution", "ch3/ray_plane"], &dir);
    assert!(out.status.success(), "{text}");
    assert!(text.contains("pub fn ray_plane("), "{text}");
    let (out, _, _) = grade(&["--solution", "ch9/nothing"], &dir);
    assert_eq!(out.status.code(), Some(2));
}
