//! Every chapter renders a non-square Cornell box (wide and tall), headless
//! through the shared runner, and chapter 6 uses its stored square
//! reference only at a whole multiple of its own size and aspect.

use std::sync::Arc;

use raystep::ch6_global_illumination::reference::{scale_factor, StoredReference};
use raystep::core::run::run_headless;
use raystep::core::stage::Settings;
use raystep::scene::Scene;

use crate::common;

const SIZES: [(u32, u32); 2] = [(256, 128), (128, 256)];

#[test]
fn every_chapter_renders_wide_and_tall_cornell_boxes() {
    let settings = Settings::default();
    for chapter in raystep::chapters::all() {
        for (w, h) in SIZES {
            let dir = common::temp_dir(&format!("non-square-ch{}-{w}x{h}", chapter.info().number));
            let scene = Scene::builtin().with_resolution(w, h).unwrap();
            let mut printed = Vec::new();
            let summary = run_headless(chapter, scene.clone(), &settings, &dir, 16, &mut printed)
                .unwrap_or_else(|e| panic!("ch{} at {w}x{h}: {e}", chapter.info().number));
            let png = &summary.files[0];
            let film = raystep::core::film::Film::read_png(png).unwrap();
            assert_eq!(
                (film.width, film.height),
                (w, h),
                "ch{} wrote {}",
                chapter.info().number,
                png.display()
            );
            // The stage's own reference, where it has one, is the image's
            // size; a reference of another shape is never offered.
            let mut render = chapter.start(Arc::new(scene), &settings).unwrap();
            while !render.pass().complete {}
            for i in 0..chapter.info().views.len() {
                let v = render.snapshot().views[i].clone();
                assert_eq!(
                    (v.width, v.height),
                    (w, h),
                    "ch{} view {i}",
                    chapter.info().number
                );
            }
            if let Some(r) = render.snapshot().reference {
                assert_eq!((r.width, r.height), (w, h), "ch{}", chapter.info().number);
            }
            let _ = std::fs::remove_dir_all(&dir);
        }
    }
}

#[test]
fn the_square_reference_is_only_used_at_its_own_aspect() {
    assert_eq!(scale_factor(64, 64, 64, 64), Some(1));
    assert_eq!(scale_factor(256, 256, 64, 64), Some(4));
    assert_eq!(scale_factor(256, 128, 64, 64), None, "other aspect");
    assert_eq!(scale_factor(128, 256, 64, 64), None, "other aspect");
    assert_eq!(scale_factor(96, 96, 64, 64), None, "not a whole multiple");
    assert_eq!(
        scale_factor(32, 32, 64, 64),
        None,
        "smaller than the reference"
    );
    let at = |w, h| StoredReference::for_render(&Scene::builtin().with_resolution(w, h).unwrap());
    assert_eq!(at(128, 128).map(|(_, f)| f), Some(2));
    assert!(at(256, 128).is_none());
    assert!(at(128, 256).is_none());
}
