//! The wrong pictures of chapters 5 and 6: shadow rays that start on the
//! surface they leave, a Lambertian BRDF without its 1/π, and Russian
//! roulette that does not divide the survivors by q.

use glam::{Vec2, Vec3};
use rayon::prelude::*;
use raystep::ch1_projection::camera::{Camera, CameraDesc};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch3_ray_triangle::spawn::stop_distance;
use raystep::ch5_reflection::material::lambert::Lambertian;
use raystep::ch5_reflection::material::Frame;
use raystep::ch5_reflection::world::World;
use raystep::core::error::Result;
use raystep::core::film::Film;
use raystep::core::sampling::random;
use raystep::grading::exercises::paths::{reference_path, reset_tally, PathFn, PathScene};
use raystep::scene::Scene;

use super::wrong_pair::{scene, Pair};

/// The pairs of chapters 5 and 6.
pub fn pairs() -> Result<Vec<Pair>> {
    let cornell = scene("cornell-box.toml")?;
    let mut pairs = ch5_pairs(&cornell)?;
    pairs.push(ch6_roulette(&cornell)?);
    Ok(pairs)
}

/// The Cornell box's camera at `size` x `size` pixels.
fn camera(scene: &Scene, size: u32) -> Result<Camera> {
    Camera::new(CameraDesc {
        width: size,
        height: size,
        ..scene.camera
    })
}

/// `sample(x, y, s)` averaged over `spp` samples per pixel, rows in
/// parallel.
fn gather(camera: &Camera, spp: u32, sample: &(dyn Fn(u32, u32, u32) -> Vec3 + Sync)) -> Film {
    let (w, h) = (camera.width, camera.height);
    let mut film = Film::new(w, h);
    film.pixels
        .par_chunks_mut(w as usize)
        .enumerate()
        .for_each(|(y, row)| {
            for (x, px) in row.iter_mut().enumerate() {
                let sum: Vec3 = (0..spp).map(|s| sample(x as u32, y as u32, s)).sum();
                *px = sum / spp as f32;
            }
        });
    film
}

// ---------------------------------------------------------------- chapter 5

/// A Lambertian BRDF (local shading frame, normal +z) as a student might
/// write it from "the surface reflects the same in every direction".
fn lambert_f_wrong(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    if wo.z * wi.z > 0.0 {
        // BUG: the 1/π is forgotten. ∫ ρ cos θ dω over the hemisphere is
        // π ρ, so the surface reflects π times more light than arrives.
        rho
    } else {
        Vec3::ZERO
    }
}

/// The lesson's Lambertian BRDF, ρ/π.
fn lambert_f(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    Lambertian { rho }.f(wo, wi)
}

/// Whether nothing blocks the segment from the surface point `p` to the
/// light's point `dist` away along `wi`, as a student might first test it.
fn unoccluded_wrong(world: &World, p: Vec3, wi: Vec3, dist: f32) -> bool {
    // BUG: the shadow ray starts at the hit point itself. The rounded
    // point lies a hair above or below its surface; from below, the ray
    // hits the very surface it leaves, and the point is in its own
    // shadow. (The far end stops short of the light as the lesson's does.)
    let Ok(ray) = Ray::new(p, wi) else {
        return false;
    };
    let t_max = if dist.is_finite() {
        dist - stop_distance(p + wi * dist)
    } else {
        f32::INFINITY
    };
    world.intersect_within(&ray, t_max).is_none()
}

type Brdf = fn(Vec3, Vec3, Vec3) -> Vec3;

