//! The wrong pictures of chapters 3 and 4: a triangle test that lets rays
//! through shared edges, and an implicit sphere that is not a distance.

use glam::{DVec3, Vec3};
use rayon::prelude::*;
use raystep::ch1_projection::camera::{Camera, CameraDesc};
use raystep::ch3_ray_triangle::geometry::Geometry;
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::render::{films_from_sums, render_sum};
use raystep::ch3_ray_triangle::triangle::{intersect_watertight, Hit};
use raystep::ch4_implicit_surfaces::hit::{Surface, SurfaceHit};
use raystep::ch4_implicit_surfaces::march::sphere_trace;
use raystep::ch4_implicit_surfaces::normal::{normal, NormalScheme};
use raystep::ch4_implicit_surfaces::primitives::{sd_plane, sd_sphere};
use raystep::ch4_implicit_surfaces::render::{hit_range, pixel_ray, views, Pixel};
use raystep::ch4_implicit_surfaces::stage::DEFAULT as CH4;
use raystep::core::error::Result;
use raystep::core::film::Film;
use raystep::scene::Scene;

use super::wrong_pair::{magnify, scene, Pair};

/// The pairs of chapters 3 and 4.
pub fn pairs() -> Result<Vec<Pair>> {
    Ok(vec![ch3_leak()?, ch4_squared_distance()?])
}

// ---------------------------------------------------------------- chapter 3

/// γ(n) = n ε / (1 - n ε), as in the lesson.
const fn gamma(n: i32) -> f32 {
    let eps = f32::EPSILON * 0.5;
    (n as f32 * eps) / (1.0 - n as f32 * eps)
}

