//! Exercises 3.1 to 3.3: a ray and a plane, the barycentric inside test,
//! Möller–Trumbore. Each against hand-worked cases and random ones, with
//! the common mistakes named.

use glam::Vec3;

use super::triangle_symptoms::*;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::{self, intersect_f64};
use crate::exercise::{Check, Symptom};
use crate::exercises::draws::Draws;
use crate::exercises::{stateless, worse, worst};

pub use super::inside_cases::Uv;

/// A hit as (t, u, v).
pub type Tuv = (f32, f32, f32);

/// raystep's Möller–Trumbore in the exercise's signature.
pub(super) fn reference_moller_trumbore(
    o: Vec3,
    d: Vec3,
    tri: [Vec3; 3],
) -> Option<(f32, f32, f32)> {
    // Our Ray normalises d: d brought first to about unit length by a
    // power of two (exact), so that its length's square stays in f32's
    // range however long d is, and t scaled back to the caller's d.
    let m = d.abs().max_element();
    let s = match m > 0.0 && m.is_finite() {
        true => 2f32.powi((-m.log2().floor()).clamp(-126.0, 126.0) as i32),
        false => 1.0,
    };
    let ray = Ray::new(o, d * s).ok()?;
    let h = triangle::intersect_moller_trumbore(&ray, tri, 0.0, f32::INFINITY)?;
    Some((h.t / (d * s).length() * s, h.u, h.v))
}

/// The barycentric (u, v) of `p` in `tri` by least squares in f64 (the
/// normal equations of p - p0 = u e1 + v e2), when p is inside: the
/// grader's own answer for its random cases.
fn uv_f64(p: Vec3, tri: [Vec3; 3]) -> Option<Uv> {
    let [p0, p1, p2] = tri.map(|q| q.as_dvec3());
    let (e1, e2, w) = (p1 - p0, p2 - p0, p.as_dvec3() - p0);
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let det = d11 * d22 - d12 * d12;
    if det == 0.0 {
        return None;
    }
    let u = (d22 * w.dot(e1) - d12 * w.dot(e2)) / det;
    let v = (d11 * w.dot(e2) - d12 * w.dot(e1)) / det;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0).then_some((u as f32, v as f32))
}

/// Relative error of `got` against `want`, infinite when one is missing.
pub(super) fn rel(got: Option<f32>, want: Option<f32>) -> f64 {
    match (got, want) {
        (Some(g), Some(w)) => ((g - w).abs() / w.abs().max(f32::MIN_POSITIVE)) as f64,
        (None, None) => 0.0,
        _ => f64::INFINITY,
    }
}

/// The worst of `(error, which case, what went wrong)`, a NaN counting as
/// infinite.
pub(super) fn check(
    cases: impl Iterator<Item = (f64, String, Option<Symptom>)>,
    tolerance: f64,
) -> Check {
    let (error, (detail, symptom)) = worst(cases.map(|(e, what, s)| (e, (what, s))))
        .unwrap_or_else(|| (0.0, ("all cases match".into(), None)));
    Check {
        error,
        tolerance,
        detail,
        images: None,
        symptom,
    }
}

/// Whether `g` is `w` to 1e-4, relative to `w` (at least 1).
pub(super) fn near(g: f32, w: f32) -> bool {
    (g - w).abs() <= 1e-4 * w.abs().max(1.0)
}

/// Hand-worked points of one triangle, a degenerate triangle, and random
/// points against `uv_f64`, an independent f64 solution worked here.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_barycentric_inside(f: fn(Vec3, [Vec3; 3]) -> Option<(f32, f32)>) -> Check {
    stateless::unless_changed(barycentric_inside_values(f), || {
        stateless::probes::barycentric_inside(f)
    })
}

