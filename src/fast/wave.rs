//! The fast engine's path loop: a *wavefront*. Instead of following one
//! path from the camera to its end before starting the next, it starts a
//! few thousand paths at once and extends all of them by one bounce per
//! round:
//!
//! 1. every live path's ray finds its closest hit (the eight-wide tree;
//!    the first round's camera rays eight at a time, [`super::packet`]);
//! 2. the hits are shaded eight at a time ([`shade8`](super::shade8::shade8)): the local frame,
//!    the light sample with its MIS weight, the cosine-weighted next
//!    direction and Russian roulette, each step one pass over eight lanes
//!    with no branch, so the compiler turns it into vector instructions;
//! 3. every shadow ray is traced, and the light it carries added.
//!
//! A round's paths all sit at the same bounce, so they draw the same
//! dimensions of their sampler: eight numbers per path per round
//! ([`PathSampler::eight_at`](crate::ch6_global_illumination::sampler::PathSampler::eight_at)), the very numbers
//! [`trace_path`](crate::ch6_global_illumination::integrator::trace_path)
//! draws one by one.
//!
//! The lanes run the lesson's formulas in the lesson's order, with one
//! exception: the cosine and sine of the disk mapping are polynomials
//! ([`sin_cos_quarter`](super::shade8::sin_cos_quarter)), since the C library's `sincosf` has no
//! eight-lane form. So the images match the readable loop's to a few
//! units in the last place per path, not byte for byte; tests check that
//! and the statistics against the stored references.
//!
//! It covers every triangle scene (the tree holds every surface; a scene
//! with SDFs goes to the lesson's loop, [`supports`]). The lanes shade
//! what the benchmark scenes are made of: diffuse (Lambertian) vertices
//! with MIS (area lights sampled in the lanes, other kinds by the lesson's
//! code, one lane at a time). Every other vertex (glass, a mirror, a
//! glossy or retro-reflective surface, a path whose throughput went
//! through glass, an estimator other than MIS, a light sampled by solid
//! angle) runs the lesson's own steps, one path at a time
//! (`lesson_vertex`): there a path's numbers are the lesson's to the
//! bit.

use glam::{Vec2, Vec3};

use crate::ch3_ray_triangle::ray::Ray;
use crate::ch3_ray_triangle::triangle::Hit;
use crate::ch4_implicit_surfaces::hit::Surface;
use crate::ch5_reflection::direct::Strategy;
use crate::ch5_reflection::light::Light;
use crate::ch5_reflection::material::Bsdf;
use crate::ch5_reflection::world::{Interaction, World};
use crate::ch6_global_illumination::integrator::{
    direct_light, sky_emission, surface_emission, Path, PathOut, PathSettings, PathStats,
};
use crate::ch6_global_illumination::layers::Contributions;
use crate::ch6_global_illumination::vertex::Vertex;
use crate::scene::LightSampling;

use super::bvh8::Bvh8;
use super::gather8::{gather, numbers, Lane};
use super::lanes::W;
use super::level::Level;
use super::shade8::{dim, In8, Out8};
use super::step::{finish, lesson_vertex};

/// Whether the wavefront loop renders `world` as the lesson's loop would
/// (in distribution): a scene without SDFs, whose surfaces the tree holds.
pub fn supports(world: &World) -> bool {
    world.sdfs.is_empty()
}

/// Whether the lanes shade the diffuse vertices of `world` with
/// `settings`: the paths use MIS, and the scene has lights, each one the
/// lanes sample (area lights by area; other kinds by the lesson's code).
/// Otherwise every vertex runs the lesson's steps.
pub fn lanes_shade(world: &World, settings: &PathSettings) -> bool {
    let lights = &world.lights.lights;
    settings.strategy == Strategy::Mis
        && !lights.is_empty()
        && lights.iter().all(|l| match l {
            Light::Area(a) => a.sampling == LightSampling::Area,
            _ => true,
        })
}

