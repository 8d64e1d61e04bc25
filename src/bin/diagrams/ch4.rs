//! Chapter 4's diagrams: slices z = 0 through SDF scenes built from the
//! chapter's primitives and operators ([`Sdf::eval`]), with rays marched
//! by the chapter's own [`sphere_trace`] and [`fixed_step`]. Every point
//! drawn on a ray is a point where the march evaluated f.

use std::cell::RefCell;

use glam::{Quat, Vec3};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::distance::Sdf;
use raystep::ch4_implicit_surfaces::march::{fixed_step, sphere_trace, Ending, March, Trace};
use raystep::ch4_implicit_surfaces::normal::gradient_central;
use raystep::core::error::Result;

use crate::contour::Grid;
use crate::svg::{Anchor, Stroke, Svg, BLUE, FILL_ORANGE, GREEN, GREY, INK, ORANGE, RED};
use crate::Diagram;

/// Chapter 4's diagrams, in the order the chapter shows them.
pub fn diagrams() -> Result<Vec<Diagram>> {
    Ok(vec![
        Diagram {
            name: "ch4-fixed-step-diagram",
            what: "fixed steps jump over a thin plate, sphere tracing does not (fixed_step, sphere_trace)",
            svg: fixed_against_sphere()?,
        },
        Diagram {
            name: "ch4-sphere-tracing-diagram",
            what: "a ray sphere-traced through an SDF slice, each step a circle of radius f (sphere_trace, Sdf::eval)",
            svg: sphere_tracing()?,
        },
        Diagram {
            name: "ch4-grazing-diagram",
            what: "rays that pass close to a silhouette or skim a plane take many small steps (sphere_trace)",
            svg: grazing()?,
        },
    ])
}

/// The scene of the sphere-tracing diagrams: a ground plane y = -1, a
/// sphere and a tilted box, as a scene file would build them.
fn shapes() -> Sdf {
    Sdf::Union(vec![
        Sdf::Plane {
            normal: Vec3::Y,
            offset: -1.0,
        },
        Sdf::Translate {
            offset: Vec3::new(-0.5, -0.3, 0.0),
            of: Box::new(Sdf::Sphere { radius: 0.6 }),
        },
        Sdf::Translate {
            offset: Vec3::new(2.2, -0.35, 0.0),
            of: Box::new(Sdf::Rotate {
                rotation: Quat::from_rotation_z(25f32.to_radians()),
                of: Box::new(Sdf::Box {
                    half_size: Vec3::splat(0.45),
                }),
            }),
        },
    ])
}

/// The points a march evaluated f at, with f there.
type Log = Vec<((f64, f64), f64)>;

/// Marches `ray` through `sdf` with `march`, noting every evaluation of f
/// as (point, f).
fn logged(
    sdf: &Sdf,
    ray: &Ray,
    march: impl Fn(&dyn Fn(Vec3) -> f32, &Ray) -> Trace,
) -> (Trace, Log) {
    let log = RefCell::new(Vec::new());
    let f = |p: Vec3| {
        let d = sdf.eval(p);
        log.borrow_mut().push(((p.x as f64, p.y as f64), d as f64));
        d
    };
    let trace = march(&f, ray);
    (trace, log.into_inner())
}

/// A ray in the slice from `o` towards `towards`.
fn ray(o: (f32, f32), towards: (f32, f32)) -> Result<Ray> {
    Ray::new(
        Vec3::new(o.0, o.1, 0.0),
        Vec3::new(towards.0 - o.0, towards.1 - o.1, 0.0),
    )
}

/// The march settings of the diagrams: ε large enough that the last
/// circles stay visible, and no further than the picture.
fn settings(max_distance: f32) -> March {
    March {
        epsilon: 2e-3,
        max_steps: 256,
        max_distance,
        step_factor: 1.0,
    }
}