/// Direct light only (chapter 5's first rung: one light sample per light
/// and sample, from the first surface each pixel centre sees), with the
/// BRDF `brdf` and the lesson's shadow test or the student's.
fn direct(world: &World, camera: &Camera, spp: u32, brdf: Brdf, student_shadows: bool) -> Film {
    let sample = |x: u32, y: u32, s: u32| -> Vec3 {
        let ray = camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
        let Some(it) = world.intersect(&ray) else {
            return Vec3::ZERO;
        };
        let m = &world.materials[it.material];
        if m.is_emissive() {
            return world.emitted(&it, -ray.dir);
        }
        let n = if it.n.dot(ray.dir) > 0.0 { -it.n } else { it.n };
        let frame = Frame::from_normal(n);
        let wo = frame.to_local(-ray.dir);
        let pixel = (y * camera.width + x) as u64;
        let mut l = Vec3::ZERO;
        for (k, light) in world.lights.lights.iter().enumerate() {
            let u = Vec2::new(
                random(5, pixel, s as u64, 2 * k as u64),
                random(5, pixel, s as u64, 2 * k as u64 + 1),
            );
            let Some(ls) = light.sample_li(it.p, n, u) else {
                continue;
            };
            let cos = n.dot(ls.wi);
            if !(cos > 0.0 && ls.pdf > 0.0) {
                continue;
            }
            let visible = if student_shadows {
                unoccluded_wrong(world, it.p, ls.wi, ls.dist)
            } else {
                world.unoccluded(it.p, n, ls.wi, ls.dist)
            };
            if visible {
                let f = brdf(m.reflectance, wo, frame.to_local(ls.wi));
                l += f * ls.li * cos / ls.pdf;
            }
        }
        l
    };
    gather(camera, spp, &sample)
}

/// Chapter 5: the Cornell box in direct light, right; with shadow rays
/// from the hit point; with the BRDF ρ.
fn ch5_pairs(scene: &Scene) -> Result<Vec<Pair>> {
    let world = World::new(scene);
    let camera = camera(scene, 200)?;
    let spp = 16;
    let right = direct(&world, &camera, spp, lambert_f, false);
    Ok(vec![
        Pair {
            stem: "ch5-shadow-acne",
            right: right.clone(),
            wrong: direct(&world, &camera, spp, lambert_f, true),
        },
        Pair {
            stem: "ch5-lambert-pi",
            right,
            wrong: direct(&world, &camera, spp, lambert_f_wrong, false),
        },
    ])
}

// ---------------------------------------------------------------- chapter 6

/// The capstone's path loop (`reference_path`, the book's loop) with one
/// mistake in its Russian roulette.
fn path_wrong(scene: &PathScene, origin: Vec3, dir: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    let mut radiance = hit.emitted;
    let mut beta = Vec3::ONE;
    let mut bounce = 0;
    loop {
        let f = hit.albedo * std::f32::consts::FRAC_1_PI;
        let u = Vec2::new(rng(), rng());
        if let Some(ls) = scene.sample_light(&hit, u) {
            let cos = hit.n.dot(ls.wi);
            if cos > 0.0 && ls.pdf > 0.0 && scene.unoccluded(&hit, ls.wi, ls.dist) {
                radiance += beta * f * ls.li * cos / ls.pdf;
            }
        }
        let (wi, pdf) = scene.sample_cosine(&hit, Vec2::new(rng(), rng()));
        if pdf <= 0.0 {
            break;
        }
        beta *= f * hit.n.dot(wi) / pdf;
        bounce += 1;
        if bounce >= 2 {
            let q = beta.max_element().min(0.95);
            if rng() >= q {
                break;
            }
            // BUG: the survivor's throughput is not divided by q. Only a
            // fraction q of the paths goes on, and nothing makes up for
            // the ones that ended: every bounce after the second loses
            // a factor q of its light.
        }
        match scene.next_hit(&hit, wi) {
            Some(next) => hit = next,
            None => break,
        }
    }
    radiance
}

/// Chapter 6: the Cornell box path traced with the capstone's loop and
/// with the mistaken roulette, the same random numbers for both.
fn ch6_roulette(scene: &Scene) -> Result<Pair> {
    let camera = camera(scene, 200)?;
    let paths = PathScene::new(scene);
    let render = |g: PathFn| {
        let sample = |x: u32, y: u32, s: u32| -> Vec3 {
            let ray = camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
            let pixel = (y * camera.width + x) as u64;
            let mut dim = 0u64;
            let mut rng = || {
                dim += 1;
                random(6, pixel, s as u64, dim).min(1.0 - f32::EPSILON)
            };
            // The scene counts each path's bounces against its budget.
            reset_tally();
            g(&paths, ray.origin, ray.dir, &mut rng)
        };
        gather(&camera, 64, &sample)
    };
    Ok(Pair {
        stem: "ch6-roulette",
        right: render(reference_path),
        wrong: render(path_wrong),
    })
}