/// A round's shadow rays to trace (ray and `t_max`), and beside each the
/// light it carries if nothing blocks it and where that light goes. (A
/// shadow ray whose two ends meet adds its light at once; one without an
/// origin, a surface point that is not finite, is blocked.)
struct Shadows {
    rays: Vec<(Ray, f32)>,
    light: Vec<(u32, Vec3)>,
}

/// What a round of the loop keeps in its queues (allocated once, for as
/// many paths as start).
struct Queues {
    /// The paths still going (indices into `lanes`, which never move), in
    /// order.
    live: Vec<u32>,
    /// What leaves this round: the paths that go on, and shadow rays.
    leaving: Leaving,
    /// The live paths' rays, and the closest hit the tree found for each.
    rays: Vec<Ray>,
    found: Vec<Option<Hit>>,
    /// Which of the round's shadow rays something blocks.
    blocked: Vec<bool>,
}

/// What leaves a round's shading: the paths that go on past it (in
/// order), and its shadow rays.
struct Leaving {
    next: Vec<u32>,
    shadows: Shadows,
}

impl Queues {
    fn new(n: usize) -> Queues {
        Queues {
            live: (0..n as u32).collect(),
            leaving: Leaving {
                next: Vec::with_capacity(n),
                // At most one shadow ray per path per round.
                shadows: Shadows {
                    rays: Vec::with_capacity(n),
                    light: Vec::with_capacity(n),
                },
            },
            rays: Vec::with_capacity(n),
            found: Vec::with_capacity(n),
            blocked: Vec::with_capacity(n),
        }
    }
}

/// One round: the bounce count k of the light its vertices scatter, and
/// what the settings say about it.
#[derive(Clone, Copy)]
struct Round {
    k: u32,
    /// Russian roulette's scale s, where roulette plays at its vertices.
    roulette: Option<u32>,
    /// Whether its paths end at the bounce limit instead (and whether
    /// those count as cut, without `--max-bounces`).
    over_limit: bool,
    count_cut: bool,
}

/// Traces the paths `lanes` (made by
/// [`camera_lanes`](super::starts::camera_lanes)), adding path i's light
/// to `outs[lanes[i].out]` (which must hold one entry per path): one sum,
/// or one per bounce layer. Each round extends every live path by one
/// bounce, in three phases: closest hits, shading, shadow rays. Roulette
/// plays with the scale `rr_scale` (the settings' for the lanes' numbers).
pub(super) fn trace_paths<C: Contributions>(
    world: &World,
    tree: &Bvh8,
    lanes: &mut [Lane],
    (settings, rr_scale): (&PathSettings, u32),
    outs: &mut [C],
    stats: &mut PathStats,
) {
    stats.paths += lanes.len() as u64;
    let mut shade = Shade::new(world, tree.level(), settings);
    let mut q = Queues::new(lanes.len());
    let mut k = 0u32;
    while !q.live.is_empty() {
        let round = Round {
            k,
            roulette: (k + 1 >= settings.rr_min_bounce).then_some(rr_scale),
            over_limit: k > settings.bounce_limit(),
            count_cut: settings.max_bounces.is_none(),
        };
        stats.rays += q.live.len() as u64;
        closest_hits(tree, lanes, k, &mut q);
        shade_hits(&mut shade, lanes, round, &mut q, outs, stats);
        trace_shadows(tree, k, &mut q, outs, stats);
        std::mem::swap(&mut q.live, &mut q.leaving.next);
        k += 1;
    }
}

/// Phase 1: the closest hit of every live path's ray, the first round's
/// camera rays eight at a time (eight samples of a pixel leave together).
fn closest_hits(tree: &Bvh8, lanes: &[Lane], k: u32, q: &mut Queues) {
    q.rays.clear();
    q.rays.extend(q.live.iter().map(|&i| lanes[i as usize].ray));
    match k {
        0 => super::simd::closest_packets(tree, &q.rays, &mut q.found),
        _ => super::simd::closest_all(tree, &q.rays, &mut q.found),
    }
}

