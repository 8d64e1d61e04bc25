//! Issue 20: hostile and extreme input. Every item has a test here (the
//! BVH's in `hostile_bvh`, the fuzzer in `fuzz`): limits with clear errors,
//! validation in f32 units, exact array lengths, OBJ errors with line
//! numbers, outputs written as a set, control characters escaped.

use std::path::Path;
use std::process::Command;

use clap::Parser;
use raystep::core::film::{temporaries_on_disk, write_atomically, Film, OutputSet};
use raystep::core::run::{init_threads, max_threads, CommonArgs};
use raystep::core::text::escape;
use raystep::scene::obj::{parse_obj, parse_obj_limited};
use raystep::scene::{read_limited, Limits, Scene};

use crate::common;

const TRI_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

fn parse(text: &str) -> Result<Scene, String> {
    let read = |rel: &str| -> Result<(String, String), (String, String)> {
        match rel {
            "tri.obj" => Ok(("tri.obj".into(), TRI_OBJ.into())),
            _ => Err((rel.into(), "not found".into())),
        }
    };
    Scene::parse(text, "t", "t.toml", &read).map_err(|e| e.to_string())
}

/// The error `text` gives; it must mention every part.
fn error(text: &str, parts: &[&str]) {
    match parse(text) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => {
            for p in parts {
                assert!(e.contains(p), "error `{e}` does not mention `{p}`\n{text}");
            }
        }
    }
}

const SPHERE: &str = "[[objects]]\nshape = \"sphere\"\n";

#[test]
fn negative_light_is_refused_naming_the_key() {
    for (light, key) in [
        (
            "type = \"environment\"\nradiance = [-1, 1, 1]",
            "lights[0].radiance",
        ),
        (
            "type = \"sky\"\nzenith = [1, 1, 1]\nhorizon = [1, 1, 1]\nground = [-1, 0, 0]",
            "lights[0].ground",
        ),
        (
            "type = \"directional\"\ndirection = [0, -1, 0]\nirradiance = [-1, 1, 1]",
            "lights[0].irradiance",
        ),
        (
            "type = \"point\"\nposition = [0, 2, 0]\nintensity = [-5, 5, 5]",
            "lights[0].intensity",
        ),
    ] {
        error(
            &format!("{SPHERE}[[lights]]\n{light}\n"),
            &[key, "negative"],
        );
    }
}

#[test]
fn zero_directions_and_bad_cones_are_refused() {
    error(
        &format!("{SPHERE}[[lights]]\ntype = \"directional\"\ndirection = [0, 0, 0]\nirradiance = [1, 1, 1]\n"),
        &["lights[0].direction", "zero vector"],
    );
    let spot = |dir: &str, cone: &str, falloff: &str| {
        format!(
            "{SPHERE}[[lights]]\ntype = \"spot\"\nposition = [0, 2, 0]\ndirection = {dir}\nintensity = [1, 1, 1]\ncone_degrees = {cone}\nfalloff_degrees = {falloff}\n"
        )
    };
    error(&spot("[0, 0, 0]", "30", "5"), &["lights[0].direction"]);
    for cone in ["-10", "0", "200"] {
        error(
            &spot("[0, -1, 0]", cone, "0"),
            &["lights[0].cone_degrees", "(0, 180]"],
        );
    }
    error(
        &spot("[0, -1, 0]", "30", "40"),
        &["lights[0].falloff_degrees", "[0, 30]"],
    );
    assert!(parse(&spot("[0, -1, 0]", "30", "5")).is_ok());
}

#[test]
fn values_finite_in_f64_but_not_in_f32_are_refused() {
    error(
        &format!("[[materials]]\nname = \"lamp\"\nemission = [1e39, 10, 10]\n{SPHERE}material = \"lamp\"\n"),
        &["materials[0] (\"lamp\").emission", "1e20"],
    );
    error(
        &format!("{SPHERE}[[lights]]\ntype = \"point\"\nposition = [0, 1e39, 0]\nintensity = [1, 1, 1]\n"),
        &["lights[0].position", "1e12"],
    );
    error(
        &format!("[camera]\neye = [0, 1, 1e30]\n{SPHERE}"),
        &["[camera]", "`eye`", "1e12"],
    );
    error(
        &format!("{SPHERE}radius = 1e39\n"),
        &["objects[0].radius", "1e12"],
    );
    error(&format!("{SPHERE}radius = 1e-50\n"), &["objects[0].radius"]);
    error(
        &format!("{SPHERE}translate = [0, 0, 1e13]\n"),
        &["objects[0].translate", "1e12"],
    );
    error(
        &format!("{SPHERE}scale = 1e-50\n"),
        &["objects[0].scale", "non-zero"],
    );
    error(
        &format!("{SPHERE}scale = 1e10\nradius = 1e5\n"),
        &["objects[0]", "vertex", "1e12"],
    );
}

