//! A student who wants a pass they did not earn, or who breaks the grader:
//! each hostile exercise file gets FAIL (or a clear refusal) and leaves
//! nothing running and nothing written outside the grader's output folder.
//! One `grade` run grades all of them (one build of the student's
//! process). The numbered cases are those of the grader issue's list of
//! twelve ways to an unearned grade; `grader_states` has the rest
//! (old file dates, one file that breaks the link beside correct ones).

use std::process::Command;
use std::time::{Duration, Instant};

use super::grading::{copy_exercises, grade, line};
use crate::common;

/// A marker in what the hostile files would start or write, to look for
/// it afterwards.
const MARKER: &str = "raystep-hostile-7f3a";

/// The hostile files: (chapter folder, exercise, file).
fn hostile_files() -> Vec<(&'static str, &'static str, String)> {
    vec![
        // 1. Replaces the C library's `write`, which every verdict the
        // student's process printed went through.
        (
            "ch1-projection",
            "project_point",
            "use glam::{Vec2, Vec3};\n\
             #[no_mangle]\n\
             pub extern \"C\" fn write(_fd: i32, _buf: *const u8, n: usize) -> isize { n as isize }\n\
             pub fn project_point(p: Vec3) -> Option<Vec2> { todo!() }\n"
                .into(),
        ),
        // Prints a grade line and a results.json of its own, then answers
        // wrong: what it prints is not read as anything.
        (
            "ch1-projection",
            "look_at",
            "use glam::{Mat4, Vec3};\n\
             pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {\n\
             println!(\"  ch1/look_at             PASS  error 0.000e0 within 1e-4\");\n\
             println!(\"{{\\\"score\\\": 24, \\\"max_score\\\": 24}}\");\n\
             Mat4::IDENTITY\n}\n"
                .into(),
        ),
        // 5. Reads the process's own memory (std named by another name).
        (
            "ch1-projection",
            "draw_edges",
            "use glam::{Vec2, Vec3};\nuse raystep::ch1_projection::camera::Camera;\nuse std as s;\n\
             pub fn draw_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {\n\
             let _ = s::fs::read(\"/proc/self/mem\");\n\
             None\n}\n"
                .into(),
        ),
        // Asks for 16 GiB.
        (
            "ch2-rasterization",
            "edge_function",
            "use glam::Vec2;\n\
             pub fn edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32 {\n\
             let v = std::hint::black_box(vec![1u8; 16 << 30]);\n\
             v[v.len() / 2] as f32\n}\n"
                .into(),
        ),
        // Prints for ever.
        (
            "ch2-rasterization",
            "barycentric",
            "use glam::{Vec2, Vec3};\n\
             pub fn barycentric(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {\n\
             loop { println!(\"{}\", \"spam \".repeat(200)); }\n}\n"
                .into(),
        ),
        // 6. Has tmux rewrite results.json after the grader exits.
        (
            "ch2-rasterization",
            "depth_test",
            format!(
                "pub fn depth_test(depth: &mut [f32], index: usize, z: f32) -> bool {{\n\
                 let _ = ::std::process::Command::new(\"tmux\").args([\"run-shell\", \"-b\", \"sleep 2; echo '{{}}' > results.json # {MARKER}\"]).status();\n\
                 if z < depth[index] {{ depth[index] = z; true }} else {{ false }}\n}}\n"
            ),
        ),
        // Compiles and answers wrong (draws nothing): a failed image check,
        // whose images meet links planted in the output folder.
        (
            "ch2-rasterization",
            "rasterize_triangle",
            "use glam::{Vec2, Vec3};\n\
             pub fn rasterize_triangle(v: [Vec3; 3], colors: [Vec3; 3], width: u32, height: u32, depth: &mut [f32], image: &mut [Vec3]) {}\n"
                .into(),
        ),
        // 2. raystep's own solution, named by its path in raystep: the
        // student's crate sees only the building blocks, so it does not
        // compile.
        (
            "ch3-ray-triangle",
            "ray_plane",
            "use glam::Vec3;\n\
             pub fn ray_plane(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {\n\
             raystep::ch3_ray_triangle::triangle::ray_plane(o, d, n, c)\n}\n"
                .into(),
        ),
        // A panic message that would clear the grader's terminal and set
        // its title.
        (
            "ch3-ray-triangle",
            "barycentric_inside",
            "use glam::Vec3;\n\
             pub fn barycentric_inside(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {\n\
             panic!(\"\\x1b[2J\\x1b]0;pwned\\x07 gotcha\")\n}\n"
                .into(),
        ),
        // 3. The reference called on a thread of the student's own.
        (
            "ch3-ray-triangle",
            "moller_trumbore",
            "use glam::Vec3;\n\
             pub fn moller_trumbore(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {\n\
             std::thread::spawn(move || None).join().unwrap()\n}\n"
                .into(),
        ),
        // 4. No tree at all: every triangle tested on another thread,
        // where the grader would not count it.
        (
            "ch3-ray-triangle",
            "bvh_traversal",
            "use raystep::ch3_ray_triangle::ray::Ray;\n\
             use raystep::ch3_ray_triangle::readable_bvh::ReadableBvh;\n\
             use raystep::ch3_ray_triangle::triangle::{intersect_watertight, Hit};\n\
             use std::{thread as t};\n\
             pub fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {\n\
             let (tris, ray) = (bvh.tris.to_vec(), *ray);\n\
             t::spawn(move || {\n\
               let mut best: Option<Hit> = None;\n\
               for (i, tri) in tris.iter().enumerate() {\n\
                 let limit = best.map_or(t_max, |h| h.t);\n\
                 if let Some(h) = intersect_watertight(&ray, *tri, 0.0, limit) { best = Some(Hit { triangle: i as u32, ..h }); }\n\
               }\n\
               best\n\
             }).join().unwrap()\n}\n"
                .into(),
        ),
        // 12. A `main` of its own, which broke the link of every exercise.
        (
            "ch4-sphere-tracing",
            "sphere_sdf",
            "use glam::Vec3;\n#[no_mangle]\nfn main() {}\n\
             pub fn sphere_sdf(p: Vec3, center: Vec3, radius: f32) -> f32 { (p - center).length() - radius }\n"
                .into(),
        ),
        // Reads another file at compile time.
        (
            "ch4-sphere-tracing",
            "gradient_normal",
            "use glam::Vec3;\nconst SECRET: &str = include_str!(\"/etc/hostname\");\n\
             pub fn gradient_normal(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 { Vec3::Z }\n"
                .into(),
        ),
        // A path that would clear the scene's count of what it asked (its
        // light samples, shadow rays, bounces).
        (
            "ch6-global-illumination",
            "path_radiance",
            "use glam::Vec3;\n\
             use raystep::grading::exercises::paths::{self, PathScene};\n\
             pub fn path_radiance(scene: &PathScene, origin: Vec3, dir: Vec3, \
             _rng: &mut dyn FnMut() -> f32) -> Vec3 {\n\
             let l = scene.first_hit(origin, dir).map_or(Vec3::ZERO, |h| h.emitted);\n\
             paths::reset_tally();\n l\n}\n"
                .into(),
        ),
        // Right for its first calls only.
        (
            "ch6-global-illumination",
            "mis_weight",
            "use std::sync::atomic::{AtomicUsize, Ordering};\n\
             static CALLS: AtomicUsize = AtomicUsize::new(0);\n\
             pub fn mis_weight(pdf_f: f64, pdf_g: f64) -> f64 {\n\
             if CALLS.fetch_add(1, Ordering::Relaxed) > 12 { return 0.5; }\n\
             let (f, g) = (pdf_f * pdf_f, pdf_g * pdf_g);\n\
             if f == 0.0 { 0.0 } else { f / (f + g) }\n}\n"
                .into(),
        ),
    ]
}

