//! Chapter 1: exact projected coordinates, the stiff cases, what the report
//! says, and snapshots of the text outputs.

use crate::common;
use std::sync::Arc;

use glam::{DVec2, Vec3};
use raystep::ch1_projection::camera::project_pinhole;
use raystep::ch1_projection::camera::Camera;
use raystep::ch1_projection::perspective::vanishing_points;
use raystep::ch1_projection::stability::stability_cases;
use raystep::ch1_projection::stage::Projection;
use raystep::ch1_projection::wireframe::draw_scene;
use raystep::core::preview::{preview, PreviewStyle};
use raystep::core::report::{Report, Times};
use raystep::core::stage::{Chapter, Settings};
use raystep::scene::Scene;

fn scene(name: &str) -> Scene {
    Scene::load(&common::root().join("scenes").join(format!("{name}.toml"))).unwrap()
}

fn render_report(scene: Scene, studies: bool) -> (Report, Vec<raystep::core::film::Film>) {
    let settings = Settings {
        studies,
        ..Settings::default()
    };
    let mut r = Projection.start(Arc::new(scene), &settings).unwrap();
    assert!(r.pass().complete, "chapter 1 renders in one pass");
    let films = r.snapshot().views;
    (r.report(), films)
}

/// The tetrahedron scene: eye (0, 0, 5) looking at the origin, fov 45°,
/// 320x240. Camera space is world space shifted by -5 in z, so vertex
/// (x, y, z) has u = x / (5 - z), v = y / (5 - z); pixels follow from
/// t = tan(22.5°) and aspect 4/3. Worked out in f64, independently of the
/// camera code.
#[test]
fn tetrahedron_pixels_match_hand_computed_values() {
    let s = scene("tetrahedron");
    let t = (22.5f64).to_radians().tan();
    let (w, h, aspect) = (320.0, 240.0, 320.0 / 240.0);
    let table = [
        [-1.0, -1.0, -1.0],
        [1.0, -1.0, 1.0],
        [1.0, 1.0, -1.0],
        [-1.0, 1.0, 1.0],
    ];
    assert_eq!(s.meshes[0].positions.len(), 4);
    for (p, [x, y, z]) in s.meshes[0].positions.iter().zip(table) {
        assert_eq!(
            p.to_array(),
            [x as f32, y as f32, z as f32],
            "the lecture's table"
        );
        let (u, v) = (x / (5.0 - z), y / (5.0 - z));
        let want = DVec2::new((u / (aspect * t) + 1.0) / 2.0 * w, (1.0 - v / t) / 2.0 * h);
        let got = Camera::of(&s).project(*p).unwrap().as_dvec2();
        assert!(
            (got - want).length() < 1e-4,
            "vertex {p}: got {got}, want {want}"
        );
    }
    // Vertex 0 by hand, to the last digit printed in the report.
    let got = Camera::of(&s).project(Vec3::new(-1.0, -1.0, -1.0)).unwrap();
    assert!((got.x - 111.7157).abs() < 1e-3 && (got.y - 168.2843).abs() < 1e-3);
    assert_eq!(
        s.meshes[0].triangles,
        [[0, 2, 1], [0, 3, 2], [3, 0, 1], [3, 1, 2]]
    );
}

#[test]
fn the_pinhole_is_similar_triangles() {
    assert_eq!(
        project_pinhole(Vec3::new(2.0, -4.0, -2.0)),
        Some(glam::Vec2::new(1.0, -2.0))
    );
    // Farther is smaller: twice the depth, half the image.
    let near = project_pinhole(Vec3::new(1.0, 1.0, -2.0)).unwrap();
    let far = project_pinhole(Vec3::new(1.0, 1.0, -4.0)).unwrap();
    assert_eq!(near, far * 2.0);
}

#[test]
fn every_stiff_case_comes_out_as_expected() {
    for name in ["tetrahedron", "cornell-box"] {
        let cases = stability_cases(&Camera::of(&scene(name)));
        assert!(cases.len() >= 10);
        for c in &cases {
            assert!(
                c.ok,
                "{name}: {}: expected {}, measured {}",
                c.name, c.expected, c.measured
            );
        }
    }
}

