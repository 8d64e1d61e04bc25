//! Chapter 5's diagrams: Lambert's law and the solid angle with the values
//! [`radiometry`] computes, the four kinds of light with the irradiance
//! each casts on a floor ([`lights`]), and the BRDF lobes drawn from the
//! materials' own `f` ([`Bsdf::f`]).

mod lights;

use std::f64::consts::{FRAC_PI_2, PI};

use glam::{Vec2, Vec3};
use raystep::ch5_reflection::material::glossy::Glossy;
use raystep::ch5_reflection::material::lambert::Lambertian;
use raystep::ch5_reflection::material::mirror::Mirror;
use raystep::ch5_reflection::material::retro::Retro;
use raystep::ch5_reflection::material::semigloss::SemiGloss;
use raystep::ch5_reflection::material::Bsdf;
use raystep::ch5_reflection::radiometry::{
    cap_solid_angle, directional_irradiance, sphere_solid_angle,
};
use raystep::core::error::Result;

use crate::svg::{Anchor, Stroke, Svg, BLUE, FILL_BLUE, FILL_ORANGE, GREY, INK, ORANGE, RED};
use crate::Diagram;

/// Chapter 5's diagrams, in the order the chapter shows them.
pub fn diagrams() -> Result<Vec<Diagram>> {
    Ok(vec![
        Diagram {
            name: "ch5-lambert-diagram",
            what: "a beam spread over a tilted surface, A' = A / cos θ (directional_irradiance)",
            svg: lambert(),
        },
        Diagram {
            name: "ch5-solid-angle-diagram",
            what: "a sphere's solid angle as its shadow on the unit hemisphere (sphere_solid_angle, cap_solid_angle)",
            svg: solid_angle(),
        },
        Diagram {
            name: "ch5-lights-diagram",
            what: "directional, point, spot and area light, each with the irradiance it casts on a floor (directional_irradiance, point_irradiance, Spot::falloff, polygon_irradiance)",
            svg: lights::lights(),
        },
        Diagram {
            name: "ch5-brdf-lobes-diagram",
            what: "the BRDF lobes of the materials for one incoming direction (Bsdf::f, Bsdf::sample for the mirror)",
            svg: lobes(),
        },
    ])
}

/// Points of the circle of radius `r` around `c` from angle `a0` to `a1`
/// (radians, counter-clockwise from +x).
pub fn arc(c: (f64, f64), r: f64, a0: f64, a1: f64) -> Vec<(f64, f64)> {
    let n = ((a1 - a0).abs() * 24.0).ceil().max(2.0) as usize;
    (0..=n)
        .map(|k| {
            let a = a0 + (a1 - a0) * k as f64 / n as f64;
            (c.0 + r * a.cos(), c.1 + r * a.sin())
        })
        .collect()
}

/// `p + t·d`.
fn along(p: (f64, f64), d: (f64, f64), t: f64) -> (f64, f64) {
    (p.0 + t * d.0, p.1 + t * d.1)
}

/// A label in italics (a symbol), centred.
fn symbol(s: &mut Svg, at: (f64, f64), label: &str, colour: &str) {
    s.text(at, (0.0, 5.0), label, 15.0, Anchor::Middle, colour, true);
}

