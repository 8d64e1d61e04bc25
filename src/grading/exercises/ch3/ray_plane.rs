//! Exercise 3.1, the ray-plane intersection: hand-worked planes from
//! `src/grading/cases.toml`, then drawn rays and planes over every scale,
//! and rays within a hair of parallel, against the closed form in f64.

use glam::Vec3;

use super::triangle_checks::{check, near, rel};
use super::triangle_symptoms::{PARALLEL, PLANE_SIGN};
use crate::cases::{self, v3, V3};
use crate::exercise::Check;
use crate::exercises::draws::Draws;
use crate::exercises::stateless;

/// A hand-worked plane and ray (`src/grading/cases.toml`): `expect` is
/// t, left out for a parallel ray.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct PlaneCase {
    o: V3,
    d: V3,
    n: V3,
    c: f32,
    expect: Option<f32>,
}

/// Hand-worked planes, a parallel ray, then random cases against the
/// closed form t = (c - N·o) / (N·d) worked in f64 here (not against
/// raystep's `ray_plane`, which would check the reference against itself).
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_ray_plane(f: fn(Vec3, Vec3, Vec3, f32) -> Option<f32>) -> Check {
    stateless::unless_changed(ray_plane_values(f), || {
        stateless::probes::ray_plane(f, crate::ch3_ray_triangle::triangle::ray_plane)
    })
}

/// [`check_ray_plane`]'s checks of the values.
fn ray_plane_values(f: fn(Vec3, Vec3, Vec3, f32) -> Option<f32>) -> Check {
    let cases: Vec<cases::Case<PlaneCase>> = match cases::of("ch3/ray_plane") {
        Ok(c) => c,
        Err(e) => return cases::unreadable(e),
    };
    // Drawn rays and planes: at scales from 10⁻³ to 10³, up to 100 times
    // their size from the origin, N and d of any length from 10⁻³ to 10³.
    let mut draws = Draws::new(31);
    let mut long = Draws::new(131);
    let mut drawn = Vec::new();
    let mut last_n: Option<Vec3> = None;
    for _ in 0..draws.count(200, 800) {
        draws.next_case();
        let scale = draws.decades(-3.0, 3.0);
        let place = draws.place_for(scale, 2.0);
        let (o, d, n) = (
            place + draws.in_cube() * 3.0 * scale,
            draws.direction() * draws.decades(-3.0, 3.0),
            draws.direction() * draws.decades(-3.0, 3.0),
        );
        // A sixth of the cases with N and d both short: Nᵀd far below
        // any absolute threshold, and nothing parallel about it.
        // A sixth with N and d 10⁻¹² to 10⁻¹¹ long (Nᵀd down to 10⁻²⁵,
        // whose square is below f32's range).
        let (d, n) = match draws.count(0, 5) {
            0 => (
                d.normalize() * draws.decades(-4.0, -2.5),
                n.normalize() * draws.decades(-4.0, -2.5),
            ),
            1 => (
                d.normalize() * draws.decades(-12.0, -11.0),
                n.normalize() * draws.decades(-12.0, -11.0),
            ),
            _ => (d, n),
        };
        // A tenth of those with d 10⁻³ long or more: N 10²⁰ to 10²⁵ or
        // 10⁻²⁶ to 10⁻²⁰ long (from a stream of their own), where |N|² is
        // past f32's range or subnormal and N·d and c are not.
        long.next_case();
        let n = match long.unit() < 0.1 && d.length() >= 1e-3 {
            true => match long.unit() < 0.5 {
                true => n.normalize() * long.decades(20.0, 25.0),
                false => n.normalize() * long.decades(-26.0, -20.0),
            },
            false => n,
        };
        // A fifth keep the last plane's N, with another c (a plane
        // parallel to it): t depends on c too.
        let n = match last_n {
            Some(last) if draws.unit() < 0.2 => last,
            _ => n,
        };
        last_n = Some(n);
        if n.as_dvec3().normalize().dot(d.as_dvec3().normalize()).abs() > 0.1 {
            let c = n.dot(place + draws.in_cube() * scale);
            let f64s = |v: Vec3| v.as_dvec3();
            let t = (c as f64 - f64s(n).dot(f64s(o))) / f64s(n).dot(f64s(d));
            drawn.push((o, d, n, c, t));
        }
    }
    // Rays within 10⁻⁹ to 10⁻⁴ rad of parallel to a plane z = 0 (so N·d
    // is one exact product: nearly parallel is not parallel), t from 1/2
    // to 2 at any scale.
    for _ in 0..draws.count(20, 60) {
        draws.next_case();
        let scale = draws.decades(-3.0, 3.0);
        let k = draws.decades(-9.0, -4.0);
        let along = draws.direction();
        let d = Vec3::new(along.x, along.y, -k) * scale;
        let o = Vec3::new(
            draws.range(-1.0, 1.0) * scale,
            draws.range(-1.0, 1.0) * scale,
            draws.range(0.5, 2.0) * k * scale,
        );
        let n = Vec3::new(0.0, 0.0, draws.sign() * draws.decades(-3.0, 3.0));
        let t = -(n.z as f64 * o.z as f64) / (n.z as f64 * d.z as f64);
        drawn.push((o, d, n, 0.0, t));
    }
    // A drawn case's t is known to what the f32 inputs allow: the error of
    // c - N·o is a few roundings of |c| + |N||o|, which divided by |N·d|
    // is the scale T of t's rounding. Its error counts relative to
    // |t| or T/100, whichever is larger.
    let drawn = drawn.into_iter().map(|(o, d, n, c, t)| {
        let (n64, o64) = (n.as_dvec3(), o.as_dvec3());
        let scale = (c.abs() as f64 + n64.length() * o64.length()) / n64.dot(d.as_dvec3()).abs();
        let got = f(o, d, n, c);
        let err = match got {
            Some(g) => (g as f64 - t).abs() / t.abs().max(scale * 1e-2),
            None => f64::INFINITY,
        };
        let symptom = got
            .filter(|g| near(-g, t as f32) && !near(*g, t as f32))
            .map(|_| PLANE_SIGN);
        (
            err,
            format!("o {o}, d {d}, N {n}, c {c}: got {got:?}, expected Some({t}) (a drawn case)"),
            symptom,
        )
    });
    check(
        cases
            .into_iter()
            .map(|cases::Case { why, case }| {
                let (o, d, n, c, want) = (v3(case.o), v3(case.d), v3(case.n), case.c, case.expect);
                let got = f(o, d, n, c);
                let symptom = match (got, want) {
                    (Some(g), Some(w)) if w != 0.0 && !near(g, w) && near(-g, w) => {
                        Some(PLANE_SIGN)
                    }
                    (Some(_), None) => Some(PARALLEL),
                    _ => None,
                };
                (
                    rel(got, want),
                    format!("{why}: o {o}, d {d}, N {n}, c {c}: got {got:?}, expected {want:?}"),
                    symptom,
                )
            })
            .collect::<Vec<_>>()
            .into_iter()
            .chain(drawn),
        1e-4,
    )
}
