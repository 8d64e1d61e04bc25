//! Chapter 6's capstone: the path loop with next-event estimation and
//! Russian roulette, written by the student against a small scene
//! interface ([`PathScene`]: hits, light samples, shadow rays, cosine
//! directions) and graded ([`check_path_radiance`]) in a closed furnace
//! with a known answer (nothing escapes there, so only roulette ends a
//! path) and in the Cornell box against the reference.
//!
//! The scene counts what a path asks of it ([`Tally`], per thread, reset
//! by the check before each call): the check reads from it whether the
//! loop samples a light at every surface, casts its shadow rays, bounces
//! above the surface, and ends at all.

use std::cell::Cell;
use std::f32::consts::FRAC_1_PI;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

use glam::{Vec2, Vec3};

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch5_reflection::material::Frame;
use crate::ch5_reflection::warp::cosine_hemisphere;
use crate::ch5_reflection::world::World;

mod bright;
mod capstone;
mod check;
mod cornell;
mod furnace;
mod numbers;
mod open;

pub use capstone::check_path_radiance;
pub use check::*;
pub(crate) use cornell::camera_sample;
use furnace::Furnace;
use numbers::quarter;
pub use open::LIGHT_THROUGH_OCCLUDER;

/// Where a path meets a surface (every surface of the capstone's scenes is
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

/// A point drawn on a light, seen from a hit: chapter 5's light sample
/// (`wi`, its distance `dist`, the radiance `li` arriving along it, its
/// density `pdf` per steradian; `delta` is always false here).
pub use crate::ch5_reflection::light::LightSample;

/// A path may go this many bounces (calls of [`PathScene::next_hit`]);
/// the next call ends it and marks the loop as never ending. With Russian
/// roulette that survives with probability at most 0.95 per bounce, a path
/// this long has probability 0.95¹⁰⁰⁰ ≈ 5·10⁻²³.
pub const BOUNCE_BUDGET: u32 = 1000;

/// What the paths of one call asked of the scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Calls of `next_hit`.
    pub bounces: u32,
    /// Surfaces reached (`first_hit` and `next_hit` returning one).
    pub vertices: u32,
    /// Calls of `sample_light`.
    pub light_samples: u32,
    /// Light samples returned (the light could be seen from that side).
    pub lights_found: u32,
    /// Of those, the ones that could light the surface (cos > 0 at it, a
    /// positive density and radiance, an albedo not black): each needs
    /// its shadow ray before it counts.
    pub lights_useful: u32,
    /// Calls of `unoccluded`.
    pub shadow_rays: u32,
    /// Bounces along a direction on the far side of the surface.
    pub below: u32,
    /// Whether a path ran into [`BOUNCE_BUDGET`].
    pub over_budget: bool,
    /// The numbers handed to `sample_cosine`, by quarter of [0, 1): u.x's,
    /// then u.y's (a number outside [0, 1) in the first or last).
    pub cosine_quarters: [[u32; 4]; 2],
    /// Light samples drawn from the very numbers of the bounce that
    /// reached their surface (the light point then depends on where the
    /// surface is: biased).
    pub light_from_bounce_numbers: u32,
    /// Of the numbers counted in `cosine_quarters`, those whose direction
    /// the path went on along (`next_hit` followed): whether a path goes
    /// on must not depend on the numbers its direction was drawn from.
    pub cosine_went_on: [[u32; 4]; 2],
    /// The numbers handed to `sample_light`, by cell of a 4 × 4 grid over
    /// [0, 1)² (4 · u.x's quarter + u.y's; a number outside [0, 1) in the
    /// first or last quarter): a light point is where the light's own
    /// density says only if both numbers are uniform and independent.
    pub light_cells: [u32; 16],
}

thread_local! {
    static TALLY: Cell<Tally> = const { Cell::new(Tally {
        bounces: 0, vertices: 0, light_samples: 0, lights_found: 0, lights_useful: 0,
        shadow_rays: 0, below: 0, over_budget: false, cosine_quarters: [[0; 4]; 2],
        light_from_bounce_numbers: 0, cosine_went_on: [[0; 4]; 2], light_cells: [0; 16],
    }) };
    /// The quarters of [0, 1) of this thread's last `sample_cosine`'s
    /// numbers, until a `next_hit` goes on from it.
    static PENDING_BOUNCE: Cell<Option<[usize; 2]>> = const { Cell::new(None) };
    /// The numbers and the surface point of this thread's last
    /// `sample_cosine`, as bits.
    static LAST_BOUNCE: Cell<Option<([u32; 2], [u32; 3])>> = const { Cell::new(None) };
}

/// Path `i` of a furnace run drawn from `seed`: its direction from
/// [`FURNACE_ORIGIN`] (uniform over the sphere), and its random numbers.
pub(super) fn furnace_path(seed: u64, i: u64) -> (Vec3, impl FnMut() -> f32) {
    use crate::core::sampling::random;
    let (u, v) = (random(seed, i, 0, 0), random(seed, i, 0, 1));
    let z = 1.0 - 2.0 * u;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = std::f32::consts::TAU * v;
    let mut dim = 1u64;
    let numbers = move || {
        dim += 1;
        random(seed, i, 0, dim).min(1.0 - f32::EPSILON)
    };
    (Vec3::new(r * phi.cos(), r * phi.sin(), z), numbers)
}

