//! Chapter 2: exact coverage counts, interpolation against hand values, the
//! depth buffer, determinism, the report, mesh checks and the exercises.

use std::path::Path;
use std::sync::Arc;

use glam::{DVec2, DVec3, I64Vec2, Vec3};
use raystep::ch1_projection::camera::Camera;
use raystep::ch2_rasterization::clip::ClipVertex;
use raystep::ch2_rasterization::coverage::{coverage_counts, rasterize};
use raystep::ch2_rasterization::frame::render_frame;
use raystep::ch2_rasterization::interpolate::{interpolate, Interpolation};
use raystep::ch2_rasterization::mesh_check::check_mesh;
use raystep::ch2_rasterization::setup::{raster_triangle, setup_raster_polygon, ScreenTriangle};
use raystep::ch2_rasterization::stability::stability_cases;
use raystep::ch2_rasterization::stage::Rasterization;
use raystep::ch2_rasterization::studies::{screen_fan, screen_grid, star, test_camera};
use raystep::core::report::Times;
use raystep::core::stage::{Chapter, Settings};
use raystep::grading;
use raystep::scene::mesh::Mesh;
use raystep::scene::{Material, Scene};

fn scene(name: &str) -> Scene {
    Scene::load(
        &Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(name),
    )
    .unwrap()
}

/// Coverage as ASCII: one letter per covering triangle (by order), `.` for
/// none, `#` for more than one.
fn ascii(tris: &[ScreenTriangle], w: u32, h: u32) -> String {
    let mut s = String::new();
    for y in 0..h {
        for x in 0..w {
            let p = I64Vec2::new(x as i64 * 256 + 128, y as i64 * 256 + 128);
            let hits: Vec<usize> = (0..tris.len())
                .filter(|&t| raystep::ch2_rasterization::coverage::covers(&tris[t], p))
                .collect();
            s.push(match hits.len() {
                0 => '.',
                1 => (b'a' + hits[0] as u8) as char,
                _ => '#',
            });
        }
        s.push('\n');
    }
    s
}

#[test]
fn coverage_patterns_as_text() {
    let v = DVec2::new;
    // Two triangles sharing a diagonal that passes through pixel centres.
    let mut quad = raster_triangle([v(1.5, 1.5), v(12.5, 1.5), v(12.5, 8.5)], 0, 16, 10);
    quad.extend(raster_triangle(
        [v(1.5, 1.5), v(12.5, 8.5), v(1.5, 8.5)],
        1,
        16,
        10,
    ));
    // A fan of four triangles around an off-grid point.
    let c = v(7.3, 4.6);
    let corners = [v(0.0, 0.0), v(16.0, 0.0), v(16.0, 10.0), v(0.0, 10.0)];
    let fan: Vec<ScreenTriangle> = (0..4)
        .flat_map(|k| raster_triangle([c, corners[k], corners[(k + 1) % 4]], k as u32, 16, 10))
        .collect();
    // A thin sliver and a triangle with vertices on pixel centres.
    let sliver = raster_triangle([v(0.2, 2.0), v(15.8, 6.0), v(0.2, 2.6)], 0, 16, 10);
    let small = raster_triangle([v(2.5, 2.5), v(6.5, 2.5), v(2.5, 6.5)], 0, 16, 10);
    insta::assert_snapshot!(
        "coverage_patterns",
        format!(
            "quad split on a diagonal through pixel centres:\n{}\nfan of four around (7.3, 4.6):\n{}\nsliver:\n{}\nright triangle with vertices on pixel centres:\n{}",
            ascii(&quad, 16, 10),
            ascii(&fan, 16, 10),
            ascii(&sliver, 16, 10),
            ascii(&small, 16, 10)
        )
    );
    assert!(!ascii(&quad, 16, 10).contains('#'));
    assert!(!ascii(&fan, 16, 10).contains(['#', '.']));
}

