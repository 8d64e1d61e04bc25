//! The lecture's four kinds of light, each above a floor, with the
//! irradiance E it casts along the floor computed by the chapter's own
//! functions: [`directional_irradiance`], [`point_irradiance`], the spot's
//! [`Spot::sample_li`] (its falloff) and, for an area light,
//! [`polygon_irradiance`].

use glam::{DVec3, Vec3};
use raystep::ch5_reflection::light::area::emitted_towards;
use raystep::ch5_reflection::light::spot::Spot;
use raystep::ch5_reflection::radiometry::{
    directional_irradiance, point_irradiance, polygon_irradiance,
};

use crate::svg::{Anchor, Stroke, Svg, FILL_ORANGE, GREY, INK, ORANGE, RED};

/// Height of every light above its floor.
const HEIGHT: f64 = 1.6;
/// Half the width of a panel's floor.
const HALF: f64 = 1.4;

/// A panel: draws its light above the floor at the given origin and
/// returns the irradiance along that floor, E(x).
type Panel = fn(&mut Svg, (f64, f64)) -> Box<dyn Fn(f64) -> f64>;

/// The four panels, two by two.
pub fn lights() -> Svg {
    let mut s = Svg::new(640.0, [-1.55, 4.85, -4.6, 2.25]);
    let panels: [(&str, &str, Panel); 4] = [
        ("directional", "E = E⊥ cos θ", directional),
        ("isotropic point", "E = I cos θ / r²", point),
        ("spot", "E = I s(ω) cos θ / r²", spot),
        ("area", "E = ∫ Le cos θ dω", area),
    ];
    for (k, (title, law, draw)) in panels.into_iter().enumerate() {
        let o = (3.3 * (k % 2) as f64, -3.4 * (k / 2) as f64);
        s.line(
            (o.0 - HALF, o.1),
            (o.0 + HALF, o.1),
            Stroke::solid(INK, 2.0),
        );
        let e = draw(&mut s, o);
        plot(&mut s, o, &*e);
        s.text(
            (o.0 - HALF, o.1 + 2.1),
            (0.0, 0.0),
            title,
            15.0,
            Anchor::Start,
            INK,
            false,
        );
        s.text(
            (o.0 + HALF, o.1 + 2.1),
            (0.0, 0.0),
            law,
            14.0,
            Anchor::End,
            GREY,
            true,
        );
    }
    s.caption("below each floor: the irradiance E along it, each scaled to its largest value");
    s
}

/// The irradiance profile `e(x)` below the floor at `o`.
fn plot(s: &mut Svg, o: (f64, f64), e: &dyn Fn(f64) -> f64) {
    let base = o.1 - 0.95;
    let xs: Vec<f64> = (0..=112)
        .map(|k| -HALF + 2.0 * HALF * k as f64 / 112.0)
        .collect();
    let values: Vec<f64> = xs.iter().map(|&x| e(x)).collect();
    let top = values.iter().cloned().fold(1e-12, f64::max);
    let mut curve: Vec<(f64, f64)> = xs
        .iter()
        .zip(&values)
        .map(|(&x, &v)| (o.0 + x, base + 0.6 * v / top))
        .collect();
    s.polyline(&curve, Stroke::solid(ORANGE, 1.8), None);
    curve.insert(0, (o.0 - HALF, base));
    curve.push((o.0 + HALF, base));
    s.area(&curve, FILL_ORANGE);
    s.polyline(&curve[1..curve.len() - 1], Stroke::solid(ORANGE, 1.8), None);
    s.line(
        (o.0 - HALF, base),
        (o.0 + HALF, base),
        Stroke::solid(GREY, 1.0),
    );
    s.text(
        (o.0 - HALF, base),
        (-4.0, -6.0),
        "E",
        14.0,
        Anchor::End,
        ORANGE,
        true,
    );
}

/// A floor point `x` of the panel, in the light's 3D frame (the floor is
/// y = 0, the light above x = 0).
fn floor(x: f64) -> DVec3 {
    DVec3::new(x, 0.0, 0.0)
}

