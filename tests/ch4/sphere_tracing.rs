//! Chapter 4: sphere-traced hits against analytic ones, the Eikonal check,
//! the stiff cases, scene files with SDFs, what the report says it built
//! and left out, determinism, and a snapshot of the report.

use crate::common;
use std::sync::Arc;

use glam::{DVec3, Vec2, Vec3};
use raystep::ch4_implicit_surfaces::distance::{Exactness, ScaleBound};
use raystep::ch4_implicit_surfaces::eikonal::eikonal_check;
use raystep::ch4_implicit_surfaces::march::{
    fixed_step, over_relaxed, sphere_trace, Ending, March,
};
use raystep::ch4_implicit_surfaces::normal::{normal, NormalScheme};
use raystep::ch4_implicit_surfaces::render::Method;
use raystep::ch4_implicit_surfaces::stability::{
    ellipsoid_wrong_pixels, grazing, stability_cases, thin_plate_wrong_pixels,
};
use raystep::ch4_implicit_surfaces::stage::{SphereTracing, DEFAULT};
use raystep::ch4_implicit_surfaces::studies::{
    analytic_hit, error_against_time, ray_ellipsoid, sphere_on_plane, study_camera,
};
use raystep::core::film::Film;
use raystep::core::report::{Report, Times};
use raystep::core::stage::{Chapter, Settings};
use raystep::scene::Scene;

fn scene(name: &str) -> Scene {
    Scene::load(&common::root().join("scenes").join(format!("{name}.toml"))).unwrap()
}

fn parse(text: &str) -> raystep::Result<Scene> {
    Scene::from_text(text, "test")
}

fn render(stage: &SphereTracing, scene: Scene, studies: bool) -> (Report, Vec<Film>) {
    let settings = Settings {
        studies,
        ..Settings::default()
    };
    let mut r = stage.start(Arc::new(scene), &settings).unwrap();
    // A coarse first look, then the full pass (one pass below 64 pixels).
    let mut passes = 1;
    while !r.pass().complete {
        passes += 1;
    }
    assert!(passes <= 2, "{passes} passes");
    let films = r.snapshot().views;
    (r.report(), films)
}