#[test]
fn tilings_cover_every_sample_exactly_once() {
    for (tris, w, h) in [
        (screen_fan(40, 30), 40, 30),
        (screen_grid(40, 30, 7, 5), 40, 30),
    ] {
        for spp in [1, 4] {
            let counts = coverage_counts(&tris, w, h, spp, 9);
            assert!(counts.iter().all(|&c| c == 1), "spp {spp}");
        }
    }
}

#[test]
fn bounding_box_loop_matches_the_readable_loop() {
    let tris = star(48, 10);
    for spp in [1, 4] {
        let counts = coverage_counts(&tris, 48, 48, spp, 5);
        let buf = rasterize(&tris, 48, 0..48, spp, 5);
        assert!(counts.iter().all(|&c| c <= 1));
        let fast: Vec<u32> = buf
            .samples
            .iter()
            .map(|s| u32::from(s.is_covered()))
            .collect();
        assert_eq!(fast, counts);
        assert!(counts.iter().sum::<u32>() > 100);
    }
}

#[test]
fn every_stiff_case_comes_out_as_expected() {
    let cases = stability_cases();
    assert!(cases.len() >= 12);
    for c in &cases {
        assert!(
            c.ok,
            "{}: expected {}, measured {}",
            c.name, c.expected, c.measured
        );
    }
}

/// A screen triangle (0,0), (8,0), (0,8) with red = 0, 1, 0 and 1/w = 1,
/// 0.25, 1.
fn slanted() -> ScreenTriangle {
    let pts = [
        (0.0, 0.0, 1.0, 0.0),
        (8.0, 0.0, 0.25, 1.0),
        (0.0, 8.0, 1.0, 0.0),
    ];
    let polygon = pts
        .iter()
        .map(|&(x, y, inv_w, red)| ClipVertex {
            p: DVec3::new(x, y, inv_w),
            attr: [red * inv_w, 0.0, 0.0, 0.0, 0.0, 0.0],
        })
        .collect();
    let mut out = Vec::new();
    setup_raster_polygon(polygon, 16, 16, Vec3::Z, 0, false, &mut out);
    out[0]
}

#[test]
fn interpolation_matches_hand_computed_values() {
    let tri = slanted();
    let p = I64Vec2::new(4 * 256, 0);
    // Half way along the edge in screen space: φ = (1/2, 1/2, 0).
    let (affine, _) = interpolate(&tri, p, Interpolation::Affine);
    assert!((affine[0] - 0.5).abs() < 1e-12);
    // Perspective-correct: (½·0·1 + ½·1·¼) / (½·1 + ½·¼) = 0.125 / 0.625.
    let (persp, depth) = interpolate(&tri, p, Interpolation::Perspective);
    assert!((persp[0] - 0.2).abs() < 1e-12, "{}", persp[0]);
    assert!((depth - 1.6).abs() < 1e-12);
    // The lecture's colour(x) = Σ colour(xn)·φn at the centroid of a
    // triangle at equal depth: the average of the three colours.
    let mut rgb = raster_triangle(
        [
            DVec2::new(0.0, 0.0),
            DVec2::new(9.0, 0.0),
            DVec2::new(0.0, 9.0),
        ],
        0,
        16,
        16,
    )[0];
    rgb.attr[0][..3].copy_from_slice(&[1.0, 0.0, 0.0]);
    rgb.attr[1][..3].copy_from_slice(&[0.0, 1.0, 0.0]);
    rgb.attr[2][..3].copy_from_slice(&[0.0, 0.0, 1.0]);
    for mode in [Interpolation::Affine, Interpolation::Perspective] {
        let (a, _) = interpolate(&rgb, I64Vec2::new(3 * 256, 3 * 256), mode);
        for c in &a[..6] {
            assert!((c - 1.0 / 3.0).abs() < 1e-12, "{a:?}");
        }
    }
}

#[test]
fn slanted_triangle_differs_between_perspective_and_affine() {
    let s = scene("interpenetrating.toml")
        .with_resolution(96, 72)
        .unwrap();
    let f = render_frame(&Camera::of(&s), &s.meshes, &s.materials, 1, 0, false).unwrap();
    let diff = f.films[0].rmse(&f.films[1]);
    assert!(
        diff > 1e-3,
        "perspective and affine colours should differ: {diff}"
    );
}

