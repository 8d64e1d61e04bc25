//! Chapter 6's diagram: one path through the Cornell box, as the render
//! traced it. [`record_path`] runs the render's own loop
//! ([`trace_path`](raystep::ch6_global_illumination::integrator::trace_path))
//! for one sample of one pixel and writes down every vertex, its light
//! sample and its shadow ray; the diagram draws that record seen from the
//! side.

use glam::Vec3;
use raystep::ch1_projection::camera::Camera;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::hit::Surface;
use raystep::ch5_reflection::world::World;
use raystep::ch6_global_illumination::integrator::PathSettings;
use raystep::ch6_global_illumination::path_record::{record_path, PathEnd, PathRecord};
use raystep::ch6_global_illumination::sampler::SamplerKind;
use raystep::core::error::Result;
use raystep::scene::Scene;

use crate::svg::{Anchor, Stroke, Svg, BLUE, GREEN, GREY, INK, RED};
use crate::Diagram;

/// Chapter 6's diagrams, in the order the chapter shows them.
pub fn diagrams() -> Result<Vec<Diagram>> {
    Ok(vec![Diagram {
        name: "ch6-path-diagram",
        what: "one path through the Cornell box with its shadow rays, seen from the side (record_path, trace_path)",
        svg: path()?,
    }])
}

/// The side view: world (x, y, z) seen from −x, so z runs to the right
/// (towards the camera) and y up.
fn side(p: Vec3) -> (f64, f64) {
    (p.z as f64, p.y as f64)
}