/// Phase 2: what each path found (the sky, or a surface and what it
/// emits), the paths that end there, and the rest shaded eight at a time
/// while their hits are near, so each path's light is still added in the
/// lesson's order.
fn shade_hits<C: Contributions>(
    shade: &mut Shade,
    lanes: &mut [Lane],
    round: Round,
    q: &mut Queues,
    outs: &mut [C],
    stats: &mut PathStats,
) {
    let world = shade.world;
    q.leaving.shadows.rays.clear();
    q.leaving.shadows.light.clear();
    q.leaving.next.clear();
    for (&i, hit) in q.live.iter().zip(&q.found) {
        let lane = &mut lanes[i as usize];
        let mut out = PathOut {
            layers: &mut outs[lane.out as usize],
            stats,
        };
        let Some(it) = hit.map(|hit| interaction(world, hit)) else {
            let sky = sky_emission(world, lane.ray.dir, &lane.path);
            out.add_sky(&lane.path, lane.ray.dir, sky);
            continue;
        };
        // Most surfaces emit nothing: no call to find that out.
        let emitted = match shade.emissive[it.material] {
            true => surface_emission(world, &it, -lane.ray.dir, &lane.path),
            false => None,
        };
        out.add_emitted(&lane.path, &it, emitted);
        if round.over_limit {
            out.stats.cut += u64::from(round.count_cut);
            continue;
        }
        if !shade.in_lanes(&it, &lane.path) {
            if lesson_vertex(world, lane, &it, round.k, round.roulette, &mut out) {
                q.leaving.next.push(i);
            }
            continue;
        }
        shade.ids.push(i);
        shade.its.push(it);
        if shade.ids.len() == W {
            shade.eight(lanes, round, &mut q.leaving, outs, stats);
        }
    }
    if !shade.ids.is_empty() {
        shade.eight(lanes, round, &mut q.leaving, outs, stats);
    }
}

/// Phase 3: the round's shadow rays, and the light of those nothing
/// blocks.
fn trace_shadows<C: Contributions>(
    tree: &Bvh8,
    k: u32,
    q: &mut Queues,
    outs: &mut [C],
    stats: &mut PathStats,
) {
    super::simd::occluded_all(tree, &q.leaving.shadows.rays, &mut q.blocked);
    for (&(i, light), _) in q
        .leaving
        .shadows
        .light
        .iter()
        .zip(&q.blocked)
        .filter(|(_, b)| !**b)
    {
        let mut out = PathOut {
            layers: &mut outs[i as usize],
            stats,
        };
        out.add(Some(k), light);
    }
}

/// What shading eight lanes at a time needs besides the lanes: the scene
/// and the lanes' arrays, allocated once.
struct Shade<'a> {
    world: &'a World,
    level: Level,
    input: Box<In8>,
    o: Box<Out8>,
    /// Whether the lanes read the number that chooses a light (dimension 0
    /// of a vertex): not where the scene has one area light.
    choose: bool,
    /// Which materials emit.
    emissive: Vec<bool>,
    /// Which materials the lanes shade: diffuse ones, where the paths use
    /// MIS and every light is one the lanes sample (none where they do
    /// not).
    lanes: Vec<bool>,
    /// The hits of up to eight paths waiting to be shaded together.
    ids: Vec<u32>,
    its: Vec<Interaction>,
}

/// The numbers of a vertex every diffuse path reads: the light sample's
/// two and the next direction's two (bit d for dimension d).
const WANTED: u8 =
    1 << dim::LIGHT[0] | 1 << dim::LIGHT[1] | 1 << dim::DIRECTION[0] | 1 << dim::DIRECTION[1];

