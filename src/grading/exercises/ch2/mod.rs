//! Chapter 2's exercises and how each is graded. The capstone's check is
//! in [`raster`] and [`shading`], the mistakes it can name in [`model`];
//! the manifold counts' check is in [`manifold`], and the barycentric
//! coordinates' in `barycentric.rs`.

use glam::Vec2;

use crate::cases;
use crate::ch2_rasterization::{depth, edge, triangle};
use crate::exercise::{Check, Exercise, Symptom};
use crate::exercises::draws::{fold_drawn, worst_drawn, Draws};
use crate::exercises::stateless;

mod barycentric;
mod common;
mod depth_test;
mod drawn_cover;
pub mod manifold;
pub mod model;
pub mod raster;
pub mod shading;

pub use barycentric::check_barycentric;
pub use depth_test::check_depth_test;
pub use manifold::{check_manifold, ManifoldFn};
pub use raster::{check_rasterize_triangle, fill_rule_triangles, RasterFn};

/// The edge function with the opposite sign.
pub const EDGE_SIGN: Symptom = Symptom {
    name: "the sign is flipped",
};
/// Barycentrics that belong to other corners.
pub const BARY_ORDER: Symptom = Symptom {
    name: "coordinates belong to other corners",
};
/// Barycentrics that do not sum to 1.
pub const BARY_SCALE: Symptom = Symptom {
    name: "coordinates do not sum to 1",
};
/// A depth test that lets a tie through.
pub const TIE: Symptom = Symptom {
    name: "a tie replaced the first surface",
};
/// A depth test that forgets to store the depth.
pub const NOT_STORED: Symptom = Symptom {
    name: "the depth was not stored",
};
/// Capstone: gaps or double cover along shared edges.
pub const TOP_LEFT: Symptom = Symptom {
    name: "samples on shared edges drawn twice or not at all",
};
/// Capstone: everything shifted by half a pixel.
pub const HALF_PIXEL: Symptom = Symptom {
    name: "shifted by half a pixel",
};
/// Capstone: one winding drawn, the other not.
pub const WINDING: Symptom = Symptom {
    name: "one winding is not drawn",
};
/// Capstone: wrong pixels where a triangle reaches past the image.
pub const OFF_IMAGE: Symptom = Symptom {
    name: "pixels past the image border",
};
/// Capstone: a triangle without area drew something.
pub const DEGENERATE: Symptom = Symptom {
    name: "a triangle without area drew",
};
/// Capstone: colours interpolated in screen space.
pub const AFFINE: Symptom = Symptom {
    name: "affine colours",
};
/// Capstone: the wrong depth stored.
pub const DEPTH_VALUE: Symptom = Symptom {
    name: "the wrong depth at a sample",
};
/// Capstone: colours not swapped with their corners.
pub const COLOUR_ORDER: Symptom = Symptom {
    name: "colours on the wrong corners",
};
/// Capstone: the nearer surface did not win.
pub const DEPTH_TEST: Symptom = Symptom {
    name: "the nearer surface did not win",
};
/// Capstone: a tie replaced the first surface.
pub const DEPTH_TIE: Symptom = Symptom {
    name: "a tie replaced the first surface",
};

/// Chapter 2's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 2,
            name: "edge_function",
            file: "chapters/ch2-rasterization/exercises/edge_function.rs",
            symptoms: &[EDGE_SIGN],
            reference: || check_edge_function(edge::edge_function),
        },
        Exercise {
            chapter: 2,
            name: "barycentric",
            file: "chapters/ch2-rasterization/exercises/barycentric.rs",
            symptoms: &[BARY_ORDER, BARY_SCALE],
            reference: || check_barycentric(edge::barycentric),
        },
        Exercise {
            chapter: 2,
            name: "depth_test",
            file: "chapters/ch2-rasterization/exercises/depth_test.rs",
            symptoms: &[TIE, NOT_STORED],
            reference: || check_depth_test(depth::depth_test),
        },
        Exercise {
            chapter: 2,
            name: "rasterize_triangle",
            file: "chapters/ch2-rasterization/exercises/rasterize_triangle.rs",
            symptoms: &[
                TOP_LEFT,
                HALF_PIXEL,
                WINDING,
                OFF_IMAGE,
                DEGENERATE,
                AFFINE,
                DEPTH_VALUE,
                COLOUR_ORDER,
                DEPTH_TEST,
                DEPTH_TIE,
            ],
            reference: || check_rasterize_triangle(triangle::rasterize_triangle),
        },
        Exercise {
            chapter: 2,
            name: "manifold",
            file: "chapters/ch2-rasterization/exercises/manifold.rs",
            symptoms: &[
                manifold::BOUNDARY,
                manifold::BOOK_EDGES,
                manifold::FANS,
                manifold::ORIENTATION,
                manifold::REPEATED_INDEX,
            ],
            reference: || check_manifold(manifold::reference_counts),
        },
    ]
}

/// The worst case as a check, `ok` its detail when every case matches.
pub(super) fn worst_of(
    cases: impl Iterator<Item = (f64, String)>,
    tolerance: f64,
    ok: &str,
) -> Check {
    let (error, detail) = super::worst(cases).unwrap_or_else(|| (0.0, ok.to_string()));
    Check {
        error,
        tolerance,
        detail,
        images: None,
        symptom: None,
    }
}

/// A hand-worked edge function value (`src/grading/cases.toml`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct EdgeCase {
    a: [f32; 2],
    b: [f32; 2],
    p: [f32; 2],
    expect: f32,
}