/// Cases 9 and 10: a crate of the student's around the exercises, whose
/// build script would start a daemon and whose `main` would print passes.
/// The grader builds its own crates, so none of this runs.
fn hostile_crate() -> Vec<(&'static str, String)> {
    vec![
        (
            "Cargo.toml",
            "[package]\nname = \"raystep-exercises\"\nversion = \"0.1.0\"\nedition = \"2021\"\nbuild = \"build.rs\"\n\n[[bin]]\nname = \"grade-student\"\npath = \"runner.rs\"\n".into(),
        ),
        (
            "build.rs",
            format!(
                "fn main() {{ let _ = std::fs::write(concat!(env!(\"CARGO_MANIFEST_DIR\"), \"/{MARKER}-build\"), \"ran\"); }}\n"
            ),
        ),
        (
            "runner.rs",
            "fn main() { for i in 0..24 { println!(\"PASS {i}\"); } }\n".into(),
        ),
    ]
}

fn processes_with_marker() -> Vec<String> {
    let Ok(out) = Command::new("pgrep").args(["-af", MARKER]).output() else {
        return Vec::new();
    };
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter(|l| !l.contains("pgrep"))
        .map(str::to_string)
        .collect()
}

// Linux only: elsewhere the address-space limit may not hold, and the
// 16 GiB file would really ask the system for 16 GiB.
#[cfg(target_os = "linux")]
#[test]
fn hostile_exercises_fail_and_leave_nothing_behind() {
    let exercises = copy_exercises(common::temp_dir("hostile-src"));
    for (folder, name, text) in hostile_files() {
        let path = exercises
            .join(folder)
            .join("exercises")
            .join(format!("{name}.rs"));
        std::fs::write(path, text).unwrap();
    }
    for (name, text) in hostile_crate() {
        std::fs::write(exercises.join(name), text).unwrap();
    }
    let out = common::temp_dir("hostile-out");
    // 11. Links planted where the grader writes, pointing outside.
    let outside_dir = common::temp_dir("hostile-outside");
    let outside = outside_dir.join("target.txt");
    std::fs::write(&outside, "untouched").unwrap();
    for name in [
        "ch2-rasterize_triangle-student.png",
        "ch2-rasterize_triangle-diff.png",
    ] {
        std::os::unix::fs::symlink(&outside, out.join(name)).unwrap();
    }
    let (run, text, took) = grade(
        &[
            "ch1",
            "ch2",
            "ch3",
            "ch4/sphere_sdf",
            "ch4/gradient_normal",
            "ch6/mis_weight",
            "ch6/path_radiance",
            "--timeout",
            "3",
            "--json",
            "--exercises",
            exercises.to_str().expect("a UTF-8 temp path"),
        ],
        &out,
    );
    assert_eq!(run.status.code(), Some(1), "{text}");
    assert!(took < Duration::from_secs(240), "{took:?}\n{text}");
    let refused = |id: &str, what: &str| {
        let l = line(&text, id);
        assert!(l.contains("FAIL  does not compile"), "{id}: {text}");
        let message = text.split(l).nth(1).unwrap_or("");
        let message = message.split("\n  ch").next().unwrap_or("");
        assert!(message.contains(what), "{id}: {what}: {message}");
    };
    refused("ch1/project_point", "may not use `extern`");
    refused("ch1/draw_edges", "may not use `std` other than as a path");
    refused("ch2/depth_test", "may not use `std::process`");
    refused("ch3/ray_plane", "`ray_plane`");
    refused("ch3/moller_trumbore", "may not use `std::thread`");
    refused("ch3/bvh_traversal", "may not use `std::thread`");
    refused("ch4/sphere_sdf", "no_mangle");
    refused("ch4/gradient_normal", "may not use `include_str!`");
    // The scene's own count is the grader's: the crate the file is built
    // in does not reach it.
    refused("ch6/path_radiance", "reset_tally");

    // What the student's code prints is never read as a grade.
    let look_at = line(&text, "ch1/look_at");
    assert!(look_at.contains("FAIL  error"), "{look_at}");
    assert_eq!(text.matches("ch1/look_at ").count(), 1, "{text}");
    let memory = line(&text, "ch2/edge_function");
    assert!(
        memory.contains("FAIL") && memory.contains("out of memory"),
        "{memory}"
    );
    let flood = line(&text, "ch2/barycentric");
    assert!(
        flood.contains("FAIL") && flood.contains("printed more than"),
        "{flood}"
    );
    let escape = line(&text, "ch3/barycentric_inside");
    assert!(
        escape.contains("FAIL") && escape.contains("gotcha"),
        "{escape}"
    );
    assert!(escape.contains("\\u{1b}[2J"), "escaped: {escape}");
    assert!(!text.contains('\x1b'), "no raw escape reaches the terminal");
    // The panic names the student's file and line.
    assert!(
        escape.contains("ch3-ray-triangle/exercises/barycentric_inside.rs:3:"),
        "{escape}"
    );
    assert!(line(&text, "ch6/mis_weight").contains("FAIL"), "{text}");
    let raster = line(&text, "ch2/rasterize_triangle");
    assert!(raster.contains("FAIL"), "{raster}");
    assert!(
        text.contains("not a regular file"),
        "the links refused: {text}"
    );
    // Every exercise graded failed (or was not started).
    let graded = text
        .lines()
        .find_map(|l| {
            l.strip_prefix("grading ")?
                .split(' ')
                .next()?
                .parse::<usize>()
                .ok()
        })
        .expect("the count of exercises graded");
    assert!(graded >= 14, "{text}");
    assert!(text.contains(&format!("0 of {graded} passed")), "{text}");

    // The sandbox holds whole where CI runs (Linux with Landlock and
    // seccomp): no file system, no process, thread or socket.
    if std::env::var_os("CI").is_some() {
        assert!(
            !text.contains("cannot give your code's process"),
            "CI's kernel confines the student's process: {text}"
        );
    }
    // Nothing left running, nothing written late, through a link or by a
    // build script of the student's.
    std::thread::sleep(Duration::from_secs(3));
    assert_eq!(processes_with_marker(), Vec::<String>::new());
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "untouched");
    assert!(!exercises.join(format!("{MARKER}-build")).exists());
    let json = std::fs::read_to_string(out.join("results.json")).unwrap();
    assert!(json.contains("\"score\": 0,"), "{json}");
    assert!(
        json.contains(&format!("\"max_score\": {graded},")),
        "{json}"
    );
}