/// Draws the slice of `sdf` over `world`, shifted up by `dy`: the solids
/// (f < 0) filled, their outline f = 0, and the level sets f = `levels`.
fn slice(s: &mut Svg, sdf: &Sdf, world: [f64; 4], dy: f64, levels: &[f64]) {
    let [x0, x1, y0, y1] = world;
    let cell = 0.03;
    let (nx, ny) = (
        ((x1 - x0) / cell).round() as usize,
        ((y1 - y0) / cell).round() as usize,
    );
    let f = |x: f64, y: f64| sdf.eval(Vec3::new(x as f32, y as f32, 0.0)) as f64;
    let grid = Grid::sample(&f, world, nx, ny);
    let shift = |line: &[(f64, f64)]| line.iter().map(|p| (p.0, p.1 + dy)).collect::<Vec<_>>();
    for line in grid.closed(1e-6).level(0.0) {
        s.area(&shift(&line), FILL_ORANGE);
    }
    for &level in levels {
        for line in grid.level(level) {
            s.polyline(&shift(&line), Stroke::solid("#c8c8c8", 1.0), None);
        }
    }
    for line in grid.level(0.0) {
        s.polyline(&shift(&line), Stroke::solid(INK, 1.8), None);
    }
}

/// Dots at the points a march evaluated, shifted by `dy`, with the ray's
/// path through them.
fn evaluations(s: &mut Svg, log: &[((f64, f64), f64)], dy: f64, colour: &'static str) {
    let pts: Vec<(f64, f64)> = log.iter().map(|(p, _)| (p.0, p.1 + dy)).collect();
    s.polyline(&pts, Stroke::solid(colour, 1.6), None);
    for p in &pts {
        s.dot(*p, 3.0, colour);
    }
}

/// Circles of radius |f| around the points a march evaluated, clipped to
/// the slice `world` (shifted by `dy`).
fn circles(s: &mut Svg, log: &[((f64, f64), f64)], world: [f64; 4], dy: f64) {
    let [x0, x1, y0, y1] = world;
    s.clipped([x0, x1, y0 + dy, y1 + dy], |s| {
        for &(p, d) in log {
            if d.abs() * s.scale() > 1.5 {
                s.circle((p.0, p.1 + dy), d.abs(), Stroke::solid(BLUE, 1.0), None);
            }
        }
    });
}

fn how_it_ended(t: &Trace) -> &'static str {
    match t.ending {
        Ending::Hit => "hit",
        Ending::Escaped => "left the picture",
        Ending::Budget => "ran out of steps",
    }
}

/// The lecture's first march against sphere tracing, on a plate thinner
/// than the step.
fn fixed_against_sphere() -> Result<Svg> {
    let sdf = Sdf::Union(vec![
        Sdf::Plane {
            normal: Vec3::Y,
            offset: -1.0,
        },
        Sdf::Translate {
            offset: Vec3::new(0.45, -0.35, 0.0),
            of: Box::new(Sdf::Box {
                half_size: Vec3::new(0.05, 0.65, 1.0),
            }),
        },
        Sdf::Translate {
            offset: Vec3::new(2.1, -0.3, 0.0),
            of: Box::new(Sdf::Sphere { radius: 0.55 }),
        },
    ]);
    let world = [-3.0, 3.0, -1.25, 1.0];
    let gap = 2.45;
    let mut s = Svg::new(620.0, [world[0], world[1], world[2] - gap, world[3]]);
    let r = ray((-2.8, 0.55), (0.0, 0.0))?;
    let delta = 0.6;
    let m = settings(6.5);
    let (fixed, fixed_log) = logged(&sdf, &r, |f, r| fixed_step(f, r, delta, &m));
    let (traced, traced_log) = logged(&sdf, &r, |f, r| sphere_trace(f, r, &m));
    // Top: the fixed step; bottom (shifted down): sphere tracing.
    for (dy, log, trace, colour) in [
        (0.0, &fixed_log, &fixed, ORANGE),
        (-gap, &traced_log, &traced, BLUE),
    ] {
        slice(&mut s, &sdf, world, dy, &[]);
        if dy < 0.0 {
            circles(&mut s, log, world, dy);
        }
        evaluations(&mut s, log, dy, colour);
        let end = log.last().expect("a march evaluates f").0;
        s.dot((end.0, end.1 + dy), 5.0, if dy < 0.0 { GREEN } else { RED });
        let o = (r.origin.x as f64, r.origin.y as f64 + dy);
        s.text(o, (-2.0, 18.0), "o", 15.0, Anchor::Middle, INK, true);
        let title = if dy < 0.0 {
            format!(
                "sphere_trace: steps of f, {} evaluations, {}",
                trace.steps,
                how_it_ended(trace)
            )
        } else {
            format!(
                "fixed_step: steps of Δ = {delta}, {} evaluations, hits what is behind",
                trace.steps
            )
        };
        s.text(
            (world[0], world[3] + dy),
            (6.0, 14.0),
            &title,
            14.0,
            Anchor::Start,
            colour,
            false,
        );
    }
    s.text(
        (0.45, 0.3),
        (8.0, 0.0),
        "a plate thinner than Δ",
        13.0,
        Anchor::Start,
        INK,
        false,
    );
    s.caption("f changes sign only inside the plate, and no sample of the fixed step lands there");
    Ok(s)
}