/// Lambert's law: the same beam on a surface facing it and on one tilted
/// by θ.
fn lambert() -> Svg {
    let mut s = Svg::new(660.0, [-1.7, 7.7, -0.75, 2.45]);
    let theta = 60f64.to_radians();
    let e_tilted = directional_irradiance(1.0, theta.cos());
    let width = 1.0; // A, the beam's cross-section
    for (centre, angle) in [(0.0, 0.0), (4.6, theta)] {
        // The surface, and the beam arriving along -ω (ω towards the light).
        s.line(
            (centre - 1.5, 0.0),
            (centre + 1.5 + 1.1 * (angle > 0.0) as i32 as f64, 0.0),
            Stroke::solid(INK, 2.0),
        );
        let w = (-angle.sin(), angle.cos());
        let across = (w.1, -w.0);
        let length = 1.9;
        // The beam: a cross-section A across ω at the top, each of its
        // points carried down along −ω to the surface, A' apart there.
        let ray = |side: f64| {
            let top = along(along((centre, 0.0), w, length), across, side * width);
            (top, along(top, w, -top.1 / w.1))
        };
        let ((t0, f0), (t1, f1)) = (ray(-0.5), ray(0.5));
        s.area(&[f0, f1, t1, t0], FILL_ORANGE);
        for k in 0..5 {
            let (top, foot) = ray(-0.4 + 0.2 * k as f64);
            s.arrow(top, along(foot, w, 0.08), Stroke::solid(RED, 1.4));
        }
        s.line(f0, f1, Stroke::solid(ORANGE, 6.0));
        // A, the cross-section, drawn across the beam near its top.
        let top = along((centre, 0.0), w, length - 0.15);
        let (l, r) = (along(top, across, -0.5), along(top, across, 0.5));
        s.line(l, r, Stroke::solid(INK, 1.4));
        symbol(&mut s, along(along(top, across, -0.72), w, 0.05), "A", INK);
        symbol(&mut s, along(top, w, 0.45), "Φ", RED);
        if angle > 0.0 {
            s.arrow((centre, 0.0), (centre, 1.2), Stroke::solid(GREY, 1.4));
            symbol(&mut s, (centre + 0.12, 1.32), "n", GREY);
            s.polyline(
                &arc((centre, 0.0), 0.65, FRAC_PI_2, FRAC_PI_2 + angle),
                Stroke::solid(INK, 1.2),
                None,
            );
            symbol(&mut s, (centre - 0.33, 0.9), "θ", INK);
            s.text(
                (centre, 0.0),
                (0.0, 24.0),
                "A′ = A / cos θ",
                15.0,
                Anchor::Middle,
                ORANGE,
                false,
            );
            s.text(
                (centre, -0.45),
                (0.0, 20.0),
                &format!("E = Φ / A′ = Φ cos θ / A = {e_tilted:.2} Φ / A  (θ = 60°)"),
                14.0,
                Anchor::Middle,
                INK,
                false,
            );
        } else {
            s.text(
                (centre, 0.0),
                (0.0, 24.0),
                "A",
                15.0,
                Anchor::Middle,
                ORANGE,
                true,
            );
            s.text(
                (centre, -0.45),
                (0.0, 20.0),
                "E = Φ / A",
                14.0,
                Anchor::Middle,
                INK,
                false,
            );
        }
    }
    s
}

/// The solid angle of a sphere seen from p: the arc its outline cuts from
/// the unit hemisphere above p.
fn solid_angle() -> Svg {
    let mut s = Svg::new(580.0, [-2.0, 3.4, -0.5, 3.05]);
    let p = (0.0, 0.0);
    let (radius, distance) = (0.62, 2.25);
    let towards = 52f64.to_radians();
    let c = along(p, (towards.cos(), towards.sin()), distance);
    let alpha = (radius / distance).asin();
    let omega = sphere_solid_angle(radius, distance);
    debug_assert!((omega - cap_solid_angle(alpha)).abs() < 1e-9);
    // The cone from p around the sphere, and its cut through the hemisphere.
    let (a0, a1) = (towards - alpha, towards + alpha);
    let mut cone = vec![p];
    cone.extend(arc(p, 1.0, a0, a1));
    s.area(&cone, FILL_BLUE);
    for a in [a0, a1] {
        s.line(
            p,
            along(p, (a.cos(), a.sin()), distance * alpha.cos()),
            Stroke::dashed(GREY, 1.2),
        );
    }
    s.line((-1.9, 0.0), (3.3, 0.0), Stroke::solid(INK, 2.0));
    s.polyline(&arc(p, 1.0, 0.0, PI), Stroke::solid(GREY, 1.4), None);
    s.polyline(&arc(p, 1.0, a0, a1), Stroke::solid(BLUE, 5.0), None);
    s.circle(c, radius, Stroke::solid(INK, 1.6), Some(FILL_ORANGE));
    s.line(
        c,
        along(c, (-a1.sin(), a1.cos()), radius),
        Stroke::solid(INK, 1.0),
    );
    symbol(
        &mut s,
        along(c, (-a1.sin() - 0.2, a1.cos() + 0.5), radius * 0.55),
        "r",
        INK,
    );
    s.arrow(p, (0.0, 1.45), Stroke::solid(GREY, 1.4));
    symbol(&mut s, (0.12, 1.55), "n", GREY);
    s.dot(p, 4.0, INK);
    symbol(&mut s, (0.0, -0.22), "p", INK);
    s.polyline(&arc(p, 0.55, towards, a1), Stroke::solid(INK, 1.0), None);
    symbol(
        &mut s,
        along(
            p,
            ((towards + 0.6 * alpha).cos(), (towards + 0.6 * alpha).sin()),
            0.4,
        ),
        "α",
        INK,
    );
    s.text(
        along(p, (a1.cos(), a1.sin()), 1.02),
        (-6.0, -6.0),
        "Ω",
        16.0,
        Anchor::End,
        BLUE,
        true,
    );
    s.text(
        (-0.7, 0.72),
        (-6.0, 0.0),
        "unit hemisphere",
        13.0,
        Anchor::End,
        GREY,
        false,
    );
    s.line(p, c, Stroke::dashed(GREY, 1.0));
    s.text(c, (0.0, 5.0), "object", 13.0, Anchor::Middle, INK, false);
    s.text(
        (1.0, 2.9),
        (0.0, 0.0),
        &format!("Ω = 2π (1 − cos α) = {omega:.3} sr   (d = {distance}, r = {radius})"),
        14.0,
        Anchor::Middle,
        INK,
        false,
    );
    let middle = along(p, (towards.cos(), towards.sin()), 1.25);
    s.text(middle, (8.0, 4.0), "d", 15.0, Anchor::Start, GREY, true);
    s.caption(
        "the solid angle is the area of the object's projection onto the unit hemisphere above p",
    );
    s
}

