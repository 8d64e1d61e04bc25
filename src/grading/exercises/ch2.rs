//! Chapter 2's exercises and how each is graded.

use glam::{Vec2, Vec3};

use super::images;
use crate::ch1_projection::camera::Camera;
use crate::ch2_rasterization::depth;
use crate::ch2_rasterization::edge;
use crate::core::film::Film;
use crate::grading::exercise::{Check, Exercise};

/// Chapter 2's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 2,
            name: "edge_function",
            file: "chapters/ch2-rasterization/exercises/edge_function.rs",
            hints: [
                "slide \"edge functions\": the sign of a 2D cross product says on which side of a line a point lies.",
                "take the edge vector b - a and the vector p - a; their 2D cross product is dx·ey - dy·ex.",
                "E_ab(p) = (b.x - a.x)·(p.y - a.y) - (b.y - a.y)·(p.x - a.x); positive when p is left of a→b (y up)",
            ],
            symptoms: &[],
            reference: || check_edge_function(edge::edge_function),
        },
        Exercise {
            chapter: 2,
            name: "barycentric",
            file: "chapters/ch2-rasterization/exercises/barycentric.rs",
            hints: [
                "slide \"barycentrics\": each coordinate is an area ratio, the sub-triangle opposite a vertex over the whole triangle.",
                "the edge function is twice a signed area: divide edge functions of the sub-triangles by the one of the whole triangle (signs cancel for clockwise order).",
                "φi = E(pj, pk, p) / E(pi, pj, pk), and so on around the triangle; None when E(pi, pj, pk) = 0",
            ],
            symptoms: &[],
            reference: || check_barycentric(edge::barycentric),
        },
        Exercise {
            chapter: 2,
            name: "depth_test",
            file: "chapters/ch2-rasterization/exercises/depth_test.rs",
            hints: [
                "slide \"visibility: the depth buffer\": keep the nearest surface seen so far at each sample.",
                "compare strictly: a tie must keep what was drawn first, and any comparison with NaN is false, which is what you want.",
                "pass only if z < depth[index] (strictly: ties keep the first; NaN compares false), then store z",
            ],
            symptoms: &[],
            reference: || check_depth_test(depth::depth_test),
        },
        Exercise {
            chapter: 2,
            name: "rasterize_triangle",
            file: "chapters/ch2-rasterization/exercises/rasterize_triangle.rs",
            hints: [
                "slides \"edge functions, the top-left rule, barycentrics\" and \"the depth buffer\": test every sample in the triangle's bounding box with three edge functions; samples exactly on an edge need a rule so shared edges are drawn once.",
                "orient the triangle so the edge functions are positive inside (swap two vertices if its area is negative). A sample with an edge function of exactly 0 counts only for a top or left edge. The three edge functions over the area are the barycentrics: they interpolate z and the colours.",
                "for the edge a→b, top-left is (b.y < a.y) || (b.y == a.y && b.x > a.x); inside when every w > 0, or w == 0 on a top-left edge. φ = (E(b,c,p), E(c,a,p), E(a,b,p)) / E(a,b,c); z = φ·(za, zb, zc); write if z < depth[i]",
            ],
            symptoms: &[],
            reference: || check_rasterize_triangle(reference_rasterize),
        },
    ]
}

/// The capstone's candidate: one triangle (raster x, y and depth per
/// vertex), its vertex colours, the image size, the depth buffer and the
/// colour buffer.
pub type RasterFn = fn([Vec3; 3], [Vec3; 3], u32, u32, &mut [f32], &mut [Vec3]);

