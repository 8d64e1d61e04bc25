//! Stored references are matched to a scene by its content (the hash of
//! its geometry, materials, lights and camera), not by its name: a user's
//! own `cornell-box.toml` with another colour gets no "RMSE against the
//! stored reference", and the report says why.

use std::path::{Path, PathBuf};

use raystep::ch6_global_illumination::reference::StoredReference;
use raystep::scene::Scene;

use crate::common;

/// `text` written as `<dir>/<stem>.toml`, beside a copy of the Cornell
/// box's meshes (the scene file names them by relative path).
fn scene_file(dir: &Path, stem: &str, text: &str) -> PathBuf {
    let meshes = dir.join("meshes/cornell-box");
    std::fs::create_dir_all(&meshes).unwrap();
    for e in std::fs::read_dir(common::root().join("scenes/meshes/cornell-box")).unwrap() {
        let e = e.unwrap();
        std::fs::copy(e.path(), meshes.join(e.file_name())).unwrap();
    }
    let path = dir.join(format!("{stem}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

fn cornell_text() -> String {
    std::fs::read_to_string(common::root().join("scenes/cornell-box.toml")).unwrap()
}

#[test]
fn the_shipped_cornell_box_finds_its_references() {
    let file = common::shipped_scene("cornell-box", 64, 64);
    let builtin = Scene::builtin();
    assert_eq!(file.content_hash(), builtin.content_hash());
    for scene in [&file, &builtin] {
        assert!(StoredReference::for_scene(scene).is_some());
        assert!(StoredReference::for_scene_at(scene, 256, 256).is_some());
        let big = scene.clone().with_resolution(256, 256).unwrap();
        assert!(StoredReference::for_render(&big).is_some());
        assert_eq!(StoredReference::why_none(&big), None);
    }
    // Every stored reference records the hash of its shipped scene
    // (scenes/<scene>.toml, the `scene = ` line).
    for e in std::fs::read_dir(common::root().join("scenes/references")).unwrap() {
        let path = e.unwrap().path();
        if path.extension().is_some_and(|x| x == "txt") {
            let text = std::fs::read_to_string(&path).unwrap();
            let name = text
                .lines()
                .find_map(|l| l.strip_prefix("scene = "))
                .unwrap_or_else(|| panic!("{} names no scene", path.display()));
            let scene = Scene::load(&common::root().join(format!("scenes/{name}.toml"))).unwrap();
            let line = format!("content = {}", scene.content_hash());
            assert!(
                text.lines().any(|l| l == line),
                "{} lacks `{line}`: run `cargo run --release --bin ch6 -- --annotate-references`",
                path.display()
            );
        }
    }
}

#[test]
fn a_changed_colour_vertex_or_camera_finds_no_reference_and_says_why() {
    let base = common::shipped_scene("cornell-box", 64, 64);
    let mut colour = base.clone();
    colour.materials[1].reflectance.x += 0.01;
    let mut vertex = base.clone();
    vertex.meshes[0].positions[0].y += 1e-3;
    let mut camera = base.clone();
    camera.camera.eye.z += 0.01;
    let mut light = base.clone();
    let lamp = light
        .materials
        .iter_mut()
        .find(|m| m.emission != glam::Vec3::ZERO)
        .unwrap();
    lamp.emission *= 2.0;
    for (what, scene) in [
        ("colour", colour),
        ("vertex", vertex),
        ("camera", camera),
        ("light", light),
    ] {
        assert_ne!(scene.content_hash(), base.content_hash(), "{what}");
        assert!(StoredReference::for_scene(&scene).is_none(), "{what}");
        assert!(StoredReference::for_render(&scene).is_none(), "{what}");
        let why = StoredReference::why_none(&scene).unwrap_or_default();
        assert!(
            why.starts_with("this scene's content differs from cornell-box's (hash ")
                && why.contains(&scene.content_hash()),
            "{what}: {why}"
        );
    }
    // A scene of another name has no reference, and nothing to explain.
    let mut other = base.clone();
    other.name = "my-box".into();
    assert!(StoredReference::for_scene(&other).is_none());
    assert_eq!(StoredReference::why_none(&other), None);
}

#[test]
fn the_hash_ignores_path_names_key_order_and_comments() {
    let base = common::shipped_scene("cornell-box", 64, 64).content_hash();
    let dir = common::temp_dir("reference-match-format");
    // The same file elsewhere and under another name.
    let moved = scene_file(&dir, "my-own-box", &cornell_text());
    let moved = Scene::load(&moved).unwrap();
    assert_eq!(moved.content_hash(), base);
    // Re-serialised (keys in another order, no comments), then commented.
    let table: toml::Table = toml::from_str(&cornell_text()).unwrap();
    let text = format!(
        "# my own comment\n{}",
        toml::to_string(&table)
            .unwrap()
            .replace('\n', "   # a comment\n")
    );
    assert_ne!(text, cornell_text());
    let path = scene_file(&dir, "cornell-box", &text);
    let reformatted = Scene::load(&path).unwrap();
    assert_eq!(reformatted.content_hash(), base);
    // Under the shipped name, from another folder, it finds the reference.
    let sized = reformatted.with_resolution(64, 64).unwrap();
    assert!(StoredReference::for_scene(&sized).is_some());
    // Material names are names: renaming one changes nothing.
    let renamed = cornell_text().replace("\"white\"", "\"wall\"");
    let renamed = Scene::load(&scene_file(&dir, "renamed", &renamed)).unwrap();
    assert_eq!(renamed.content_hash(), base);
}

/// The user's own `cornell-box.toml` with one colour changed: the ch6
/// report has no RMSE against the stored reference, and one line saying
/// why; the shipped one has its RMSE.
#[test]
fn the_report_says_why_there_is_no_rmse() {
    let dir = common::temp_dir("reference-match-report");
    let text = cornell_text().replace("0.570068, 0.0430135", "0.6, 0.0430135");
    assert_ne!(text, cornell_text());
    let scene = scene_file(&dir, "cornell-box", &text);
    let run = |scene: &Path, out: &str| {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_ch6"))
            .args([
                "--width",
                "64",
                "--height",
                "64",
                "--spp",
                "1",
                "--final-only",
                "--scene",
            ])
            .arg(scene)
            .arg("--out")
            .arg(dir.join(out))
            .output()
            .unwrap();
        assert!(o.status.success(), "{o:?}");
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let mine = run(&scene, "mine");
    // Report lines may wrap: read the words.
    let words = mine.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        words.contains(
            "no stored reference: this scene's content differs from cornell-box's (hash "
        ),
        "{mine}"
    );
    assert!(
        !words.contains("RMSE against the stored reference"),
        "{mine}"
    );
    let shipped = run(&common::root().join("scenes/cornell-box.toml"), "shipped");
    assert!(
        shipped.contains("RMSE against the stored reference"),
        "{shipped}"
    );
    assert!(!shipped.contains("no stored reference"), "{shipped}");
}