/// [`check_barycentric_inside`]'s checks of the values.
fn barycentric_inside_values(f: fn(Vec3, [Vec3; 3]) -> Option<(f32, f32)>) -> Check {
    let mut cases = super::inside_cases::hand_cases();
    // Drawn triangles from 10⁻³ to 10³ across, up to 10³ times their size
    // from the origin (a fifth 10^3.5 to 10⁴ times, in a plane z = const
    // so that p is exactly in it), and points in and around them; a tenth
    // exactly at p0 (u and v exactly 0, of either sign); a tenth with a
    // corner repeated, asked at their corners.
    let mut draws = Draws::new(32);
    for _ in 0..draws.count(300, 900) {
        draws.next_case();
        let scale = draws.triangle_scale();
        let far = draws.unit() < 0.2;
        let place = match far {
            true => draws.direction() * scale * draws.decades(3.5, 4.0),
            false => draws.place_for(scale, 3.0),
        };
        let t = [0; 3].map(|_| {
            let v = place + draws.in_cube() * scale;
            if far {
                Vec3::new(v.x, v.y, place.z)
            } else {
                v
            }
        });
        let (mut u, mut v) = (draws.range(-0.5, 1.1), draws.range(-0.5, 1.1));
        // A third of them near the origin, where rounding is 10⁻⁶ of the
        // size: points 3·10⁻⁶ to 10⁻³ of the way inside or outside an
        // edge (a point outside by less than the contract's 10⁻⁴ is still
        // outside; below 1.5·10⁻⁵ only on well-shaped triangles, below).
        let near_edge = draws.unit() < 1.0 / 3.0;
        let t = if near_edge { t.map(|q| q - place) } else { t };
        if near_edge {
            let (s, m) = (
                draws.range(0.1, 0.9),
                draws.sign() * draws.decades(-5.5, -3.0),
            );
            (u, v) = match draws.count(0, 2) {
                0 => (-m, s),
                1 => (s, -m),
                _ => (s * (1.0 + m), (1.0 - s) * (1.0 + m)),
            };
        }
        let p = t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
        // Only well-shaped triangles: on a sliver, rounding decides.
        let sides = (t[1] - t[0])
            .length()
            .max((t[2] - t[0]).length())
            .max((t[2] - t[1]).length());
        let shape = (t[1] - t[0]).cross(t[2] - t[0]).length() / (sides * sides);
        if shape < 0.05 {
            continue;
        }
        // Skip points right on an edge, where rounding decides: an f32
        // solution's u and v are off by a few ε over the shape (the
        // course's, against f64 on 200,000 drawn near-edge cases: at most
        // 1.3·10⁻⁶ on the shapes kept, 3.2·10⁻⁷ from 0.4; an equilateral
        // triangle's shape is 0.87).
        let margin = match (near_edge, shape >= 0.4) {
            (true, true) => 3e-6,
            (true, false) => 1.5e-5,
            (false, _) => 1e-3,
        };
        if u.abs().min(v.abs()).min((1.0 - u - v).abs()) > margin {
            cases.push((p, t, uv_f64(p, t)));
        }
        if draws.unit() < 0.1 {
            cases.push((t[0], t, Some((0.0, 0.0))));
        }
        // A tenth of them with no area, a corner repeated (where every
        // method's area is exactly 0), asked at a corner or between.
        if draws.unit() < 0.1 {
            let flat = match draws.count(0, 2) {
                0 => [t[0], t[0], t[2]],
                1 => [t[0], t[1], t[1]],
                _ => [t[2], t[1], t[2]],
            };
            let at = match draws.count(0, 3) {
                3 => (flat[0] + flat[1]) * 0.5,
                k => flat[k],
            };
            cases.push((at, flat, None));
        }
    }
    check(
        cases.into_iter().map(|(p, t, want)| {
            let got = f(p, t);
            let err = match (got, want) {
                (Some(g), Some(w)) => worse((g.0 - w.0).abs().into(), (g.1 - w.1).abs().into()),
                (None, None) => 0.0,
                _ => f64::INFINITY,
            };
            let area = (t[1] - t[0]).cross(t[2] - t[0]).length_squared();
            let symptom = match (got, want) {
                (Some(_), None) if area == 0.0 => Some(DEGENERATE),
                (Some(g), Some(w)) if near(g.0, w.1) && near(g.1, w.0) => Some(SWAPPED_UV),
                (None, Some(w)) if w.0 == 0.0 || w.1 == 0.0 || w.0 + w.1 == 1.0 => {
                    Some(EDGES_OUTSIDE)
                }
                _ => None,
            };
            (
                err,
                format!("p {p} in {t:?}: got {got:?}, expected {want:?}"),
                symptom,
            )
        }),
        1e-4,
    )
}

