//! The capstone's check, clause by clause: coverage (samples at pixel
//! centres, the top-left rule, either winding), triangles reaching off
//! the image, triangles without area; then (in [`super::shading`])
//! perspective-correct depth and colour, the depth test, and last the
//! chapter's scene.

use glam::{DVec2, Vec3};

use super::common::{corners, drawn_alone, edge64, failed, Draw, H, UNTOUCHED, W};
use super::model::Model;
use super::shading::{depth_order, interpolation, scene};
use super::{DEGENERATE, HALF_PIXEL, OFF_IMAGE, TOP_LEFT, WINDING};
use crate::ch2_rasterization::triangle::rasterize_triangle;
use crate::core::film::Film;
use crate::exercise::Check;

/// The capstone's candidate: one triangle (raster x, y and depth per
/// vertex), its vertex colours, the image size, the depth buffer and the
/// colour buffer.
pub type RasterFn = fn([Vec3; 3], [Vec3; 3], u32, u32, &mut [f32], &mut [Vec3]);

/// The capstone: every clause in turn; the first that fails is the result
/// (with the scene drawn both ways as its images when the clause has none).
pub fn check_rasterize_triangle(f: RasterFn) -> Check {
    let parts: [fn(RasterFn) -> Check; 7] = [
        coverage,
        off_image,
        degenerate,
        interpolation,
        depth_order,
        |f| super::drawn_cover::drawn_coverage(&f),
        scene,
    ];
    let mut last = None;
    for part in parts {
        let check = part(f);
        if !check.passed() && check.images.is_none() {
            // The scene drawn both ways, to look at.
            return Check {
                images: scene(f).images,
                ..check
            };
        }
        if !check.passed() {
            return check;
        }
        last = Some(check);
    }
    last.expect("seven parts")
}

/// Each triangle drawn alone (fresh buffers): the samples it wrote.
fn masks(g: Draw, tris: &[[Vec3; 3]], what: &str) -> Vec<Vec<bool>> {
    tris.iter()
        .enumerate()
        .map(|(k, t)| {
            crate::progress(format_args!(
                "rasterizing {what} triangle {k}: {}",
                corners(t)
            ));
            let (_, image) = drawn_alone(g, *t, [Vec3::ONE; 3], (W, H));
            image.iter().map(|c| *c != UNTOUCHED).collect()
        })
        .collect()
}

/// How many (triangle, sample) pairs two sets of masks disagree on.
fn disagree(a: &[Vec<bool>], b: &[Vec<bool>]) -> usize {
    a.iter()
        .zip(b)
        .map(|(a, b)| a.iter().zip(b).filter(|(x, y)| x != y).count())
        .sum()
}

/// Per pixel, how many of the triangles cover it (0.25 each), as a picture.
fn count_film(masks: &[Vec<bool>]) -> Film {
    let mut film = Film::new(W, H);
    for m in masks {
        for (i, on) in m.iter().enumerate() {
            if *on {
                film.pixels[i] += Vec3::splat(0.25);
            }
        }
    }
    film
}

/// Triangles at general positions (no sample on an edge, both windings):
/// the fill rule never decides, the sample position does.
pub fn general_triangles() -> Vec<[Vec3; 3]> {
    let mut tris = Vec::new();
    for k in 0..12 {
        let (x, y) = (2.3 + 5.1 * k as f32, 34.2 + 0.37 * k as f32);
        let t =
            [(x, y), (x + 4.61, y + 1.13), (x + 1.27, y + 8.71)].map(|(x, y)| Vec3::new(x, y, 1.0));
        tris.push(if k % 2 == 0 { t } else { [t[0], t[2], t[1]] });
    }
    tris
}

