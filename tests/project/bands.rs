//! Issue 48: no single allocation of gigabytes where tiles would do. A run
//! whose pixels need more than a gigabyte at once, or more than the
//! process may still get, renders in bands of rows and streams them into
//! its files (`core::bands`). A banded run writes the same pixels as the
//! whole one (the EXR the same bytes), and one that was refused under an
//! address-space limit now completes.

use std::path::Path;
use std::process::Command;

use raystep::core::bands::{rows_per_band, BAND_BYTES, MIN_BAND_ROWS};
use raystep::core::film::Film;
use raystep::core::run::{run_banded, run_headless};
use raystep::core::stage::{Chapter, Settings};
use raystep::scene::Scene;

use crate::common;

fn files_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// The same files (but the figures a banded run leaves out, chapter 6's
/// per-bounce layers), the same pixels in every PNG, the same bytes in
/// every EXR; no temporary or scratch file is left.
fn assert_same_outputs(whole: &Path, banded: &Path, what: &str) {
    let figure = |n: &String| n.contains("-layer-") || n.ends_with("-bounces.png");
    let names: Vec<String> = files_in(whole).into_iter().filter(|n| !figure(n)).collect();
    assert_eq!(names, files_in(banded), "{what}");
    assert!(
        names.iter().any(|n| n.ends_with(".png")),
        "{what}: {names:?}"
    );
    for name in &names {
        let (a, b) = (whole.join(name), banded.join(name));
        if name.ends_with(".png") {
            let (fa, fb) = (Film::read_png(&a).unwrap(), Film::read_png(&b).unwrap());
            assert!(fa == fb, "{what}: {name} differs");
        } else if name.ends_with(".exr") {
            let (ba, bb) = (std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
            assert!(ba == bb, "{what}: {name} differs");
        }
    }
}

/// Every chapter, at a size whose rows do not divide
/// into the bands evenly (41 rows in bands of 6): the banded run's files
/// are the whole run's.
#[test]
fn a_banded_run_writes_what_the_whole_run_writes() {
    let dir = common::temp_dir("bands-same");
    let mut scene = Scene::builtin();
    (scene.camera.width, scene.camera.height) = (37, 41);
    let mut chapters: Vec<&dyn Chapter> = raystep::chapters::all();
    // Chapter 6's lesson engine as well as the fast one.
    chapters.push(raystep::chapters::with_engine(true)[5]);
    let mut checked = Vec::new();
    for (k, chapter) in chapters.into_iter().enumerate() {
        let info = chapter.info();
        if !info.bands {
            continue;
        }
        let settings = Settings {
            spp: 3,
            seed: 7,
            ..Settings::default()
        };
        let (whole, banded) = (
            dir.join(format!("whole{k}")),
            dir.join(format!("banded{k}")),
        );
        let mut text = Vec::new();
        run_headless(chapter, scene.clone(), &settings, &whole, 16, &mut text).unwrap();
        let mut text = Vec::new();
        let summary =
            run_banded(chapter, scene.clone(), &settings, &banded, 16, 6, &mut text).unwrap();
        let text = String::from_utf8(text).unwrap();
        assert!(text.contains("bands: 7 of up to 6 rows"), "{text}");
        if info.number == 6 {
            assert!(text.contains("per-bounce layers and figures"), "{text}");
        }
        assert_eq!(summary.files.len(), files_in(&banded).len());
        assert_same_outputs(&whole, &banded, &format!("chapter {}", info.number));
        checked.push(info.number);
    }
    assert_eq!(checked, [1, 2, 3, 4, 5, 6, 6]);
}

/// Whether a run is banded, and how: only above a gigabyte of pixels (or
/// what the process may still get), and never with a band of no rows.
#[test]
fn runs_are_banded_only_where_their_pixels_do_not_fit() {
    let chapters = raystep::chapters::all();
    let ch3 = chapters[2].info();
    let mut scene = Scene::builtin();
    let size =
        |scene: &mut Scene, w: u32, h: u32| (scene.camera.width, scene.camera.height) = (w, h);
    size(&mut scene, 1024, 1024);
    assert_eq!(rows_per_band(&ch3, &scene, None), None);
    size(&mut scene, 16384, 16384);
    let rows = rows_per_band(&ch3, &scene, None).unwrap();
    assert!(rows >= 1 && (rows as u64) * 16384 * ch3.bytes_per_pixel <= BAND_BYTES);
    // Under a tight limit the bands shrink to what is left...
    let room = 512 << 20;
    let tight = rows_per_band(&ch3, &scene, Some(room)).unwrap();
    assert!(tight < rows && (tight as u64) * 16384 * ch3.bytes_per_pixel <= room);
    // ... a small image that does not fit is banded too ...
    size(&mut scene, 2048, 2048);
    assert!(rows_per_band(&ch3, &scene, Some(room)).is_some());
    // ... and with no room at all a band has the fewest rows (the memory
    // check refuses it).
    assert_eq!(rows_per_band(&ch3, &scene, Some(0)), Some(MIN_BAND_ROWS));
    // Every chapter renders bands (those with views scaled over the whole
    // image render each band twice).
    size(&mut scene, 16384, 16384);
    for chapter in &chapters {
        let info = chapter.info();
        assert!(info.bands, "chapter {}", info.number);
        assert!(rows_per_band(&info, &scene, None).is_some());
        assert_eq!(info.scaled_views, [2, 4].contains(&info.number));
    }
}

/// The real binary under an address-space limit that refused the whole
/// run (2048x1024 in chapter 3 needs about 740 MiB whole): it now renders
/// in bands and writes the pixels of the unlimited, whole run.
#[test]
fn a_run_refused_under_a_limit_completes_in_bands() {
    let dir = common::temp_dir("bands-limit");
    let bin = env!("CARGO_BIN_EXE_ch3");
    let args = ["--width", "2048", "--height", "1024"];
    let whole = Command::new(bin)
        .args(args)
        .arg("--out")
        .arg(dir.join("whole"))
        .output()
        .unwrap();
    assert!(whole.status.success(), "{whole:?}");
    let limited = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {} && exec \"$0\" \"$@\"", 640 << 10))
        .arg(bin)
        .args(args)
        .arg("--out")
        .arg(dir.join("banded"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&limited.stdout);
    assert!(
        limited.status.success(),
        "{:?} {}",
        limited.status,
        String::from_utf8_lossy(&limited.stderr)
    );
    assert!(stdout.contains("bands: "), "{stdout}");
    assert!(!String::from_utf8_lossy(&whole.stdout).contains("bands: "));
    assert_same_outputs(&dir.join("whole"), &dir.join("banded"), "chapter 3");
}