/// Where the furnace's camera rays start (any point inside sees the same).
pub(super) const FURNACE_ORIGIN: Vec3 = Vec3::new(0.3, -0.2, 0.1);

/// Starts a fresh [`Tally`] on this thread.
pub fn reset_tally() {
    TALLY.with(|t| t.set(Tally::default()));
    LAST_BOUNCE.with(|b| b.set(None));
    PENDING_BOUNCE.with(|b| b.set(None));
}

/// This thread's [`Tally`] since the last [`reset_tally`].
pub fn tally() -> Tally {
    TALLY.with(|t| t.get())
}

/// Sets this thread's tally to what a student's process counted (the
/// grader's replay of its transcript).
pub(crate) fn set_tally(tally: Tally) {
    TALLY.with(|t| t.set(tally));
}

fn count(f: impl FnOnce(&mut Tally)) {
    TALLY.with(|t| {
        let mut v = t.get();
        f(&mut v);
        t.set(v);
    });
}

enum Inner {
    World(Box<World>),
    Furnace(Furnace),
}

/// What a path may ask of the scene.
pub struct PathScene {
    inner: Inner,
    /// Set once a path ran into [`BOUNCE_BUDGET`]: every later path then
    /// finds nothing, so that a loop without an end fails fast.
    ran_away: AtomicBool,
    /// Light samples that could light their surface and were counted, or
    /// dropped, without a shadow ray, over every path so far.
    unshadowed: AtomicU64,
}

/// The scene's building blocks run raystep's own code (lights, sampling,
/// tracing) for the student's `path_radiance`; the student's crate sees
/// only these methods, not the code behind them.
impl PathScene {
    /// The scene of `scene` (its first light is the one sampled).
    pub fn new(scene: &crate::scene::Scene) -> PathScene {
        PathScene::of(Inner::World(Box::new(World::new(scene))))
    }

    /// The closed furnace: the inside of a sphere of radius 1 about the
    /// origin, every point of it Lambertian with albedo `albedo` and
    /// emitting `le`, all of it one light. Every ray from inside sees
    /// le / (1 − albedo) per channel.
    pub fn furnace(albedo: f32, le: Vec3) -> PathScene {
        PathScene::furnace_coloured(Vec3::splat(albedo), le)
    }

    /// [`PathScene::furnace`] with an albedo per channel.
    pub fn furnace_coloured(albedo: Vec3, le: Vec3) -> PathScene {
        PathScene::of(Inner::Furnace(Furnace::new(albedo, le)))
    }

    /// The furnace as a diagnostic: surfaces reached by a bounce report
    /// no emission (a loop that counts emission only where the camera sees
    /// it gives the same answer as in [`PathScene::furnace`]).
    pub fn furnace_without_bounce_emission(albedo: f32, le: Vec3) -> PathScene {
        PathScene::of(Inner::Furnace(Furnace {
            hide_bounce_emission: true,
            ..Furnace::new(Vec3::splat(albedo), le)
        }))
    }

    /// The furnace as a diagnostic: its light sampler finds no sample
    /// (`None`) for an eighth of its numbers, and the others' density
    /// carries that eighth (a loop that adds nothing where there is no
    /// sample gives the same answer as in [`PathScene::furnace`]).
    pub fn furnace_with_missing_light_samples(albedo: f32, le: Vec3) -> PathScene {
        PathScene::of(Inner::Furnace(Furnace {
            no_sample: 0.125,
            ..Furnace::new(Vec3::splat(albedo), le)
        }))
    }

    /// The furnace as a diagnostic: its light samples come with their
    /// radiance and their density both `scale` times the furnace's (a
    /// light as faint as it is rarely sampled: the same light per sample,
    /// and a loop that uses the density it is given gives the same answer
    /// as in [`PathScene::furnace`]).
    pub fn furnace_with_faint_light(albedo: f32, le: Vec3, scale: f32) -> PathScene {
        PathScene::of(Inner::Furnace(Furnace {
            light_scale: scale,
            ..Furnace::new(Vec3::splat(albedo), le)
        }))
    }

    fn of(inner: Inner) -> PathScene {
        PathScene {
            inner,
            ran_away: AtomicBool::new(false),
            unshadowed: AtomicU64::new(0),
        }
    }

    /// Whether a path ran into [`BOUNCE_BUDGET`] in this scene.
    pub fn ran_away(&self) -> bool {
        self.ran_away.load(Ordering::Relaxed)
    }

    /// Marks the scene as run away when a student's process saw it so
    /// (the grader's replay of its transcript).
    pub(crate) fn note_ran_away(&self, ran_away: bool) {
        self.ran_away.fetch_or(ran_away, Ordering::Relaxed);
    }