/// Hand-worked rays, parallel and degenerate cases, and random rays against
/// an f64 solution of the same 3x3 system (Cramer's rule, `intersect_f64`:
/// not the Möller–Trumbore under test).
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_moller_trumbore(f: fn(Vec3, Vec3, [Vec3; 3]) -> Option<Tuv>) -> Check {
    stateless::unless_changed(moller_trumbore_values(f), || {
        stateless::probes::moller_trumbore(f, reference_moller_trumbore)
    })
}

/// [`check_moller_trumbore`]'s checks of the values.
fn moller_trumbore_values(f: fn(Vec3, Vec3, [Vec3; 3]) -> Option<Tuv>) -> Check {
    let tri = [
        Vec3::new(0.0, 0.0, -2.0),
        Vec3::new(2.0, 0.0, -2.0),
        Vec3::new(0.0, 2.0, -2.0),
    ];
    let mut cases: Vec<(Vec3, Vec3, [Vec3; 3], Option<Tuv>)> = vec![
        // Straight down -z onto (1, 0.5, -2): t = 2, u = 0.5, v = 0.25.
        (
            Vec3::new(1.0, 0.5, 0.0),
            -Vec3::Z,
            tri,
            Some((2.0, 0.5, 0.25)),
        ),
        // The same with an unnormalised direction: t halves.
        (
            Vec3::new(1.0, 0.5, 0.0),
            -Vec3::Z * 2.0,
            tri,
            Some((1.0, 0.5, 0.25)),
        ),
        // On an edge, on the long edge and at a vertex: edges and vertices
        // belong to the triangle (each u, v exact here).
        (
            Vec3::new(1.0, 0.0, 0.0),
            -Vec3::Z,
            tri,
            Some((2.0, 0.5, 0.0)),
        ),
        (
            Vec3::new(1.0, 1.0, 0.0),
            -Vec3::Z,
            tri,
            Some((2.0, 0.5, 0.5)),
        ),
        (
            Vec3::new(0.0, 2.0, 0.0),
            -Vec3::Z,
            tri,
            Some((2.0, 0.0, 1.0)),
        ),
        // The origin on the triangle: t = 0, not a hit (t > 0).
        (Vec3::new(1.0, 0.5, -2.0), -Vec3::Z, tri, None),
        // 2^-17 above a triangle 2,000 across: every t > 0 is a hit, however
        // small beside the triangle (exact in f32 by any of the formulas).
        (
            Vec3::new(3.0, 7.0, 2f32.powi(-17)),
            -Vec3::Z,
            [
                Vec3::new(-1000.0, -1000.0, 0.0),
                Vec3::new(1000.0, -1000.0, 0.0),
                Vec3::new(0.0, 1000.0, 0.0),
            ],
            Some((2f32.powi(-17), 0.24975, 0.5035)),
        ),
        // Behind the origin, outside, parallel, degenerate: no hit.
        (Vec3::new(1.0, 0.5, 0.0), Vec3::Z, tri, None),
        (Vec3::new(3.0, 3.0, 0.0), -Vec3::Z, tri, None),
        (Vec3::new(0.0, 0.0, -2.0), Vec3::X, tri, None),
        // Parallel 2^-14 above the triangle's plane, across it: no hit,
        // however near (a ray tilted by 10⁻⁴ would hit).
        (
            Vec3::new(0.2, 0.5, -2.0 + 2f32.powi(-14)),
            Vec3::X,
            tri,
            None,
        ),
        (
            Vec3::ZERO,
            -Vec3::Z,
            [Vec3::ZERO, Vec3::X, Vec3::X * 2.0],
            None,
        ),
        // A corner given twice: no area either.
        (
            Vec3::new(0.2, 0.1, 1.0),
            -Vec3::Z,
            [Vec3::ZERO, Vec3::ZERO, Vec3::X],
            None,
        ),
    ];
    // Axis-aligned triangles in all eight orientations, hit at p0 and at
    // the middle of the edges from it: u and v exactly 0, of either sign;
    // in a plane of each axis (a box's walls: the x and y coordinates of
    // an upright triangle enclose no area).
    let turn = |v: Vec3, axis: usize| match axis {
        0 => v,
        1 => Vec3::new(v.z, v.x, v.y),
        _ => Vec3::new(v.y, v.z, v.x),
    };
    for (k, axis) in (0..8).flat_map(|k| (0..3).map(move |axis| (k, axis))) {
        let (sx, sy) = ([1.0, -1.0][k & 1], [1.0, -1.0][(k >> 1) & 1]);
        let (a, b) = (Vec3::new(2.0 * sx, 0.0, 0.0), Vec3::new(0.0, 2.0 * sy, 0.0));
        let (a, b) = if k >= 4 { (b, a) } else { (a, b) };
        let p0 = Vec3::new(1.0, -1.0, -2.0);
        let tri = [p0, p0 + a, p0 + b].map(|p| turn(p, axis));
        let d = turn(-Vec3::Z, axis);
        for at in [p0, p0 + 0.5 * a, p0 + 0.5 * b] {
            let o = turn(Vec3::new(at.x, at.y, 0.0), axis);
            let want = intersect_f64(o.as_dvec3(), d.as_dvec3(), tri.map(|p| p.as_dvec3()));
            cases.push((
                o,
                d,
                tri,
                want.map(|(t, u, v)| (t as f32, u as f32, v as f32)),
            ));
        }
    }
    // Drawn triangles and rays: 10⁻³ to 10³ across, up to 10⁵ times their
    // size from the origin (a fifth 10^4.5 to 10⁵, the ray's origin near
    // them: the world's coordinates dwarf the triangle), d of any length
    // (t up to 10⁵, in units of the d given; from a stream of their own,
    // every hit again with d 10⁻²² to 10⁻¹⁹ or 10¹⁹ to 10²⁴ times as
    // long, where |d|² leaves f32's range and t does not).
    let mut draws = Draws::new(33);
    let mut long = Draws::new(333);
    let mut afar = Vec::new();
    for _ in 0..draws.count(300, 900) {
        draws.next_case();
        long.next_case();
        let scale = draws.triangle_scale();
        let place = match draws.unit() < 0.2 {
            true => draws.direction() * scale * draws.decades(4.5, 5.0),
            false => draws.place_for(scale, 5.0),
        };
        let at = |q: Vec3| place + q * scale;
        let t = [
            at(draws.in_cube() + Vec3::new(0.0, 0.0, -3.0)),
            at(draws.in_cube() + Vec3::new(0.0, 0.0, -3.0)),
            at(draws.in_cube() + Vec3::new(0.0, 0.0, -3.0)),
        ];
        let (o, d) = (
            at(draws.in_cube() * 0.5),
            Vec3::new(draws.range(-1.0, 1.0), draws.range(-1.0, 1.0), -2.0)
                * draws.decades(-5.0, 2.0),
        );
        let want = intersect_f64(o.as_dvec3(), d.as_dvec3(), t.map(|p| p.as_dvec3()));
        let n = triangle::unit_normal(t).unwrap_or(Vec3::ZERO);
        let clear = match want {
            Some((_, u, v)) => u.min(v).min(1.0 - u - v) > 1e-3,
            None => true,
        };
        if clear && n.dot(d.normalize()).abs() > 0.05 {
            cases.push((
                o,
                d,
                t,
                want.map(|(t, u, v)| (t as f32, u as f32, v as f32)),
            ));
            // A hit again with d 10³ to 10⁵ times shorter: t that many
            // times larger, the same point.
            if want.is_some() {
                let short = d * draws.decades(-5.0, -3.0);
                // (A share of 1: always a far scale, tiny or huge.)
                let far = long.far_scale(1.0, (-22.0, -19.0), (19.0, 24.0));
                for (d, to) in [(short, &mut cases), (d * far.unwrap_or(1.0), &mut afar)] {
                    let want = intersect_f64(o.as_dvec3(), d.as_dvec3(), t.map(|p| p.as_dvec3()));
                    to.push((
                        o,
                        d,
                        t,
                        want.map(|(t, u, v)| (t as f32, u as f32, v as f32)),
                    ));
                }
            }
        }
    }
    // Rays at a triangle in the plane z = 0, where the products are
    // exact. Grazing: 10⁻⁹ to 10⁻⁵ rad off its plane, at any scale (the
    // determinant one exact product: small is not zero). Close by: from
    // 10⁻⁷ to 10⁻⁴ in front of it (in units of a d about 1 long), the
    // triangle at most 100 times that size, so that rounding leaves t to
    // 10⁻⁵: any t > 0 is a hit.
    for grazing in [true, false] {
        for _ in 0..draws.count(20, 60) {
            draws.next_case();
            let near = draws.decades(-7.0, -4.0);
            let scale = match grazing {
                true => draws.triangle_scale(),
                false => near * draws.decades(0.0, 2.0),
            };
            let t = [0, 1, 2].map(|_| {
                let q = draws.in_cube() * scale;
                Vec3::new(q.x, q.y, 0.0)
            });
            let (u, v) = (draws.range(0.1, 0.45), draws.range(0.1, 0.45));
            let hit = t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
            let along = draws.direction();
            let (d, tau) = match grazing {
                true => (
                    Vec3::new(along.x, along.y, -draws.decades(-9.0, -5.0)) * scale,
                    draws.range(0.5, 2.0),
                ),
                false => (Vec3::new(along.x, along.y, -along.z.abs().max(0.3)), near),
            };
            let o = hit - d * tau;
            let want = intersect_f64(o.as_dvec3(), d.as_dvec3(), t.map(|p| p.as_dvec3()));
            let area = (t[1] - t[0]).cross(t[2] - t[0]).length();
            let clear = match want {
                Some((_, u, v)) => u.min(v).min(1.0 - u - v) > 1e-3,
                None => false,
            };
            if clear && area > 0.05 * scale * scale {
                cases.push((
                    o,
                    d,
                    t,
                    want.map(|(t, u, v)| (t as f32, u as f32, v as f32)),
                ));
            }
        }
    }
    cases.extend(super::triangle_edges::near_edges(&mut draws));
    let judge = |(o, d, t, want): (Vec3, Vec3, [Vec3; 3], Option<Tuv>)| {
        let got = f(o, d, t);
        let err = match (got, want) {
            (Some(g), Some(w)) => worse(
                ((g.0 - w.0).abs() / w.0.abs()).into(),
                worse((g.1 - w.1).abs().into(), (g.2 - w.2).abs().into()),
            ),
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        let normal = (t[1] - t[0]).cross(t[2] - t[0]);
        let symptom = match (got, want) {
            (Some(g), Some(w)) if !near(g.0, w.0) && near(g.0, w.0 * d.length()) => Some(UNIT_T),
            (Some(_), None) if normal.length_squared() == 0.0 => Some(DEGENERATE),
            (Some(_), None) if normal.dot(d) == 0.0 => Some(PARALLEL),
            (Some(g), None) if g.0 <= 0.0 => Some(BEHIND),
            _ => None,
        };
        (
            err,
            format!("o {o}, d {d}, {t:?}: got {got:?}, expected {want:?}"),
            symptom,
        )
    };
    // The far lengths of d last, once the rest passes (so that a mistake
    // the rest shows keeps its name).
    let main = check(cases.into_iter().map(judge), 1e-4);
    match main.passed() {
        true => check(afar.into_iter().map(judge), 1e-4),
        false => main,
    }
}