/// The lesson's `intersect_watertight`, line for line, with one mistake
/// in its inside test.
fn intersect_watertight_wrong(ray: &Ray, tri: [Vec3; 3], t_min: f32, t_max: f32) -> Option<Hit> {
    let [p0, p1, p2] = tri;
    if (p2 - p0).cross(p1 - p0).length_squared() == 0.0 {
        return None;
    }
    let (a, b, c) = (p0 - ray.origin, p1 - ray.origin, p2 - ray.origin);
    let d_abs = ray.dir.abs();
    let kz = if d_abs.x > d_abs.y {
        if d_abs.x > d_abs.z {
            0
        } else {
            2
        }
    } else if d_abs.y > d_abs.z {
        1
    } else {
        2
    };
    let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
    let perm = |v: Vec3| Vec3::new(v[kx], v[ky], v[kz]);
    let (d, mut a, mut b, mut c) = (perm(ray.dir), perm(a), perm(b), perm(c));
    let (sx, sy, sz) = (-d.x / d.z, -d.y / d.z, 1.0 / d.z);
    for p in [&mut a, &mut b, &mut c] {
        p.x += sx * p.z;
        p.y += sy * p.z;
    }
    let mut e0 = b.x * c.y - b.y * c.x;
    let mut e1 = c.x * a.y - c.y * a.x;
    let mut e2 = a.x * b.y - a.y * b.x;
    if e0 == 0.0 || e1 == 0.0 || e2 == 0.0 {
        let f = |p: f32, q: f32, r: f32, s: f32| (p as f64 * q as f64 - r as f64 * s as f64) as f32;
        e0 = f(b.x, c.y, b.y, c.x);
        e1 = f(c.x, a.y, c.y, a.x);
        e2 = f(a.x, b.y, a.y, b.x);
    }
    // BUG: inside only when all three signs are strictly the same, so an
    // edge function of exactly 0 counts as outside. A ray through the
    // edge two triangles share then misses both: the mesh leaks.
    let inside = (e0 > 0.0 && e1 > 0.0 && e2 > 0.0) || (e0 < 0.0 && e1 < 0.0 && e2 < 0.0);
    if !inside {
        return None;
    }
    let det = e0 + e1 + e2;
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    a.z *= sz;
    b.z *= sz;
    c.z *= sz;
    let t_scaled = e0 * a.z + e1 * b.z + e2 * c.z;
    if det < 0.0 && (t_scaled >= t_min * det || t_scaled < t_max * det) {
        return None;
    }
    if det > 0.0 && (t_scaled <= t_min * det || t_scaled > t_max * det) {
        return None;
    }
    let inv_det = 1.0 / det;
    let t = t_scaled * inv_det;
    // The lesson's bound on t's rounding error (its f64 tie-break is left
    // out: no triangle here is tiny next to its distance).
    let max_zt = a.z.abs().max(b.z.abs()).max(c.z.abs());
    let max_xt = a.x.abs().max(b.x.abs()).max(c.x.abs());
    let max_yt = a.y.abs().max(b.y.abs()).max(c.y.abs());
    let delta_z = gamma(3) * max_zt;
    let delta_x = gamma(5) * (max_xt + max_zt);
    let delta_y = gamma(5) * (max_yt + max_zt);
    let delta_e = 2.0 * (gamma(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
    let max_e = e0.abs().max(e1.abs()).max(e2.abs());
    let delta_t =
        3.0 * (gamma(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * inv_det.abs();
    if t <= delta_t {
        return None;
    }
    Some(Hit {
        t,
        u: e1 * inv_det,
        v: e2 * inv_det,
        triangle: 0,
    })
}

/// The scene of the leak: a sphere (icosphere) seen straight down an axis
/// from a camera whose image has an odd width, so that the middle column
/// of pixel centres lies exactly in the plane x = 0, which holds a great
/// circle of the sphere's shared edges.
fn leak_scene() -> Result<Scene> {
    Scene::from_text(
        "[camera]\neye = [0.0, 0.0, 3.2]\ntarget = [0.0, 0.0, 0.0]\nfov = 42.0\n\
         width = 81\nheight = 81\n\n[[objects]]\nshape = \"sphere\"\nsubdivisions = 2\n",
        "leak",
    )
}

/// Chapter 3: the normal view of the sphere at one ray per pixel centre,
/// through the same BVH with each test, magnified 3 times.
fn ch3_leak() -> Result<Pair> {
    let scene = leak_scene()?;
    let camera = Camera::of(&scene);
    let geometry = Geometry::new(&scene);
    let bvh = geometry.bvh.as_ref().expect("a sphere has triangles");
    let render = |test: fn(&Ray, [Vec3; 3], f32, f32) -> Option<Hit>| {
        let trace = |r: &Ray| bvh.closest_with(r, f32::INFINITY, test);
        let (sums, _) = render_sum(&camera, &geometry, 0..camera.height, 0..1, 1, 0, &trace);
        // The normal view.
        magnify(&films_from_sums(&camera, &sums, 1)[1], 3)
    };
    Ok(Pair {
        stem: "ch3-leak",
        right: render(intersect_watertight),
        wrong: render(intersect_watertight_wrong),
    })
}

// ---------------------------------------------------------------- chapter 4

/// The balls of the chapter 4 pair: (centre, radius, material of
/// `sdf-shapes.toml`: 1 red, 2 blue, 3 gold): one resting on the plane
/// y = 0, two floating above it.
const BALLS: [(Vec3, f32, usize); 3] = [
    (Vec3::new(-1.9, 0.45, 0.3), 0.45, 1),
    (Vec3::new(0.0, 3.4, -0.4), 0.8, 2),
    (Vec3::new(2.2, 2.6, 0.5), 0.55, 3),
];

/// Exercise 4.1's sphere as a student might write it from the lecture's
/// implicit sphere x² + y² + z² − 1 = 0.
fn sd_sphere_wrong(p: Vec3, r: f32) -> f32 {
    // BUG: zero on the same sphere, negative inside, but not a distance:
    // at distance d from the surface it is d (d + 2r). Far away that is
    // much more than d, so a sphere-tracing step jumps over the ball;
    // near a ball of radius above 1/2 it still overstates d.
    p.length_squared() - r * r
}

/// The ground plane and the balls, with `sphere` for the balls' distance:
/// the distance and the nearest object (0 the ground, k the k-th ball).
fn balls(p: Vec3, sphere: fn(Vec3, f32) -> f32) -> (f32, usize) {
    let mut best = (sd_plane(p, Vec3::Y, 0.0), 0);
    for (k, (c, r, _)) in BALLS.iter().enumerate() {
        let d = sphere(p - *c, *r);
        if d < best.0 {
            best = (d, k + 1);
        }
    }
    best
}

/// Chapter 4: three balls on a plane sphere traced, the balls' distance
/// from the lesson's `sd_sphere` and from the student's; the headlight
/// view of `views`.
fn ch4_squared_distance() -> Result<Pair> {
    let shapes = scene("sdf-shapes.toml")?;
    let camera = Camera::new(CameraDesc {
        eye: DVec3::new(0.0, 1.0, 8.0),
        target: DVec3::new(0.0, 1.9, 0.0),
        up: DVec3::Y,
        fov_degrees: 45.0,
        width: 240,
        height: 180,
    })?;
    let march = CH4.march;
    let render = |sphere: fn(Vec3, f32) -> f32| -> Film {
        let f = |p: Vec3| balls(p, sphere).0;
        let pixels: Vec<Pixel> = (0..camera.width * camera.height)
            .into_par_iter()
            .map(|i| {
                let ray = pixel_ray(&camera, i % camera.width, i / camera.width);
                let trace = sphere_trace(&f, &ray, &march);
                let hit = trace.hit().map(|t| {
                    let p = ray.at(t);
                    let object = balls(p, sphere).1;
                    let h = march.epsilon_at(p).max(1e-4);
                    let n = normal(&f, p, h, NormalScheme::Tetrahedron, -ray.dir);
                    SurfaceHit {
                        t,
                        normal: if n.dot(ray.dir) > 0.0 { -n } else { n },
                        material: if object == 0 { 0 } else { BALLS[object - 1].2 },
                        surface: Surface::Sdf(object),
                    }
                });
                Pixel { trace, hit, ray }
            })
            .collect();
        let size = (camera.width, camera.height);
        views(&pixels, size, &shapes.materials, &march, hit_range(&pixels)).swap_remove(0)
    };
    Ok(Pair {
        stem: "ch4-squared-distance",
        right: render(sd_sphere),
        wrong: render(sd_sphere_wrong),
    })
}
