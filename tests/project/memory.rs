//! Issue 48: memory refused before it runs out. Under an address-space
//! limit (`ulimit -v`, as a course's sandbox or a CI runner sets) a
//! 16384² image aborted on allocation (exit 134) and so did reading a large
//! scene; both are now refused with an error that names the limit (the
//! image only where not even a band of it fits). Each
//! chapter's estimate is an upper bound: a run given its estimate (plus
//! room for what the process had mapped when it checked) completes.

use std::path::Path;
use std::process::{Command, Output};

use raystep::core::memory::{Run, BASE_BYTES};
use raystep::scene::Scene;

use crate::common;

/// `bin` with `args` under an address-space limit of `kib` KiB.
fn limited(kib: u64, bin: &str, args: &[&str], out: &Path) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {kib} && exec \"$0\" \"$@\""))
        .arg(bin)
        .args(args)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

fn bin(chapter: u32) -> &'static str {
    [
        env!("CARGO_BIN_EXE_ch1"),
        env!("CARGO_BIN_EXE_ch2"),
        env!("CARGO_BIN_EXE_ch3"),
        env!("CARGO_BIN_EXE_ch4"),
        env!("CARGO_BIN_EXE_ch5"),
        env!("CARGO_BIN_EXE_ch6"),
    ][chapter as usize - 1]
}

/// Every chapter renders a huge image in bands (tests/project/bands.rs);
/// under a limit that leaves room for not even the thinnest band (16
/// rows) it is refused.
#[test]
fn a_huge_image_is_refused_under_an_address_space_limit() {
    let dir = common::temp_dir("memory-huge");
    for chapter in [1, 3, 6] {
        let args = ["--width", "16384", "--height", "16384"];
        let run = limited(300 << 10, bin(chapter), &args, &dir.join("out"));
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "chapter {chapter}: {stderr}");
        assert!(
            stderr.contains("16384x16384 pixels, 16 rows at a time")
                && stderr.contains("address-space limit"),
            "{stderr}"
        );
    }
    assert!(!dir.join("out").exists());
}

#[test]
fn a_large_file_is_refused_before_it_is_read_under_a_limit() {
    let dir = common::temp_dir("memory-file");
    // 40 MB of vertices: about 300 MiB to read and parse.
    let line = "v 0.123456 0.654321 0.777777\n";
    let obj = format!(
        "{}v 1 0 0\nv 0 1 0\nf 1 2 3\n",
        line.repeat(40_000_000 / line.len())
    );
    common::write_files(
        &dir,
        &[
            ("big.obj", &obj),
            ("big.toml", "[[objects]]\nmesh = \"big.obj\"\n"),
        ],
    );
    let scene = dir.join("big.toml");
    let args = [
        "--scene",
        scene.to_str().unwrap(),
        "--width",
        "8",
        "--height",
        "8",
        "--threads",
        "1",
    ];
    // One render thread, so the room does not depend on the machine's
    // cores: with its allocator arena and the signal thread's mapped
    // before the first check (`init_threads`, `clean_up_on_signals`), the
    // program has about 144 MiB mapped there. 320 MiB then leaves about
    // 176 MiB: room for the scene file (64 MiB asked) and not for the OBJ
    // (38 MiB × 6 + 64 MiB = 292 MiB), with a margin of over 100 MiB
    // either way.
    let run = limited(320 << 10, bin(1), &args, &dir.join("out"));
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("big.obj: reading this 38 MiB file") && stderr.contains("address-space"),
        "{stderr}"
    );
}

/// Every chapter at 1024x1024 (chapter 6 with its bounce layers, its
/// largest) completes under its own estimate plus 192 MiB, what the
/// process has mapped when it checks; an estimate too low would abort.
#[test]
fn each_chapters_estimate_is_enough_for_its_run() {
    let dir = common::temp_dir("memory-enough");
    let mut scene = Scene::builtin();
    (scene.camera.width, scene.camera.height) = (1024, 1024);
    for (k, chapter) in raystep::chapters::all().into_iter().enumerate() {
        let info = chapter.info();
        let need = Run {
            pixels: 1024 * 1024,
            triangles: scene.triangle_count() as u64,
            per_pixel: info.bytes_per_pixel,
            per_triangle: info.bytes_per_triangle,
        }
        .estimate();
        assert!(need > BASE_BYTES);
        let kib = (need + (192 << 20)) >> 10;
        let args = ["--width", "1024", "--height", "1024", "--spp", "1"];
        let run = limited(kib, bin(k as u32 + 1), &args, &dir.join(format!("out{k}")));
        assert!(
            run.status.success(),
            "chapter {}: under {} MiB: {:?} {}",
            k + 1,
            kib >> 10,
            run.status,
            String::from_utf8_lossy(&run.stderr)
        );
    }
}
