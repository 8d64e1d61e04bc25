//! Chapter 2's diagrams: an edge function's two sides and the inside test
//! ([`edge_function`]), barycentric coordinates as areas
//! ([`barycentric`]), the top-left rule on a pixel grid (in
//! [`crate::ch2_top_left`]), and affine against perspective-correct
//! interpolation ([`interpolate_phi`]).

use glam::{DVec2, Vec2};
use raystep::ch2_rasterization::edge::{barycentric, edge_function};
use raystep::ch2_rasterization::interpolate::{interpolate_phi, Interpolation};
use raystep::ch2_rasterization::setup::raster_triangle;
use raystep::core::error::{Error, Result};

use crate::ch1::clip;
use crate::ch2_top_left::FILL_RED;
use crate::svg::{
    Anchor, Stroke, Svg, BLUE, FILL_BLUE, FILL_GREEN, FILL_ORANGE, GREEN, GREY, INK, ORANGE, RED,
};
use crate::Diagram;

/// Chapter 2's diagrams, in the order the chapter shows them.
pub fn diagrams() -> Result<Vec<Diagram>> {
    Ok(vec![
        Diagram {
            name: "ch2-edge-function-diagram",
            what: "the two sides of one edge and the inside of a triangle, shaded by the sign of edge_function",
            svg: edge_sides(),
        },
        Diagram {
            name: "ch2-top-left-diagram",
            what: "a 7x7 pixel grid tiled by four triangles: which pixel centres edge_fixed > 0, >= 0 and covers (top-left rule) give each",
            svg: crate::ch2_top_left::top_left()?,
        },
        Diagram {
            name: "ch2-barycentric-diagram",
            what: "barycentric coordinates as the areas of the three sub-triangles, computed by barycentric",
            svg: barycentric_areas()?,
        },
        Diagram {
            name: "ch2-perspective-diagram",
            what: "an attribute along a receding edge: affine against perspective-correct, from interpolate_phi",
            svg: perspective()?,
        },
    ])
}

/// The part of `poly` where `f` ≥ 0 (one step of Sutherland–Hodgman; `f`
/// is affine, so a crossing is found by linear interpolation).
fn keep(poly: &[(f64, f64)], f: impl Fn((f64, f64)) -> f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for (n, &a) in poly.iter().enumerate() {
        let b = poly[(n + 1) % poly.len()];
        let (fa, fb) = (f(a), f(b));
        if fa >= 0.0 {
            out.push(a);
        }
        if (fa >= 0.0) != (fb >= 0.0) {
            let t = fa / (fa - fb);
            out.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
        }
    }
    out
}

/// [`edge_function`] of the edge a→b at a picture point.
fn edge_at(a: Vec2, b: Vec2, p: (f64, f64)) -> f64 {
    edge_function(a, b, Vec2::new(p.0 as f32, p.1 as f32)) as f64
}

fn pt(v: Vec2) -> (f64, f64) {
    (v.x as f64, v.y as f64)
}

