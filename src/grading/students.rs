//! The student's functions as the checks call them: [`Students`] names
//! the exercise functions with raystep's own types, and [`checks`]
//! gives each exercise's check called on them through [`bridge::call`],
//! which records each call in the student's process and replays it in the
//! grader's (see [`bridge`]).
//!
//! The student's process implements [`Students`] with the student's code
//! (the `raystep-grade-child` crate the grader writes: see
//! [`crate::build`]); the grader uses [`Replayed`], whose
//! functions are never called, since a replay answers from the transcript.

use glam::{Mat4, Vec2, Vec3};

use crate::bridge::{self, no_callbacks, Side};
use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;
use crate::ch4_implicit_surfaces::march::March;
use crate::ch6_global_illumination::layers::LAYER_SLOTS;
use crate::counted::ReadableBvh;
use crate::exercise::Check;
use crate::exercises::bounce_layers::Gathered;
use crate::exercises::{bounce_layers, ch1, ch2, ch3, ch4, ch5, ch6, paths, refraction};
use crate::wire::{apply, changes, fingerprint, from_bytes, to_bytes, Wire};
use crate::work::{self, Work};

/// The exercise functions, with the grader's types.
#[allow(missing_docs, clippy::too_many_arguments)]
pub trait Students {
    fn project_point(p: Vec3) -> Option<Vec2>;
    fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4;
    fn draw_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)>;
    fn edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32;
    fn barycentric(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3>;
    fn depth_test(depth: &mut [f32], index: usize, z: f32) -> bool;
    fn rasterize_triangle(
        v: [Vec3; 3],
        colors: [Vec3; 3],
        width: u32,
        height: u32,
        depth: &mut [f32],
        image: &mut [Vec3],
    );
    fn manifold_counts(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize);
    fn ray_plane(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32>;
    fn barycentric_inside(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)>;
    fn moller_trumbore(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)>;
    fn closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit>;
    fn sah_split(boxes: &[[Vec3; 2]], centroids: &[Vec3]) -> Option<(usize, f32)>;
    fn sphere_sdf(p: Vec3, center: Vec3, radius: f32) -> f32;
    fn sphere_trace(
        sdf: &dyn Fn(Vec3) -> f32,
        origin: Vec3,
        dir: Vec3,
        epsilon: f32,
        max_steps: u32,
        max_distance: f32,
    ) -> Option<f32>;
    fn gradient_normal(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3;
    fn trace_scene(
        sdf: &dyn Fn(Vec3) -> f32,
        origin: Vec3,
        dir: Vec3,
        march: &March,
    ) -> Option<(f32, Vec3)>;
    fn lambert_brdf(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3;
    fn cosine_hemisphere(u: Vec2) -> (Vec3, f32);
    fn point_light_irradiance(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3;
    fn area_to_solid_angle(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32;
    fn solid_angle(p: Vec3, tri: [Vec3; 3]) -> f32;
    fn spot_power(intensity: Vec3, inner: f32, outer: f32) -> Vec3;
    fn direct_light(
        p: Vec3,
        n: Vec3,
        rho: Vec3,
        y: Vec3,
        n_light: Vec3,
        area: f32,
        le: Vec3,
        visible: &dyn Fn(Vec3, Vec3) -> bool,
    ) -> Vec3;
    fn mc_integral(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64;
    fn russian_roulette(value: f64, q: f64, u: f64) -> f64;
    fn mis_weight(pdf_f: f64, pdf_g: f64) -> f64;
    fn path_radiance(
        scene: &paths::PathScene,
        origin: Vec3,
        dir: Vec3,
        rng: &mut dyn FnMut() -> f32,
    ) -> Vec3;
    fn refract(d: Vec3, n: Vec3, eta_outside: f32, eta_inside: f32) -> Option<(Vec3, f32)>;
    fn bounce_layers(path: &[Gathered]) -> [Vec3; LAYER_SLOTS];
}

/// The grader's side: a replay never calls the student's functions.
pub struct Replayed;

macro_rules! replayed {
    ($($name:ident($($arg:ident: $t:ty),*) $(-> $r:ty)?;)*) => {
        impl Students for Replayed {
            $(fn $name($($arg: $t),*) $(-> $r)? {
                $(let _ = $arg;)*
                unreachable!("a replay answers from the transcript")
            })*
        }
    };
}

replayed! {
    project_point(p: Vec3) -> Option<Vec2>;
    look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4;
    draw_edges(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)>;
    edge_function(a: Vec2, b: Vec2, p: Vec2) -> f32;
    barycentric(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3>;
    depth_test(depth: &mut [f32], index: usize, z: f32) -> bool;
    rasterize_triangle(v: [Vec3; 3], colors: [Vec3; 3], width: u32, height: u32, depth: &mut [f32], image: &mut [Vec3]);
    manifold_counts(triangles: &[[u32; 3]]) -> (usize, usize, usize, usize);
    ray_plane(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32>;
    barycentric_inside(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)>;
    moller_trumbore(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)>;
    closest_hit(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit>;
    sah_split(boxes: &[[Vec3; 2]], centroids: &[Vec3]) -> Option<(usize, f32)>;
    sphere_sdf(p: Vec3, center: Vec3, radius: f32) -> f32;
    sphere_trace(sdf: &dyn Fn(Vec3) -> f32, origin: Vec3, dir: Vec3, epsilon: f32, max_steps: u32, max_distance: f32) -> Option<f32>;
    gradient_normal(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3;
    trace_scene(sdf: &dyn Fn(Vec3) -> f32, origin: Vec3, dir: Vec3, march: &March) -> Option<(f32, Vec3)>;
    lambert_brdf(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3;
    cosine_hemisphere(u: Vec2) -> (Vec3, f32);
    point_light_irradiance(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3;
    area_to_solid_angle(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32;
    solid_angle(p: Vec3, tri: [Vec3; 3]) -> f32;
    spot_power(intensity: Vec3, inner: f32, outer: f32) -> Vec3;
    direct_light(p: Vec3, n: Vec3, rho: Vec3, y: Vec3, n_light: Vec3, area: f32, le: Vec3, visible: &dyn Fn(Vec3, Vec3) -> bool) -> Vec3;
    mc_integral(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64;
    russian_roulette(value: f64, q: f64, u: f64) -> f64;
    mis_weight(pdf_f: f64, pdf_g: f64) -> f64;
    path_radiance(scene: &paths::PathScene, origin: Vec3, dir: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3;
    refract(d: Vec3, n: Vec3, eta_outside: f32, eta_inside: f32) -> Option<(Vec3, f32)>;
    bounce_layers(path: &[Gathered]) -> [Vec3; LAYER_SLOTS];
}

/// A call with nothing but arguments and an answer.
fn pure<R: Wire>(args: &impl Wire, run: impl FnOnce() -> R) -> R {
    bridge::call(args, Side::none(), &mut no_callbacks, run)
}

/// A call whose one callback (slot 0) takes an `A` and answers an `R`.
fn with_callback<A: Wire, C: Wire, R: Wire>(
    args: &impl Wire,
    grader: &dyn Fn(A) -> C,
    run: impl FnOnce() -> R,
) -> R {
    let mut replay = |slot: u8, arg: &[u8]| -> Option<Vec<u8>> {
        (slot == 0).then_some(())?;
        Some(to_bytes(&grader(from_bytes::<A>(arg)?)))
    };
    bridge::call(args, Side::none(), &mut replay, run)
}

fn depth_test<S: Students>(depth: &mut [f32], index: usize, z: f32) -> bool {
    let args = (fingerprint(depth), index, z);
    let before = depth.to_vec();
    let (passed, changed) = pure(&args, || {
        let passed = S::depth_test(depth, index, z);
        (passed, changes(&before, depth))
    });
    if !apply(depth, &changed) {
        bridge::mismatch("a changed entry lies outside the buffer");
    }
    passed
}

fn rasterize<S: Students>(
    v: [Vec3; 3],
    colors: [Vec3; 3],
    width: u32,
    height: u32,
    depth: &mut [f32],
    image: &mut [Vec3],
) {
    let args = (
        v,
        colors,
        width,
        height,
        fingerprint(depth),
        fingerprint(image),
    );
    let (depth_before, image_before) = (depth.to_vec(), image.to_vec());
    let (dz, dc) = pure(&args, || {
        S::rasterize_triangle(v, colors, width, height, depth, image);
        (changes(&depth_before, depth), changes(&image_before, image))
    });
    if !(apply(depth, &dz) && apply(image, &dc)) {
        bridge::mismatch("a changed entry lies outside the buffer");
    }
}

fn closest_hit<S: Students>(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    let args = (ray.origin, ray.dir, t_max, bvh.nodes.len(), bvh.tris.len());
    let before = Work::now();
    let side = Side {
        record: Box::new(move || {
            let w = Work::now().since(before);
            to_bytes(&(w.box_tests, w.triangle_tests, w.shrinks, w.last_t_max()))
        }),
        replay: Box::new(|bytes| match from_bytes::<(u64, u64, u64, f32)>(bytes) {
            Some((box_tests, triangle_tests, shrinks, last_t_max)) => {
                work::credit(Work::counted(
                    box_tests,
                    triangle_tests,
                    shrinks,
                    last_t_max,
                ));
                true
            }
            None => false,
        }),
    };
    bridge::call(&args, side, &mut no_callbacks, || {
        S::closest_hit(bvh, ray, t_max)
    })
}

fn path_radiance<S: Students>(
    scene: &paths::PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    let side = Side {
        record: Box::new(|| to_bytes(&(paths::tally(), scene.ran_away()))),
        replay: Box::new(|bytes| match from_bytes::<(paths::Tally, bool)>(bytes) {
            Some((tally, ran_away)) => {
                paths::set_tally(tally);
                scene.note_ran_away(ran_away);
                true
            }
            None => false,
        }),
    };
    // The random numbers are the check's own, made afresh for each call
    // from (seed, path, dimension): a replay need not draw them again.
    bridge::call(&(origin, dir), side, &mut no_callbacks, || {
        S::path_radiance(scene, origin, dir, rng)
    })
}

/// One exercise's check, called on the functions of `S`.
pub type Entry = (&'static str, fn() -> Check);

/// Every exercise's check on the functions of `S`, by id (`chN/name`).
pub fn checks<S: Students>() -> Vec<Entry> {
    vec![
        ("ch1/project_point", || {
            ch1::check_project_point(|p| pure(&p, || S::project_point(p)))
        }),
        ("ch1/look_at", || {
            ch1::check_look_at(|e, t, u| pure(&(e, t, u), || S::look_at(e, t, u)))
        }),
        ("ch1/draw_edges", || {
            ch1::check_draw_edges(|c, a, b, near| {
                let args = (c.camera_from_world, c.width, c.height, a, b, near);
                pure(&args, || S::draw_edges(c, a, b, near))
            })
        }),
        ("ch2/edge_function", || {
            ch2::check_edge_function(|a, b, p| pure(&(a, b, p), || S::edge_function(a, b, p)))
        }),
        ("ch2/barycentric", || {
            ch2::check_barycentric(|i, j, k, p| pure(&(i, j, k, p), || S::barycentric(i, j, k, p)))
        }),
        ("ch2/depth_test", || ch2::check_depth_test(depth_test::<S>)),
        ("ch2/rasterize_triangle", || {
            ch2::check_rasterize_triangle(rasterize::<S>)
        }),
        ("ch2/manifold", || {
            ch2::check_manifold(|t| pure(&t.to_vec(), || S::manifold_counts(t)))
        }),
        ("ch3/ray_plane", || {
            ch3::check_ray_plane(|o, d, n, c| pure(&(o, d, n, c), || S::ray_plane(o, d, n, c)))
        }),
        ("ch3/barycentric_inside", || {
            ch3::check_barycentric_inside(|p, t| pure(&(p, t), || S::barycentric_inside(p, t)))
        }),
        ("ch3/moller_trumbore", || {
            ch3::check_moller_trumbore(|o, d, t| pure(&(o, d, t), || S::moller_trumbore(o, d, t)))
        }),
        ("ch3/bvh_traversal", || {
            ch3::check_bvh_traversal(closest_hit::<S>)
        }),
        ("ch3/sah", || {
            // The node's boxes and centroids by their bits' hash: a node
            // holds up to the whole scene.
            ch3::check_sah(|b, c| {
                let args = (b.len(), fingerprint(b.as_flattened()), fingerprint(c));
                pure(&args, || S::sah_split(b, c))
            })
        }),
        ("ch4/sphere_sdf", || {
            ch4::check_sphere_sdf(|p, c, r| pure(&(p, c, r), || S::sphere_sdf(p, c, r)))
        }),
        ("ch4/sphere_trace", || {
            ch4::check_sphere_trace(|sdf, o, d, eps, steps, far| {
                with_callback(&(o, d, eps, steps, far), &|p: Vec3| sdf(p), || {
                    let counted = |p: Vec3| bridge::callback(0, p, |p| sdf(*p));
                    S::sphere_trace(&counted, o, d, eps, steps, far)
                })
            })
        }),
        ("ch4/gradient_normal", || {
            ch4::check_gradient_normal(|sdf, p, h| {
                with_callback(&(p, h), &|q: Vec3| sdf(q), || {
                    let counted = |q: Vec3| bridge::callback(0, q, |q| sdf(*q));
                    S::gradient_normal(&counted, p, h)
                })
            })
        }),
        ("ch4/trace_scene", || {
            ch4::check_trace_scene(|sdf, o, d, m| {
                let args = (o, d, m.epsilon, m.max_steps, m.max_distance, m.step_factor);
                with_callback(&args, &|p: Vec3| sdf(p), || {
                    let counted = |p: Vec3| bridge::callback(0, p, |p| sdf(*p));
                    S::trace_scene(&counted, o, d, m)
                })
            })
        }),
        ("ch5/lambert_brdf", || {
            ch5::check_lambert_brdf(|r, o, i| pure(&(r, o, i), || S::lambert_brdf(r, o, i)))
        }),
        ("ch5/cosine_hemisphere", || {
            ch5::check_cosine_hemisphere(|u| pure(&u, || S::cosine_hemisphere(u)))
        }),
        ("ch5/point_light", || {
            ch5::check_point_light(|i, l, p, n| {
                pure(&(i, l, p, n), || S::point_light_irradiance(i, l, p, n))
            })
        }),
        ("ch5/area_pdf", || {
            ch5::check_area_pdf(|a, x, y, n| {
                pure(&(a, x, y, n), || S::area_to_solid_angle(a, x, y, n))
            })
        }),
        ("ch5/solid_angle", || {
            ch5::check_solid_angle(|p, t| pure(&(p, t), || S::solid_angle(p, t)))
        }),
        ("ch5/spot", || {
            ch5::check_spot(|i, a, b| pure(&(i, a, b), || S::spot_power(i, a, b)))
        }),
        ("ch5/direct_light", || {
            ch5::check_direct_light(|p, n, rho, y, nl, area, le, visible| {
                let args = ((p, n, rho, y, nl), area, le);
                let grader = |(a, b): (Vec3, Vec3)| visible(a, b);
                with_callback(&args, &grader, || {
                    let counted =
                        |a: Vec3, b: Vec3| bridge::callback(0, (a, b), |(a, b)| visible(*a, *b));
                    S::direct_light(p, n, rho, y, nl, area, le, &counted)
                })
            })
        }),
        ("ch6/mc_integral", || {
            ch6::check_mc_integral(|f, a, b, u| {
                with_callback(&(a, b, u.to_vec()), &|x: f64| f(x), || {
                    let counted = |x: f64| bridge::callback(0, x, |x| f(*x));
                    S::mc_integral(&counted, a, b, u)
                })
            })
        }),
        ("ch6/russian_roulette", || {
            ch6::check_russian_roulette(|v, q, u| pure(&(v, q, u), || S::russian_roulette(v, q, u)))
        }),
        ("ch6/mis_weight", || {
            ch6::check_mis_weight(|f, g| pure(&(f, g), || S::mis_weight(f, g)))
        }),
        ("ch6/path_radiance", || {
            paths::check_path_radiance(path_radiance::<S>)
        }),
        ("ch6/refraction", || {
            refraction::check_refraction(|d, n, o, i| {
                pure(&(d, n, o, i), || S::refract(d, n, o, i))
            })
        }),
        ("ch6/bounce_layers", || {
            bounce_layers::check_bounce_layers(|p| pure(&p.to_vec(), || S::bounce_layers(p)))
        }),
    ]
}

/// The check of exercise `id` on the functions of `S`.
pub fn check<S: Students>(id: &str) -> Option<fn() -> Check> {
    checks::<S>()
        .into_iter()
        .find(|(i, _)| *i == id)
        .map(|e| e.1)
}

/// Exercise 5.2's directions as the warp view tests them
/// ([`crate::core::warp_test`]): the student's `cosine_hemisphere`
/// through the bridge.
pub fn warp_sample<S: Students>(u: Vec2) -> Option<Vec3> {
    Some(pure(&u, || S::cosine_hemisphere(u)).0)
}
