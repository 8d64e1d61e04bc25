//! Coverage on drawn triangles: corners anywhere (ordinary floats, not on
//! a grid), from a pixel to 10⁵ pixels across, in and around the image,
//! either winding, half of them with an edge passing a sample at a drawn
//! distance. Each sample's side of each edge is decided in f64;
//! samples so near an edge that an f32 edge function's rounding could
//! put them on either side are left out, and every other sample must be
//! drawn exactly when it is inside.

use glam::{DVec2, Vec2, Vec3};

use super::common::{corners, drawn_alone, edge64, failed, Draw, H, UNTOUCHED, W};
use crate::exercise::Check;
use crate::exercises::draws::Draws;

/// The drawn triangles' coverage, sample by sample, against the f64
/// answer away from rounding's reach.
pub(super) fn drawn_coverage(f: Draw) -> Check {
    let mut draws = Draws::new(27);
    let count = draws.count(100, 200);
    for k in 0..count {
        draws.next_case();
        // Most of them with edges across the image: 3 to 3,000 pixels
        // across about a point in it; a quarter up to 10⁵ across.
        let size = match draws.unit() < 0.25 {
            true => draws.decades(0.0, 5.0),
            false => draws.decades(0.5, 3.5),
        };
        let centre = Vec2::new(
            draws.range(-0.25, 1.25) * W as f32,
            draws.range(-0.25, 1.25) * H as f32,
        );
        let at = match draws.unit() < 0.5 {
            // Half of them with an edge that passes a sample at a drawn
            // distance, from 10⁻⁶ to 0.3 pixels, on either side.
            true => {
                let sample = Vec2::new(
                    draws.count(0, W as usize - 1) as f32 + 0.5,
                    draws.count(0, H as usize - 1) as f32 + 0.5,
                );
                let along = Vec2::from_angle(draws.range(0.0, std::f32::consts::TAU));
                let across = along.perp() * draws.sign();
                let on = sample + across * draws.sign() * draws.decades(-6.0, -0.5);
                [
                    on - along * size * draws.range(0.2, 1.0),
                    on + along * size * draws.range(0.2, 1.0),
                    on + along * size * draws.range(-1.0, 1.0)
                        + across * size * draws.range(0.3, 1.0),
                ]
            }
            false => [0; 3].map(|_| centre + draws.in_square() * size),
        };
        let tri = at.map(|c| Vec3::new(c.x, c.y, draws.range(1.0, 10.0)));
        crate::progress(format_args!(
            "rasterizing drawn triangle {k}: {}",
            corners(&tri)
        ));
        let (_, image) = drawn_alone(f, tri, [Vec3::ONE; 3], (W, H));
        if let Some(wrong) = wrong_sample(&tri, &image, W) {
            return wrong.failed(&format!("drawn triangle {k}"));
        }
    }
    // Long rows: an image 4,096 samples wide and two high, and triangles
    // thousands of pixels across that reach past its left border, with an
    // edge that passes a sample near the right end at a few times
    // rounding's reach. An edge function computed at each sample errs by
    // no more than that reach; one stepped from sample to sample along the
    // row gathers each step's rounding, thousands of them. Every other one
    // is the same kind of triangle with x and y swapped, in an image two
    // samples wide and 4,096 high: edge functions carried down a column
    // from row to row gather them the same way.
    let long = draws.count(16, 32);
    for k in 0..long {
        draws.next_case();
        let size = draws.decades(3.5, 4.0);
        let sample = Vec2::new(
            (LONG_W - 1 - draws.count(0, 255) as u32) as f32 + 0.5,
            draws.count(0, 1) as f32 + 0.5,
        );
        let along = Vec2::from_angle(draws.range(0.2, std::f32::consts::PI - 0.2));
        let across = along.perp() * draws.sign();
        // Rounding's reach there, as a distance: 2 ε times the edge's
        // length (about 2 size).
        let reach = 4.0 * f32::EPSILON * size;
        let on = sample + across * draws.sign() * reach * draws.decades(0.3, 2.5);
        let at = [
            on - along * size,
            on + along * size,
            on + across * size * draws.range(0.5, 1.0) - Vec2::X * size,
        ];
        let tall = k % 2 == 1;
        let tri = at.map(|c| match tall {
            true => Vec3::new(c.y, c.x, draws.range(1.0, 10.0)),
            false => Vec3::new(c.x, c.y, draws.range(1.0, 10.0)),
        });
        let (width, height, what) = match tall {
            true => (LONG_H, LONG_W, "column"),
            false => (LONG_W, LONG_H, "row"),
        };
        crate::progress(format_args!(
            "rasterizing a long {what}'s triangle {k}: {}",
            corners(&tri)
        ));
        let (_, image) = drawn_alone(f, tri, [Vec3::ONE; 3], (width, height));
        if let Some(wrong) = wrong_sample(&tri, &image, width) {
            return wrong.failed(&format!(
                "long-{what} triangle {k} (an image {width} x {height})"
            ));
        }
    }
    Check {
        error: 0.0,
        tolerance: 0.0,
        detail: format!(
            "coverage matches on {count} drawn triangles and {long} long rows and columns"
        ),
        images: None,
        symptom: None,
    }
}

