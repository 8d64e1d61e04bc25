//! Chapter 2's top-left rule diagram: which pixel centres each of four
//! triangles takes under a strict test, a loose one and [`covers`].

use glam::DVec2;
use raystep::ch2_rasterization::coverage::{covers, sample_position};
use raystep::ch2_rasterization::edge::edge_fixed;
use raystep::ch2_rasterization::setup::{raster_triangle, ScreenTriangle};
use raystep::core::error::{Error, Result};

use crate::svg::{Anchor, Stroke, Svg, FILL_BLUE, FILL_GREEN, FILL_ORANGE, GREEN, GREY, INK, RED};

/// A light red fill (φi's sub-triangle; red as in the barycentrics view).
pub const FILL_RED: &str = "#f6d3cf";
/// A light violet fill (a fourth triangle).
const FILL_VIOLET: &str = "#e4daf3";

/// Which rule decides a sample on an edge.
#[derive(Clone, Copy)]
enum Rule {
    /// Every edge function > 0: samples on an edge belong to nobody.
    Strict,
    /// Every edge function ≥ 0: they belong to everybody.
    Loose,
    /// [`covers`]: the top-left rule.
    TopLeft,
}

/// A 7 x 7 screen tiled by four triangles around the pixel centre
/// (3.5, 3.5); the diagonals run through 12 more pixel centres. Three
/// panels: how many triangles take each centre under each rule.
pub fn top_left() -> Result<Svg> {
    let n = 7u32;
    let size = n as f64;
    let v = DVec2::new;
    let centre = v(3.5, 3.5);
    let corners = [v(0.0, 0.0), v(size, 0.0), v(size, size), v(0.0, size)];
    let tris: Vec<ScreenTriangle> = (0..4)
        .flat_map(|k| raster_triangle([centre, corners[k], corners[(k + 1) % 4]], k as u32, n, n))
        .collect();
    if tris.len() != 4 {
        return Err(Error::Usage(
            "top-left diagram: a triangle was lost in setup".into(),
        ));
    }
    let fills = [FILL_BLUE, FILL_ORANGE, FILL_GREEN, FILL_VIOLET];
    let gap = 1.0;
    let mut s = Svg::new(660.0, [0.0, 3.0 * size + 2.0 * gap, -1.1, size + 0.8]);
    let rules = [
        (Rule::Strict, "every E > 0"),
        (Rule::Loose, "every E ≥ 0"),
        (Rule::TopLeft, "top-left rule"),
    ];
    for (panel, (rule, title)) in rules.into_iter().enumerate() {
        let x0 = panel as f64 * (size + gap);
        // Raster (y down) to picture (y up).
        let at = |x: f64, y: f64| (x0 + x, size - y);
        let (mut twice, mut missed) = (0, 0);
        let mut counts = Vec::new();
        for y in 0..n {
            for x in 0..n {
                let p = sample_position(1, 0, n, x, y, 0);
                let owners: Vec<usize> = tris
                    .iter()
                    .enumerate()
                    .filter(|(_, t)| takes(t, p, rule))
                    .map(|(k, _)| k)
                    .collect();
                let on_edge = tris
                    .iter()
                    .any(|t| (0..3).any(|e| edge_fixed(t.v[e], t.v[(e + 1) % 3], p) == 0));
                let (x, y) = (x as f64, y as f64);
                let cell = [
                    at(x, y),
                    at(x + 1.0, y),
                    at(x + 1.0, y + 1.0),
                    at(x, y + 1.0),
                ];
                let fill = match owners.as_slice() {
                    [k] => fills[*k],
                    [] => "#ffffff",
                    _ => FILL_RED,
                };
                s.area(&cell, fill);
                let c = at(x + 0.5, y + 0.5);
                match owners.len() {
                    1 => s.dot(c, 2.5, INK),
                    0 => {
                        missed += 1;
                        s.circle(c, 0.17, Stroke::solid(RED, 1.8), Some("#ffffff"));
                    }
                    k => {
                        twice += 1;
                        counts.push((c, format!("{k}")));
                    }
                }
                if on_edge && owners.len() == 1 {
                    s.circle(c, 0.17, Stroke::solid(INK, 1.2), None);
                }
            }
        }
        for k in 0..=n {
            let k = k as f64;
            s.line(at(k, 0.0), at(k, size), Stroke::solid(GREY, 0.6));
            s.line(at(0.0, k), at(size, k), Stroke::solid(GREY, 0.6));
        }
        for c in corners {
            s.line(
                at(centre.x, centre.y),
                at(c.x, c.y),
                Stroke::solid(INK, 1.4),
            );
        }
        for (c, label) in &counts {
            s.circle(*c, 0.24, Stroke::solid(RED, 1.2), Some("#ffffff"));
            s.text(*c, (0.0, 5.0), label, 14.0, Anchor::Middle, RED, false);
        }
        s.text(
            at(size / 2.0, 0.0),
            (0.0, -8.0),
            title,
            15.0,
            Anchor::Middle,
            INK,
            false,
        );
        let tally = match (missed, twice) {
            (0, 0) => "each centre drawn once".to_string(),
            (m, 0) => format!("{m} centres missed"),
            (0, t) => format!("{t} centres drawn twice or more"),
            (m, t) => format!("{m} missed, {t} drawn twice"),
        };
        let colour = if missed + twice == 0 { GREEN } else { RED };
        s.text(
            at(size / 2.0, size),
            (0.0, 22.0),
            &tally,
            14.0,
            Anchor::Middle,
            colour,
            false,
        );
    }
    Ok(s)
}

/// Whether triangle `t` takes the sample `p` under `rule`.
fn takes(t: &ScreenTriangle, p: glam::I64Vec2, rule: Rule) -> bool {
    let e = |k: usize| edge_fixed(t.v[k], t.v[(k + 1) % 3], p);
    match rule {
        Rule::Strict => (0..3).all(|k| e(k) > 0),
        Rule::Loose => (0..3).all(|k| e(k) >= 0),
        Rule::TopLeft => covers(t, p),
    }
}