/// Two panels (y up, so the inside of a counter-clockwise triangle is
/// where every edge function is positive). Left: the line through a and
/// b, and the half-planes where E_ab is positive and negative. Right: a
/// grid of sample points, green where all three edge functions are ≥ 0.
fn edge_sides() -> Svg {
    let (w, h, gap) = (10.0, 7.6, 1.0);
    let mut s = Svg::new(660.0, [0.0, 2.0 * w + gap, 0.0, h + 0.7]);
    let a = Vec2::new(1.6, 1.4);
    let b = Vec2::new(8.4, 2.8);
    let c = Vec2::new(3.8, 6.8);
    for panel in 0..2 {
        let x0 = panel as f64 * (w + gap);
        let shift = Vec2::new(x0 as f32, 0.0);
        let (a, b, c) = (a + shift, b + shift, c + shift);
        let rect = [(x0, 0.0), (x0 + w, 0.0), (x0 + w, h), (x0, h)];
        let bounds = [x0, x0 + w, 0.0, h];
        if panel == 0 {
            let plus = keep(&rect, |p| edge_at(a, b, p));
            let minus = keep(&rect, |p| -edge_at(a, b, p));
            s.area(&plus, FILL_BLUE);
            s.area(&minus, FILL_ORANGE);
            // The edge's line, the edge itself and its direction.
            let far = |t: f32| pt(a + t * (b - a));
            if let Some((p, q)) = clip(far(-1.0), far(2.0), bounds) {
                s.line(p, q, Stroke::dashed(INK, 1.2));
            }
            s.polyline(
                &[pt(a), pt(b), pt(c)],
                Stroke::solid(GREY, 1.2),
                Some("none"),
            );
            s.arrow(pt(a), pt(b), Stroke::solid(INK, 2.6));
            let mid = pt(c);
            s.text(
                mid,
                (0.0, 34.0),
                "E_ab(p) > 0",
                15.0,
                Anchor::Middle,
                BLUE,
                false,
            );
            s.text(
                (x0 + 7.6, 0.7),
                (0.0, 0.0),
                "E_ab(p) < 0",
                15.0,
                Anchor::Middle,
                ORANGE,
                false,
            );
        } else {
            let inside = keep(
                &keep(&keep(&rect, |p| edge_at(a, b, p)), |p| edge_at(b, c, p)),
                |p| edge_at(c, a, p),
            );
            s.area(&inside, FILL_GREEN);
            for (p, q) in [(a, b), (b, c), (c, a)] {
                let far = |t: f32| pt(p + t * (q - p));
                if let Some((p, q)) = clip(far(-1.0), far(2.0), bounds) {
                    s.line(p, q, Stroke::dashed(GREY, 0.9));
                }
            }
            s.polyline(
                &[pt(a), pt(b), pt(c)],
                Stroke::solid(INK, 2.0),
                Some("none"),
            );
            // Samples at the centres of unit cells.
            for j in 0..h as usize {
                for i in 0..w as usize {
                    let p = (x0 + i as f64 + 0.5, j as f64 + 0.5);
                    let e = [edge_at(a, b, p), edge_at(b, c, p), edge_at(c, a, p)];
                    if e.iter().all(|&e| e >= 0.0) {
                        s.dot(p, 4.5, GREEN);
                    } else {
                        s.dot(p, 2.5, GREY);
                    }
                }
            }
            s.text(
                (x0 + w / 2.0, h),
                (0.0, -9.0),
                "inside: E_ab, E_bc, E_ca all ≥ 0",
                15.0,
                Anchor::Middle,
                GREEN,
                false,
            );
        }
        s.polyline(&rect, Stroke::solid(GREY, 1.0), Some("none"));
        for (v, name, dx) in [(a, "a", -10.0), (b, "b", 10.0), (c, "c", -10.0)] {
            s.dot(pt(v), 4.5, INK);
            let anchor = if dx < 0.0 { Anchor::End } else { Anchor::Start };
            s.text(pt(v), (dx, 5.0), name, 16.0, anchor, INK, true);
        }
    }
    s.text(
        (w / 2.0, h),
        (0.0, -9.0),
        "one edge: the sign tells the side",
        15.0,
        Anchor::Middle,
        INK,
        false,
    );
    s
}

/// A triangle (p_i, p_j, p_k) and a point p inside, split into the three
/// sub-triangles p makes with each edge; each φ is its sub-triangle's share
/// of the area, the one opposite its own corner.
fn barycentric_areas() -> Result<Svg> {
    let (pi, pj, pk) = (
        Vec2::new(0.6, 0.6),
        Vec2::new(9.4, 1.6),
        Vec2::new(4.0, 6.6),
    );
    let p = Vec2::new(4.6, 2.9);
    let phi = barycentric(pi, pj, pk, p)
        .ok_or_else(|| Error::Usage("barycentric diagram: degenerate triangle".into()))?;
    let mut s = Svg::new(560.0, [-0.4, 10.4, -0.3, 7.3]);
    let parts = [
        ([p, pj, pk], FILL_RED, RED, "φi", phi.x),
        ([pi, p, pk], FILL_GREEN, GREEN, "φj", phi.y),
        ([pi, pj, p], FILL_BLUE, BLUE, "φk", phi.z),
    ];
    for (tri, fill, _, _, _) in &parts {
        s.area(&tri.map(pt), fill);
    }
    for q in [pi, pj, pk] {
        s.line(pt(p), pt(q), Stroke::solid(GREY, 1.2));
    }
    s.polyline(
        &[pt(pi), pt(pj), pt(pk)],
        Stroke::solid(INK, 2.0),
        Some("none"),
    );
    for (tri, _, colour, name, value) in &parts {
        let centroid = pt((tri[0] + tri[1] + tri[2]) / 3.0);
        let label = format!("{name} = {value:.2}");
        s.text(
            centroid,
            (0.0, 5.0),
            &label,
            15.0,
            Anchor::Middle,
            colour,
            false,
        );
    }
    s.dot(pt(p), 5.0, INK);
    s.text(pt(p), (0.0, -10.0), "p", 16.0, Anchor::Middle, INK, true);
    for (q, name, colour, offset) in [
        (pi, "p_i", RED, (-6.0, 16.0)),
        (pj, "p_j", GREEN, (8.0, 14.0)),
        (pk, "p_k", BLUE, (0.0, -10.0)),
    ] {
        s.dot(pt(q), 5.0, colour);
        let anchor = if offset.0 > 0.0 {
            Anchor::Start
        } else {
            Anchor::Middle
        };
        s.text(pt(q), offset, name, 16.0, anchor, colour, true);
    }
    s.caption(&format!(
        "each φ is the area opposite its corner over the whole: {:.2} + {:.2} + {:.2} = {:.2}",
        phi.x,
        phi.y,
        phi.z,
        phi.x + phi.y + phi.z
    ));
    Ok(s)
}

