//! Exercise 4.3, the gradient normal: hand-worked normals of a sphere, a
//! box and a torus (`src/grading/cases.toml`), then drawn spheres and
//! scaled bounds, and boxes near their edges, against the reference's
//! central differences with the same h.

use glam::Vec3;

use super::{NormalFn, Shape, NOT_UNIT};
use crate::cases::{self, unit, v3, V3};
use crate::ch4_implicit_surfaces::normal::gradient_central;
use crate::ch4_implicit_surfaces::primitives::{sd_box, sd_sphere};
use crate::exercise::Check;
use crate::exercises::draws::{fold_drawn, worst_drawn, Draws};
use crate::exercises::stateless;

/// A hand-worked normal.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct NormalCase {
    sdf: Shape,
    p: V3,
    expect: V3,
}

/// Drawn boxes from 10⁻² to 10 across near the origin, at points of a
/// face between 1.2 h and 1.9 h from one of its edges, h from 10⁻³ to
/// 10⁻² of the box: differences of step h stay on the face, so its normal
/// is exact, while steps of 2h, or an h raised to a floor, reach across
/// the edge. And at each point a second shape, a sphere, asked at the same
/// p and h: the answer depends on the shape, not on p and h alone.
fn near_edges(f: NormalFn, draws: &mut Draws) -> (f64, String) {
    worst_drawn((0..draws.count(30, 80)).map(|_| {
        draws.next_case();
        let scale = draws.decades(-2.0, 1.0);
        let centre = draws.in_cube() * scale;
        let half = Vec3::new(
            draws.range(0.5, 1.0),
            draws.range(0.5, 1.0),
            draws.range(0.5, 1.0),
        ) * scale;
        let h = scale * draws.decades(-3.0, -2.0);
        // A face (axis a, side s) and an edge it shares with axis e.
        let (a, e) = (draws.count(0, 2), draws.count(1, 2));
        let e = (a + e) % 3;
        let mut q = Vec3::new(
            draws.range(-0.5, 0.5),
            draws.range(-0.5, 0.5),
            draws.range(-0.5, 0.5),
        ) * half;
        q[a] = draws.sign() * half[a];
        q[e] = draws.sign() * (half[e] - draws.range(1.2, 1.9) * h);
        let p = centre + q;
        let boxed = move |x: Vec3| sd_box(x - centre, half);
        let ball = move |x: Vec3| (x - centre - half).length() - scale;
        let (want_box, want_ball) = (
            gradient_central(&boxed, p, h).normalize(),
            gradient_central(&ball, p, h).normalize(),
        );
        let (got_box, got_ball) = (f(&boxed, p, h), f(&ball, p, h));
        // (A NaN normal is infinitely far off, whichever shape it is for.)
        let off = |e: f32| if e.is_nan() { f32::INFINITY } else { e };
        let (e_box, e_ball) = (
            off((got_box - want_box).length()),
            off((got_ball - want_ball).length()),
        );
        let (err, what, got, want) = if e_box >= e_ball {
            (
                e_box,
                format!(
                    "a box of half sizes {half} at {centre}, {:.2} h from an edge",
                    (half[e] - q[e].abs()) / h
                ),
                got_box,
                want_box,
            )
        } else {
            (
                e_ball,
                format!(
                    "a ball at {}, asked right after a box at the same p and h",
                    centre + half
                ),
                got_ball,
                want_ball,
            )
        };
        (
            err as f64,
            format!("{what}, at {p} with h = {h}: got {got}, expected {want}"),
        )
    }))
}

/// Gradient normals of a sphere, a box face and a torus against their
/// exact normals.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_gradient_normal(f: NormalFn) -> Check {
    stateless::unless_changed(gradient_normal_values(f), || {
        stateless::probes::gradient_normal(f, |f, p, h| gradient_central(f, p, h).normalize())
    })
}

