//! Chapter 2's exercises and how each is graded.

use glam::{Vec2, Vec3};

use crate::ch2_rasterization::depth;
use crate::ch2_rasterization::edge;
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
            reference: || check_depth_test(depth::depth_test),
        },
    ]
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