/// Case 11: links where the grader writes its own files (results.json,
/// the hints seen) are refused, never written through, and leave their
/// targets as they were.
#[cfg(unix)]
#[test]
fn the_grader_never_writes_through_a_link() {
    let out = common::temp_dir("hostile-links");
    let outside_dir = common::temp_dir("hostile-links-outside");
    let outside = outside_dir.join("target.txt");
    std::fs::write(&outside, "untouched").unwrap();
    for name in ["results.json", "hints-seen.txt"] {
        std::os::unix::fs::symlink(&outside, out.join(name)).unwrap();
    }
    let run = Command::new(env!("CARGO_BIN_EXE_grade"))
        .args(["--reference", "ch1/project_point", "--json", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(2));
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(err.contains("not a regular file"), "{err}");
    let run = Command::new(env!("CARGO_BIN_EXE_grade"))
        .args(["--hint", "ch1/look_at", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "untouched");
    // The output folder itself a link: refused too.
    let linked = common::temp_dir("hostile-links-dir");
    let target = common::temp_dir("hostile-links-dir-target");
    let out = linked.join("grade");
    std::os::unix::fs::symlink(&target, &out).unwrap();
    let run = Command::new(env!("CARGO_BIN_EXE_grade"))
        .args(["--reference", "ch1/project_point", "--json", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(2));
    assert!(!target.join("results.json").exists());
}

#[cfg(unix)]
#[test]
fn results_json_goes_only_to_a_regular_file() {
    let dir = common::temp_dir("hostile-fifo");
    let fifo = dir.join("results.json");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let start = Instant::now();
    let run = Command::new(env!("CARGO_BIN_EXE_grade"))
        .args(["--reference", "ch1/project_point", "--json"])
        .arg(&fifo)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(start.elapsed() < Duration::from_secs(60));
    assert_eq!(run.status.code(), Some(2));
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(err.contains("not a regular file"), "{err}");
    // By default it goes into the output folder, written whole.
    let dir = common::temp_dir("hostile-fifo-not");
    let run = Command::new(env!("CARGO_BIN_EXE_grade"))
        .args(["--reference", "ch1/project_point", "--json", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(run.status.success());
    let json = std::fs::read_to_string(dir.join("results.json")).unwrap();
    assert!(json.trim_end().ends_with('}'), "{json}");
    assert!(json.contains("\"score\": 1,"), "{json}");
}
