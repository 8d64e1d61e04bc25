//! Exercise 2.2's check: barycentric coordinates against hand-worked
//! values (thin slivers among them) and drawn triangles at every scale,
//! then asked again after other questions ([`stateless`]).

use glam::{Vec2, Vec3, Vec3Swizzles};

use crate::ch2_rasterization::edge;
use crate::exercise::Check;
use crate::exercises::draws::Draws;
use crate::exercises::{stateless, AbsMax};

use super::{worst_of, BARY_ORDER, BARY_SCALE};

/// φ of `p` in the triangle `t`, worked out in f64 from the f32 corners
/// (a triangle with area).
fn exact_phi(t: [Vec2; 3], p: Vec2) -> Vec3 {
    let [i, j, k] = t.map(|c| c.as_dvec2());
    let q = p.as_dvec2();
    let area = (j - i).perp_dot(k - i);
    Vec3::new(
        ((k - j).perp_dot(q - j) / area) as f32,
        ((i - k).perp_dot(q - k) / area) as f32,
        ((j - i).perp_dot(q - i) / area) as f32,
    )
}

/// Compares barycentric coordinates with hand values and checks that they
/// rebuild the point.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_barycentric(f: fn(Vec2, Vec2, Vec2, Vec2) -> Option<Vec3>) -> Check {
    stateless::unless_changed(barycentric_values(f), || {
        stateless::probes::barycentric(f, edge::barycentric)
    })
}