/// Clause 1: which samples each triangle covers, on a fan and a grid
/// whose edges run exactly through sample points, on triangles with
/// corners on the image's borders, and on triangles at general positions
/// (both windings). Exact: one sample more or less is a
/// failure.
fn coverage(f: RasterFn) -> Check {
    let general = general_triangles();
    let mut tris = fill_rule_triangles();
    // Corners on the image's left and top borders (a coordinate exactly
    // 0, an ordinary number), both windings.
    for t in [
        [(0.0, 0.0), (9.7, 0.0), (0.0, 7.9)],
        [(0.0, 20.5), (6.2, 25.0), (0.0, 31.0)],
        [(30.5, 0.0), (37.25, 6.5), (24.0, 0.0)],
    ] {
        let t = t.map(|(x, y)| Vec3::new(x, y, 1.5));
        tris.extend([t, [t[0], t[2], t[1]]]);
    }
    let first_general = tris.len();
    tris.extend(general.iter().copied());
    let (cand, want) = (
        masks(&f, &tris, "coverage"),
        masks(&rasterize_triangle, &tris, "coverage"),
    );
    let n = disagree(&cand, &want);
    if n == 0 {
        return Check {
            error: 0.0,
            tolerance: 0.0,
            detail: "coverage matches".into(),
            images: None,
            symptom: None,
        };
    }
    let images = Some((count_film(&cand), count_film(&want)));
    // The first sample that differs, for the message.
    let (k, i) = (0..tris.len())
        .flat_map(|k| (0..cand[k].len()).map(move |i| (k, i)))
        .find(|&(k, i)| cand[k][i] != want[k][i])
        .expect("n > 0");
    let (x, y) = (i as u32 % W, i as u32 / W);
    let c = tris[k].map(|v| v.truncate().as_dvec2());
    let sample = DVec2::new(x as f64 + 0.5, y as f64 + 0.5);
    let yours = if cand[k][i] {
        "covers"
    } else {
        "does not cover"
    };
    let first = format!(
        "coverage triangle {k}, corners ({}, {}, {}): yours {yours} the sample ({}, {}) of pixel ({x}, {y}), \
         the reference {}",
        c[0],
        c[1],
        c[2],
        sample.x,
        sample.y,
        if want[k][i] { "does" } else { "does not" }
    );
    let total = format!(
        "{n} (triangle, sample) pairs differ over {} triangles",
        tris.len()
    );
    // One winding drawn, the other not at all?
    let area = |t: &[Vec3; 3]| {
        edge64(
            t[0].truncate().as_dvec2(),
            t[1].truncate().as_dvec2(),
            t[2].truncate().as_dvec2(),
        )
    };
    for sign in [1.0, -1.0] {
        let same: Vec<usize> = (0..tris.len())
            .filter(|&k| area(&tris[k]) * sign > 0.0)
            .collect();
        let empty = same.iter().all(|&k| !cand[k].contains(&true));
        let other_drawn =
            (0..tris.len()).any(|k| area(&tris[k]) * sign < 0.0 && cand[k].contains(&true));
        if empty && other_drawn {
            let detail = format!(
                "yours draws nothing for the {} triangles whose corners run {} on the screen \
                 (doubled area {} 0), and draws the others: {first}; {total}",
                same.len(),
                if sign > 0.0 {
                    "clockwise"
                } else {
                    "counter-clockwise"
                },
                if sign > 0.0 { ">" } else { "<" }
            );
            return failed((n as f64, 0.0), detail, images, Some(WINDING));
        }
    }
    // Sampled somewhere else in the pixel? The triangles at general
    // positions tell (on the others a half-pixel shift and the
    // bottom-right rule look alike).
    let n_general = disagree(&cand[first_general..], &want[first_general..]);
    for offset in [0.0f32, 1.0] {
        let m = Model {
            offset,
            ..Model::REFERENCE
        };
        let draw = |v, c, w, h, d: &mut [f32], i: &mut [Vec3]| m.draw(v, c, w, h, d, i);
        let best = disagree(&cand[first_general..], &masks(&draw, &general, "model"));
        if n_general > 0 && best * 4 < n_general {
            let detail = format!(
                "on triangles at general positions your coverage agrees with samples at (x + {offset}, \
                 y + {offset}) far better than with the pixel centres (x + 0.5, y + 0.5): {best} samples \
                 differ from that, {n_general} from the reference; {first}"
            );
            return failed((n as f64, 0.0), detail, images, Some(HALF_PIXEL));
        }
    }
    // Every difference on an edge: the rule for samples on edges.
    let on_edge = |k: usize, i: usize| {
        let p = DVec2::new((i as u32 % W) as f64 + 0.5, (i as u32 / W) as f64 + 0.5);
        let c = tris[k].map(|v| v.truncate().as_dvec2());
        (0..3).any(|e| edge64(c[e], c[(e + 1) % 3], p) == 0.0)
    };
    let diffs: Vec<(usize, usize)> = (0..tris.len())
        .flat_map(|k| (0..cand[k].len()).map(move |i| (k, i)))
        .filter(|&(k, i)| cand[k][i] != want[k][i])
        .collect();
    if n_general == 0 && diffs.iter().all(|&(k, i)| on_edge(k, i)) {
        let extra = diffs.iter().filter(|&&(k, i)| cand[k][i]).count();
        let detail = format!(
            "every difference is a sample exactly on an edge: yours takes {extra} such samples the \
             reference leaves to the neighbour (drawn twice), and leaves {} the reference takes (a crack); {first}",
            diffs.len() - extra
        );
        return failed((n as f64, 0.0), detail, images, Some(TOP_LEFT));
    }
    failed((n as f64, 0.0), format!("{first}; {total}"), images, None)
}