impl<'a> Shade<'a> {
    fn new(world: &'a World, level: Level, settings: &PathSettings) -> Shade<'a> {
        let shade_diffuse = lanes_shade(world, settings);
        let lanes = world
            .bsdfs
            .iter()
            .map(|b| shade_diffuse && matches!(b, Bsdf::Lambertian(_)));
        Shade {
            lanes: lanes.collect(),
            world,
            level,
            input: Box::default(),
            o: Box::default(),
            choose: !matches!(world.lights.lights.as_slice(), [Light::Area(_)]),
            emissive: world.materials.iter().map(|m| m.is_emissive()).collect(),
            ids: Vec::with_capacity(W),
            its: Vec::with_capacity(W),
        }
    }

    /// Whether the lanes shade the vertex at `it` of `path`: a diffuse
    /// one (see [`Shade::lanes`]) on a path whose throughput holds no
    /// refraction's scaling (the lanes' roulette reads β alone).
    fn in_lanes(&self, it: &Interaction, path: &Path) -> bool {
        self.lanes[it.material] && path.eta_scale() == 1.0
    }

    /// Shades the waiting lanes `ids` (up to eight) at their hits `its`
    /// and empties that queue: their shadow rays and the paths that go on
    /// (in order) go to `leaving`.
    fn eight<C: Contributions>(
        &mut self,
        lanes: &mut [Lane],
        round: Round,
        leaving: &mut Leaving,
        outs: &mut [C],
        stats: &mut PathStats,
    ) {
        let (world, input, o) = (self.world, &mut *self.input, &mut *self.o);
        let (ids, its) = (&mut self.ids, &mut self.its);
        let Leaving { next, shadows } = leaving;
        let k = round.k;
        // The numbers the lanes read (a Lambertian vertex leaves the lobe's
        // and the eighth unread, the light's choice where there is one
        // area light, roulette's before it plays): only those are made.
        let wanted = WANTED
            | u8::from(self.choose) << dim::CHOOSE
            | u8::from(round.roulette.is_some()) << dim::ROULETTE;
        input.u = numbers(self.level, lanes, ids, k, wanted);
        let lesson_light = gather(world, self.level, lanes, ids, its, round.roulette, input);
        super::simd::shade8_at(self.level, input, o);
        for (j, (&i, it)) in ids.iter().zip(its.iter()).enumerate() {
            let lane = &mut lanes[i as usize];
            if lesson_light[j] {
                // A point, spot, directional or sky light: the lesson's
                // `direct_light`, shadow ray and all, one lane at a time.
                if let Some(v) = Vertex::at(world, it, -lane.ray.dir) {
                    let mut out = PathOut {
                        layers: &mut outs[lane.out as usize],
                        stats,
                    };
                    let u = &input.u;
                    let u_light = Vec2::new(u[dim::LIGHT[0]][j], u[dim::LIGHT[1]][j]);
                    let direct =
                        direct_light(world, &v, u[dim::CHOOSE][j], u_light, &lane.path, out.stats);
                    out.add_direct(k, direct);
                }
            }
            if o.valid[j] && o.shadow[j] && !lesson_light[j] {
                // The light sample's shadow ray: traced after the round,
                // or decided now.
                stats.rays += 1;
                let v3 = |a: &[[f32; W]; 3]| Vec3::new(a[0][j], a[1][j], a[2][j]);
                let light = v3(&o.contribution);
                if o.shadow_trace[j] {
                    let ray = Ray {
                        origin: v3(&o.shadow_o),
                        dir: v3(&o.shadow_d),
                    };
                    shadows.rays.push((ray, o.shadow_t[j]));
                    shadows.light.push((lane.out, light));
                } else if o.shadow_free[j] {
                    let mut out = PathOut {
                        layers: &mut outs[lane.out as usize],
                        stats,
                    };
                    out.add(Some(k), light);
                }
            }
            // Whether a path goes on is a coin flip to the branch
            // predictor once roulette plays: its ray and path are written
            // either way, and kept or dropped by a count (dropping the last
            // entry of a list is no branch).
            next.push(i);
            let goes_on = usize::from(finish(lane, it, k, o, j));
            next.truncate(next.len() + goes_on - 1);
        }
        ids.clear();
        its.clear();
    }
}

/// What `World::intersect` makes of a hit the tree found (a scene without
/// SDFs).
#[inline]
fn interaction(world: &World, hit: Hit) -> Interaction {
    let k = hit.triangle as usize;
    let mesh = world.triangles.mesh[k] as usize;
    Interaction {
        t: hit.t,
        p: hit.point(world.triangles.tris[k]),
        n: world.normals[k],
        material: world.mesh_material[mesh],
        surface: Surface::Mesh(mesh),
    }
}