#[test]
fn a_camera_inside_the_mesh_clips_edges_instead_of_smearing_them() {
    // The pinhole at the origin sits inside the lecture's tetrahedron: every
    // edge has a part behind the camera.
    let s = Scene::from_text(
        "[camera]\neye = [0, 0, 0]\ntarget = [0, 0, -1]\nfov = 120\n[[objects]]\nshape = \"tetrahedron\"\n",
        "inside",
    )
    .unwrap();
    let (films, stats) = draw_scene(&Camera::of(&s), &s.meshes, &s.materials, 0..s.camera.height);
    assert!(stats.edges_clipped > 0, "{stats:?}");
    assert_eq!(
        stats.edges_clipped + stats.edges_whole + stats.edges_culled,
        6
    );
    assert!(stats.vertices_culled >= 2, "{stats:?}");
    for f in films {
        assert_eq!(f.clone().scrub_nonfinite(), 0);
        assert!(f.pixels.iter().any(|p| p.max_element() > 0.0));
    }
}

#[test]
fn railroad_lines_meet_at_the_analytic_vanishing_point() {
    let s = scene("railroad");
    let vps = vanishing_points(&Camera::of(&s), &s.meshes);
    let rails = vps
        .iter()
        .find(|v| v.direction.z.abs() > 0.999)
        .expect("the rails' family");
    let measured = rails.measured.unwrap();
    assert!(rails.lines >= 20);
    assert!((measured - rails.analytic).length() < 0.05, "{rails:?}");
    assert!(rails.rms_miss < 0.1);
    // The rails run along -z from a camera looking slightly down: their
    // vanishing point is centred horizontally, above the image centre.
    assert!((rails.analytic.x - 160.0).abs() < 1e-3);
    assert!(rails.analytic.y < 120.0);
}

#[test]
fn the_report_says_what_was_built_and_left_out() {
    let (report, _) = render_report(scene("tetrahedron"), false);
    assert!(report
        .built
        .iter()
        .any(|b| b.contains("wireframes of 1 meshes")));
    assert!(report.facts.iter().any(|(k, v)| k == "lights"
        && v == "no lights, not used by this chapter (projection needs no light)"));
    assert!(
        report.error_vs_time.is_none() && report.stability.is_empty(),
        "no studies unless asked"
    );
    let (report, _) = render_report(scene("bunny"), true);
    assert!(report.facts.iter().any(|(k, v)| k == "lights"
        && v.ends_with(", not used by this chapter (projection needs no light)")
        && v.starts_with("1 ")));
    let et = report.error_vs_time.unwrap();
    assert_eq!(et.rows.len(), 22, "11 depths, f32 and f64");
    // The f32 camera is within a hundredth of a pixel from 1e-2 to 1e7.
    for r in et
        .rows
        .iter()
        .filter(|r| r.series == "f32 camera" && r.variant != "depth 1e-3")
    {
        assert!(r.error < 0.01, "{r:?}");
    }
    for r in et.rows.iter().filter(|r| r.series == "f64 reference") {
        assert!(r.error < 1e-9, "{r:?}");
    }
}

#[test]
fn every_shipped_scene_renders_without_nan_and_deterministically() {
    for name in ["tetrahedron", "railroad", "bunny", "cornell-box"] {
        let (report, films) = render_report(scene(name), false);
        let (_, again) = render_report(scene(name), false);
        assert_eq!(films, again, "{name}: two renders differ");
        assert_eq!(report.nonfinite_caught, 0);
        let lit = films[0]
            .pixels
            .iter()
            .filter(|p| p.max_element() > 0.0)
            .count();
        assert!(lit > 200, "{name}: only {lit} pixels drawn");
    }
}

#[test]
fn the_builtin_scene_is_the_shipped_cornell_box() {
    let builtin = Scene::builtin();
    let file = scene("cornell-box");
    assert_eq!(builtin.meshes, file.meshes);
    assert_eq!(builtin.materials, file.materials);
    assert_eq!(builtin.camera, file.camera);
    assert_eq!(builtin.triangle_count(), 36);
    assert!(builtin.has_emitters());
}

#[test]
fn snapshot_tetrahedron_report() {
    let (report, _) = render_report(scene("tetrahedron"), true);
    let text = report.to_text(Times::Hide);
    // Render time is the one fact that changes from run to run.
    let text: String = text
        .lines()
        .filter(|l| !l.contains("render time") && !l.starts_with("  scene: "))
        .collect::<Vec<_>>()
        .join("\n");
    insta::assert_snapshot!(text);
}

#[test]
fn snapshot_railroad_tables() {
    let (report, _) = render_report(scene("railroad"), false);
    let tables: String = report.tables.iter().map(|t| t.to_text() + "\n").collect();
    insta::assert_snapshot!(tables);
}

#[test]
fn snapshot_tetrahedron_ascii_preview() {
    let (_, films) = render_report(scene("tetrahedron"), false);
    insta::assert_snapshot!(preview(&films[0], 48, PreviewStyle::Ascii));
}