/// Every pixel of the study camera: sphere tracing on the sphere-on-plane
/// scene lands within ε / |cos θ| of the analytic hit (θ between the ray
/// and the normal), for the plain and the over-relaxed march.
#[test]
fn sphere_traced_hits_match_analytic_hits_within_epsilon() {
    let cam = study_camera();
    for eps in [1e-2f32, 1e-3, 1e-4] {
        let m = March {
            epsilon: eps,
            max_steps: 4096,
            max_distance: 20.0,
            step_factor: 1.0,
        };
        let mut checked = 0;
        for y in 0..cam.height {
            for x in 0..cam.width {
                let ray = cam.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
                let Some(exact) = analytic_hit(&ray).filter(|t| *t < 20.0) else {
                    continue;
                };
                // Rays passing within a few ε of the sphere without touching
                // it count as hits: the grazing case of the stiff cases.
                let (o, d) = (ray.origin, ray.dir);
                let closest = (o - d * o.dot(d)).length() - 1.0;
                if closest > 0.0 && closest < 4.0 * eps {
                    continue;
                }
                let p = ray.at(exact as f32);
                let n = normal(&sphere_on_plane, p, 1e-4, NormalScheme::Central, Vec3::Y);
                let cos = n.dot(ray.dir).abs();
                if cos < 0.05 {
                    continue; // grazing: covered by the stiff cases
                }
                for trace in [
                    sphere_trace(&sphere_on_plane, &ray, &m),
                    over_relaxed(&sphere_on_plane, &ray, &m, 1.6),
                ] {
                    let t = trace.hit().expect("a hit where the analytic ray hits");
                    let err = (t as f64 - exact).abs();
                    // ε along the normal is ε / cos θ along the ray; plus f32 rounding.
                    let bound = (eps / cos) as f64 + 1e-5 * exact;
                    assert!(
                        err <= bound,
                        "ε {eps}, pixel ({x}, {y}): t {t}, exact {exact}, error {err} > {bound}"
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 4000, "{checked}");
    }
}

#[test]
fn fixed_step_error_is_bounded_by_the_step_and_shrinks_with_it() {
    let ray = raystep::ch3_ray_triangle::ray::Ray::new(
        Vec3::new(0.0, 0.0, 5.0),
        Vec3::new(0.1, -0.05, -1.0),
    )
    .unwrap();
    let exact = ray_ellipsoid(
        ray.origin.as_dvec3(),
        ray.dir.as_dvec3(),
        DVec3::ZERO,
        DVec3::ONE,
    )
    .unwrap();
    let m = March {
        max_steps: 100_000,
        ..March::default()
    };
    let mut last = f64::INFINITY;
    for delta in [0.2f32, 0.05, 0.0125] {
        let t = fixed_step(&sphere_on_plane, &ray, delta, &m).hit().unwrap();
        let err = (t as f64 - exact).abs();
        assert!(err < delta as f64, "Δ {delta}: error {err}");
        assert!(
            err < last,
            "Δ {delta}: error {err} did not shrink from {last}"
        );
        last = err;
    }
}

#[test]
fn the_eikonal_check_reads_one_for_exact_sdfs_and_flags_the_others() {
    let s = scene("sdf-shapes");
    let rows = eikonal_check(&s.sdfs);
    assert_eq!(rows.len(), 12);
    for row in &rows {
        let r = &row.range;
        assert_eq!(r.samples, 4096, "{}", row.name);
        if row.declared == Exactness::Exact {
            assert!(
                (r.p01 - 1.0).abs() < 0.01 && (r.p99 - 1.0).abs() < 0.01,
                "{}: {r:?}",
                row.name
            );
        }
        // Nothing in this scene overestimates.
        assert!(r.p99 < 1.01, "{}: {r:?}", row.name);
    }
    let smooth = rows.iter().find(|r| r.name == "smooth union").unwrap();
    assert!(smooth.range.p01 < 0.9, "{smooth:?}");
    assert_eq!(smooth.range.verdict(), "< 1: a bound");

    let l = scene("sdf-lipschitz");
    let rows = eikonal_check(&l.sdfs);
    assert_eq!(rows[0].declared, Exactness::Bound);
    assert!(
        rows[0].range.max <= 1.01 && rows[0].range.p01 < 0.9,
        "{:?}",
        rows[0]
    );
    assert_eq!(rows[1].declared, Exactness::Unsafe);
    assert_eq!(rows[1].lipschitz, 10.0);
    assert!(
        rows[1].range.max > 5.0 && rows[1].range.max <= 10.01,
        "{:?}",
        rows[1]
    );
    assert_eq!(rows[1].range.verdict(), "> 1: unsafe");
}

#[test]
fn every_stiff_case_comes_out_as_expected() {
    let cases = stability_cases();
    assert!(cases.len() >= 8);
    for c in &cases {
        assert!(
            c.ok,
            "{}: expected {}, measured {}",
            c.name, c.expected, c.measured
        );
    }
}

#[test]
fn grazing_rays_rarely_exhaust_the_budget() {
    let (share, steps) = grazing();
    assert!(share > 0.0 && share <= 0.01, "{share}");
    // Steps grow as the ray passes closer to the silhouette...
    assert!(steps[0] < steps[3], "{steps:?}");
    // ... until it passes within ε and counts as a hit.
    assert!(steps.iter().all(|s| *s < 1000), "{steps:?}");
}

#[test]
fn an_overestimating_sdf_leaves_holes_that_a_step_factor_closes() {
    let (wrong, over, n) = ellipsoid_wrong_pixels(ScaleBound::Max, 1.0);
    assert!(
        wrong > 50 && over > 0,
        "{wrong} wrong of {n}, {over} oversteps"
    );
    assert_eq!(ellipsoid_wrong_pixels(ScaleBound::Max, 0.1).0, 0);
    assert_eq!(ellipsoid_wrong_pixels(ScaleBound::Min, 1.0).0, 0);
}

#[test]
fn a_thin_plate_is_found_by_sphere_tracing_and_missed_by_fixed_steps() {
    let (wrong, covered) = thin_plate_wrong_pixels(Method::Plain);
    assert!(covered > 500, "{covered}");
    assert_eq!(wrong, 0);
    assert_eq!(thin_plate_wrong_pixels(Method::OverRelaxed(1.9)).0, 0);
    let (wrong, _) = thin_plate_wrong_pixels(Method::FixedStep(0.01));
    assert!(wrong * 2 > covered, "{wrong} of {covered}");
}

#[test]
fn inside_or_outside_is_one_evaluation() {
    let f = |p: Vec3| p.length() - 1.0;
    let m = March::default();
    let from_inside = raystep::ch3_ray_triangle::ray::Ray::new(Vec3::ZERO, Vec3::Y).unwrap();
    let t = sphere_trace(&f, &from_inside, &m);
    assert!(
        t.inside && t.ending == Ending::Hit && (t.t - 1.0).abs() < 1e-4,
        "{t:?}"
    );
    let from_outside =
        raystep::ch3_ray_triangle::ray::Ray::new(Vec3::new(0.0, -3.0, 0.0), Vec3::Y).unwrap();
    let t = sphere_trace(&f, &from_outside, &m);
    assert!(!t.inside && (t.t - 2.0).abs() < 1e-4, "{t:?}");
    assert_eq!(
        t.steps, 2,
        "one evaluation at the origin, one step of exactly 2"
    );
}

#[test]
fn sdf_only_scenes_load_no_mesh_and_build_no_bvh() {
    let s = scene("sdf-shapes");
    assert!(s.meshes.is_empty());
    assert_eq!(s.triangle_count(), 0);
    assert_eq!(s.sdfs.len(), 12);
    let (report, films) = render(&DEFAULT, s, false);
    assert!(report
        .left_out
        .iter()
        .any(|l| l == "meshes and BVH: the scene has no meshes, none loaded, no BVH built"));
    assert!(report
        .built
        .iter()
        .any(|b| b.starts_with("sphere tracer over 12 SDF objects")));
    assert_eq!(report.nonfinite_caught, 0);
    assert_eq!(films.len(), 5);
}

#[test]
fn mesh_only_scenes_evaluate_no_sdf() {
    let (report, films) = render(&DEFAULT, scene("tetrahedron"), false);
    assert!(report
        .left_out
        .iter()
        .any(|l| l == "SDF evaluation: the scene has no [[sdfs]] (0 evaluations of f)"));
    assert!(report
        .built
        .iter()
        .any(|l| l.starts_with("chapter 3's BVH over 1 meshes (4 triangles")));
    assert!(report
        .facts
        .iter()
        .any(|(k, v)| k == "steps" && v.starts_with("0 evaluations")));
    // No SDF, so no steps anywhere; but the tetrahedron itself is seen.
    assert!(films[3].pixels.iter().all(|p| *p == Vec3::ZERO));
    assert!(
        films[0]
            .pixels
            .iter()
            .filter(|p| p.max_element() > 0.2)
            .count()
            > 1000
    );
    // No SDF table means no SDF allocation either.
    assert_eq!(scene("tetrahedron").sdfs.capacity(), 0);
}

#[test]
fn a_mixed_scene_traces_both_and_the_nearer_surface_wins() {
    use raystep::ch4_implicit_surfaces::hit::Surface;
    use raystep::ch4_implicit_surfaces::render::{trace_pixel, MeshTracer};
    // A unit sphere (SDF) at z = 0 and a square (mesh) at z = -2 behind it,
    // then the square moved to z = +2, in front of it.
    for (square_z, want_mesh) in [(-2.0f32, false), (2.0, true)] {
        let s = parse(&format!(
            "[camera]\neye = [0, 0, 5]\nwidth = 40\nheight = 30\n\
             [[objects]]\nshape = \"rectangle\"\nsize = [3, 3]\ntranslate = [0, 0, {square_z}]\n\
             [[sdfs]]\ntype = \"sphere\"\n"
        ))
        .unwrap();
        let geometry = raystep::ch3_ray_triangle::geometry::Geometry::new(&s);
        let meshes = Some(MeshTracer {
            geometry: &geometry,
            meshes: &s.meshes,
        });
        let ray = raystep::ch1_projection::camera::Camera::of(&s).ray(Vec2::new(20.0, 15.0));
        let m = March::default();
        let px = trace_pixel(
            &ray,
            &s.sdfs,
            &m,
            Method::Plain,
            NormalScheme::Tetrahedron,
            meshes,
        );
        let hit = px.hit.expect("the centre ray hits something");
        // Analytic: the sphere's front at t = 5 - 1 = 4, the square at 5 - z.
        let (want_t, want_surface) = if want_mesh {
            (5.0 - square_z, Surface::Mesh(0))
        } else {
            (4.0, Surface::Sdf(0))
        };
        assert_eq!(hit.surface, want_surface, "square at z = {square_z}");
        assert!((hit.t - want_t).abs() < 1e-3, "t = {} for {want_t}", hit.t);
        assert!(hit.normal.dot(ray.dir) < 0.0, "normals face the viewer");
    }
    // The whole stage on a mixed scene: both parts drawn, and the report
    // says chapter 3's BVH was built.
    let s = parse(
        "[camera]\nwidth = 40\nheight = 30\n[[objects]]\nshape = \"box\"\ntranslate = [2, 0, 0]\n\
         [[sdfs]]\ntype = \"sphere\"\ntranslate = [-1, 0, 0]\n",
    )
    .unwrap();
    let (report, films) = render(&DEFAULT, s, false);
    assert!(report
        .built
        .iter()
        .any(|b| b.starts_with("sphere tracer over 1 SDF objects")));
    assert!(report
        .built
        .iter()
        .any(|b| b.starts_with("chapter 3's BVH over 1 meshes")));
    let lit = |x0: u32, x1: u32| {
        (0..30)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .filter(|&(x, y)| films[1].get(x, y) != Vec3::ZERO)
            .count()
    };
    assert!(lit(0, 20) > 50, "the sphere (left half): {}", lit(0, 20));
    assert!(lit(20, 40) > 50, "the box (right half): {}", lit(20, 40));
}

#[test]
fn renders_are_the_same_on_one_and_two_threads() {
    let s = scene("sdf-shapes").with_resolution(64, 48).unwrap();
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| render(&DEFAULT, s.clone(), false).1)
    };
    let one = run(1);
    assert_eq!(one, run(2));
    let over = SphereTracing {
        method: Method::OverRelaxed(1.6),
        ..DEFAULT
    };
    let a = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap()
        .install(|| render(&over, s.clone(), false).1);
    assert_eq!(a, render(&over, s.clone(), false).1);
    // Over-relaxation changes the steps, not the picture (much).
    assert!(a[0].rmse(&one[0]) < 0.01);
}

#[test]
fn no_nan_reaches_any_view_of_the_shipped_sdf_scenes() {
    for name in ["sdf-shapes", "sdf-lipschitz"] {
        let s = scene(name).with_resolution(64, 48).unwrap();
        for method in [
            Method::Plain,
            Method::OverRelaxed(1.9),
            Method::FixedStep(0.05),
        ] {
            let stage = SphereTracing { method, ..DEFAULT };
            let (report, films) = render(&stage, s.clone(), false);
            assert_eq!(report.nonfinite_caught, 0, "{name} {method:?}");
            for f in films {
                assert!(f.pixels.iter().all(|p| p.is_finite()));
            }
        }
    }
}

#[test]
fn the_error_against_time_study_converges() {
    let et = error_against_time();
    assert!(et.show_slopes);
    let series = |name: &str| -> Vec<f64> {
        et.rows
            .iter()
            .filter(|r| r.series == name)
            .map(|r| r.error)
            .collect()
    };
    let plain = series("sphere tracing, ε");
    assert_eq!(plain.len(), 5);
    assert!(plain[4] < 1e-3 && plain[0] > plain[4], "{plain:?}");
    let over = series("over-relaxed ω = 1.6, ε");
    assert!(over[4] < 1e-3, "{over:?}");
    let budget = series("sphere tracing, budget");
    assert!(budget[0] > 10.0 * budget[5], "{budget:?}");
    let fixed = series("fixed step, Δ");
    assert!(fixed[4] < fixed[0], "{fixed:?}");
    for r in &et.rows {
        assert!(r.error.is_finite() && r.seconds > 0.0, "{r:?}");
    }
}

#[test]
fn bad_sdf_entries_get_errors_naming_the_key() {
    let cases = [
        ("[[sdfs]]\nradius = 1\n", "sdfs[0]", "missing `type`"),
        ("[[sdfs]]\ntype = \"sphre\"\n", "sdfs[0].type", "did you mean `sphere`?"),
        ("[[sdfs]]\ntype = \"sphere\"\nradius = -1\n", "sdfs[0].radius", "positive"),
        ("[[sdfs]]\ntype = \"sphere\"\nradus = 1\n", "sdfs[0].radus", "did you mean `radius`?"),
        ("[[sdfs]]\ntype = \"box\"\nsize = [1, 0, 1]\n", "sdfs[0].size", "3 positive numbers"),
        (
            "[[sdfs]]\ntype = \"union\"\nof = [{ type = \"sphere\" }, { type = \"torus\", minor = \"x\" }]\n",
            "sdfs[0].of[1].minor",
            "finite number",
        ),
        ("[[sdfs]]\ntype = \"union\"\nof = [{ type = \"sphere\" }]\n", "sdfs[0].of", "at least 2"),
        (
            "[[sdfs]]\ntype = \"union\"\nof = [{ type = \"sphere\", material = \"x\" }, { type = \"box\" }]\n",
            "sdfs[0].of[0].material",
            "top-level",
        ),
        ("[[sdfs]]\ntype = \"sphere\"\nmaterial = \"gold\"\n", "sdfs[0].material", "no material named `gold`"),
        ("[[sdfs]]\ntype = \"sphere\"\nscale_bound = \"max\"\n", "sdfs[0].scale_bound", "per-axis"),
        ("[[sdfs]]\ntype = \"sphere\"\nscale = [1, -1, 1]\n", "sdfs[0].scale", "factors must lie in"),
        ("[[sdfs]]\ntype = \"plane\"\nnormal = [0, 0, 0]\n", "sdfs[0].normal", "zero vector"),
        (
            "[[sdfs]]\ntype = \"sphere\"\nrotate = { axis = [0, 0, 0], degrees = 3 }\n",
            "sdfs[0].rotate.axis",
            "not zero",
        ),
        ("[[sdfs]]\ntype = \"rounded_box\"\nsize = [1, 1, 1]\nradius = 0.7\n", "sdfs[0].radius", "half the smallest side"),
        ("[[sdfs]]\ntype = \"sphere\"\ntranslate = [1, 2]\n", "sdfs[0].translate", "[x, y, z]"),
    ];
    for (text, at, words) in cases {
        let err = parse(text).unwrap_err().to_string();
        assert!(
            err.contains(&format!("test.toml: {at}: ")) && err.contains(words),
            "{text}\n→ {err}\n(expected `{at}` and `{words}`)"
        );
    }
}

#[test]
fn snapshot_sdf_shapes_report() {
    let s = scene("sdf-shapes").with_resolution(80, 60).unwrap();
    let (report, _) = render(&DEFAULT, s, false);
    let text: String = report
        .to_text(Times::Hide)
        .lines()
        .filter(|l| !l.contains("render time") && !l.contains("  scene: "))
        .collect::<Vec<_>>()
        .join("\n");
    insta::assert_snapshot!(text);
}

#[test]
fn snapshot_sdf_shapes_ascii_preview() {
    let s = scene("sdf-shapes").with_resolution(96, 72).unwrap();
    let (_, films) = render(&DEFAULT, s, false);
    insta::assert_snapshot!(raystep::core::preview::preview(
        &films[0],
        48,
        raystep::core::preview::PreviewStyle::Ascii
    ));
}

#[test]
fn central_and_tetrahedron_normals_agree() {
    let s = scene("sdf-shapes").with_resolution(64, 48).unwrap();
    let normals = |normals| {
        let stage = SphereTracing { normals, ..DEFAULT };
        render(&stage, s.clone(), false).1[1].clone()
    };
    let (a, b) = (
        normals(NormalScheme::Central),
        normals(NormalScheme::Tetrahedron),
    );
    assert_ne!(a, b, "two different schemes");
    assert!(a.rmse(&b) < 0.01, "{}", a.rmse(&b));
}

#[test]
fn over_relaxation_falls_back_when_its_step_is_not_certified() {
    // Head-on at a sphere, ω = 1.9 overshoots: the balls stop overlapping,
    // the march goes back and finishes with plain steps.
    let f = |p: Vec3| p.length() - 1.0;
    let ray = raystep::ch3_ray_triangle::ray::Ray::new(Vec3::new(0.0, 0.3, 6.0), -Vec3::Z).unwrap();
    let m = March::default();
    let plain = sphere_trace(&f, &ray, &m);
    let over = over_relaxed(&f, &ray, &m, 1.9);
    assert!(over.oversteps > 0, "{over:?}");
    assert_eq!(over.ending, Ending::Hit);
    assert!((over.t - plain.t).abs() < 2e-4, "{over:?} vs {plain:?}");
    // ω = 1 is plain sphere tracing, step for step.
    let one = over_relaxed(&f, &ray, &m, 1.0);
    assert_eq!((one.steps, one.oversteps), (plain.steps, 0));
}

/// The first picture comes quickly: a pass at a quarter of the resolution,
/// enlarged to the full size, then the full pass, whose pictures are the
/// same as a render without the first look.
#[test]
fn a_coarse_first_pass_comes_before_the_full_one() {
    let scene = Arc::new(crate::common::shipped_scene("sdf-shapes", 128, 96));
    let stage = DEFAULT;
    let mut r = stage.start(scene.clone(), &Settings::default()).unwrap();
    let first = r.pass();
    assert_eq!((first.done, first.planned, first.complete), (1, 2, false));
    assert_eq!(first.rays, 32 * 24, "a sixteenth of the rays");
    let look = r.snapshot().views;
    assert_eq!(
        (look[0].width, look[0].height),
        (128, 96),
        "enlarged to the full size"
    );
    let last = r.pass();
    assert_eq!((last.done, last.planned, last.complete), (2, 2, true));
    assert_eq!(last.rays, 128 * 96);
    let full = r.snapshot().views;
    assert_ne!(look[0], full[0]);
    // Small images have one pass.
    let small = Arc::new(crate::common::shipped_scene("sdf-shapes", 32, 24));
    assert!(
        stage
            .start(small, &Settings::default())
            .unwrap()
            .pass()
            .complete
    );
}