#[test]
fn same_bytes_on_one_and_two_threads() {
    let s = scene("interpenetrating.toml")
        .with_resolution(96, 72)
        .unwrap();
    let run = |n: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .unwrap();
        pool.install(|| {
            render_frame(&Camera::of(&s), &s.meshes, &s.materials, 4, 3, false).unwrap()
        })
    };
    let (a, b) = (run(1), run(2));
    assert_eq!(a.buffer, b.buffer);
    for (x, y) in a.films.iter().zip(&b.films) {
        let bits = |f: &raystep::core::film::Film| -> Vec<u32> {
            f.pixels
                .iter()
                .flat_map(|p| p.to_array().map(f32::to_bits))
                .collect()
        };
        assert_eq!(bits(x), bits(y));
    }
}

#[test]
fn back_face_culling_changes_nothing_on_a_closed_convex_mesh() {
    let s = scene("tetrahedron.toml").with_resolution(80, 60).unwrap();
    let all = render_frame(&Camera::of(&s), &s.meshes, &s.materials, 4, 0, false).unwrap();
    let culled = render_frame(&Camera::of(&s), &s.meshes, &s.materials, 4, 0, true).unwrap();
    assert!(culled.stats.culled_back > 0);
    assert!(culled.tris.len() < all.tris.len());
    assert_eq!(all.films[0], culled.films[0]);
    // A rectangle facing +z seen from +z is a front face.
    let rect = Mesh::rectangle(1.0, 1.0);
    let mut moved = rect.clone();
    moved.transform(&glam::Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0)));
    let f = render_frame(
        &test_camera(32, 24),
        &[moved],
        &[Material::default_grey()],
        1,
        0,
        true,
    )
    .unwrap();
    assert_eq!(f.stats.culled_back, 0);
    assert!(f.buffer.samples.iter().any(|s| s.is_covered()));
}

#[test]
fn bad_sample_counts_are_errors_not_panics() {
    let s = Arc::new(scene("tetrahedron.toml"));
    for spp in [0, 100_000] {
        let settings = Settings {
            spp,
            ..Settings::default()
        };
        let err = Rasterization::default()
            .start(s.clone(), &settings)
            .err()
            .unwrap();
        assert!(err.to_string().contains("--spp"), "{err}");
    }
}

#[test]
fn report_lists_mesh_checks_and_what_was_built() {
    let s = Arc::new(scene("tetrahedron.toml"));
    let settings = Settings {
        studies: true,
        ..Settings::default()
    };
    let mut r = Rasterization::default().start(s, &settings).unwrap();
    while !r.pass().complete {}
    let report = r.report();
    assert!(report.built.iter().any(|b| b.contains("vertex-colour")));
    assert!(report
        .left_out
        .iter()
        .any(|b| b.contains("near-plane clipping")));
    assert!(report
        .left_out
        .iter()
        .any(|b| b.contains("back-face culling")));
    assert!(report.all_stable());
    let et = report.error_vs_time.as_ref().unwrap();
    // More samples, less error, in the stratified series.
    let errs: Vec<f64> = et
        .rows
        .iter()
        .filter(|r| r.series == "stratified")
        .map(|r| r.error)
        .collect();
    assert_eq!(errs.len(), 4);
    assert!(errs.windows(2).all(|w| w[1] < w[0]), "{errs:?}");
    assert!(errs[3] < 0.02);
    // Without the machine-dependent lines (the scene's absolute path, times).
    let text: String = report
        .to_text(Times::Hide)
        .lines()
        .filter(|l| !l.starts_with("  scene:") && !l.starts_with("  render time:"))
        .map(|l| format!("{l}\n"))
        .collect();
    insta::assert_snapshot!("report_tetrahedron", text);

    // A scene with a triangle through the near plane builds the clipper.
    let mut floor = Mesh::rectangle(20.0, 20.0);
    floor.transform(&glam::Mat4::from_rotation_x(-std::f32::consts::FRAC_PI_2));
    floor.transform(&glam::Mat4::from_translation(Vec3::new(0.0, -1.0, 0.0)));
    let mut s2 = scene("tetrahedron.toml");
    s2.meshes = vec![floor];
    let chapter = Rasterization {
        cull_back_faces: true,
    };
    let mut r = chapter.start(Arc::new(s2), &Settings::default()).unwrap();
    while !r.pass().complete {}
    let report = r.report();
    assert!(
        report
            .built
            .iter()
            .any(|b| b.contains("near-plane clipping")),
        "{:?}",
        report.built
    );
    assert!(report.built.iter().any(|b| b.contains("back-face culling")));
    assert!(report.left_out.iter().any(|b| b.contains("vertex colours")));
}

