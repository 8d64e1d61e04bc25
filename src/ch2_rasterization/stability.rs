//! The stiff and extreme cases of chapter 2 (requirement 2): sliver and
//! zero-area triangles, shared edges, triangles crossing the near plane,
//! z-fighting, huge coordinates.

use glam::{DVec2, Vec3};

use super::coverage::{coverage_counts, rasterize};
use super::frame::{render_frame, Frame};
use super::interpolate::{interpolate, Interpolation};
use super::setup::raster_triangle;
use super::studies::{screen_fan, screen_grid, test_camera};
use crate::core::report::StabilityCase;
use crate::scene::mesh::Mesh;
use crate::scene::Material;

/// How many samples are covered 0, 1, and 2+ times.
fn histogram(counts: &[u32]) -> [usize; 3] {
    let mut h = [0; 3];
    for &c in counts {
        h[(c as usize).min(2)] += 1;
    }
    h
}

/// Requirement 2 for chapter 2: the named stiff and extreme cases.
pub fn stability_cases() -> Vec<StabilityCase> {
    let mut cases = Vec::new();
    let mut case = |name: &str, expected: &str, measured: String, ok: bool| {
        cases.push(StabilityCase::new(name, expected, measured, ok))
    };
    let (w, h) = (64, 48);

    // Tilings: every sample exactly once.
    for (name, tris) in [
        ("fan of 36 triangles tiling the screen", screen_fan(w, h)),
        (
            "grid of 192 triangles with jittered vertices",
            screen_grid(w, h, 12, 8),
        ),
    ] {
        for spp in [1, 16] {
            let hist = histogram(&coverage_counts(&tris, w, h, spp, 3));
            case(
                &format!("{name}, {spp} spp"),
                "every sample covered exactly once",
                format!("0x: {}, 1x: {}, 2+x: {}", hist[0], hist[1], hist[2]),
                hist[0] == 0 && hist[2] == 0,
            );
        }
    }

    // Vertices exactly on pixel centres: a square (2.5, 2.5)-(10.5, 10.5)
    // split on its diagonal covers the 8x8 centres of its top-left half-open
    // extent, each once.
    let sq = |x: f64, y: f64| DVec2::new(x, y);
    let mut tris = raster_triangle([sq(2.5, 2.5), sq(10.5, 2.5), sq(10.5, 10.5)], 0, w, h);
    tris.extend(raster_triangle(
        [sq(2.5, 2.5), sq(10.5, 10.5), sq(2.5, 10.5)],
        1,
        w,
        h,
    ));
    let hist = histogram(&coverage_counts(&tris, w, h, 1, 0));
    case(
        "square with corners on pixel centres, two triangles",
        "64 centres covered once (top and left edges in, bottom and right out), none twice",
        format!("1x: {}, 2+x: {}", hist[1], hist[2]),
        hist[1] == 64 && hist[2] == 0,
    );

    // A sliver of aspect ratio 1e-6 along a row of pixel centres.
    let (len, y) = (4096.0, 10.5);
    let tri = raster_triangle(
        [
            sq(-2000.0, y - 0.002),
            sq(-2000.0 + len, y - 0.002),
            sq(48.0, y + 0.002),
        ],
        0,
        w,
        h,
    );
    let buf = rasterize(&tri, w, 0..h, 1, 0);
    let mut rows = std::collections::BTreeSet::new();
    let mut finite = true;
    let mut covered = 0;
    for py in 0..h {
        for px in 0..w {
            let s = buf.samples[(py * w + px) as usize];
            if s.is_covered() {
                covered += 1;
                rows.insert(py);
                let (a, d) =
                    interpolate(&tri[0], buf.position(px, py, 0), Interpolation::Perspective);
                let sum = a[3] + a[4] + a[5];
                finite &=
                    a.iter().all(|v| v.is_finite()) && d.is_finite() && (sum - 1.0).abs() < 1e-9;
            }
        }
    }
    case(
        "sliver triangle, aspect ratio 1e-6 (4096 px by 0.004 px)",
        "covers pixels of row 10 only; φ finite and summing to 1",
        format!("{covered} pixels covered in rows {rows:?}; finite: {finite}"),
        rows.iter().all(|&r| r == 10) && finite,
    );

    // Zero-area triangles.
    let collinear = raster_triangle([sq(1.0, 1.0), sq(20.0, 11.0), sq(39.0, 21.0)], 0, w, h);
    let point = raster_triangle([sq(5.5, 5.5); 3], 1, w, h);
    let cam = test_camera(w, h);
    let flat = Mesh::new(
        "flat",
        vec![
            Vec3::new(-1.0, 0.0, -3.0),
            Vec3::new(1.0, 0.0, -3.0),
            Vec3::new(0.3, 0.0, -3.0),
        ],
        vec![[0, 1, 2], [0, 0, 1]],
    );
    let frame = render_frame(&cam, &[flat], &[Material::default_grey()], 4, 0, false);
    let (nan, cov) = frame.as_ref().map_or((u64::MAX, usize::MAX), |f| {
        (
            f.films.iter().map(|x| x.clone().scrub_nonfinite()).sum(),
            f.buffer.samples.iter().filter(|s| s.is_covered()).count(),
        )
    });
    case(
        "zero-area triangles (collinear, one point, a 3D triangle seen edge-on)",
        "no screen triangle, nothing covered, no NaN",
        format!(
            "screen triangles: {}, {}; covered samples {cov}, NaN/Inf {nan}",
            collinear.len(),
            point.len()
        ),
        collinear.is_empty() && point.is_empty() && cov == 0 && nan == 0,
    );

    // Vertices far off screen.
    for far in [1e6, 1e9] {
        let tri = raster_triangle([sq(-far, -10.0), sq(far, -10.0), sq(32.0, far)], 0, w, h);
        let hist = histogram(&coverage_counts(&tri, w, h, 4, 1));
        case(
            &format!("triangle with vertices {far:e} px off screen covering it"),
            if far > super::clip::GUARD_BAND {
                "clipped to the guard band; every sample covered once"
            } else {
                "no overflow; every sample covered once"
            },
            format!("0x: {}, 1x: {}, 2+x: {}", hist[0], hist[1], hist[2]),
            hist[0] == 0 && hist[2] == 0,
        );
    }
    let far = [sq(3.3, 4.1), sq(1e6, 0.37e6 + 4.1), sq(-0.5e6 + 3.3, 1e6)];
    let tri = raster_triangle(far, 0, w, h);
    let counts = coverage_counts(&tri, w, h, 1, 0);
    let mut wrong = 0;
    for py in 0..h {
        for px in 0..w {
            let p = sq(px as f64 + 0.5, py as f64 + 0.5);
            // Signed distances to the three edges, in pixels (f64, unsnapped).
            let d = |a: DVec2, b: DVec2| (b - a).perp_dot(p - a) / (b - a).length();
            let ds = [d(far[0], far[1]), d(far[1], far[2]), d(far[2], far[0])];
            if ds.iter().any(|x| x.abs() < 0.01) {
                continue;
            }
            let inside = ds.iter().all(|x| *x > 0.0) || ds.iter().all(|x| *x < 0.0);
            wrong += usize::from(inside != (counts[(py * w + px) as usize] == 1));
        }
    }
    case(
        "edges from a vertex 1e6 px off screen crossing the image",
        "the same pixels as an exact f64 inside test",
        format!("{wrong} pixels differ"),
        wrong == 0,
    );

    // The near plane.
    let crossing = Mesh::new(
        "crossing",
        vec![
            Vec3::new(-1.0, -0.5, -2.0),
            Vec3::new(1.0, -0.5, -2.0),
            Vec3::new(0.0, -0.5, 3.0),
        ],
        vec![[0, 1, 2]],
    );
    let behind = Mesh::new(
        "behind",
        vec![
            Vec3::new(-1.0, -0.5, 2.0),
            Vec3::new(1.0, -0.5, 2.0),
            Vec3::new(0.0, 0.5, 3.0),
        ],
        vec![[0, 1, 2]],
    );
    let grey = [Material::default_grey()];
    match (
        render_frame(&cam, &[crossing], &grey, 1, 0, false),
        render_frame(&cam, &[behind], &grey, 1, 0, false),
    ) {
        (Ok(a), Ok(b)) => {
            let cov = |f: &Frame| f.buffer.samples.iter().filter(|s| s.is_covered()).count();
            // The front edge projects to row y = 24 + 0.25·24/tan(30°)... its
            // pixels below the horizon must be covered right down to the bottom.
            let bottom = (0..w).any(|x| a.buffer.samples[((h - 1) * w + x) as usize].is_covered());
            let nan: u64 = a.films.iter().map(|x| x.clone().scrub_nonfinite()).sum();
            case(
                "triangle crossing the near plane",
                "clipped, not dropped: its front part covers down to the bottom row; no NaN",
                format!(
                    "cut: {}, {} screen triangles, {} samples covered, bottom row reached: {bottom}, NaN {nan}",
                    a.stats.clipped_near, a.tris.len(), cov(&a)
                ),
                a.stats.clipped_near == 1 && cov(&a) > 0 && bottom && nan == 0,
            );
            case(
                "triangle entirely behind the camera",
                "nothing",
                format!("behind: {}, {} samples covered", b.stats.behind, cov(&b)),
                b.stats.behind == 1 && cov(&b) == 0,
            );
        }
        (a, b) => case(
            "triangles at the near plane",
            "render",
            format!("{:?} {:?}", a.err(), b.err()),
            false,
        ),
    }

    // Coincident triangles: same vertices, equal depth everywhere.
    let mut twins = Mesh::new(
        "twins",
        vec![
            Vec3::new(-1.0, -1.0, -3.0),
            Vec3::new(1.0, -1.0, -3.0),
            Vec3::new(0.0, 1.0, -2.0),
        ],
        vec![[0, 1, 2], [1, 2, 0], [2, 0, 1]],
    );
    twins.colors = Some(vec![Vec3::X, Vec3::Y, Vec3::Z]);
    match render_frame(&cam, &[twins], &grey, 4, 0, false) {
        Ok(f) => {
            let ids: std::collections::BTreeSet<u32> = f
                .buffer
                .samples
                .iter()
                .filter(|s| s.is_covered())
                .map(|s| f.tris[s.tri as usize].id)
                .collect();
            case(
                "three coincident triangles at equal depth",
                "the first (triangle 0) wins every sample, whatever the drawing order",
                format!("winning triangles: {ids:?}"),
                ids.len() == 1 && ids.contains(&0),
            );
        }
        Err(e) => case("three coincident triangles", "render", e.to_string(), false),
    }
    cases
}