/// A fan around a sample point and a grid of triangles, every corner on a
/// sample point, so that edges run through samples and the fill rule
/// decides; both windings occur. Small triangles with a sample a hair
/// inside one edge. And edges through a sample whose ends are not on
/// samples, most of them nearly flat.
pub fn fill_rule_triangles() -> Vec<[Vec3; 3]> {
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
    // Triangles 0.2 pixels across with the sample (1.5, 1.5), and then
    // (60.5, 40.5), 10⁻⁵ pixels inside one edge (its edge function
    // 2·10⁻⁶, where rounding of differences is 10⁻⁹, and of products of
    // coordinates 10⁻⁴), turned so that the edge is top, left, bottom or
    // right, both windings: the sample is strictly inside, so it is drawn.
    for (k, s) in (0..32).map(|k| {
        (
            k % 16,
            [Vec3::new(1.5, 1.5, 1.0), Vec3::new(60.5, 40.5, 1.0)][k / 16],
        )
    }) {
        let (sin, cos) = (0.1 + k as f32 * std::f32::consts::FRAC_PI_4).sin_cos();
        let turn = |x: f32, y: f32| s + Vec3::new(x * cos - y * sin, x * sin + y * cos, 0.0);
        let t = [turn(-0.1, -1e-5), turn(0.1, -1e-5), turn(0.0, 0.1)];
        tris.push(if k < 8 { t } else { [t[0], t[2], t[1]] });
    }
    // Edges through the sample (16.5, 40.5) whose ends are off the grid
    // of samples, all but two of them rising by less than a pixel: the
    // rule is decided by the edge itself, not by the pixels its ends fall
    // in (there it would be flat). Each edge with a third corner above
    // and below it, both windings.
    let s = Vec3::new(16.5, 40.5, 1.0);
    for (dx, dy) in [
        (8.0, 0.25),
        (8.0, -0.25),
        (16.0, 0.25),
        (16.0, -0.25),
        (12.0, 0.5),
        (12.0, -0.75),
    ] {
        let (p, q) = (s + Vec3::new(dx, dy, 0.0), s - Vec3::new(dx, dy, 0.0));
        for third in [s + Vec3::new(0.0, 5.0, 0.0), s - Vec3::new(0.0, 5.0, 0.0)] {
            tris.push([p, q, third]);
            tris.push([q, p, third]);
        }
    }
    tris
}

/// Clause 2: triangles reaching past every border of the image, one of
/// them 10⁵ pixels past (a loop over its whole bounding box would not
/// finish): the same samples, and nothing written outside the image.
fn off_image(f: RasterFn) -> Check {
    let t =
        |a: (f32, f32), b: (f32, f32), c: (f32, f32)| [a, b, c].map(|(x, y)| Vec3::new(x, y, 2.0));
    let tris = [
        t((40.3, 5.2), (90.7, 20.1), (50.2, 40.6)),
        t((-30.2, -20.7), (30.4, 10.3), (-5.1, 44.2)),
        t((10.3, 30.2), (55.6, 35.7), (20.2, 80.9)),
        t((50.1, 30.4), (120.3, 70.2), (30.6, 90.8)),
        t((-100000.3, -100000.7), (300000.1, -50.2), (-50.6, 300000.9)),
        t((-40000.0, 12.1), (40000.0, 27.3), (9.7, 30000.0)),
    ];
    let (cand, want) = (
        masks(&f, &tris, "off-image"),
        masks(&rasterize_triangle, &tris, "off-image"),
    );
    let n = disagree(&cand, &want);
    if n == 0 {
        return failed((0.0, 0.0), "off-image triangles match".into(), None, None);
    }
    let k = (0..tris.len())
        .find(|&k| cand[k] != want[k])
        .expect("n > 0");
    let [yours, theirs] = [&cand[k], &want[k]].map(|m| m.iter().filter(|b| **b).count());
    let detail = format!(
        "the triangle with corners {} reaches past the image ({W} x {H}): yours draws {yours} of its \
         pixels, the reference {theirs} ({n} samples differ over {} such triangles)",
        corners(&tris[k]),
        tris.len()
    );
    failed(
        (n as f64, 0.0),
        detail,
        Some((count_film(&cand), count_film(&want))),
        Some(OFF_IMAGE),
    )
}