/// raystep's answer to the capstone, in f32 as the lecture writes it.
pub fn reference_rasterize(
    v: [Vec3; 3],
    colors: [Vec3; 3],
    width: u32,
    height: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    let (mut v, mut colors) = (v, colors);
    let e = edge::edge_function;
    let area = e(v[0].truncate(), v[1].truncate(), v[2].truncate());
    if area == 0.0 || !area.is_finite() {
        return;
    }
    if area < 0.0 {
        v.swap(1, 2);
        colors.swap(1, 2);
    }
    let area = area.abs();
    let [a, b, c] = v.map(|p| p.truncate());
    let top_left = |a: Vec2, b: Vec2| b.y < a.y || (b.y == a.y && b.x > a.x);
    let edges = [(b, c), (c, a), (a, b)];
    let lo = a.min(b).min(c);
    let hi = a.max(b).max(c);
    let x0 = (lo.x - 0.5).ceil().max(0.0) as u32;
    let y0 = (lo.y - 0.5).ceil().max(0.0) as u32;
    let x1 = ((hi.x - 0.5).floor() + 1.0).clamp(0.0, width as f32) as u32;
    let y1 = ((hi.y - 0.5).floor() + 1.0).clamp(0.0, height as f32) as u32;
    for y in y0..y1 {
        for x in x0..x1 {
            let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let w = edges.map(|(s, t)| e(s, t, p));
            let inside = w
                .iter()
                .zip(edges)
                .all(|(w, (s, t))| *w > 0.0 || (*w == 0.0 && top_left(s, t)));
            if !inside {
                continue;
            }
            let phi = Vec3::from(w) / area;
            let z = phi.dot(Vec3::new(v[0].z, v[1].z, v[2].z));
            let i = (y * width + x) as usize;
            if z < depth[i] {
                depth[i] = z;
                image[i] = colors[0] * phi.x + colors[1] * phi.y + colors[2] * phi.z;
            }
        }
    }
}

/// The capstone: (1) the fill rule, on a fan and a grid of triangles whose
/// edges run through sample points, each drawn into a fresh buffer: every
/// sample is covered by exactly as many triangles as the reference says
/// (once inside the fan and grid); (2) chapter 2's interpenetrating shapes
/// (`interpenetrating.toml`, 160 × 120) behind a big triangle reaching
/// off screen, drawn with one depth buffer: colours and depths match.
pub fn check_rasterize_triangle(f: RasterFn) -> Check {
    let (w, h) = (64u32, 48u32);
    let tris = fill_rule_triangles();
    let coverage = |g: RasterFn| {
        let mut film = Film::new(w, h);
        for (k, t) in tris.iter().enumerate() {
            crate::grading::progress(format_args!("rasterizing fill-rule triangle {k}: {t:?}"));
            let mut depth = vec![f32::INFINITY; (w * h) as usize];
            let mut image = vec![Vec3::splat(-1.0); (w * h) as usize];
            g(*t, [Vec3::ONE; 3], w, h, &mut depth, &mut image);
            for (i, c) in image.iter().enumerate() {
                if *c != Vec3::splat(-1.0) {
                    film.pixels[i] += Vec3::splat(0.25);
                }
            }
        }
        film
    };
    let (cs, cr) = (coverage(f), coverage(reference_rasterize));
    let count = |film: &Film, x: u32, y: u32| (film.get(x, y).x / 0.25).round() as u32;
    let explain = |x: u32, y: u32| {
        format!(
            "the sample ({}, {}) is covered by {} of the triangles, the reference {} \
             (a sample on an edge shared by two triangles belongs to exactly one)",
            x as f32 + 0.5,
            y as f32 + 0.5,
            count(&cs, x, y),
            count(&cr, x, y)
        )
    };
    let check = images::compare(cs.clone(), cr.clone(), 0.1, 0.0, "coverage count", &explain);
    if !check.passed() {
        return check;
    }
    // The chapter's scene with one depth buffer.
    let scene = images::scene("interpenetrating.toml");
    let camera = Camera::of(&scene)
        .with_resolution(160, 120)
        .expect("a valid camera");
    let (w, h) = (camera.width, camera.height);
    let mut scene_tris: Vec<([Vec3; 3], [Vec3; 3])> = vec![(
        [
            Vec3::new(-300.0, -40.0, 90.0),
            Vec3::new(400.0, 60.0, 90.0),
            Vec3::new(20.0, 500.0, 90.0),
        ],
        [
            Vec3::new(0.1, 0.1, 0.3),
            Vec3::new(0.1, 0.3, 0.1),
            Vec3::new(0.3, 0.1, 0.1),
        ],
    )];
    for mesh in &scene.meshes {
        let base = scene.materials[mesh.material].reflectance;
        for t in &mesh.triangles {
            let p = t.map(|i| mesh.positions[i as usize]);
            let cam = p.map(|q| camera.to_camera(q));
            if cam.iter().any(|q| q.z > -0.1) {
                continue;
            }
            let raster = cam.map(|q| {
                let uv = Vec2::new(q.x / -q.z, q.y / -q.z);
                camera.raster_from_image_plane(uv).extend(-q.z)
            });
            let shade = [1.0, 0.7, 0.4].map(|k| base * k);
            scene_tris.push((raster, shade));
        }
    }
    let draw = |g: RasterFn| {
        let mut depth = vec![f32::INFINITY; (w * h) as usize];
        let mut film = Film::new(w, h);
        for (k, (t, c)) in scene_tris.iter().enumerate() {
            crate::grading::progress(format_args!("rasterizing scene triangle {k}: {t:?}"));
            g(*t, *c, w, h, &mut depth, &mut film.pixels);
        }
        (film, depth)
    };
    let ((fs, ds), (fr, dr)) = (draw(f), draw(reference_rasterize));
    let explain = |x: u32, y: u32| {
        let i = (y * w + x) as usize;
        format!(
            "yours drew colour {:.3} at depth {:.3} m, the reference colour {:.3} at depth {:.3} m",
            fs.pixels[i], ds[i], fr.pixels[i], dr[i]
        )
    };
    images::compare(fs.clone(), fr.clone(), 0.02, 2e-3, "scene", &explain)
}

