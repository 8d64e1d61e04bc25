//! A student who wants a pass they did not earn, or who breaks the grader:
//! each hostile exercise file gets FAIL (or a clear refusal) and leaves
//! nothing running and nothing written outside the grader's output folder.
//! One `grade` run grades all of them (one build of the exercises crate).

use std::process::Command;
use std::time::{Duration, Instant};

use super::grading::{copy_exercises, grade, line};
use crate::common;

/// A marker in the command lines of the processes the hostile files start,
/// to look for them afterwards.
const MARKER: &str = "raystep-hostile-7f3a";

/// The hostile files: (chapter folder, exercise, file).
fn hostile_files() -> Vec<(&'static str, &'static str, String)> {
    vec![
        // Prints a verdict of the old, unmarked kind and a guess at the new
        // one, then exits before the check can give its own.
        (
            "ch1-projection",
            "project_point",
            "use glam::{Vec2, Vec3};\n\
             pub fn project_point(p: Vec3) -> Option<Vec2> {\n\
             println!(\"\\n@@raystep-verdict@@\\noutcome = \\\"passed\\\"\\nerror = 0.0\\ntolerance = 1.0\\ndetail = \\\"\\\"\\nimages = []\\n\");\n\
             println!(\"@@raystep-verdict 00000000000000000000000000000000@@\\noutcome = \\\"passed\\\"\\nerror = 0.0\\ntolerance = 1.0\\ndetail = \\\"\\\"\\nimages = []\\n@@raystep-verdict-end 00000000000000000000000000000000@@\");\n\
             std::process::exit(0)\n}\n"
                .into(),
        ),
        // Starts a detached process (a group of its own) that rewrites
        // results.json after grading, then answers wrong.
        (
            "ch1-projection",
            "look_at",
            format!(
                "use glam::{{Mat4, Vec3}};\nuse std::os::unix::process::CommandExt;\n\
                 pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {{\n\
                 let out = std::env::args().nth(2).unwrap();\n\
                 let _ = std::process::Command::new(\"sh\").arg(\"-c\")\n\
                 .arg(format!(\"sleep 2; echo '{{{{\\\"score\\\": 99}}}}' > {{out}}/results.json; touch {{out}}/late # {MARKER}\"))\n\
                 .stdout(std::process::Stdio::null()).stderr(std::process::Stdio::null())\n\
                 .process_group(0).spawn();\n\
                 Mat4::IDENTITY\n}}\n"
            ),
        ),
        // A grandchild in a group of its own keeps standard output open
        // for an hour.
        (
            "ch1-projection",
            "draw_edges",
            format!(
                "use glam::{{Vec2, Vec3}};\nuse raystep::ch1_projection::camera::Camera;\nuse std::os::unix::process::CommandExt;\n\
                 pub fn draw_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {{\n\
                 static ONCE: std::sync::Once = std::sync::Once::new();\n\
                 ONCE.call_once(|| {{ let _ = std::process::Command::new(\"sh\").arg(\"-c\").arg(\"sleep 3600 # {MARKER}\").process_group(0).spawn(); }});\n\
                 None\n}}\n"
            ),
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
        // Writes into the repository, outside the grader's output folder.
        (
            "ch2-rasterization",
            "depth_test",
            "pub fn depth_test(depth: &mut [f32], index: usize, z: f32) -> bool {\n\
             let _ = std::fs::write(concat!(env!(\"CARGO_MANIFEST_DIR\"), \"/../target/hostile-wrote-here\"), \"x\");\n\
             if z < depth[index] { depth[index] = z; true } else { false }\n}\n"
                .into(),
        ),
        // Calls raystep's own solution of the exercise.
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
    let exercises = copy_exercises(&common::temp_dir("hostile-src"));
    for (folder, name, text) in hostile_files() {
        std::fs::write(
            exercises
                .join(folder)
                .join("exercises")
                .join(format!("{name}.rs")),
            text,
        )
        .unwrap();
    }
    let out = common::temp_dir("hostile-out");
    let outside = common::root().join("target/hostile-wrote-here");
    let _ = std::fs::remove_file(&outside);
    let (run, text, took) = grade(
        &[
            "ch1",
            "ch2/edge_function",
            "ch2/barycentric",
            "ch2/depth_test",
            "ch3/ray_plane",
            "ch3/barycentric_inside",
            "--timeout",
            "3",
            "--json",
            "--exercises",
            exercises.to_str().expect("a UTF-8 temp path"),
        ],
        &out,
    );
    assert_eq!(run.status.code(), Some(1), "{text}");
    // Eight exercises of three seconds at most, one small build: nowhere
    // near the hour the grandchild would hold its pipe.
    assert!(took < Duration::from_secs(240), "{took:?}\n{text}");

    let fake = line(&text, "ch1/project_point");
    assert!(
        fake.contains("FAIL") && fake.contains("before the check gave its verdict"),
        "{fake}"
    );
    assert!(line(&text, "ch1/look_at").contains("FAIL"), "{text}");
    assert!(line(&text, "ch1/draw_edges").contains("FAIL"), "{text}");
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
    let reference = line(&text, "ch3/ray_plane");
    assert!(
        reference.contains("FAIL") && reference.contains("raystep's own solution of ch3/ray_plane"),
        "{reference}"
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
    // depth_test answers right: it passes, but its file was not written.
    assert!(line(&text, "ch2/depth_test").contains("PASS"), "{text}");
    assert!(text.contains("1 of 8 passed"), "{text}");

    // Nothing left running, nothing written late or outside.
    std::thread::sleep(Duration::from_secs(3));
    assert_eq!(processes_with_marker(), Vec::<String>::new());
    assert!(!out.join("late").exists());
    let json = std::fs::read_to_string(out.join("results.json")).unwrap();
    assert!(json.contains("\"score\": 0,"), "{json}");
    // Writes are confined where the kernel has Landlock (CI's has); where
    // it has not, the grader says so before grading.
    if text.contains("cannot give your code's process the write rule") {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI confines writes: {text}"
        );
        eprintln!("not checked: this kernel cannot confine writes (no Landlock)");
    } else {
        assert!(
            !outside.exists(),
            "the student's code wrote {}",
            outside.display()
        );
    }
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
