//! Reports a person can read: every chapter's `--report` output, at a
//! small size, fits in 100 columns, lists its files one per line, and says
//! the same thing about the scene's lights in every chapter.

use std::path::PathBuf;

use raystep::ch3_ray_triangle::report::add_studies;
use raystep::ch3_ray_triangle::studies::StudySize;
use raystep::chapters;
use raystep::core::report::{Report, Times, COLUMNS};
use raystep::core::run::run_headless;
use raystep::core::stage::Settings;
use raystep::scene::Scene;

/// Every chapter's report on `scene` at 32x24, 1 spp, studies on.
/// Chapter 3's studies run at [`StudySize::layout`] (every row of its
/// tables, but with the naive loop skipped and few rays, because the full
/// size takes half a minute in a debug build): its run is headless without
/// studies, and the studies' text is added from `add_studies` at that size.
fn reports(scene: &str) -> Vec<(u32, String, Vec<PathBuf>)> {
    let root = std::env::temp_dir().join(format!("raystep-reports-{}", std::process::id()));
    let settings = Settings {
        width: Some(32),
        height: Some(24),
        spp: 1,
        seed: 0,
        studies: true,
        variant: None,
        rows: None,
        scale: None,
    };
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{scene}.toml"));
    let mut out = Vec::new();
    for chapter in chapters::all() {
        let scene = Scene::load(&path).unwrap();
        let n = chapter.info().number;
        let dir = root.join(format!("ch{n}"));
        let mut text = Vec::new();
        let summary = if n == 3 {
            let quick = Settings {
                studies: false,
                ..settings.clone()
            };
            let mut report = Report::default();
            let small = scene.clone().with_resolution(32, 24).unwrap();
            add_studies(&mut report, &small, &settings, &StudySize::layout());
            text.extend(report.to_text(Times::Hide).into_bytes());
            run_headless(chapter, scene, &quick, &dir, 32, &mut text).unwrap()
        } else {
            run_headless(chapter, scene, &settings, &dir, 32, &mut text).unwrap()
        };
        out.push((
            chapter.info().number,
            String::from_utf8(text).unwrap(),
            summary.files,
        ));
    }
    let _ = std::fs::remove_dir_all(&root);
    out
}

#[test]
fn every_report_on_the_cornell_box_fits_in_100_columns_and_agrees_on_lights() {
    let all = reports("cornell-box");
    assert_eq!(all.len(), 6, "every chapter renders the Cornell box");
    for (n, text, files) in &all {
        for line in text.lines() {
            assert!(
                line.chars().count() <= COLUMNS,
                "ch{n}: a line of {} columns:\n{line}",
                line.chars().count()
            );
        }
        // The files written, one per line under "wrote N files:".
        let listed: Vec<&str> = text
            .lines()
            .skip_while(|l| !l.trim_start().starts_with("wrote "))
            .skip(1)
            .take_while(|l| !l.trim().is_empty())
            .map(str::trim)
            .collect();
        assert_eq!(listed.len(), files.len(), "ch{n}: {text}");
        for (line, file) in listed.iter().zip(files) {
            assert_eq!(*line, file.display().to_string(), "ch{n}");
        }
        // One scene, one account of its lights: the Cornell box has one
        // area light, whether or not the chapter uses it.
        assert!(
            text.contains("1 area light"),
            "ch{n} does not say the scene has 1 area light:\n{text}"
        );
        assert!(!text.contains("the scene has none"), "ch{n}:\n{text}");
        // Every label the report prints is defined in the book's glossary.
        let undefined = super::glossary::undefined_labels(text);
        assert!(
            undefined.is_empty(),
            "ch{n} prints labels book/src/glossary.md does not define: {undefined:?}"
        );
    }
}