/// A fan around a sample point and a grid of triangles, every vertex on a
/// sample point, so that edges run through samples and the fill rule
/// decides; both windings occur.
fn fill_rule_triangles() -> Vec<[Vec3; 3]> {
    let v = |x: f32, y: f32| Vec3::new(x + 0.5, y + 0.5, 1.0);
    let c = v(16.0, 16.0);
    let ring = [
        v(28.0, 16.0),
        v(26.0, 25.0),
        v(16.0, 28.0),
        v(6.0, 26.0),
        v(4.0, 16.0),
        v(8.0, 5.0),
        v(16.0, 4.0),
        v(27.0, 7.0),
    ];
    let mut tris: Vec<[Vec3; 3]> = (0..ring.len())
        .map(|k| [c, ring[k], ring[(k + 1) % ring.len()]])
        .collect();
    for gy in 0..4 {
        for gx in 0..4 {
            let (x, y) = (36.0 + 6.0 * gx as f32, 8.0 + 8.0 * gy as f32);
            let (a, b, cc, d) = (v(x, y), v(x + 6.0, y), v(x + 6.0, y + 8.0), v(x, y + 8.0));
            tris.push([a, b, cc]);
            tris.push([a, d, cc]);
        }
    }
    tris
}

fn worst_of(cases: impl Iterator<Item = (f64, String)>, tolerance: f64, ok: &str) -> Check {
    let mut worst = (0.0f64, ok.to_string());
    for (err, detail) in cases {
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            worst = (err, detail);
        }
    }
    Check {
        error: worst.0,
        tolerance,
        detail: worst.1,
        images: None,
        symptom: None,
    }
}

/// Compares an edge function with values worked out by hand.
pub fn check_edge_function(f: fn(Vec2, Vec2, Vec2) -> f32) -> Check {
    let v = Vec2::new;
    // (a, b, p, E) by hand: (b - a) × (p - a).
    let cases = [
        (v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0), 1.0),
        (v(0.0, 0.0), v(1.0, 0.0), v(0.0, -1.0), -1.0),
        (v(0.0, 0.0), v(4.0, 0.0), v(2.0, 0.0), 0.0),
        (v(1.0, 2.0), v(4.0, 6.0), v(3.0, 1.0), -11.0),
        (v(-2.0, 1.0), v(2.0, 3.0), v(0.0, 5.0), 12.0),
        (v(0.5, 0.5), v(0.5, 8.5), v(3.5, 4.0), -24.0),
    ];
    worst_of(
        cases.into_iter().map(|(a, b, p, want)| {
            let got = f(a, b, p);
            (
                (got - want).abs() as f64,
                format!("a = {a}, b = {b}, p = {p}: got {got}, expected {want}"),
            )
        }),
        1e-5,
        "all cases match",
    )
}