#[test]
fn mesh_checks_on_the_lecture_cases() {
    // The tetrahedron: closed manifold.
    let c = check_mesh(&Mesh::tetrahedron());
    assert!(c.is_closed() && c.is_manifold());
    assert_eq!((c.vertices, c.edges, c.triangles, c.euler()), (4, 6, 4, 2));
    assert_eq!(c.inconsistent_edges, 0);

    // A single rectangle: one boundary loop of 4 edges.
    let c = check_mesh(&Mesh::rectangle(2.0, 1.0));
    assert!(!c.is_closed() && c.is_manifold());
    assert_eq!(c.boundary_edges, 4);
    assert_eq!(c.boundary_loops, vec![4]);

    // Two triangles touching at one vertex: a non-manifold vertex (two
    // fans), two boundary loops of 3 through it.
    let p = vec![Vec3::ZERO, Vec3::X, Vec3::Y, -Vec3::X, -Vec3::Y];
    let c = check_mesh(&Mesh::new("bowtie", p, vec![[0, 1, 2], [0, 3, 4]]));
    assert_eq!(c.nonmanifold_vertices, vec![0]);
    assert!(c.nonmanifold_edges.is_empty());
    assert_eq!(c.boundary_loops, vec![3, 3]);
    assert!(!c.is_manifold());

    // Three triangles on one edge: a non-manifold edge.
    let p = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z, -Vec3::Y];
    let c = check_mesh(&Mesh::new("book", p, vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]]));
    assert_eq!(c.nonmanifold_edges, vec![[0, 1]]);
    assert!(!c.is_manifold());
    assert!(c.verdict().starts_with("not manifold"));

    // The bunny shipped in scenes/: closed, manifold, genus 0
    // (V - E + F = 1839 - 5511 + 3674 = 2), consistently oriented.
    let bunny = scene("bunny.toml");
    let c = check_mesh(&bunny.meshes[0]);
    assert_eq!((c.vertices, c.edges, c.triangles), (1839, 5511, 3674));
    assert!(c.is_closed() && c.is_manifold());
    assert_eq!(c.euler(), 2);
    assert_eq!(c.inconsistent_edges, 0);
    assert_eq!(c.verdict(), "closed manifold");
}

#[test]
fn exercise_references_pass() {
    let ex: Vec<_> = grading::all()
        .into_iter()
        .filter(|e| e.chapter == 2)
        .collect();
    assert_eq!(ex.len(), 5);
    for e in &ex {
        assert!(Path::new(env!("CARGO_MANIFEST_DIR")).join(e.file).is_file());
        assert!(grading::run(e).is_pass(), "{}", e.id());
    }
}

#[test]
fn graders_catch_wrong_answers() {
    use raystep::grading::exercises::ch2::{
        check_barycentric, check_depth_test, check_edge_function,
    };
    // Sign flipped edge function, unnormalised barycentrics, `<=` depth test.
    assert!(
        !check_edge_function(|a, b, p| -raystep::ch2_rasterization::edge::edge_function(a, b, p))
            .passed()
    );
    assert!(
        !check_barycentric(
            |a, b, c, p| raystep::ch2_rasterization::edge::barycentric(a, b, c, p).map(|v| v * 2.0)
        )
        .passed()
    );
    assert!(!check_depth_test(|d, i, z| {
        if z <= d[i] {
            d[i] = z;
            true
        } else {
            false
        }
    })
    .passed());
}