#[test]
fn extra_array_elements_are_an_error_naming_the_key() {
    let cases = [
        ("[camera]\neye = [0, 1, 5, 1]\n", "`eye`"),
        (
            "[[materials]]\nname = \"red\"\nreflectance = [0.8, 0.2, 0.2, 99]\n",
            "`reflectance`",
        ),
        ("[[objects]]\nshape = \"box\"\ntranslate = [0, 2.5, 0, \"junk\"]\n", "line 3"),
        (
            "[[objects]]\nshape = \"box\"\nmatrix = [[1, 0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n",
            "`matrix`",
        ),
        ("[[objects]]\nshape = \"box\"\nscale = [1, 2, 3, 4]\n", "`scale`"),
        (
            "[[objects]]\nshape = \"box\"\nrotate = { axis = [0, 1, 0, 0], degrees = 30 }\n",
            "`axis`",
        ),
        (
            "[[objects]]\nshape = \"box\"\n[[lights]]\ntype = \"point\"\nposition = [0, 1, 0]\nintensity = [1, 1, 1, 1]\n",
            "`intensity`",
        ),
    ];
    for (text, key) in cases {
        error(text, &["t.toml", key]);
    }
    error("[camera]\neye = [0, 1]\n", &["`eye`", "exactly 3", "got 2"]);
    // Exactly the right length still loads.
    assert!(
        parse("[camera]\neye = [0, 1, 5]\n[[objects]]\nshape = \"box\"\nscale = [1, 2, 3]\n")
            .is_ok()
    );
}

#[test]
fn obj_errors_name_the_line() {
    let e = |text: &str| parse_obj(text, "m.obj").unwrap_err().to_string();
    let m = e("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//x 2 3\n");
    assert!(
        m.contains("m.obj:4") && m.contains("`x`") && m.contains("normal"),
        "{m}"
    );
    let m = e("v 1 2 3 4 5 6 7\nf 1 1 1\n");
    assert!(m.contains("m.obj:1") && m.contains("got 7 numbers"), "{m}");
    let m = e("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/4 2 3\n");
    assert!(
        m.contains("m.obj:4") && m.contains("texture coordinate 4"),
        "{m}"
    );
    let m = e("v 0 0 0 0\nf 1 1 1\n");
    assert!(m.contains("m.obj:1") && m.contains("weight"), "{m}");
    let m = e("v 0 0 1e39\nf 1 1 1\n");
    assert!(m.contains("m.obj:1") && m.contains("finite"), "{m}");
    // CR-only line endings (classic Mac) load like any other.
    let mesh = parse_obj("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r", "cr.obj").unwrap();
    assert_eq!(mesh.triangles.len(), 1);
    let mesh = parse_obj("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n", "crlf.obj").unwrap();
    assert_eq!(mesh.triangles.len(), 1);
    // v x y z w and v x y z r g b (on every vertex) are valid.
    assert!(parse_obj("v 0 0 0\nv 1 0 0 2\nv 0 1 0\nf 1 2 3\n", "w.obj").is_ok());
    let rgb = "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n";
    assert!(parse_obj(rgb, "rgb.obj").is_ok());
    let m = e("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    assert!(
        m.contains("m.obj:2") && m.contains("every vertex or none"),
        "{m}"
    );
}