/// Compares barycentric coordinates with hand values and checks that they
/// rebuild the point.
pub fn check_barycentric(f: fn(Vec2, Vec2, Vec2, Vec2) -> Option<Vec3>) -> Check {
    let v = Vec2::new;
    let (a, b, c) = (v(0.0, 0.0), v(4.0, 0.0), v(0.0, 2.0));
    let mut cases: Vec<(Vec2, Vec2, Vec2, Vec2, Option<Vec3>)> = vec![
        (a, b, c, v(1.0, 0.5), Some(Vec3::new(0.5, 0.25, 0.25))),
        (a, b, c, b, Some(Vec3::Y)),
        (
            a,
            b,
            c,
            v(4.0 / 3.0, 2.0 / 3.0),
            Some(Vec3::splat(1.0 / 3.0)),
        ),
        // Outside: φ may be negative, still summing to 1.
        (a, b, c, v(4.0, 2.0), Some(Vec3::new(-1.0, 1.0, 1.0))),
        // Clockwise order gives the same φ.
        (a, c, b, v(1.0, 0.5), Some(Vec3::new(0.5, 0.25, 0.25))),
        // No area, no coordinates.
        (a, b, v(8.0, 0.0), v(1.0, 1.0), None),
        (a, a, a, a, None),
    ];
    // A few more whose φ must rebuild the point.
    for k in 0..5 {
        let t = k as f32;
        let (pi, pj, pk) = (v(t, -1.0), v(3.0 + t, 2.0 * t), v(-2.0, 5.0 - t));
        let phi = Vec3::new(0.2 + 0.1 * t, 0.5 - 0.05 * t, 0.3 - 0.05 * t);
        let p = pi * phi.x + pj * phi.y + pk * phi.z;
        cases.push((pi, pj, pk, p, Some(phi)));
    }
    worst_of(
        cases.into_iter().map(|(pi, pj, pk, p, want)| {
            let got = f(pi, pj, pk, p);
            let err = match (got, want) {
                (Some(g), Some(w)) => (g - w).abs().max_element() as f64,
                (None, None) => 0.0,
                _ => f64::INFINITY,
            };
            (
                err,
                format!("triangle ({pi}, {pj}, {pk}), p = {p}: got {got:?}, expected {want:?}"),
            )
        }),
        1e-5,
        "all cases match",
    )
}

/// Runs a sequence of depth tests on a small buffer against the expected
/// results and final contents.
pub fn check_depth_test(f: fn(&mut [f32], usize, f32) -> bool) -> Check {
    let inf = f32::INFINITY;
    // (index, z, passes)
    let steps = [
        (0, 5.0, true),
        (0, 7.0, false),
        (0, 5.0, false), // a tie keeps the first
        (1, 2.0, true),
        (0, 3.0, true),
        (1, f32::NAN, false),
        (2, inf, false),
        (0, 0.5, true),
    ];
    let mut buffer = vec![inf; 3];
    let mut fails = Vec::new();
    for (i, (index, z, want)) in steps.into_iter().enumerate() {
        let got = f(&mut buffer, index, z);
        if got != want {
            fails.push((
                1.0,
                format!(
                    "step {i}: depth_test(index {index}, z {z}) returned {got}, expected {want}"
                ),
            ));
        }
    }
    let expected = [0.5, 2.0, inf];
    if buffer != expected {
        fails.push((
            1.0,
            format!("buffer ends as {buffer:?}, expected {expected:?}"),
        ));
    }
    worst_of(fails.into_iter(), 0.0, "every step matches")
}