/// One ray, sphere-traced, with the level sets of f behind it.
fn sphere_tracing() -> Result<Svg> {
    let sdf = shapes();
    let world = [-3.0, 3.2, -1.3, 1.5];
    let mut s = Svg::new(640.0, world);
    slice(&mut s, &sdf, world, 0.0, &[0.25, 0.5, 0.75, 1.0, 1.25, 1.5]);
    let r = ray((-2.8, 1.3), (2.0, 0.1))?;
    let (trace, log) = logged(&sdf, &r, |f, r| sphere_trace(f, r, &settings(8.0)));
    circles(&mut s, &log, world, 0.0);
    evaluations(&mut s, &log, 0.0, BLUE);
    let hit = log.last().expect("a march evaluates f").0;
    s.dot(hit, 5.0, GREEN);
    let (p0, d0) = log[0];
    // The first radius, labelled: towards the nearest surface point, down
    // the gradient of f.
    let g = gradient_central(
        &|p| sdf.eval(p),
        Vec3::new(p0.0 as f32, p0.1 as f32, 0.0),
        1e-3,
    )
    .normalize();
    let edge = (p0.0 - d0 * g.x as f64, p0.1 - d0 * g.y as f64);
    s.line(p0, edge, Stroke::dashed(INK, 1.2));
    s.text(
        ((p0.0 + edge.0) / 2.0, (p0.1 + edge.1) / 2.0),
        (6.0, 4.0),
        "f(o)",
        15.0,
        Anchor::Start,
        INK,
        true,
    );
    s.text(p0, (-4.0, -8.0), "o", 15.0, Anchor::End, INK, true);
    s.text(
        hit,
        (8.0, -6.0),
        "|f| < ε",
        14.0,
        Anchor::Start,
        GREEN,
        true,
    );
    s.text(
        (2.2, -0.35),
        (0.0, 5.0),
        "f < 0",
        14.0,
        Anchor::Middle,
        INK,
        true,
    );
    s.text(
        (2.6, 1.2),
        (0.0, 0.0),
        "f > 0",
        14.0,
        Anchor::Middle,
        GREY,
        true,
    );
    s.caption(&format!(
        "sphere_trace: {} evaluations of f; grey lines: f = 0.25, 0.5, ..., 1.5",
        trace.steps
    ));
    Ok(s)
}

/// Rays that pass close to a surface: beside a silhouette, and along a
/// plane.
fn grazing() -> Result<Svg> {
    let sdf = shapes();
    let world = [-3.0, 3.2, -1.3, 1.5];
    let mut s = Svg::new(640.0, world);
    slice(&mut s, &sdf, world, 0.0, &[]);
    let rays = [
        ray((-2.8, 0.5), (-0.5, 0.4))?,
        ray((-2.8, -0.55), (-1.2, -1.0))?,
    ];
    let mut counts = Vec::new();
    for (r, colour) in rays.iter().zip([BLUE, ORANGE]) {
        let (trace, log) = logged(&sdf, r, |f, r| sphere_trace(f, r, &settings(6.0)));
        circles(&mut s, &log, world, 0.0);
        evaluations(&mut s, &log, 0.0, colour);
        counts.push(trace);
    }
    s.text(
        (-2.8, 0.5),
        (0.0, -10.0),
        &format!(
            "past the silhouette: {} evaluations, {}",
            counts[0].steps,
            how_it_ended(&counts[0])
        ),
        14.0,
        Anchor::Start,
        BLUE,
        false,
    );
    s.text(
        (-2.8, -0.55),
        (0.0, -10.0),
        &format!(
            "skimming the ground: {} evaluations, {}",
            counts[1].steps,
            how_it_ended(&counts[1])
        ),
        14.0,
        Anchor::Start,
        ORANGE,
        false,
    );
    s.caption("near a surface f is small, so the steps are small, even where the ray never hits");
    Ok(s)
}