/// [`check_barycentric`]'s checks of the values.
fn barycentric_values(f: fn(Vec2, Vec2, Vec2, Vec2) -> Option<Vec3>) -> Check {
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
        // Each corner exactly, either winding: 1 at its own corner.
        (a, b, c, a, Some(Vec3::X)),
        (a, b, c, c, Some(Vec3::Z)),
        (a, c, b, b, Some(Vec3::Z)),
        (a, c, b, c, Some(Vec3::Y)),
        // No area, no coordinates: on a line (the point off it too).
        (a, b, v(8.0, 0.0), v(1.0, 1.0), None),
        (a, a, a, a, None),
        (v(0.1, 0.1), v(0.2, 0.2), v(0.3, 0.3), v(0.7, -0.4), None),
        // Thin, but with an area (its unit edges' cosine rounds to 1).
        (
            a,
            v(1.0, 0.0),
            v(0.5, 2f32.powi(-13)),
            v(0.5, 2f32.powi(-14)),
            Some(Vec3::new(0.25, 0.25, 0.5)),
        ),
    ];
    // A few more whose φ must rebuild the point.
    for k in 0..5 {
        let t = k as f32;
        let (pi, pj, pk) = (v(t, -1.0), v(3.0 + t, 2.0 * t), v(-2.0, 5.0 - t));
        let phi = Vec3::new(0.2 + 0.1 * t, 0.5 - 0.05 * t, 0.3 - 0.05 * t);
        let p = pi * phi.x + pj * phi.y + pk * phi.z;
        cases.push((pi, pj, pk, p, Some(phi)));
    }
    // Drawn well-shaped triangles from 10⁻³ to 10³ across, up to 10³ times
    // that from the origin, either winding, points in and around them and
    // just off their edges, and their neighbours; φ worked out in f64 from
    // the f32 corners. (The symptoms are read from the hand cases only.)
    let hand = cases.len();
    // Thinner slivers (after the hand cases the symptoms are read from,
    // whose sums they would round away): the sine of the corner angles
    // (2^-40) far below f32's epsilon, and a doubled area (2^-140) so
    // small that 1 / area overflows. Each φ is exact in f32.
    for h in [-40, -140] {
        cases.push((
            a,
            v(1.0, 0.0),
            v(0.5, 2f32.powi(h)),
            v(0.5, 2f32.powi(h - 1)),
            Some(Vec3::new(0.25, 0.25, 0.5)),
        ));
    }
    let mut draws = Draws::new(22);
    let mut tiny = Draws::new(122);
    let mut far = Draws::new(222);
    for _ in 0..draws.count(200, 800) {
        draws.next_case();
        tiny.next_case();
        far.next_case();
        let scale = draws.decades(-3.0, 3.0);
        // A tenth from 10⁻¹² to 10⁻³ across (from a stream of their own).
        let scale = match tiny.unit() < 0.1 {
            true => tiny.decades(-12.0, -3.0),
            false => scale,
        };
        let place = draws.place_for(scale, 3.0).truncate();
        let (pi, pj, pk) = (
            place + draws.in_square() * scale,
            place + draws.in_square() * scale,
            place + draws.in_square() * scale,
        );
        let p = place + draws.in_square() * scale * 1.5;
        let (i, j, k) = (pi.as_dvec2(), pj.as_dvec2(), pk.as_dvec2());
        let area = (j - i).perp_dot(k - i);
        let longest = (j - i).length().max((k - i).length()).max((k - j).length());
        if area.abs() < 0.05 * longest * longest {
            continue;
        }
        cases.push((pi, pj, pk, p, Some(exact_phi([pi, pj, pk], p))));
        // A point just off one edge (φ of that edge's corner 10⁻⁷ to 10⁻³,
        // either sign), and then, the very next call, the neighbour across
        // the edge (pi, pj) with its own point: φ owes nothing to the call
        // before.
        let near = draws.count(0, 2);
        let small = (draws.sign() * draws.decades(-7.0, -3.0)) as f64;
        let t = draws.range(-0.2, 1.2) as f64;
        let mut w = [t, 1.0 - t - small, small];
        w.rotate_right(near);
        let p_near = (i * w[0] + j * w[1] + k * w[2]).as_vec2();
        cases.push((pi, pj, pk, p_near, Some(exact_phi([pi, pj, pk], p_near))));
        let across = pi + pj - pk;
        let p_across = place + draws.in_square() * scale * 1.5;
        let phi_across = exact_phi([pi, pj, across], p_across);
        cases.push((pi, pj, across, p_across, Some(phi_across)));
        // And a point 10 to 10⁴ times the triangle's size away, where the
        // φ are as large and the three sub-areas nearly cancel (from a
        // stream of their own).
        let (sin, cos) = far.range(0.0, std::f32::consts::TAU).sin_cos();
        let p_far = place + Vec2::new(cos, sin) * scale * far.decades(1.0, 4.0);
        cases.push((pi, pj, pk, p_far, Some(exact_phi([pi, pj, pk], p_far))));
    }
    // The mistakes it can name: φ that are right but belong to other
    // corners, or right up to a common factor (not divided by the area).
    let (mut permuted, mut scaled, mut some) = (true, true, false);
    for &(pi, pj, pk, p, want) in &cases[..hand] {
        if let (Some(g), Some(w)) = (f(pi, pj, pk, p), want) {
            some = true;
            let close = |a: Vec3| (a - w).abs_max() <= 1e-4;
            let perms = [g.yzx(), g.zxy(), g.xzy(), g.zyx(), g.yxz()];
            permuted &= close(g) || perms.iter().any(|q| close(*q));
            let sum = g.x + g.y + g.z;
            scaled &= sum.abs() > 1e-6 && close(g / sum);
        }
    }
    let symptom = match (some && permuted, some && scaled) {
        (true, _) => Some(BARY_ORDER),
        (_, true) => Some(BARY_SCALE),
        _ => None,
    };
    let check = worst_of(
        cases.into_iter().map(|(pi, pj, pk, p, want)| {
            let got = f(pi, pj, pk, p);
            // Absolute to 1e-5 near the triangle; relative to the largest φ
            // far from it (where φ grows with the distance, and so does
            // its rounding).
            let err = match (got, want) {
                (Some(g), Some(w)) => ((g - w).abs_max() / w.abs_max().max(1.0)) as f64,
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
    );
    match symptom {
        Some(symptom) if !check.passed() => check.with_symptom(symptom),
        _ => check,
    }
}