#[test]
fn triangle_and_file_size_limits_name_the_bound() {
    let obj = format!("v 0 0 0\nv 1 0 0\nv 0 1 0\n{}", "f 1 2 3\n".repeat(11));
    let m = parse_obj_limited(&obj, "big.obj", 10)
        .unwrap_err()
        .to_string();
    assert!(
        m.contains("big.obj:14") && m.contains("more than 10 triangles"),
        "{m}"
    );
    // A convex polygon of 13 corners: a fan of 11 triangles.
    let mut polygon = String::new();
    for k in 0..13 {
        let a = std::f64::consts::TAU * k as f64 / 13.0;
        polygon.push_str(&format!("v {} {} 0\n", a.cos(), a.sin()));
    }
    polygon.push_str("f 1 2 3 4 5 6 7 8 9 10 11 12 13\n");
    let m = parse_obj_limited(&polygon, "fan.obj", 10)
        .unwrap_err()
        .to_string();
    assert!(
        m.contains("fan.obj:14") && m.contains("--max-triangles"),
        "{m}"
    );
    let read = |_: &str| -> Result<(String, String), (String, String)> { unreachable!() };
    let limits = Limits {
        max_triangles: 1000,
        ..Limits::default()
    };
    let m = Scene::parse_with(
        "[[objects]]\nshape = \"sphere\"\nsubdivisions = 5\n",
        "t",
        "t.toml",
        &read,
        &limits,
    )
    .unwrap_err()
    .to_string();
    assert!(m.contains("objects[0]") && m.contains("1000"), "{m}");

    let dir = common::temp_dir("hostile-size");
    let big = dir.join("big.toml");
    std::fs::write(&big, "#".repeat(3 << 20)).unwrap();
    let m = read_limited(&big, 2 << 20).unwrap_err().to_string();
    assert!(
        m.contains("big.toml") && m.contains("2 MiB") && m.contains("--max-file-mib"),
        "{m}"
    );
    let limits = Limits {
        max_file_bytes: 2 << 20,
        ..Limits::default()
    };
    assert!(Scene::load_with(&big, &limits).is_err());
    // An endless file is refused at once, not read until memory runs out.
    if Path::new("/dev/zero").exists() {
        let start = std::time::Instant::now();
        let m = Scene::load(Path::new("/dev/zero")).unwrap_err().to_string();
        assert!(
            m.contains("/dev/zero") && m.contains("not a regular file"),
            "{m}"
        );
        assert!(start.elapsed().as_secs_f64() < 5.0);
    }
}

#[derive(Parser)]
struct Cli {
    #[command(flatten)]
    common: CommonArgs,
}

#[test]
fn flags_are_bounded_and_errors_name_the_flag() {
    let e = |args: &[&str]| match Cli::try_parse_from(["ch1"].iter().chain(args)) {
        Ok(_) => panic!("{args:?} accepted"),
        Err(e) => e.to_string(),
    };
    let m = e(&["--width", "-5"]);
    assert!(m.contains("--width") && m.contains("-5"), "{m}");
    assert!(e(&["--height", "100000"]).contains("--height"));
    assert!(e(&["--spp", "2000000"]).contains("--spp"));
    assert!(e(&["--threads", "-1"]).contains("--threads"));
    let ok = Cli::try_parse_from(["ch1", "--max-file-mib", "1024", "--width", "16"]).unwrap();
    assert_eq!(ok.common.limits().max_file_bytes, 1024 << 20);
    // A file is read whole: not more than a gibibyte in one piece.
    let m = e(&["--max-file-mib", "1025"]);
    assert!(
        m.contains("--max-file-mib") && m.contains("1..=1024"),
        "{m}"
    );

    let m = init_threads(Some(5000)).unwrap_err().to_string();
    assert!(
        m.contains("--threads") && m.contains(&max_threads().to_string()),
        "{m}"
    );
    assert!(init_threads(Some(0)).is_err());
}