fn directional(s: &mut Svg, o: (f64, f64)) -> Box<dyn Fn(f64) -> f64> {
    let theta = 25f64.to_radians();
    let d = (theta.sin(), -theta.cos());
    for k in 0..6 {
        let foot = (o.0 - 0.55 + 0.38 * k as f64, o.1);
        let from = (foot.0 - d.0 * 1.75, foot.1 - d.1 * 1.75);
        s.arrow(
            from,
            (foot.0 - 0.04 * d.0, foot.1 - 0.04 * d.1),
            Stroke::solid(RED, 1.4),
        );
    }
    Box::new(move |_| directional_irradiance(1.0, theta.cos()))
}

fn point(s: &mut Svg, o: (f64, f64)) -> Box<dyn Fn(f64) -> f64> {
    let c = (o.0, o.1 + HEIGHT);
    for k in 0..16 {
        let a = std::f64::consts::TAU * k as f64 / 16.0;
        let (x, y) = (a.cos(), a.sin());
        s.arrow(
            (c.0 + 0.12 * x, c.1 + 0.12 * y),
            (c.0 + 0.45 * x, c.1 + 0.45 * y),
            Stroke::solid(RED, 1.4),
        );
    }
    s.dot(c, 5.0, RED);
    s.text(c, (8.0, -6.0), "I", 15.0, Anchor::Start, RED, true);
    Box::new(|x| {
        let to = DVec3::new(0.0, HEIGHT, 0.0) - floor(x);
        point_irradiance(1.0, to.length(), to.normalize().y)
    })
}

fn spot(s: &mut Svg, o: (f64, f64)) -> Box<dyn Fn(f64) -> f64> {
    let light = Spot::new(
        Vec3::new(0.0, HEIGHT as f32, 0.0),
        Vec3::NEG_Y,
        Vec3::ONE,
        32.0,
        14.0,
    );
    let c = (o.0, o.1 + HEIGHT);
    // Every 6°, an arrow as long as the spot's falloff s(ω) in that direction.
    for k in -13..=13 {
        let a = (6.0 * k as f64).to_radians();
        let w = Vec3::new(a.sin() as f32, -a.cos() as f32, 0.0);
        let length = 1.25 * light.falloff(w) as f64;
        if length > 0.0 {
            let (x, y) = (a.sin(), -a.cos());
            s.arrow(
                (c.0 + 0.12 * x, c.1 + 0.12 * y),
                (c.0 + (0.12 + length) * x, c.1 + (0.12 + length) * y),
                Stroke::solid(RED, 1.4),
            );
        }
    }
    let outer = light.cos_outer.acos() as f64;
    for side in [-1.0, 1.0] {
        let to = (c.0 + side * HEIGHT * outer.tan(), o.1);
        s.line(c, to, Stroke::dashed(GREY, 1.0));
    }
    s.dot(c, 5.0, RED);
    Box::new(move |x| {
        let p = floor(x).as_vec3();
        light
            .sample_li(p)
            .map_or(0.0, |l| (l.li.x * l.wi.dot(Vec3::Y).max(0.0)) as f64)
    })
}

fn area(s: &mut Svg, o: (f64, f64)) -> Box<dyn Fn(f64) -> f64> {
    let half = 0.45;
    let y = o.1 + HEIGHT;
    s.line((o.0 - half, y), (o.0 + half, y), Stroke::solid(RED, 5.0));
    // From points of the emitter: arrows as long as the intensity
    // Le cos θ it sends (Le from the one emission rule; none upwards).
    let n = Vec3::NEG_Y;
    for k in 0..3 {
        let x = o.0 - half + 0.15 + 0.3 * k as f64;
        for j in -3..=3 {
            let a = (25.0 * j as f64).to_radians();
            let w = Vec3::new(a.sin() as f32, -a.cos() as f32, 0.0);
            let le = emitted_towards(Vec3::ONE, false, n, w).x as f64;
            let length = 0.65 * le * n.dot(w) as f64;
            if length > 0.02 {
                s.arrow(
                    (x, y - 0.04),
                    (x + length * w.x as f64, y - 0.04 + length * w.y as f64),
                    Stroke::solid(RED, 1.1),
                );
            }
        }
    }
    s.text(
        (o.0 + half, y),
        (6.0, 5.0),
        "Le",
        15.0,
        Anchor::Start,
        RED,
        true,
    );
    Box::new(move |x| {
        let corners = [(-half, -half), (half, -half), (half, half), (-half, half)]
            .map(|(a, b)| DVec3::new(a, HEIGHT, b));
        polygon_irradiance(floor(x), DVec3::Y, &corners, 1.0)
    })
}