/// [`check_gradient_normal`]'s checks of the values.
fn gradient_normal_values(f: NormalFn) -> Check {
    let sphere = |p: Vec3| sd_sphere(p - Vec3::new(1.0, 0.0, 0.0), 2.0);
    let hand = cases::worst("ch4/gradient_normal", |case: &NormalCase| {
        let sdf = |p: Vec3| case.sdf.distance(p);
        let (p, want) = (v3(case.p), unit(case.expect));
        let got = f(&sdf, p, 1e-3);
        (
            (got - want).length() as f64,
            format!("at {p}: got {got}, expected {want}"),
        )
    });
    let (mut error, mut detail) = match hand {
        Ok(w) => w,
        Err(check) => return check,
    };
    // Drawn spheres from 10⁻² to 10² across, up to 10 times that from the
    // origin, points near their surface, h from 10⁻³ to 10⁻² of the radius,
    // half of them scaled (a bound whose gradient is not unit length),
    // against the reference's central differences (the same h: the same
    // truncation, and rounding far below the tolerance).
    let mut draws = Draws::new(44);
    // From a stream of their own, a sixth of the bounds within 1 % of a
    // distance, k from 1 ± 0.2 % to 1 ± 0.9 % (a gradient nearly unit is
    // not unit: it is normalised all the same).
    let mut nearly = Draws::new(144);
    // And from another, a tenth of the bounds 10⁻⁶ to 10⁻³·⁵ times the
    // distance (a gradient that short is still a direction), and a tenth
    // of the points 10³ to 10⁵ radii out (f there is large, and still
    // what it is).
    let mut extreme = Draws::new(244);
    let drawn = worst_drawn((0..draws.count(50, 200)).map(|_| {
        draws.next_case();
        nearly.next_case();
        extreme.next_case();
        let r = draws.decades(-2.0, 2.0);
        let centre = draws.place_for(r, 1.0);
        let out = draws.direction();
        let p = centre + out * r * draws.range(0.9, 1.1);
        let far = extreme.unit() < 0.1;
        let p = match far {
            true => centre + out * r * extreme.decades(3.0, 5.0),
            false => p,
        };
        let h = r * draws.decades(-3.0, -2.0);
        // (Far out, h from 10⁻⁵ to 10⁻⁴ of p's largest coordinate: p ± h
        // must be other points than p in f32.)
        let h = match far {
            true => p.abs().max_element() * extreme.decades(-5.0, -4.0),
            false => h,
        };
        // Half of them a bound, not a distance: k times it, k from 1/10 to
        // 10, whose gradient is k long (the normal is still unit).
        let k = if draws.unit() < 0.5 {
            1.0
        } else {
            draws.decades(-1.0, 1.0)
        };
        let k = match nearly.unit() < 1.0 / 6.0 {
            true => 1.0 + nearly.sign() * nearly.range(0.002, 0.009),
            false => k,
        };
        let k = match extreme.unit() < 0.1 {
            true => extreme.decades(-6.0, -3.5),
            false => k,
        };
        let sdf = move |q: Vec3| k * ((q - centre).length() - r);
        let want = gradient_central(&sdf, p, h).normalize();
        let got = f(&sdf, p, h);
        (
            (got - want).length() as f64,
            format!("{k} × the distance to a sphere of radius {r} at {centre}, at {p} with h = {h}: got {got}, expected {want}"),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    fold_drawn(&mut error, &mut detail, near_edges(f, &mut draws));
    // Twice the sphere's distance: a gradient 2 long.
    let twice = |p: Vec3| 2.0 * sphere(p);
    let length = f(&twice, Vec3::new(3.0, 0.0, 0.0), 1e-3).length();
    // A NaN length is not unit length either.
    let unit = (length - 1.0).abs() <= 1e-2;
    let symptom = (error > 1e-3 && !unit).then_some(NOT_UNIT);
    Check {
        error,
        tolerance: 1e-3,
        detail,
        images: None,
        symptom,
    }
}
