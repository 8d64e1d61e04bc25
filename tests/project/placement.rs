//! Issue 48: the picture must not depend on the unit of length or on where
//! the scene sits. The Cornell box (chapters 3, 5, 6) and the lit SDF scene
//! (chapters 4, 5, 6) at ×1e-5, ×1e-3, ×1e3, +1e4 on every axis, +1e6 and at
//! +9.99e11, next to 1e12, the largest coordinate a scene accepts, each compared block by
//! block (8×8 pixels) with the same scene at the origin.
//!
//! Tolerances: chapters 5 and 6 sample; the same seed draws the same
//! numbers wherever the scene is, so a moved scene differs from the one at
//! the origin only by rounding. The tolerance is measured: three times the
//! largest block difference between two renders of the scene at the origin
//! with different seeds (the noise of a block). Chapters 3 and 4 do not
//! sample: a block may differ by an edge pixel or two turning (2 of 64
//! pixels at full contrast: 1/32 of the block's brightest value).

use std::sync::Arc;

use glam::{DVec3, Vec3};
use raystep::core::stage::{Chapter, Settings};
use raystep::scene::Scene;

const SIZE: u32 = 32;
const BLOCK: u32 = 8;

fn render(chapter: &dyn Chapter, scene: &Scene, seed: u64) -> Vec<Vec3> {
    let settings = Settings {
        spp: 16,
        seed,
        ..Settings::default()
    };
    let mut r = chapter.start(Arc::new(scene.clone()), &settings).unwrap();
    while !r.pass().complete {}
    r.snapshot().views.swap_remove(0).pixels
}

/// Mean luminance of each block.
fn blocks(pixels: &[Vec3]) -> Vec<f64> {
    let per = SIZE / BLOCK;
    let mut out = vec![0.0; (per * per) as usize];
    for y in 0..SIZE {
        for x in 0..SIZE {
            let p = pixels[(y * SIZE + x) as usize];
            out[((y / BLOCK) * per + x / BLOCK) as usize] += p.element_sum() as f64 / 3.0;
        }
    }
    out.iter().map(|b| b / (BLOCK * BLOCK) as f64).collect()
}

fn placements() -> Vec<(&'static str, DVec3, f64)> {
    vec![
        ("x1e-5", DVec3::ZERO, 1e-5),
        ("x1e-3", DVec3::ZERO, 1e-3),
        ("x1e3", DVec3::ZERO, 1e3),
        ("+1e3", DVec3::splat(1e3), 1.0),
        ("+1e4", DVec3::splat(1e4), 1.0),
        ("+1e6", DVec3::new(-1e6, 1e6, 1e6), 1.0),
        ("+9.99e11, the limit", DVec3::splat(9.99e11), 1.0),
    ]
}

fn check(chapter_index: usize, scene: Scene) {
    let chapter = raystep::chapters::all()[chapter_index];
    let n = chapter.info().number;
    let scene = scene.with_resolution(SIZE, SIZE).unwrap();
    let origin = blocks(&render(chapter, &scene, 1));
    let brightest = origin.iter().cloned().fold(0.0, f64::max);
    let tolerance = if chapter.info().radiance {
        let other = blocks(&render(chapter, &scene, 2));
        let noise = origin
            .iter()
            .zip(&other)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        3.0 * noise
    } else {
        brightest / 32.0
    };
    assert!(tolerance > 0.0, "chapter {n}: {tolerance}");
    for (label, offset, scale) in placements() {
        let moved = blocks(&render(chapter, &scene.clone().placed(offset, scale), 1));
        let worst = origin
            .iter()
            .zip(&moved)
            .map(|(a, b)| (a - b).abs() / tolerance)
            .fold(0.0, f64::max);
        println!(
            "chapter {n}, {} at {label}: worst block {worst:.2} of the tolerance",
            scene.name
        );
        for (k, (a, b)) in origin.iter().zip(&moved).enumerate() {
            assert!(
                (a - b).abs() <= tolerance,
                "chapter {n}, {} at {label}: block {k} is {b:.4}, at the origin {a:.4} \
                 (tolerance {tolerance:.4})",
                scene.name
            );
        }
    }
}

fn cornell() -> Scene {
    Scene::builtin()
}

/// The bunny: a mesh of tens of thousands of small triangles, whose
/// contact shadows and silhouettes are the first to move with the place.
fn bunny() -> Scene {
    Scene::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/bunny.toml"
    )))
    .unwrap()
}

fn sdf_lit() -> Scene {
    Scene::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/sdf-lit.toml"
    )))
    .unwrap()
}

#[test]
fn chapter_3_does_not_depend_on_unit_or_place() {
    check(2, cornell());
    check(2, bunny());
}

#[test]
fn chapter_4_does_not_depend_on_unit_or_place() {
    check(3, sdf_lit());
}

#[test]
fn chapter_5_does_not_depend_on_unit_or_place() {
    check(4, cornell());
    check(4, sdf_lit());
}

#[test]
fn chapter_6_does_not_depend_on_unit_or_place() {
    check(5, cornell());
    check(5, sdf_lit());
    // Glass among diffuse walls: the fast engine's lanes and the lesson's
    // steps in the same round.
    check(
        5,
        crate::common::shipped_scene("cornell-glassball", SIZE, SIZE),
    );
}

/// The bunny, which round 4 found off by 0.3% from +1e3 on: chapter 6 at
/// every placement, block by block.
#[test]
fn the_bunny_does_not_depend_on_unit_or_place() {
    check(5, bunny());
}

/// The same through a scene file: a box on a floor under a point light,
/// written at the origin and 1e4 and 9.99e11 away (camera, objects and
/// light moved in the file), renders alike in chapters 3 and 5.
#[test]
fn a_scene_file_far_from_the_origin_renders_like_one_at_it() {
    let text = |d: f64| {
        format!(
            "[camera]\neye = [{x}, {y1}, {z5}]\ntarget = [{x}, {y0}, {z0}]\nwidth = 32\nheight = 32\n\
             [[objects]]\nshape = \"box\"\nsize = [1, 1, 1]\ntranslate = [{x}, {yb}, {z0}]\n\
             [[objects]]\nshape = \"rectangle\"\nsize = [6, 6]\nrotate = {{ axis = [1, 0, 0], degrees = -90 }}\n\
             translate = [{x}, {y0}, {z0}]\n\
             [[lights]]\ntype = \"point\"\nposition = [{xl}, {y3}, {zl}]\nintensity = [8, 8, 8]\n",
            x = d,
            y0 = d,
            y1 = d + 1.5,
            yb = d + 0.5,
            y3 = d + 3.0,
            z0 = d,
            z5 = d + 5.0,
            xl = d + 1.0,
            zl = d + 1.0,
        )
    };
    let at_origin = Scene::from_text(&text(0.0), "near").unwrap();
    assert_eq!(at_origin.origin, DVec3::ZERO);
    for d in [1e4, 9.99e11] {
        let far = Scene::from_text(&text(d), "far").unwrap();
        assert!(far.origin.length() > d, "{d}: {}", far.origin);
        for index in [2, 4] {
            let chapter = raystep::chapters::all()[index];
            let (a, b) = (
                blocks(&render(chapter, &at_origin, 1)),
                blocks(&render(chapter, &far, 1)),
            );
            let brightest = a.iter().cloned().fold(0.0, f64::max);
            for (k, (a, b)) in a.iter().zip(&b).enumerate() {
                assert!(
                    (a - b).abs() <= brightest / 32.0,
                    "chapter {}, {d}: block {k}: {b} against {a}",
                    index + 1
                );
            }
        }
    }
}