/// The long rows' image: 4,096 samples wide, two high (the columns'
/// turned a quarter).
const LONG_W: u32 = 4096;
const LONG_H: u32 = 2;

/// A sample drawn when it is outside, or not drawn when it is inside.
struct Wrong {
    c: [DVec2; 3],
    x: u32,
    y: u32,
    p: DVec2,
    inside: bool,
}

impl Wrong {
    fn failed(&self, what: &str) -> Check {
        let Wrong { c, x, y, p, inside } = self;
        let d = sides_distance(*c, *p);
        failed(
            (f64::INFINITY, 0.0),
            format!(
                "{what}, corners ({}, {}, {}): yours {} the sample ({}, {}) of pixel ({x}, {y}), \
                 which is {} it, {d:.3e} pixels from its nearest edge",
                c[0],
                c[1],
                c[2],
                if *inside { "does not cover" } else { "covers" },
                p.x,
                p.y,
                if *inside { "inside" } else { "outside" },
            ),
            None,
            None,
        )
    }
}

/// The first sample of `image` (`width` wide) that `tri` was drawn on
/// though it is outside, or not drawn on though it is inside, each side
/// decided in f64; samples within rounding's reach of an edge are left out.
fn wrong_sample(tri: &[Vec3; 3], image: &[Vec3], width: u32) -> Option<Wrong> {
    let c = tri.map(|v| v.truncate().as_dvec2());
    let area = edge64(c[0], c[1], c[2]);
    if area == 0.0 {
        return None;
    }
    for (i, px) in image.iter().enumerate() {
        let (x, y) = (i as u32 % width, i as u32 / width);
        let p = DVec2::new(x as f64 + 0.5, y as f64 + 0.5);
        let sides = [0, 1, 2].map(|e| {
            let (a, b) = (c[e], c[(e + 1) % 3]);
            // What rounding in f32 may do to the edge function, from
            // either end of the edge: a few units in the last place of
            // its two products (an ulp is at most ε times the number).
            let reach = 2.0
                * f32::EPSILON as f64
                * (b - a).length()
                * (p - a).length().max((p - b).length());
            let e = edge64(a, b, p) * area.signum();
            (e.abs() > reach).then_some(e > 0.0)
        });
        let Some(inside) = sides.iter().try_fold(true, |all, s| s.map(|s| all && s)) else {
            continue; // within rounding of an edge
        };
        if (*px != UNTOUCHED) != inside {
            return Some(Wrong { c, x, y, p, inside });
        }
    }
    None
}

/// How far p is from the nearest of the triangle's edges (as lines).
fn sides_distance(c: [DVec2; 3], p: DVec2) -> f64 {
    (0..3)
        .map(|e| {
            let (a, b) = (c[e], c[(e + 1) % 3]);
            edge64(a, b, p).abs() / (b - a).length()
        })
        .fold(f64::INFINITY, f64::min)
}