/// One lobe panel: the surface, n, the incoming ωi, and `f(ωr, ωi)` over
/// the plane of incidence as a polar curve (or, for a delta, the one
/// reflected direction).
fn lobe(s: &mut Svg, at: (f64, f64), title: &str, bsdf: &Bsdf, wi: Vec3) {
    let (x, y) = at;
    s.line((x - 1.35, y), (x + 1.35, y), Stroke::solid(INK, 2.0));
    s.arrow((x, y), (x, y + 1.3), Stroke::solid(GREY, 1.2));
    symbol(s, (x + 0.13, y + 1.33), "n", GREY);
    if bsdf.is_delta() {
        // f is a delta: the only direction light leaves in is the sampled one.
        let wr = bsdf
            .sample(wi, Vec2::splat(0.5), 0.5)
            .map_or(Vec3::Z, |b| b.wi);
        let to = (x + 1.2 * wr.x as f64, y + 1.2 * wr.z as f64);
        s.arrow((x, y), to, Stroke::solid(BLUE, 2.6));
        symbol(s, (to.0 + 0.08, to.1 + 0.14), "ωr", BLUE);
    } else {
        lobe_curve(s, at, bsdf, wi);
    }
    let from = (x + 1.25 * wi.x as f64, y + 1.25 * wi.z as f64);
    s.arrow(from, (x, y), Stroke::solid(RED, 2.0));
    symbol(s, (from.0 - 0.12, from.1 + 0.1), "ωi", RED);
    s.text((x, y), (0.0, 22.0), title, 14.0, Anchor::Middle, INK, false);
}

/// The polar curve of `f(ωr, ωi)` over the plane of incidence.
fn lobe_curve(s: &mut Svg, (x, y): (f64, f64), bsdf: &Bsdf, wi: Vec3) {
    let out = |a: f64| Vec3::new(a.sin() as f32, 0.0, a.cos() as f32);
    let angles: Vec<f64> = (0..=180).map(|k| (k as f64 - 90.0).to_radians()).collect();
    let values: Vec<f64> = angles
        .iter()
        .map(|&a| bsdf.f(out(a), wi).x as f64)
        .collect();
    let top = values.iter().cloned().fold(0.0, f64::max);
    let mut curve = vec![(x, y)];
    curve.extend(
        angles
            .iter()
            .zip(&values)
            .map(|(&a, &v)| (x + 1.15 * v / top * a.sin(), y + 1.15 * v / top * a.cos())),
    );
    s.polyline(&curve, Stroke::solid(BLUE, 1.8), Some(FILL_BLUE));
}

/// The lecture's basic reflection functions and the red semi-gloss paint,
/// for light arriving 45° from the normal.
fn lobes() -> Svg {
    let mut s = Svg::new(680.0, [-1.45, 7.15, -3.55, 1.5]);
    let a = 45f32.to_radians();
    let wi = Vec3::new(-a.sin(), 0.0, a.cos());
    let rho = Vec3::splat(0.8);
    let panels = [
        ("ideal diffuse", Bsdf::Lambertian(Lambertian { rho })),
        ("ideal specular (mirror)", Bsdf::Mirror(Mirror { r: rho })),
        ("glossy (n = 20)", Bsdf::Glossy(Glossy { rs: rho, n: 20.0 })),
        (
            "retro-reflective (n = 8)",
            Bsdf::Retro(Retro { rho, n: 8.0 }),
        ),
        (
            "semi-gloss paint (kₛ = 0.3)",
            Bsdf::SemiGloss(SemiGloss {
                rho,
                ks: 0.3,
                n: 40.0,
            }),
        ),
    ];
    for (k, (title, bsdf)) in panels.iter().enumerate() {
        let at = (2.85 * (k % 3) as f64, -2.5 * (k / 3) as f64);
        lobe(&mut s, at, title, bsdf, wi);
    }
    let key = (2.85 * 2.0 - 1.3, -1.6);
    for (k, line) in [
        "blue: radius ∝ f(ωi, ωr) over",
        "the plane of incidence, for the",
        "red ωi; each lobe scaled to fit",
        "",
        "the mirror's f is a delta: it is",
        "drawn as its one direction ωr",
    ]
    .iter()
    .enumerate()
    {
        s.text(
            key,
            (0.0, 19.0 * k as f64),
            line,
            13.0,
            Anchor::Start,
            GREY,
            false,
        );
    }
    s
}