/// An attribute a going from 0 at a near corner (w = 1) to 1 at a far one
/// (w = 4), along their edge on the screen: interpolated with screen-space
/// φ (affine) and with a/w and 1/w (perspective-correct), both by
/// [`interpolate_phi`]. Below the plot, where a = 0.1, 0.2, ..., 0.9 lands
/// on the edge under each.
fn perspective() -> Result<Svg> {
    let v = DVec2::new;
    let mut tri = raster_triangle([v(1.0, 1.0), v(9.0, 1.0), v(5.0, 6.0)], 0, 16, 16)
        .into_iter()
        .next()
        .ok_or_else(|| Error::Usage("perspective diagram: no triangle".into()))?;
    // Put the near corner first whatever order setup chose: a = 0 there.
    let (near, far) = (0, 1);
    tri.inv_w = [1.0, 1.0, 1.0];
    tri.inv_w[far] = 0.25;
    for (n, attr) in tri.attr.iter_mut().enumerate() {
        attr[0] = if n == far { 1.0 } else { 0.0 };
    }
    let value = |s_: f64, mode| {
        let mut phi = [0.0; 3];
        phi[near] = 1.0 - s_;
        phi[far] = s_;
        interpolate_phi(&tri, phi, mode).0[0]
    };
    // Plot: screen position s along the edge → 10 s, a → 5 a.
    let (sx, sy) = (10.0, 5.0);
    let mut s = Svg::new(620.0, [-0.7, 11.0, -3.3, 5.9]);
    s.arrow((0.0, 0.0), (10.6, 0.0), Stroke::solid(GREY, 1.2));
    s.arrow((0.0, 0.0), (0.0, 5.6), Stroke::solid(GREY, 1.2));
    s.text(
        (10.6, 0.0),
        (0.0, 18.0),
        "position on the screen",
        13.0,
        Anchor::End,
        GREY,
        false,
    );
    s.text(
        (0.0, 5.6),
        (8.0, 10.0),
        "a",
        15.0,
        Anchor::Start,
        GREY,
        true,
    );
    for (a, label) in [(0.0, "0"), (1.0, "1")] {
        s.line((-0.12, sy * a), (0.0, sy * a), Stroke::solid(GREY, 1.2));
        s.text(
            (0.0, sy * a),
            (-8.0, 5.0),
            label,
            13.0,
            Anchor::End,
            GREY,
            false,
        );
    }
    s.text(
        (0.0, 0.0),
        (0.0, 18.0),
        "near corner, w = 1",
        13.0,
        Anchor::Start,
        INK,
        false,
    );
    s.text(
        (sx, 0.0),
        (0.0, -8.0),
        "far corner, w = 4",
        13.0,
        Anchor::End,
        INK,
        false,
    );
    let samples = 64;
    for (mode, colour, name) in [
        (Interpolation::Affine, ORANGE, "affine"),
        (Interpolation::Perspective, BLUE, "perspective-correct"),
    ] {
        let curve: Vec<(f64, f64)> = (0..=samples)
            .map(|k| {
                let t = k as f64 / samples as f64;
                (sx * t, sy * value(t, mode))
            })
            .collect();
        s.polyline(&curve, Stroke::solid(colour, 2.4), None);
        let at = (sx * 0.5, sy * value(0.5, mode));
        let dy = if matches!(mode, Interpolation::Affine) {
            -10.0
        } else {
            20.0
        };
        s.text(at, (8.0, dy), name, 14.0, Anchor::Start, colour, false);
    }
    // Where a reaches each tenth: the affine marks are evenly spaced, the
    // perspective-correct ones crowd towards the far corner.
    for (row, mode, colour) in [
        (-1.5, Interpolation::Affine, ORANGE),
        (-2.9, Interpolation::Perspective, BLUE),
    ] {
        s.line((0.0, row), (sx, row), Stroke::solid(INK, 1.4));
        for tenth in 1..10 {
            let target = tenth as f64 / 10.0;
            let (mut lo, mut hi) = (0.0f64, 1.0f64);
            for _ in 0..50 {
                let mid = 0.5 * (lo + hi);
                if value(mid, mode) < target {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let x = sx * 0.5 * (lo + hi);
            s.line((x, row - 0.22), (x, row + 0.22), Stroke::solid(colour, 2.2));
        }
    }
    let rows = [
        (-1.5, ORANGE, "affine: where a = 0.1, 0.2, …, 0.9"),
        (
            -2.9,
            BLUE,
            "perspective-correct: where a = 0.1, 0.2, …, 0.9",
        ),
    ];
    for (row, colour, label) in rows {
        s.text(
            (0.0, row),
            (0.0, -14.0),
            label,
            13.0,
            Anchor::Start,
            colour,
            false,
        );
    }
    Ok(s)
}