#[test]
fn raystep_refuses_a_missing_scenes_folder() {
    let out = Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(["--headless", "--scenes", "/nonexistent/scenes"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("/nonexistent/scenes") && stderr.contains("no such folder"),
        "{stderr}"
    );
}

#[test]
fn control_characters_never_reach_the_terminal() {
    let name = "\u{1b}[2J\u{1b}[H\u{1b}[?1049l";
    let text = format!(
        "[[materials]]\nname = \"{}\"\n[[objects]]\nshape = \"box\"\nmaterial = \"missing\\u001b]0;x\\u0007\"\n",
        "\\u001b[2J\\u001b[H\\u001b[?1049l"
    );
    let e = parse(&text).unwrap_err();
    assert!(!e.chars().any(|c| c.is_control()), "{e:?}");
    assert!(e.contains(&*escape(name)), "{e}");
    // Through a chapter binary: nothing raw on stderr or stdout.
    let dir = common::temp_dir("hostile-escape");
    common::write_files(&dir, &[("esc\u{1b}[2J.toml", &text)]);
    let out = Command::new(env!("CARGO_BIN_EXE_ch1"))
        .arg("--scene")
        .arg(dir.join("esc\u{1b}[2J.toml"))
        .args(["--width", "8", "--height", "8", "--out"])
        .arg(dir.join("out"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains('\u{1b}'), "{stderr:?}");
    assert!(stderr.contains("\\u{1b}[2J"), "{stderr:?}");
}

/// Issue 48: clap's own messages quote the arguments as given; a second
/// file name from `--scene dir/*.toml`, or a bad value, printed raw escape
/// sequences. Every binary's message now shows them written out.
#[test]
fn command_line_errors_show_control_characters_written_out() {
    let hostile = "b\u{1b}[31mred\u{1b}]0;title\u{7}.toml";
    for (bin, args) in [
        (
            env!("CARGO_BIN_EXE_ch1"),
            vec!["--scene", "a.toml", hostile],
        ),
        (env!("CARGO_BIN_EXE_ch6"), vec!["--width", "\u{1b}[2J"]),
        (env!("CARGO_BIN_EXE_raystep"), vec!["--\u{1b}[?1049h"]),
    ] {
        let out = Command::new(bin).args(&args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            !stderr.chars().any(|c| c.is_control() && c != '\n'),
            "{stderr:?}"
        );
        assert!(stderr.contains("\\u{1b}["), "{args:?}: {stderr:?}");
    }
}

/// Issue 48: a 200 MB object name made chapter 1 print 839 MB. Names in
/// a scene have at most 256 characters (a longer one is refused at its
/// key, the message quoting its start), an unknown material's name is
/// quoted cut, and report table cells are cut at 1,024 characters.
#[test]
fn names_are_bounded_in_messages_and_reports() {
    let long = "n".repeat(300_000);
    for (text, key) in [
        (
            format!("[[objects]]\nshape = \"box\"\nname = \"{long}\"\n"),
            "objects[0].name",
        ),
        (
            format!("[[materials]]\nname = \"{long}\"\n"),
            "materials[0].name",
        ),
        (
            format!("[[sdfs]]\ntype = \"sphere\"\nname = \"{long}\"\n"),
            "sdfs[0].name",
        ),
        (
            format!("[[objects]]\nshape = \"box\"\nmaterial = \"{long}\"\n"),
            "objects[0].material",
        ),
    ] {
        let e = parse(&text).unwrap_err();
        assert!(
            e.contains(key) && e.contains("300000 characters") && e.len() < 400,
            "{}",
            &e[..e.len().min(400)]
        );
    }
    // 256 characters: accepted, and the report stays small.
    let name = "m".repeat(256);
    let dir = common::temp_dir("hostile-names");
    common::write_files(
        &dir,
        &[(
            "named.toml",
            &format!("[[objects]]\nshape = \"box\"\nname = \"{name}\"\n"),
        )],
    );
    let out = Command::new(env!("CARGO_BIN_EXE_ch1"))
        .arg("--scene")
        .arg(dir.join("named.toml"))
        .args(["--width", "8", "--height", "8", "--out"])
        .arg(dir.join("out"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stdout.len() < 32 << 10, "{} bytes", out.stdout.len());
}

/// Issue 48: chapter 5's cost grows with lights x SDF nodes (a shadow ray
/// per light per sample, every SDF node at every step of it), with no
/// word. 70 lights x 64 moved spheres (128 nodes) are now warned about, with an estimate,
/// before anything renders; the shipped SDF scene is not.
#[test]
fn chapter_5_warns_about_lights_times_sdfs() {
    let mut text = String::new();
    for k in 0..70 {
        text.push_str(&format!(
            "[[lights]]\ntype = \"point\"\nposition = [{}, 3, 3]\nintensity = [1, 1, 1]\n",
            k as f32 * 0.1
        ));
    }
    for k in 0..64 {
        text.push_str(&format!(
            "[[sdfs]]\ntype = \"sphere\"\ntranslate = [{}, 0, -2]\nradius = 0.05\n",
            k as f32 * 0.1 - 3.2
        ));
    }
    let dir = common::temp_dir("hostile-shadow-work");
    common::write_files(&dir, &[("many.toml", &text)]);
    let run = |scene: &Path| {
        let out = Command::new(env!("CARGO_BIN_EXE_ch5"))
            .arg("--scene")
            .arg(scene)
            .args(["--width", "4", "--height", "4", "--out"])
            .arg(dir.join("out"))
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    let warned = run(&dir.join("many.toml"));
    assert!(
        warned.contains("70 lights x 128 SDF shapes") && warned.contains("may take about"),
        "{warned}"
    );
    let shipped = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/sdf-lit.toml");
    assert!(!run(&shipped).contains("warning"));
}

#[test]
fn an_output_set_appears_whole_or_not_at_all() {
    let dir = common::temp_dir("hostile-set");
    let film = Film::new(2, 2);
    let (a, b) = (dir.join("a.png"), dir.join("b.exr"));
    {
        let _set = OutputSet::begin();
        film.write_png(&a).unwrap();
        film.write_exr(&b).unwrap();
        assert!(!a.exists() && !b.exists(), "staged files appeared early");
        // Dropped without commit (an error or a panic): nothing is left.
    }
    let leftovers: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
    let set = OutputSet::begin();
    film.write_png(&a).unwrap();
    write_atomically(&dir.join("c.csv"), |tmp| {
        std::fs::write(tmp, "x\n").map_err(|e| e.to_string())
    })
    .unwrap();
    set.commit().unwrap();
    assert!(a.exists() && dir.join("c.csv").exists());
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(names.iter().all(|n| !n.starts_with('.')), "{names:?}");
    assert_eq!(temporaries_on_disk(), 0);
}

/// SIGTERM, SIGINT and SIGHUP at many moments of a ch6 run (which writes an image,
/// an EXR and a dozen layer files): afterwards there is never a temporary
/// file, and the set of outputs is either complete or absent.
#[cfg(unix)]
#[test]
fn interrupted_runs_leave_all_outputs_or_none_and_no_temporaries() {
    let dir = common::temp_dir("hostile-signal");
    // The full set, from an uninterrupted run.
    let run = |out: &Path| {
        Command::new(env!("CARGO_BIN_EXE_ch6"))
            .args([
                "--width",
                "24",
                "--height",
                "24",
                "--spp",
                "2",
                "--threads",
                "1",
                "--out",
            ])
            .arg(out)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap()
    };
    let full = dir.join("full");
    let began = std::time::Instant::now();
    assert!(run(&full).wait().unwrap().success());
    // Signals spread over the whole run, writing included.
    let duration = began.elapsed();
    let list = |d: &Path| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .map(|r| {
                r.map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                    .collect()
            })
            .unwrap_or_default();
        v.sort();
        v
    };
    let complete = list(&full);
    assert!(complete.len() > 5, "{complete:?}");
    let (mut whole, mut none) = (0, 0);
    for k in 0..16u64 {
        let out = dir.join(format!("run{k}"));
        let mut child = run(&out);
        std::thread::sleep(duration * k as u32 / 14);
        let signal = ["-TERM", "-INT", "-HUP"][k as usize % 3];
        let _ = Command::new("kill")
            .args([signal, &child.id().to_string()])
            .status();
        let _ = child.wait().unwrap();
        let files = list(&out);
        assert!(
            files.iter().all(|f| !f.starts_with('.')),
            "run {k}: debris {files:?}"
        );
        if files.is_empty() {
            none += 1;
        } else {
            assert_eq!(files, complete, "run {k}: a partial set");
            whole += 1;
        }
    }
    eprintln!("interrupted runs: {whole} complete sets, {none} without outputs");
}

/// Issue 48: temporaries of a run killed with SIGKILL (no handler runs)
/// stayed in the output folder for good. The next run into that folder
/// removes those of processes that no longer run, and leaves a live
/// process's temporaries and every other file.
#[test]
fn temporaries_of_killed_runs_are_swept_by_the_next_run() {
    let dir = common::temp_dir("hostile-stale");
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    // A real run killed in the middle of a long pass: its temporaries may
    // or may not exist yet, so one more, named as its would be, is added.
    let mut child = Command::new(env!("CARGO_BIN_EXE_ch6"))
        .args([
            "--spp", "100000", "--width", "64", "--height", "64", "--out",
        ])
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let killed = child.id();
    std::thread::sleep(std::time::Duration::from_millis(300));
    child.kill().unwrap();
    child.wait().unwrap();
    let stale = out.join(format!(
        ".{killed}.tmp0123456789abcdef.0-ch6-cornell-box.png"
    ));
    let stale_copy = out.join(format!(".{killed}.old1-ch6-cornell-box.exr"));
    // This test process runs: its temporary stays.
    let live = out.join(format!(
        ".{}.tmp00000000000000ff.2-x.png",
        std::process::id()
    ));
    let other = out.join(".notes");
    for f in [&stale, &stale_copy, &live, &other] {
        std::fs::write(f, "x").unwrap();
    }
    let run = Command::new(env!("CARGO_BIN_EXE_ch1"))
        .args(["--width", "8", "--height", "8", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let left: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.'))
        .collect();
    assert!(live.exists() && other.exists(), "{left:?}");
    assert!(
        left.iter().all(|n| !n.starts_with(&format!(".{killed}."))),
        "{left:?}"
    );
}

#[test]
fn too_many_samples_are_refused_before_anything_renders() {
    let parent = common::temp_dir("hostile-samples");
    let dir = parent.join("out");
    let settings = raystep::core::stage::Settings {
        width: Some(16384),
        height: Some(16384),
        spp: 1_000_000,
        ..Default::default()
    };
    let chapter = raystep::chapters::all()[5];
    let mut sink = Vec::new();
    let start = std::time::Instant::now();
    let e =
        raystep::core::run::run_headless(chapter, Scene::builtin(), &settings, &dir, 8, &mut sink)
            .unwrap_err()
            .to_string();
    assert!(
        e.contains("2^40") && e.contains("--spp") && e.contains("268435456 pixels"),
        "{e}"
    );
    assert!(
        start.elapsed().as_secs_f64() < 10.0,
        "refused only after rendering"
    );
    assert!(!dir.exists());
}

/// Issue 48: chapter 6's `--spp-figure N` renders up to N more samples
/// per pixel; they count towards the sample limit and warning. (The scene
/// has no light, so a run that passes the check stops right after it.)
#[test]
fn the_spp_figure_counts_towards_the_sample_limit_and_warning() {
    let dir = common::temp_dir("hostile-spp-figure");
    let file = dir.join("dark.toml");
    std::fs::write(&file, "[[objects]]\nshape = \"box\"\n").unwrap();
    let run = |size: &str, out: &str| {
        let run = Command::new(env!("CARGO_BIN_EXE_ch6"))
            .args(["--spp", "1", "--spp-figure", "1000000", "--final-only"])
            .args(["--width", size, "--height", size, "--scene"])
            .arg(&file)
            .arg("--out")
            .arg(dir.join(out))
            .output()
            .unwrap();
        String::from_utf8_lossy(&run.stderr).into_owned()
    };
    // 4096^2 pixels x (1 + 524,288) samples: past 2^40.
    let refused = run("4096", "big");
    assert!(
        refused.contains("2^40") && refused.contains("524289 samples per pixel"),
        "{refused}"
    );
    // 64^2 x 524,289: past the warning's 2^30.
    let warned = run("64", "small");
    assert!(
        warned.contains("warning: ") && warned.contains("524289 per pixel"),
        "{warned}"
    );
}

/// Found by the fuzzer: chapter 5's "can anything cast a shadow?" test
/// compared every vertex with every face, seconds for a sphere of 81,920
/// triangles and a minute for the largest one a scene may ask for. Above a
/// fixed amount of work it now answers "maybe" (and traces shadow rays).
#[test]
fn the_shadow_question_stays_cheap_on_a_fine_sphere() {
    use raystep::ch5_reflection::shadowing::scene_cannot_shadow;
    let fine = parse("[[objects]]\nshape = \"sphere\"\nsubdivisions = 6\n").unwrap();
    let start = std::time::Instant::now();
    assert!(!scene_cannot_shadow(&fine));
    assert!(start.elapsed().as_secs_f64() < 1.0);
    let coarse = parse("[[objects]]\nshape = \"sphere\"\nsubdivisions = 3\n").unwrap();
    assert!(scene_cannot_shadow(&coarse));
}
