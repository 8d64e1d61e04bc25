//! The stiff and extreme cases of chapter 3 (requirement 2): rays parallel
//! to a triangle, rays through edges and vertices of a closed mesh (no
//! leaks), geometry far from the origin, tiny triangles, self-intersection
//! without a fixed epsilon, and agreement with chapter 2's raster image.

use glam::{DVec3, Vec3};

use crate::ch3_ray_triangle::geometry::Geometry;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::{intersect_f64, Intersector};
use crate::core::format::format_number;
use crate::core::report::StabilityCase;
use crate::core::sampling::random;
use crate::scene::mesh::Mesh;
use crate::scene::Scene;

use super::leaks::{bvh_escapes, self_intersections, t_relative_error, LeakCount};
use super::studies::StudySize;

/// Requirement 2 for chapter 3: the named stiff and extreme cases.
pub fn stability_cases(size: &StudySize, leaks: &[LeakCount]) -> Vec<StabilityCase> {
    let mut cases = Vec::new();
    let mut case = |name: &str, expected: &str, measured: String, ok: bool| {
        cases.push(StabilityCase::new(name, expected, measured, ok))
    };
    let all = |ray: &Ray, tri: [Vec3; 3]| {
        Intersector::ALL.map(|x| x.intersect(ray, tri, 0.0, f32::INFINITY))
    };
    let shown = |h: &[Option<crate::ch3_ray_triangle::triangle::Hit>; 3]| {
        h.iter()
            .map(|h| match h {
                Some(h) => format!("t = {}", format_number(h.t as f64)),
                None => "miss".into(),
            })
            .collect::<Vec<_>>()
            .join(" / ")
    };
    let finite = |h: &[Option<crate::ch3_ray_triangle::triangle::Hit>; 3]| {
        h.iter()
            .flatten()
            .all(|h| h.t.is_finite() && h.u.is_finite() && h.v.is_finite())
    };
    let unit = [
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
    ];

    // Rays parallel to the triangle's plane: in it, and above it.
    for (name, origin) in [
        (
            "ray parallel to the triangle, in its plane",
            Vec3::new(-5.0, 0.0, 0.0),
        ),
        (
            "ray parallel to the triangle, above it",
            Vec3::new(-5.0, 0.0, 1e-3),
        ),
    ] {
        let h = all(&Ray::new(origin, Vec3::X).expect("valid"), unit);
        case(
            name,
            "miss with all three tests, no NaN",
            shown(&h),
            h.iter().all(Option::is_none),
        );
    }

    // Leaks.
    for mesh in ["sphere", "bunny.obj"] {
        let of = |x: Intersector| leaks.iter().find(|c| c.mesh == mesh && c.intersector == x);
        if let (Some(w), Some(p), Some(m)) = (
            of(Intersector::Watertight),
            of(Intersector::PlaneInside),
            of(Intersector::MollerTrumbore),
        ) {
            case(
                &format!(
                    "{} rays at edges and vertices of the {mesh} from inside",
                    w.rays
                ),
                "0 leaks with the watertight test (the others are reported)",
                format!(
                    "watertight {}, plane + inside {}, Möller–Trumbore {}",
                    w.leaks, p.leaks, m.leaks
                ),
                w.leaks == 0,
            );
        }
    }
    let n = (size.leak_rays / 10).max(1000);
    let escapes = bvh_escapes(&Mesh::icosphere(4), n, 3);
    case(
        &format!("{n} rays from inside the icosphere through the BVH"),
        "every ray hits the sphere",
        format!("{escapes} escaped"),
        escapes == 0,
    );

    // Far from the origin: camera and triangle both at coordinates D.
    for k in [5, 6, 7] {
        let d = 10f32.powi(k);
        let base = Vec3::splat(d);
        let tri = unit.map(|p| base + p * 10.0 + Vec3::new(0.0, 0.0, -10.0));
        let ray = Ray::new(base, Vec3::new(0.05, 0.1, -1.0)).expect("valid");
        let h = all(&ray, tri);
        let reference = intersect_f64(
            ray.origin.as_dvec3(),
            ray.dir.as_dvec3(),
            tri.map(|p| p.as_dvec3()),
        );
        let err = match (h[2], reference) {
            (Some(h), Some((t, _, _))) => (h.t as f64 - t).abs() / t,
            _ => f64::INFINITY,
        };
        case(
            &format!("ray and triangle at coordinates 1e{k}"),
            "all three hit; watertight t within 1e-5 relative of f64",
            format!(
                "{}; watertight rel. error {}",
                shown(&h),
                format_number(err)
            ),
            h.iter().all(Option::is_some) && finite(&h) && err < 1e-5,
        );
    }

    // A tiny triangle, edge 1e-6, 1 unit away.
    let tiny = unit.map(|p| p * 0.5e-6 + Vec3::new(0.3, 0.2, -1.0));
    let aim = (tiny[0] + tiny[1] + tiny[2]) / 3.0;
    let h = all(&Ray::new(Vec3::ZERO, aim).expect("valid"), tiny);
    let u_ok = h.iter().flatten().all(|h| (h.u - 1.0 / 3.0).abs() < 0.05);
    case(
        "tiny triangle (edge 1e-6) hit at its centroid",
        "all three hit, u and v near 1/3",
        shown(&h),
        h.iter().all(Option::is_some) && finite(&h) && u_ok,
    );

    // Degenerate triangles: no area, many rays.
    let degenerate = [
        [Vec3::ZERO, Vec3::X, Vec3::X * 2.0],
        [Vec3::ONE, Vec3::ONE, Vec3::new(1.0, 2.0, 1.0)],
        [Vec3::splat(0.5); 3],
    ];
    let mut hits = 0;
    let mut nan = 0;
    for (i, tri) in degenerate.iter().enumerate() {
        for r in 0..1000u64 {
            let rnd = |d: u64| random(5, r, i as u64, d);
            let target = tri[0].lerp(tri[2], rnd(0)) + (tri[1] - tri[0]) * rnd(1);
            let origin = Vec3::new(rnd(2), rnd(3), rnd(4)) * 4.0 - 2.0;
            if let Ok(ray) = Ray::new(origin, target - origin) {
                let h = all(&ray, *tri);
                hits += h.iter().flatten().count();
                nan += usize::from(!finite(&h));
            }
        }
    }
    case(
        "degenerate triangles (collinear, repeated vertices, a point), 3000 rays",
        "no hit, no NaN",
        format!("{hits} hits, {nan} NaN"),
        hits == 0 && nan == 0,
    );

    // Grazing rays: angle θ to the plane, hitting inside at t = 3.
    let big = unit.map(|p| p * 10.0);
    let mut worst: f64 = 0.0;
    let mut missed = 0;
    for k in 1..=5 {
        let theta = 10f64.powi(-k);
        let o = DVec3::new(0.0, 0.0, 3.0 * theta.sin());
        let d = DVec3::new(theta.cos(), 0.0, -theta.sin());
        let ray = Ray::new(o.as_vec3(), d.as_vec3()).expect("valid");
        let reference = intersect_f64(
            ray.origin.as_dvec3(),
            ray.dir.as_dvec3(),
            big.map(|p| p.as_dvec3()),
        );
        for h in all(&ray, big) {
            match (h, reference) {
                (Some(h), Some((t, _, _))) => worst = worst.max((h.t as f64 - t).abs() / t),
                _ => missed += 1,
            }
        }
    }
    case(
        "grazing rays, 1e-1 to 1e-5 rad to the plane",
        "all hit; t within 1e-4 relative of f64",
        format!("{missed} missed, worst rel. error {}", format_number(worst)),
        missed == 0 && worst < 1e-4,
    );

    // Bad directions are refused where the ray is built.
    let zero = Ray::new(Vec3::ZERO, Vec3::ZERO);
    let nan_dir = Ray::new(Vec3::ZERO, Vec3::new(f32::NAN, 1.0, 0.0));
    case(
        "ray with a zero or NaN direction",
        "refused by Ray::new with an error",
        format!(
            "zero: {}; NaN: {}",
            zero.err().map_or("accepted".into(), |e| e.to_string()),
            nan_dir.err().map_or("accepted".into(), |e| e.to_string())
        ),
        Ray::new(Vec3::ZERO, Vec3::ZERO).is_err() && Ray::new(Vec3::ZERO, Vec3::NAN).is_err(),
    );

    // Self-intersection far from the origin.
    for d in [1e5f32, 1e6] {
        let (scaled, fixed) = self_intersections(d, size.spawn_rays, 1e-4);
        case(
            &format!(
                "{} secondary rays leaving a sphere at 1e{}",
                size.spawn_rays,
                d.log10()
            ),
            "0 self-hits with the scaled offset (a fixed ε = 1e-4 is reported)",
            format!("scaled offset: {scaled}; fixed ε: {fixed}"),
            scaled == 0,
        );
    }

    // Precision of t across distances.
    let worst = (0..=7)
        .map(|k| t_relative_error(10f64.powi(k), 200, Intersector::Watertight))
        .fold((0.0f64, 0u64), |a, b| (a.0.max(b.0), a.1 + b.1));
    case(
        "relative error of t, distances 1 to 1e7 (watertight)",
        "below 1e-5 at every distance, no miss",
        format!("worst {}, {} missed", format_number(worst.0), worst.1),
        worst.0 < 1e-5 && worst.1 == 0,
    );
    cases
}

/// The stiff case "primary visibility agrees with chapter 2's raster
/// image on this scene": only edge pixels may differ.
pub fn agreement_case(scene: &Scene) -> StabilityCase {
    let geometry = Geometry::new(scene);
    let measured = crate::ch3_ray_triangle::agreement::raster_agreement(scene, &geometry);
    let (measured, ok) = match measured {
        Ok(a) => (
            format!(
                "{} of {} pixels differ ({:.2}%), {} of them off edges",
                a.differ,
                a.pixels,
                100.0 * a.differ as f64 / a.pixels.max(1) as f64,
                a.differ_off_edges
            ),
            a.differ_off_edges == 0,
        ),
        Err(e) => (
            format!("chapter 2 could not rasterize the scene: {e}"),
            false,
        ),
    };
    StabilityCase::new(
        "first hits against chapter 2's raster image (pixel centres)",
        "the same triangle everywhere but on edges",
        measured,
        ok,
    )
}