/// The convex hull of `points` (Andrew's monotone chain), counter-clockwise.
fn hull(mut points: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    points.sort_by(|a, b| a.partial_cmp(b).expect("finite points"));
    points.dedup();
    let cross = |o: (f64, f64), a: (f64, f64), b: (f64, f64)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let mut lower: Vec<(f64, f64)> = Vec::new();
    for &p in &points {
        while lower.len() >= 2 && cross(lower[lower.len() - 2], lower[lower.len() - 1], p) <= 0.0 {
            lower.pop();
        }
        lower.push(p);
    }
    let mut upper: Vec<(f64, f64)> = Vec::new();
    for &p in points.iter().rev() {
        while upper.len() >= 2 && cross(upper[upper.len() - 2], upper[upper.len() - 1], p) <= 0.0 {
            upper.pop();
        }
        upper.push(p);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

/// Whether a record makes a readable picture: a few bounces, none on the
/// side walls (they face the viewer of a side view), and both a light
/// sample that got through and one that was blocked.
fn readable(scene: &Scene, r: &PathRecord) -> bool {
    let on_side_wall = |v: &raystep::ch6_global_illumination::path_record::Vertex| match v.surface {
        Surface::Mesh(i) => scene.meshes[i].name.contains("wall"),
        Surface::Sdf(_) => true,
    };
    let lights: Vec<bool> = r
        .vertices
        .iter()
        .filter_map(|v| v.light.map(|l| l.visible))
        .collect();
    let on_box = |v: &raystep::ch6_global_illumination::path_record::Vertex| match v.surface {
        Surface::Mesh(i) => scene.meshes[i].name.contains("box"),
        Surface::Sdf(_) => true,
    };
    (3..=4).contains(&r.vertices.len())
        && !r.vertices.iter().any(on_side_wall)
        && !on_box(&r.vertices[0])
        && lights.contains(&true)
        && lights.contains(&false)
        && r.end == PathEnd::Roulette
}

/// Where the ray from `p` along `dir` first meets the scene.
fn first_hit(world: &World, p: Vec3, dir: Vec3) -> Option<Vec3> {
    let ray = Ray::new(p + 1e-3 * dir, dir).ok()?;
    world.intersect(&ray).map(|it| it.p)
}

/// One path of the Cornell box's render, with its shadow rays.
fn path() -> Result<Svg> {
    let scene = Scene::builtin();
    let world = World::new(&scene);
    let camera = Camera::of(&scene);
    // Roulette at scale 1, as with independent numbers: at the Sobol
    // points' scale 2 it rarely ends a path as short as one a diagram can
    // show.
    let settings = PathSettings {
        rr_scale: Some(1),
        ..PathSettings::default()
    };
    let (kind, seed) = (SamplerKind::Sobol, 0);
    let record = (0..64u32)
        .flat_map(|sample| {
            (1..8u32).flat_map(move |j| (1..8u32).map(move |i| (32 * i, 32 * j, sample)))
        })
        .map(|(x, y, sample)| record_path(&world, &camera, &settings, kind, seed, (x, y), sample))
        .find(|r| readable(&scene, r))
        .expect("some path of the Cornell box is readable");
    let mut s = Svg::new(660.0, [-1.25, 2.95, -1.3, 1.25]);
    // The box: back wall, floor and ceiling; the two blocks; the light.
    s.polyline(
        &[(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)],
        Stroke::solid(INK, 2.0),
        None,
    );
    for mesh in &scene.meshes {
        let outline = hull(mesh.positions.iter().map(|&p| side(p)).collect());
        if mesh.name.contains("box") {
            s.polyline(&outline, Stroke::solid(GREY, 1.2), Some("#ececec"));
        } else if mesh.name.contains("light") {
            s.polyline(&outline, Stroke::solid(RED, 4.0), Some("none"));
        }
    }
    s.text(
        (0.0, 1.0),
        (0.0, -8.0),
        "light",
        13.0,
        Anchor::Middle,
        RED,
        false,
    );
    // The camera ray, from where it enters the picture.
    let first = side(record.vertices[0].p);
    let t_in = (2.95 - camera_eye_z(&scene)) / record.camera_dir.z as f64;
    let eye = scene.camera.eye;
    let entry = (
        eye[2] + t_in * record.camera_dir.z as f64,
        eye[1] + t_in * record.camera_dir.y as f64,
    );
    s.arrow(entry, first, Stroke::solid(BLUE, 2.2));
    s.text(
        entry,
        (-4.0, -10.0),
        "from the camera",
        13.0,
        Anchor::End,
        BLUE,
        false,
    );
    let mut prev = first;
    for (k, v) in record.vertices.iter().enumerate() {
        let at = side(v.p);
        if k > 0 {
            s.arrow(prev, at, Stroke::solid(BLUE, 2.2));
        }
        if let Some(l) = v.light {
            if let Some(end) = first_hit(&world, v.p, l.wi) {
                let colour = if l.visible { GREEN } else { RED };
                s.line(at, side(end), Stroke::dashed(colour, 1.6));
                if !l.visible {
                    s.text(side(end), (0.0, 5.0), "×", 18.0, Anchor::Middle, RED, false);
                }
            }
        }
        prev = at;
    }
    for (k, v) in record.vertices.iter().enumerate() {
        let at = side(v.p);
        s.dot(at, 4.5, INK);
        s.text(
            at,
            (8.0, 16.0),
            &format!("x{}", sub(k + 1)),
            15.0,
            Anchor::Start,
            INK,
            true,
        );
    }
    let last = record
        .vertices
        .last()
        .expect("a readable path has vertices");
    if let Some((q, _)) = last.roulette {
        s.text(
            side(last.p),
            (8.0, 34.0),
            &format!("Russian roulette ends it (q = {q:.2})"),
            13.0,
            Anchor::Start,
            INK,
            false,
        );
    }
    key(&mut s);
    s.caption(&format!(
        "pixel ({}, {}), sample {}, as record_path traces it; seen from the side, through the red wall",
        record.pixel.0, record.pixel.1, record.sample
    ));
    Ok(s)
}

/// The z of the camera's eye.
fn camera_eye_z(scene: &Scene) -> f64 {
    scene.camera.eye[2]
}

/// A key in the free space in front of the box.
fn key(s: &mut Svg) {
    let x = 1.45;
    let rows: [(&str, &'static str, bool); 3] = [
        ("the path", BLUE, false),
        ("shadow ray, light seen", GREEN, true),
        ("shadow ray, blocked", RED, true),
    ];
    for (k, (label, colour, dashed)) in rows.into_iter().enumerate() {
        let y = -0.55 - 0.17 * k as f64;
        let stroke = if dashed {
            Stroke::dashed(colour, 1.6)
        } else {
            Stroke::solid(colour, 2.2)
        };
        s.line((x, y), (x + 0.2, y), stroke);
        s.text(
            (x + 0.2, y),
            (6.0, 5.0),
            label,
            12.5,
            Anchor::Start,
            INK,
            false,
        );
    }
}

/// `n` in subscript digits.
fn sub(n: usize) -> String {
    n.to_string()
        .chars()
        .map(|c| char::from_u32(0x2080 + c.to_digit(10).unwrap_or(0)).unwrap_or(c))
        .collect()
}