/// The book's table of limits says above what size the chapters render in
/// bands, and which render each band twice.
#[test]
fn the_book_says_when_runs_render_in_bands() {
    let page = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("book/src/scene-files.md"),
    )
    .unwrap();
    let all = raystep::chapters::all();
    assert!(all.iter().all(|c| c.info().bands));
    let scaled: Vec<String> = all
        .iter()
        .map(|c| c.info())
        .filter(|i| i.scaled_views)
        .map(|i| i.number.to_string())
        .collect();
    for phrase in [
        format!(
            "every chapter renders an image whose pixels need more than {} GiB at once",
            BAND_BYTES >> 30
        ),
        format!("chapters {} render each band twice", scaled.join(" and ")),
    ] {
        assert!(
            page.contains(&phrase),
            "the limits table should say: {phrase}"
        );
    }
}

/// A banded run stopped by a signal while its files are half written
/// leaves nothing behind: the streamed temporaries are removed like any
/// other, and the exit status is the signal's.
#[test]
fn an_interrupted_banded_run_leaves_no_file() {
    let dir = common::temp_dir("bands-signal");
    let out = dir.join("out");
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {} && exec \"$0\" \"$@\"", 640 << 10))
        .arg(env!("CARGO_BIN_EXE_ch3"))
        .args([
            "--width", "2048", "--height", "1024", "--spp", "16", "--out",
        ])
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .stderr(std::fs::File::create(dir.join("stderr")).unwrap())
        .spawn()
        .unwrap();
    // The streamed files exist as temporaries from the first band on.
    let started = std::time::Instant::now();
    let streaming = || std::fs::read_dir(&out).is_ok_and(|d| d.count() > 0);
    while !streaming() && started.elapsed().as_secs() < 120 {
        // A run that ended before writing anything says why.
        if let Some(status) = child.try_wait().unwrap() {
            let stderr = std::fs::read_to_string(dir.join("stderr")).unwrap_or_default();
            panic!("ch3 ended ({status:?}) before writing a file:\n{stderr}");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(
        streaming(),
        "no file appeared in {out:?} in {:?}",
        started.elapsed()
    );
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130), "{status:?}");
    assert_eq!(std::fs::read_dir(&out).unwrap().count(), 0, "{out:?}");
}
