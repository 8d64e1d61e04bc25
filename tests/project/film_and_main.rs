//! Images leave the renderer whole or not at all; EXR keeps linear values;
//! and the main program runs headless when its output is piped.

use crate::common;
use glam::Vec3;
use raystep::core::film::Film;

fn gradient(w: u32, h: u32) -> Film {
    let mut f = Film::new(w, h);
    for y in 0..h {
        for x in 0..w {
            *f.get_mut(x, y) = Vec3::new(x as f32 / w as f32, y as f32 / h as f32, 2.5);
        }
    }
    f
}

#[test]
fn exr_round_trips_linear_values_above_one() {
    let dir = common::temp_dir("exr");
    let f = gradient(7, 5);
    f.write_exr(&dir.join("g.exr")).unwrap();
    let back = Film::read_exr(&dir.join("g.exr")).unwrap();
    assert_eq!(back, f, "EXR must keep linear f32 values, including 2.5");
}

#[test]
fn png_is_srgb_encoded_and_reads_back_within_quantisation() {
    let dir = common::temp_dir("png");
    let f = gradient(8, 4);
    f.write_png(&dir.join("g.png")).unwrap();
    let back = Film::read_png(&dir.join("g.png")).unwrap();
    for (a, b) in f.pixels.iter().zip(&back.pixels) {
        // Clamped to 1 and quantised to 8 bits in sRGB.
        let want = a.min(Vec3::ONE);
        assert!((want - *b).abs().max_element() < 0.01, "{a} -> {b}");
    }
}

#[test]
fn a_failed_write_leaves_no_file_behind() {
    let dir = common::temp_dir("atomic");
    // A path whose folder is a file cannot be written.
    std::fs::write(dir.join("not-a-dir"), "x").unwrap();
    let target = dir.join("not-a-dir/image.png");
    assert!(gradient(4, 4).write_png(&target).is_err());
    // An encoder that fails half-way leaves neither the target nor a temp file.
    let target = dir.join("half.png");
    let result = raystep::core::film::write_atomically(&target, |tmp| {
        std::fs::write(tmp, b"half an image").unwrap();
        Err("the encoder gave up".into())
    });
    let err = result.unwrap_err().to_string();
    assert!(
        err.contains("half.png") && err.contains("the encoder gave up"),
        "{err}"
    );
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(
        left,
        vec![std::ffi::OsString::from("not-a-dir")],
        "left behind: {left:?}"
    );
    // And a good write replaces an old image in one step.
    std::fs::write(&target, b"old").unwrap();
    gradient(4, 4).write_png(&target).unwrap();
    assert_eq!(Film::read_png(&target).unwrap().width, 4);
}

#[test]
fn the_main_program_summarises_when_piped() {
    let dir = common::temp_dir("main");
    // Few samples for the clean render: this is about the shape of the
    // output, not the picture.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(["--spp", "2"])
        .current_dir(&dir)
        .env("CI", "true")
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "stdout: {text}\nstderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    // One line per chapter, then the clean chapter 6 render and its
    // preview: short enough to read.
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.len() <= 100, "{} lines:\n{text}", lines.len());
    let wide: Vec<&&str> = lines.iter().filter(|l| l.chars().count() > 100).collect();
    assert!(wide.is_empty(), "lines over 100 columns: {wide:#?}");
    for n in 1..=6 {
        let line = lines
            .iter()
            .find(|l| l.starts_with(&format!("ch{n} ")))
            .unwrap_or_else(|| panic!("no line for ch{n}:\n{text}"));
        assert!(
            line.contains(&format!("out/ch{n}-cornell-box.png")),
            "{line}"
        );
    }
    let ch6 = lines.iter().find(|l| l.starts_with("ch6 ")).unwrap();
    assert!(ch6.contains("RMSE"), "chapter 6 has a reference: {ch6}");
    assert!(
        text.contains("ch6 clean: 2 spp, MIS + low-discrepancy"),
        "{text}"
    );
    // The studies stay behind --report.
    assert!(!text.contains("Stiff and extreme cases"), "{text}");
    // Piped output gets the ASCII preview, never colour escapes, and no
    // progress bar on a stderr that is not a terminal.
    assert!(!text.contains('\u{1b}'), "escape codes in piped output");
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let png = dir.join("out/ch1-cornell-box.png");
    let film = Film::read_png(&png).unwrap();
    assert_eq!((film.width, film.height), (256, 256));
    let clean = Film::read_png(&dir.join("out/ch6-cornell-box-clean.png")).unwrap();
    assert_eq!((clean.width, clean.height), (256, 256));
}

#[test]
fn the_main_program_explains_its_flags() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raystep"))
        .arg("--help")
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    for flag in [
        "--chapter",
        "--scene",
        "--spp",
        "--headless",
        "--out",
        "--report",
    ] {
        assert!(text.contains(flag), "--help lacks {flag}:\n{text}");
    }
    // A chapter that does not exist is refused with a clear message.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(["--headless", "--chapter", "9"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--chapter"), "{err}");
}

/// Every chapter binary's flags are clap's: `--help` lists them all,
/// including the ones that switch to a benchmark.
#[test]
fn chapter_help_lists_every_flag() {
    let bins = [
        (
            env!("CARGO_BIN_EXE_ch2"),
            &["--bench", "--cull-back-faces"][..],
        ),
        (env!("CARGO_BIN_EXE_ch3"), &["--bench", "--report"][..]),
        (env!("CARGO_BIN_EXE_ch6"), &["--bench", "--report"][..]),
    ];
    for (bin, flags) in bins {
        let out = std::process::Command::new(bin)
            .arg("--help")
            .output()
            .unwrap();
        assert!(out.status.success(), "{bin} --help failed");
        let help = String::from_utf8_lossy(&out.stdout);
        for flag in flags {
            assert!(
                help.contains(flag),
                "{bin} --help does not list {flag}:\n{help}"
            );
        }
    }
}