    /// Adds what one path's tally says: its light samples that could
    /// light their surface, less its shadow rays.
    pub(crate) fn note_shadow_rays(&self, t: &Tally) {
        let short = t.lights_useful.saturating_sub(t.shadow_rays);
        self.unshadowed
            .fetch_add(u64::from(short), Ordering::Relaxed);
    }

    /// Light samples that could light their surface, over every path so
    /// far, beyond the shadow rays cast.
    pub fn unshadowed(&self) -> u64 {
        self.unshadowed.load(Ordering::Relaxed)
    }

    fn world_hit(world: &World, ray: &Ray) -> Option<Hit> {
        let it = world.intersect(ray)?;
        let n = if it.n.dot(ray.dir) > 0.0 { -it.n } else { it.n };
        Some(Hit {
            p: it.p,
            n,
            albedo: world.materials[it.material].reflectance,
            emitted: world.emitted(&it, -ray.dir),
        })
    }

    fn found(hit: Option<Hit>) -> Option<Hit> {
        if hit.is_some() {
            count(|t| t.vertices += 1);
        }
        hit
    }

    /// The first surface along a camera ray.
    pub fn first_hit(&self, origin: Vec3, dir: Vec3) -> Option<Hit> {
        if self.ran_away() {
            return None;
        }
        let hit = match &self.inner {
            Inner::World(w) => Ray::new(origin, dir)
                .ok()
                .and_then(|r| Self::world_hit(w, &r)),
            Inner::Furnace(f) => dir.try_normalize().and_then(|d| f.hit(origin, d)),
        };
        Self::found(hit)
    }

    /// The next surface when the path leaves `at` along the unit `wi`.
    pub fn next_hit(&self, at: &Hit, wi: Vec3) -> Option<Hit> {
        let mut over = false;
        let went_on = PENDING_BOUNCE.with(|b| b.take());
        count(|t| {
            if let Some([x, y]) = went_on {
                t.cosine_went_on[0][x] += 1;
                t.cosine_went_on[1][y] += 1;
            }
            t.bounces += 1;
            let c = wi.dot(at.n);
            t.below += u32::from(c.is_nan() || c <= 0.0);
            over = t.bounces > BOUNCE_BUDGET;
            t.over_budget |= over;
        });
        if over || self.ran_away() {
            self.ran_away.fetch_or(over, Ordering::Relaxed);
            return None;
        }
        let hit = match &self.inner {
            Inner::World(w) => w.spawn(at.p, at.n, wi).and_then(|r| Self::world_hit(w, &r)),
            Inner::Furnace(f) => f.next(at, wi),
        };
        Self::found(hit)
    }

    /// A point on the light drawn from the two numbers `u` (in [0, 1)),
    /// as a direction from `at` with its solid-angle density; `None`: no
    /// sample (the light cannot be seen from that side, or, in one of the
    /// check's furnaces, the sampler found none).
    pub fn sample_light(&self, at: &Hit, u: Vec2) -> Option<LightSample> {
        count(|t| {
            t.light_samples += 1;
            t.light_cells[4 * quarter(u.x) + quarter(u.y)] += 1;
        });
        let bits = (
            u.to_array().map(f32::to_bits),
            at.p.to_array().map(f32::to_bits),
        );
        if LAST_BOUNCE
            .with(|b| b.get())
            .is_some_and(|(v, p)| v == bits.0 && p != bits.1)
        {
            count(|t| t.light_from_bounce_numbers += 1);
        }
        let s = match &self.inner {
            Inner::World(w) => w
                .lights
                .lights
                .first()
                .and_then(|l| l.sample_li(at.p, at.n, u)),
            Inner::Furnace(f) => f.sample_light(at, u),
        };
        if let Some(s) = &s {
            count(|t| t.lights_found += 1);
            let lights = at.n.dot(s.wi) > 0.0 && s.pdf > 0.0 && s.li.max_element() > 0.0;
            if lights && at.albedo.max_element() > 0.0 {
                count(|t| t.lights_useful += 1);
            }
        }
        s
    }

    /// Whether a shadow ray from `at` along `wi` reaches `dist` unblocked.
    pub fn unoccluded(&self, at: &Hit, wi: Vec3, dist: f32) -> bool {
        count(|t| t.shadow_rays += 1);
        match &self.inner {
            Inner::World(w) => w.unoccluded(at.p, at.n, wi, dist),
            // Nothing inside the sphere: every point of it sees every other.
            Inner::Furnace(_) => true,
        }
    }

    /// A direction about `at.n` with density cos θ / π, from `u`: the
    /// direction and its density.
    pub fn sample_cosine(&self, at: &Hit, u: Vec2) -> (Vec3, f32) {
        LAST_BOUNCE.with(|b| {
            b.set(Some((
                u.to_array().map(f32::to_bits),
                at.p.to_array().map(f32::to_bits),
            )))
        });
        PENDING_BOUNCE.with(|b| b.set(Some([quarter(u.x), quarter(u.y)])));
        count(|t| {
            t.cosine_quarters[0][quarter(u.x)] += 1;
            t.cosine_quarters[1][quarter(u.y)] += 1;
        });
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
