//! Outputs on disk: whole or not at all. A full disk is an error, never a
//! short file dressed as success; `--out` naming a file says so; an
//! interrupted headless run leaves no temporaries.
//!
//! The full disk: the chapter binary runs with a file-size limit (the
//! shell's `ulimit -f`, with SIGXFSZ ignored so the write fails with EFBIG
//! as on a full disk), must exit non-zero naming the file, and leave no
//! image, whole or cut, and no temporary behind. (PNGs used to go through a buffered writer
//! whose failed flush on drop was ignored: a 2 KiB limit gave an empty
//! PNG and exit status 0.)

use std::process::Command;

use crate::common;

#[test]
fn a_write_that_runs_out_of_room_fails_and_leaves_nothing() {
    let dir = common::temp_dir("full-disk");
    let out = dir.join("out");
    // 4 blocks: 2 KiB for dash, 4 KiB for bash; the smallest image of
    // this run (16x16) is larger still, its report's CSV smaller.
    let script = format!(
        "ulimit -f 4; trap '' XFSZ; exec {} --width 64 --height 64 --out {}",
        env!("CARGO_BIN_EXE_ch2"),
        out.display()
    );
    let run = Command::new("sh").args(["-c", &script]).output().unwrap();
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success(), "exit 0 with a full disk: {err}");
    assert!(
        err.contains(".png") || err.contains(".exr"),
        "names the file: {err}"
    );
    let left: Vec<String> = std::fs::read_dir(&out)
        .map(|d| {
            d.flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    assert!(
        left.iter()
            .all(|f| !f.ends_with(".png") && !f.contains(".tmp")),
        "left behind: {left:?}"
    );
}

/// `--out` naming a file (or a path through one) says so, instead of the
/// system's bare "File exists".
#[test]
fn an_output_folder_that_is_a_file_is_named() {
    let dir = common::temp_dir("out-is-a-file");
    let file = dir.join("taken");
    std::fs::write(&file, "x").unwrap();
    for out in [file.clone(), file.join("below")] {
        let run = Command::new(env!("CARGO_BIN_EXE_ch1"))
            .args(["--width", "16", "--height", "16", "--out"])
            .arg(&out)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{err}");
        assert!(
            err.contains("taken") && err.contains("is a file, not a folder"),
            "{err}"
        );
    }
}

/// `raystep --headless` cleans up on SIGTERM like the chapter binaries: it
/// exits with 143 and leaves no temporary file (it used to die at once and
/// left temporaries in 6 of 10 runs).
#[cfg(unix)]
#[test]
fn the_headless_run_cleans_up_when_terminated() {
    let out = common::temp_dir("headless-term");
    for wait_ms in [300u64, 700, 1100] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_raystep"))
            .args(["--headless", "--spp", "4000", "--out"])
            .arg(&out)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_millis(wait_ms));
        let killed = Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .unwrap();
        assert!(killed.success());
        let status = child.wait().unwrap();
        assert_eq!(status.code(), Some(143), "after {wait_ms} ms: {status:?}");
        let left: Vec<String> = std::fs::read_dir(&out)
            .map(|d| {
                d.flatten()
                    .map(|e| e.file_name().to_string_lossy().into_owned())
                    .filter(|n| n.contains(".tmp"))
                    .collect()
            })
            .unwrap_or_default();
        assert!(left.is_empty(), "after {wait_ms} ms: {left:?}");
    }
}

/// The width of a PNG, from its header.
fn png_width(path: &std::path::Path) -> u32 {
    let bytes = std::fs::read(path).unwrap();
    u32::from_be_bytes(bytes[16..20].try_into().unwrap())
}

fn ch1(width: u32, out: &std::path::Path) -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_ch1"))
        .args(["--width", &width.to_string(), "--height", "16", "--out"])
        .arg(out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap()
}

/// Two runs into one folder leave one run's set of images, never a mix
/// (they mixed in 7 of 20 tries): each set is renamed into place under a
/// lock on the folder.
#[test]
fn two_runs_into_one_folder_leave_one_whole_set() {
    let out = common::temp_dir("two-runs");
    for _ in 0..6 {
        let (mut a, mut b) = (ch1(16, &out), ch1(24, &out));
        assert!(a.wait().unwrap().success() && b.wait().unwrap().success());
        let widths: Vec<u32> = std::fs::read_dir(&out)
            .unwrap()
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x == "png"))
            .map(|p| png_width(&p))
            .collect();
        assert!(widths.len() >= 2, "{widths:?}");
        assert!(
            widths.iter().all(|w| *w == widths[0]),
            "mixed sets: {widths:?}"
        );
    }
}

/// A rename that fails part-way through a set leaves the folder as it
/// was: the files the set had already replaced are put back (it used to
/// leave half a set). Each image in turn is the one whose rename fails.
#[test]
fn a_rename_failing_part_way_leaves_the_folder_as_it_was() {
    let pngs_in = |out: &std::path::Path| {
        let mut pngs: Vec<_> = std::fs::read_dir(out)
            .unwrap()
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x == "png"))
            .collect();
        pngs.sort();
        pngs
    };
    let first = common::temp_dir("half-set-count");
    assert!(ch1(16, &first).wait().unwrap().success());
    let count = pngs_in(&first).len();
    assert!(count >= 2);
    for k in 0..count {
        let out = common::temp_dir(&format!("half-set-{k}"));
        assert!(ch1(16, &out).wait().unwrap().success());
        let pngs = pngs_in(&out);
        let before: Vec<Vec<u8>> = pngs.iter().map(|p| std::fs::read(p).unwrap()).collect();
        // Image k's place is taken by a folder that is not empty: its
        // rename fails, before or after the others'.
        std::fs::remove_file(&pngs[k]).unwrap();
        std::fs::create_dir(&pngs[k]).unwrap();
        std::fs::write(pngs[k].join("keep"), "x").unwrap();
        let run = Command::new(env!("CARGO_BIN_EXE_ch1"))
            .args(["--width", "24", "--height", "16", "--out"])
            .arg(&out)
            .output()
            .unwrap();
        assert!(!run.status.success());
        for (i, (p, old)) in pngs.iter().zip(&before).enumerate() {
            if i != k {
                assert_eq!(&std::fs::read(p).unwrap(), old, "{} changed", p.display());
            }
        }
        let stray: Vec<String> = std::fs::read_dir(&out)
            .unwrap()
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| n.contains(".tmp") || n.contains(".old"))
            .collect();
        assert!(stray.is_empty(), "{stray:?}");
    }
}