/// Clause 3: triangles without area (corners on one line, all at one
/// point) or with a corner that is not finite draw nothing, not even on
/// samples their line runs through.
fn degenerate(f: RasterFn) -> Check {
    let t =
        |a: (f32, f32), b: (f32, f32), c: (f32, f32)| [a, b, c].map(|(x, y)| Vec3::new(x, y, 2.0));
    let flat = [
        t((2.5, 5.5), (10.5, 5.5), (6.5, 5.5)),
        t((4.5, 2.5), (4.5, 20.5), (4.5, 9.5)),
        t((2.5, 2.5), (8.5, 8.5), (5.5, 5.5)),
        t((8.5, 8.5), (2.5, 2.5), (20.5, 20.5)),
        t((3.5, 3.5), (3.5, 3.5), (3.5, 3.5)),
    ];
    // Each corner in turn with an x, y or depth that is not finite (a
    // depth of ±∞ gives a weight 1/z of 0, which draws if nothing stops
    // it).
    let (inf, nan) = (f32::INFINITY, f32::NAN);
    let not_finite = (0..3).flat_map(|corner| {
        [(0, nan), (1, inf), (2, inf), (2, -inf), (2, nan)].map(|(axis, v)| {
            let mut tri = t((2.5, 3.0), (10.0, 3.0), (5.0, 10.0));
            tri[corner][axis] = v;
            tri
        })
    });
    let tris: Vec<[Vec3; 3]> = flat.into_iter().chain(not_finite).collect();
    for (k, tri) in tris.iter().enumerate() {
        crate::progress(format_args!(
            "rasterizing triangle without area {k}: {}",
            corners(tri)
        ));
        let (depth, image) = drawn_alone(&f, *tri, [Vec3::ONE; 3], (W, H));
        let written = (0..depth.len())
            .filter(|&i| image[i] != UNTOUCHED || depth[i] != f32::INFINITY)
            .count();
        if written > 0 {
            let detail = format!(
                "the triangle {} has {}: yours wrote {written} pixels (colour or depth), the reference none",
                corners(tri),
                if k < 5 { "no area" } else { "a corner that is not finite (its x, y or depth)" }
            );
            return failed((written as f64, 0.0), detail, None, Some(DEGENERATE));
        }
    }
    // A triangle 0.02 pixels across (twice its area 4·10⁻⁴) around the
    // centre of pixel (10, 10): small, but the sample is well inside.
    let tiny = [(10.49, 10.49), (10.51, 10.49), (10.5, 10.51)].map(|(x, y)| Vec3::new(x, y, 2.0));
    let (depth, image) = drawn_alone(&f, tiny, [Vec3::ONE; 3], (W, H));
    let drawn: Vec<usize> = (0..depth.len())
        .filter(|&i| image[i] != UNTOUCHED || depth[i] != f32::INFINITY)
        .collect();
    if drawn != [(10 * W + 10) as usize] {
        let detail = format!(
            "the triangle {} (0.02 pixels across, around the centre of pixel (10, 10)): yours \
             drew {} samples, the reference one, at (10, 10): a small area is still an area",
            corners(&tiny),
            drawn.len()
        );
        return failed((1.0, 0.0), detail, None, None);
    }
    failed(
        (0.0, 0.0),
        "no triangle without area drew, and a tiny one drew its sample".into(),
        None,
        None,
    )
}
