//! Chapter 6's capstone: the path loop with next-event estimation and
//! Russian roulette, written by the student against a small scene
//! interface ([`PathScene`]: hits, light samples, shadow rays, cosine
//! directions) over chapter 5's world, and graded by rendering the Cornell
//! box with the student's loop and with the reference, compared block by
//! block with z-tests.

use std::f32::consts::FRAC_1_PI;

use glam::{Vec2, Vec3};

use super::images;
use crate::ch1_projection::camera::Camera;
use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::material::Frame;
use crate::ch5_reflection::warp::cosine_hemisphere;
use crate::ch5_reflection::world::World;
use crate::core::sampling::random;
use crate::grading::exercise::Check;

/// Where a path meets a surface (every surface of the capstone's scene is
/// Lambertian).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The point.
    pub p: Vec3,
    /// The unit normal, turned to face where the path came from.
    pub n: Vec3,
    /// The albedo ρ (the BRDF is ρ/π).
    pub albedo: Vec3,
    /// The radiance the surface emits back along the path (W/(m²·sr)).
    pub emitted: Vec3,
}

/// A point drawn on a light, seen from a hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Unit direction from the hit towards the light point.
    pub wi: Vec3,
    /// Distance to the light point.
    pub dist: f32,
    /// Radiance arriving along `wi` if nothing blocks it.
    pub le: Vec3,
    /// Density of `wi` per steradian.
    pub pdf: f32,
}

/// What a path may ask of the scene.
pub struct PathScene {
    world: World,
}

impl PathScene {
    /// The scene of `scene` (its first light is the one sampled).
    pub fn new(scene: &crate::scene::Scene) -> PathScene {
        PathScene {
            world: World::new(scene),
        }
    }

    fn hit_of(&self, ray: &Ray) -> Option<Hit> {
        let it = self.world.intersect(ray)?;
        let n = if it.n.dot(ray.dir) > 0.0 { -it.n } else { it.n };
        Some(Hit {
            p: it.p,
            n,
            albedo: self.world.materials[it.material].reflectance,
            emitted: self.world.emitted(&it, -ray.dir),
        })
    }

    /// The first surface along a camera ray.
    pub fn first_hit(&self, origin: Vec3, dir: Vec3) -> Option<Hit> {
        self.hit_of(&Ray::new(origin, dir).ok()?)
    }

    /// The next surface when the path leaves `at` along the unit `wi`.
    pub fn next_hit(&self, at: &Hit, wi: Vec3) -> Option<Hit> {
        self.hit_of(&self.world.spawn(at.p, at.n, wi)?)
    }

    /// A point on the light drawn from the two numbers `u` (in [0, 1)),
    /// as a direction from `at` with its solid-angle density; `None` when
    /// the light cannot be seen from that side.
    pub fn sample_light(&self, at: &Hit, u: Vec2) -> Option<LightSample> {
        let light = self.world.lights.lights.first()?;
        let s = light.sample_li(at.p, at.n, u)?;
        Some(LightSample {
            wi: s.wi,
            dist: s.dist,
            le: s.li,
            pdf: s.pdf,
        })
    }

    /// Whether a shadow ray from `at` along `wi` reaches `dist` unblocked.
    pub fn unoccluded(&self, at: &Hit, wi: Vec3, dist: f32) -> bool {
        self.world.unoccluded(at.p, at.n, wi, dist)
    }

    /// A direction about `at.n` with density cos θ / π, from `u`: the
    /// direction and its density.
    pub fn sample_cosine(&self, at: &Hit, u: Vec2) -> (Vec3, f32) {
        let local = cosine_hemisphere(u);
        (
            Frame::from_normal(at.n).to_world(local),
            local.z * FRAC_1_PI,
        )
    }
}

/// The capstone's candidate: a camera ray to the radiance along it.
pub type PathFn = fn(&PathScene, Vec3, Vec3, &mut dyn FnMut() -> f32) -> Vec3;

/// raystep's answer: emission seen by the camera, then at every hit one
/// light sample (NEE) and one cosine-sampled bounce, Russian roulette from
/// the second bounce on with q = min(max throughput, 0.95).
pub fn reference_path(
    scene: &PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    let mut radiance = hit.emitted;
    let mut beta = Vec3::ONE;
    let mut bounce = 0;
    loop {
        let f = hit.albedo * FRAC_1_PI;
        let u = Vec2::new(rng(), rng());
        if let Some(ls) = scene.sample_light(&hit, u) {
            let cos = hit.n.dot(ls.wi);
            if cos > 0.0 && ls.pdf > 0.0 && scene.unoccluded(&hit, ls.wi, ls.dist) {
                radiance += beta * f * ls.le * cos / ls.pdf;
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
            beta /= q;
        }
        match scene.next_hit(&hit, wi) {
            // Emission found by the bounce is not added: the light sample
            // has counted it.
            Some(next) => hit = next,
            None => break,
        }
    }
    radiance
}

/// The capstone: the Cornell box (`cornell-box.toml`, 32 × 32, one ray
/// through each pixel centre), 64 paths per pixel with the candidate's
/// loop and, with other random numbers, with the reference; 8 × 8-pixel
/// blocks must agree within 5 standard errors.
pub fn check_path_radiance(f: PathFn) -> Check {
    let scene = images::scene("cornell-box.toml");
    let camera = Camera::of(&scene)
        .with_resolution(32, 32)
        .expect("a valid camera");
    let paths = PathScene::new(&scene);
    let (w, h) = (camera.width, camera.height);
    let (paths, camera) = (&paths, &camera);
    let shade = |g: PathFn, seed: u64| {
        move |x: u32, y: u32, s: u32| -> Vec3 {
            let ray = camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
            let pixel = (y * w + x) as u64;
            let mut dim = 0u64;
            let mut rng = || {
                dim += 1;
                random(seed, pixel, s as u64, dim).min(1.0 - f32::EPSILON)
            };
            if x == 0 && s == 0 {
                crate::grading::progress(format_args!(
                    "calling path_radiance for the camera rays of row {y} of {h}"
                ));
            }
            g(paths, ray.origin, ray.dir, &mut rng)
        }
    };
    let student = images::Estimate::gather(w, h, 64, &shade(f, 601));
    let reference = images::Estimate::gather(w, h, 64, &shade(reference_path, 602));
    images::z_test(student, reference, 8, 5.0, "radiance")
}