/// Compares an edge function with values worked out by hand.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_edge_function(f: fn(Vec2, Vec2, Vec2) -> f32) -> Check {
    stateless::unless_changed(edge_function_values(f), || {
        stateless::probes::edge_function(f, edge::edge_function)
    })
}

/// [`check_edge_function`]'s checks of the values.
fn edge_function_values(f: fn(Vec2, Vec2, Vec2) -> f32) -> Check {
    let cases: Vec<cases::Case<EdgeCase>> = match cases::of("ch2/edge_function") {
        Ok(c) => c,
        Err(e) => return cases::unreadable(e),
    };
    let got: Vec<f32> = cases
        .iter()
        .map(|c| f(c.case.a.into(), c.case.b.into(), c.case.p.into()))
        .collect();
    let check = worst_of(
        cases
            .iter()
            .zip(&got)
            .map(|(cases::Case { why, case: c }, &got)| {
                let (a, b, p) = (Vec2::from(c.a), Vec2::from(c.b), Vec2::from(c.p));
                // On the line: exactly 0 (the contract's own word).
                let off = match c.expect == 0.0 && got != 0.0 {
                    true => f64::INFINITY,
                    false => (got - c.expect).abs() as f64,
                };
                (
                    off,
                    format!(
                        "{why}: a = {a}, b = {b}, p = {p}: got {got}, expected {}",
                        c.expect
                    ),
                )
            }),
        1e-5,
        "all cases match",
    );
    // Every answer the negative of the right one: the sign.
    let flipped = cases
        .iter()
        .zip(&got)
        .all(|(c, g)| (g + c.case.expect).abs() <= 1e-5);
    if !check.passed() && flipped {
        return check.with_symptom(EDGE_SIGN);
    }
    let (mut error, mut detail) = (check.error, check.detail.clone());
    // Drawn edges from 10⁻⁹ to 10⁶ long, up to 10³ times that from the
    // origin: E to 10⁻⁵ of |b - a|·|p - a| (what rounding allows), and
    // exactly 0 at a, at b and on a horizontal or vertical edge; points
    // nearly on the line, near a.
    // A fifth keep the last edge's a (E depends on all three points).
    let mut draws = Draws::new(21);
    let mut last: Option<(Vec2, Vec2, f32)> = None;
    let drawn = worst_drawn((0..draws.count(300, 1500)).map(|_| {
        draws.next_case();
        let mut scale = draws.decades(-9.0, 6.0);
        let mut place = draws.place_for(scale, 3.0).truncate();
        let (mut a, mut b) = (
            place + draws.in_square() * scale,
            place + draws.in_square() * scale,
        );
        if let Some((last_a, last_place, last_scale)) = last.filter(|_| draws.unit() < 0.2) {
            (a, place, scale) = (last_a, last_place, last_scale);
            b = place + draws.in_square() * scale;
        }
        last = Some((a, place, scale));
        let mut p = place + draws.in_square() * scale;
        match draws.count(0, 7) {
            0 => p = a,
            1 => p = b,
            2 => {
                b.y = a.y;
                p.y = a.y;
            }
            3 => {
                b.x = a.x;
                p.x = a.x;
            }
            // Nearly on the line, 10⁻⁶ to 10⁻¹ rad off it, and 10⁻⁶ to 1
            // times as far from a as b is: E is still exact to rounding.
            4 | 5 => {
                let (s, c) = (draws.sign() * draws.decades(-6.0, -1.0)).sin_cos();
                let e = b - a;
                let turned = Vec2::new(e.x * c - e.y * s, e.x * s + e.y * c);
                p = a + turned * draws.sign() * draws.decades(-6.0, 0.0);
            }
            _ => {}
        }
        let (ab, ap) = ((b - a).as_dvec2(), (p - a).as_dvec2());
        let want = ab.perp_dot(ap);
        let got = f(a, b, p);
        let size = ab.length() * ap.length();
        let err = if want == 0.0 {
            if got == 0.0 {
                0.0
            } else {
                f64::INFINITY
            }
        } else {
            (got as f64 - want).abs() / size
        };
        (
            err,
            format!("a = {a}, b = {b}, p = {p}: got {got}, expected {want}"),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    // Edges about 3·10⁻²⁰ long near the origin: |b - a|·|p - a| from 10⁻³⁹
    // up, E among f32's subnormal numbers (below 1.2·10⁻³⁸), where f32's
    // products still keep it to 10⁻⁵ of that (a stream of its own).
    let mut tiny = Draws::new(121);
    let subnormal = worst_drawn((0..tiny.count(20, 40)).filter_map(|_| {
        tiny.next_case();
        let scale = tiny.decades(-19.8, -19.2);
        let place = tiny.place_for(scale, 1.0).truncate();
        let [a, b, p] = [0; 3].map(|_| place + tiny.in_square() * scale);
        let (ab, ap) = ((b - a).as_dvec2(), (p - a).as_dvec2());
        let size = ab.length() * ap.length();
        if size < 1e-39 {
            return None;
        }
        let (want, got) = (ab.perp_dot(ap), f(a, b, p));
        Some((
            (got as f64 - want).abs() / size,
            format!("a = {a}, b = {b}, p = {p}: got {got:e}, expected {want:e}"),
        ))
    }));
    fold_drawn(&mut error, &mut detail, subnormal);
    Check {
        error,
        detail,
        ..check
    }
}
