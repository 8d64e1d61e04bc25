//! A full disk is an error, never a short file dressed as success: the
//! chapter binary runs with a file-size limit (the shell's `ulimit -f`,
//! with SIGXFSZ ignored so the write fails with EFBIG as on a full disk),
//! must exit non-zero naming the file, and leave no image, whole or cut,
//! and no temporary behind. (PNGs used to go through a buffered writer
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
