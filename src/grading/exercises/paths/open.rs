//! The path capstone's contract clauses that neither the closed furnace's
//! mean nor the Cornell box can show: roulette that keeps a survivor's
//! throughput bounded (a bright furnace), and light samples from behind
//! the surface left out (an open scene, where nothing else stops them).

use glam::{Vec2, Vec3};

use super::{camera_sample, trace_furnace, FurnaceRun, PathFn, PathScene};
use crate::ch1_projection::camera::Camera;
use crate::exercise::Symptom;
use crate::exercises::AbsMax;
use crate::scene::Scene;

/// Roulette whose survival probability does not follow the throughput:
/// survivors' throughput grows without bound in a bright furnace.
pub const UNBOUNDED_THROUGHPUT: Symptom = Symptom {
    name: "survival not taken from the throughput",
};

/// A light sample from below the surface counted (negative light).
pub const LIGHT_FROM_BEHIND: Symptom = Symptom {
    name: "a light sample from behind the surface counted",
};

/// The first of these clauses `f` breaks: what was seen, and its symptom.
pub fn contract_failure(f: PathFn) -> Option<(String, Symptom)> {
    unbounded_throughput(f)
        .map(|d| (d, UNBOUNDED_THROUGHPUT))
        .or_else(|| light_from_behind(f).map(|d| (d, LIGHT_FROM_BEHIND)))
        .or_else(|| shaded_lamp(f).map(|d| (d, LIGHT_THROUGH_OCCLUDER)))
        .or_else(|| bounce_emission_added(f).map(|d| (d, BOUNCE_EMISSION_ADDED)))
        .or_else(|| emission_without_light_sample(f).map(|d| (d, BOUNCE_EMISSION_ADDED)))
        .or_else(|| black_furnace(f).map(|d| (d, BLACK_SURFACE)))
        .or_else(|| ends_of_range(f).map(|d| (d, ENDS_OF_RANGE)))
        .or_else(|| same_ray_other_scene(f).map(|d| (d, PATHS_BEFORE)))
}

/// A path's radiance that depends on the paths traced before it.
pub const PATHS_BEFORE: Symptom = Symptom {
    name: "a path depends on the paths before it",
};

/// The same ray and numbers in another scene right before must not
/// change a path's radiance: a path owes nothing to the paths before it
/// (a first hit cached by its ray, say, answers the ray in the last
/// scene).
pub fn same_ray_other_scene(f: PathFn) -> Option<String> {
    let (albedo, le) = super::furnace_of_run();
    let here = PathScene::furnace(albedo, le);
    let there =
        PathScene::furnace_coloured(Vec3::new(0.2, 0.5, 0.7), Vec3::new(le.z, le.x, le.y) * 0.5);
    let seed = 614 ^ crate::run_seed();
    let path = |scene: &PathScene, i: u64| {
        let (dir, mut rng) = super::furnace_path(seed, i);
        super::reset_tally();
        f(scene, super::FURNACE_ORIGIN, dir, &mut rng)
    };
    (0..16).find_map(|i| {
        [(&here, &there), (&there, &here)]
            .into_iter()
            .find_map(|(x, y)| {
                path(x, i + 1000);
                let alone = path(x, i);
                path(x, i + 2000);
                path(y, i);
                let after = path(x, i);
                (alone.to_array().map(f32::to_bits) != after.to_array().map(f32::to_bits)).then(
                    || {
                        format!(
                    "the same path (ray and numbers) in a furnace gave {alone} after another \
                     ray, and {after} right after the same ray in another furnace: a path owes \
                     nothing to the paths traced before it"
                )
                    },
                )
            })
    })
}

/// Something other than Le from a furnace of black walls.
pub const BLACK_SURFACE: Symptom = Symptom {
    name: "a black surface",
};

/// A furnace whose walls are black (albedo 0): every path sees the wall's
/// Le and nothing more, exactly, and finite (a throughput of 0 is not
/// 0/0).
pub fn black_furnace(f: PathFn) -> Option<String> {
    let (_, le) = super::furnace_of_run();
    let scene = PathScene::furnace(0.0, le);
    let run = trace_furnace(f, &scene, 2_000, 613 ^ crate::run_seed());
    let (mean, _) = run.mean_and_error(2_000);
    let exact = (mean - le.as_dvec3()).abs_max() <= 1e-6 * le.as_dvec3().abs_max();
    (run.non_finite > 0 || !exact).then(|| {
        format!(
            "a furnace of black walls (albedo 0, Le {le:.2}): every path sees Le and nothing \
             more, yet {} of 2000 paths were not finite and their mean is {mean:.4}",
            run.non_finite
        )
    })
}

/// A radiance that is not finite where `rng()` gives an end of [0, 1).
pub const ENDS_OF_RANGE: Symptom = Symptom {
    name: "a number at an end of [0, 1)",
};

/// Path i's camera ray (origin, direction), in [`ends_of_range`].
type RayOf<'a> = dyn Fn(u64) -> (Vec3, Vec3) + 'a;

/// `rng()` may give any number of [0, 1), its ends too. Here an eighth of
/// the numbers are exactly 0 and an eighth the largest below 1
/// (1 − 2⁻²⁴), the rest uniform, 2,048 paths in each of the run's
/// furnace, a furnace of black walls and the Cornell box (two through the
/// centre of each of 32 × 32 pixels): a cosine sample from a 0 can lie in the tangent plane, where its
/// density is 0 (in the box such a bounce runs along a wall to the next),
/// and roulette with q = 0 (a black wall's throughput) must end the path
/// even when the number is 0. Every radiance finite, and the black
/// furnace's Le.
pub fn ends_of_range(f: PathFn) -> Option<String> {
    use crate::core::sampling::random;
    let (albedo, le) = super::furnace_of_run();
    let seed = 617 ^ crate::run_seed();
    let box_scene = crate::exercises::images::scene("cornell-box.toml");
    let camera = crate::ch1_projection::camera::Camera::of(&box_scene)
        .with_resolution(32, 32)
        .expect("a valid camera");
    let furnace_ray = |i: u64| (super::FURNACE_ORIGIN, super::furnace_path(seed, i).0);
    let camera_ray = |i: u64| {
        let (x, y) = ((i / 2 % 32) as f32, (i / 64) as f32);
        let ray = camera.ray(glam::Vec2::new(x + 0.5, y + 0.5));
        (ray.origin, ray.dir)
    };
    let runs: [(&str, PathScene, &RayOf, bool); 3] = [
        (
            "the run's closed furnace",
            PathScene::furnace(albedo, le),
            &furnace_ray,
            false,
        ),
        (
            "a furnace of black walls",
            PathScene::furnace(0.0, le),
            &furnace_ray,
            true,
        ),
        (
            "the Cornell box",
            PathScene::new(&box_scene),
            &camera_ray,
            false,
        ),
    ];
    runs.iter().find_map(|(what, scene, ray, black)| {
        (0..2_048u64).find_map(|i| {
            let (origin, dir) = ray(i);
            let mut k = 0u64;
            let mut rng = || {
                k += 1;
                match random(seed, i, 1, k) {
                    c if c < 0.125 => 0.0,
                    c if c < 0.25 => 1.0 - f32::EPSILON / 2.0,
                    _ => random(seed, i, 2, k).min(1.0 - f32::EPSILON),
                }
            };
            super::reset_tally();
            let l = f(scene, origin, dir, &mut rng);
            let off = (l - le).abs().max_element() > 1e-6 * le.max_element();
            (!l.is_finite() || (*black && off)).then(|| {
                format!(
                    "{what} with rng() giving 0 or 1 - 2^-24 for a quarter of its numbers (both \
                     are numbers of [0, 1)): a path's radiance was {l}{}",
                    if *black {
                        format!(" (albedo 0, Le {le:.2}: every path sees Le)")
                    } else {
                        String::new()
                    }
                )
            })
        })
    })
}

/// Emission a bounce finds, added (in part) to the light samples'.
pub const BOUNCE_EMISSION_ADDED: Symptom = Symptom {
    name: "emission a bounce finds added",
};

/// Paths traced in the furnace whose surfaces reached by a bounce report
/// no emission ([`hidden_emission`]).
pub const HIDDEN_EMISSION_PATHS: u64 = super::FURNACE_PATHS / 4;

/// `f`'s run in the furnace of albedo `albedo` and emission `le` whose
/// surfaces reached by a bounce report no emission (the light samples
/// still see it): a loop that never adds the emission a bounce finds sees
/// Le / (1 − ρ) there too.
pub fn hidden_emission(f: PathFn, albedo: f32, le: Vec3) -> FurnaceRun {
    let scene = PathScene::furnace_without_bounce_emission(albedo, le);
    trace_furnace(f, &scene, HIDDEN_EMISSION_PATHS, 612 ^ crate::run_seed())
}

/// Whether the path adds emission that a bounce finds (the contract: the
/// light sample has counted it): the run's furnace again, its surfaces
/// reached by a bounce reporting no emission. A loop that never adds it
/// sees the same Le / (1 − ρ); one that adds it, even in part (half the
/// light sample and half the emission found is unbiased in the plain
/// furnace), is too dark here. 50,000 paths, 5 standard errors; a path
/// that is not finite fails too.
pub fn bounce_emission_added(f: PathFn) -> Option<String> {
    let (albedo, le) = super::furnace_of_run();
    let run = hidden_emission(f, albedo, le);
    let (mean, se) = run.mean_and_error(HIDDEN_EMISSION_PATHS);
    let want = le.as_dvec3() / (1.0 - f64::from(albedo));
    let z = ((mean - want).abs() / se).max_element();
    (z > 5.0 || run.non_finite > 0).then(|| {
        format!(
            "the same furnace with the emission of every surface a bounce reaches hidden (the \
             light samples still see it): your mean is {mean:.3}, not {want:.3} (z = {z:.1}); \
             emission a bounce finds must not be added, the light sample counts it"
        )
    })
}

/// Whether the path adds emission a bounce finds where the light sampler
/// found no sample (`None`): the run's furnace again, its light sampler
/// finding none for an eighth of its numbers and the others' density
/// carrying that eighth, so a loop that adds nothing there still sees
/// Le / (1 − ρ); one that adds the next surface's emission instead is too
/// bright (the contract: emission a bounce finds is never added). 50,000
/// paths, 5 standard errors; a path that is not finite fails too.
pub fn emission_without_light_sample(f: PathFn) -> Option<String> {
    let (albedo, le) = super::furnace_of_run();
    let scene = PathScene::furnace_with_missing_light_samples(albedo, le);
    let run = trace_furnace(f, &scene, HIDDEN_EMISSION_PATHS, 619 ^ crate::run_seed());
    let (mean, se) = run.mean_and_error(HIDDEN_EMISSION_PATHS);
    let want = le.as_dvec3() / (1.0 - f64::from(albedo));
    let z = ((mean - want).abs() / se).max_element();
    (z > 5.0 || run.non_finite > 0).then(|| {
        format!(
            "the same furnace with a light sampler that finds no sample (None) for an eighth of \
             its numbers, the others' density carrying that eighth: your mean is {mean:.3}, not \
             {want:.3} (z = {z:.1}); a surface without a light sample adds nothing, and emission \
             a bounce finds is never added"
        )
    })
}

/// Paths traced in the bright furnace of [`unbounded_throughput`].
const BRIGHT_PATHS: u64 = 20_000;

/// Whether roulette keeps a survivor's throughput bounded, in two bright
/// furnaces of Le = 1, where each light sample found brings β ρ (per
/// channel), so a path's radiance less 1, per sample and over ρ, is its
/// mean throughput at its samples:
///
/// - grey, of albedo 0.85 to 0.9 (drawn for the run): survival taken from
///   the throughput (q = max β, or the bounce's own f cos θ / pdf, capped
///   at 0.9 or above or not at all, from any bounce on) keeps β at most
///   about 1, while a fixed q below ρ lets it grow as (ρ/q)^k (a fixed 0.8
///   at ρ = 0.85 makes a mean of 2.3 by the 25th bounce, reached by 75
///   paths in 20,000). Past a mean of 2 fails.
/// - coloured, one channel 0.85 to 0.9, one 0.3 to 0.5, one 0.05 to 0.15
///   (drawn), three times, each channel the bright one once: q from the
///   whole throughput (its largest channel, mean or luminance) keeps every
///   channel of β within 1 / 0.0722 (luminance's smallest weight), while q
///   from its smallest channel, or from one channel, lets the largest grow
///   by up to 6 a bounce. Past a mean of 20 fails.
pub fn unbounded_throughput(f: PathFn) -> Option<String> {
    let mut d = crate::exercises::draws::Draws::new(65);
    let grey = d.range(0.85, 0.9);
    let coloured = Vec3::new(d.range(0.85, 0.9), d.range(0.3, 0.5), d.range(0.05, 0.15));
    let turned = |turn: usize| Vec3::from_array(std::array::from_fn(|c| coloured[(c + turn) % 3]));
    let first = d.count(0, 2);
    let furnaces = (0..3).map(|k| (turned((first + k) % 3), 20.0, 615 + k as u64));
    std::iter::once((Vec3::splat(grey), 2.0, 613))
        .chain(furnaces)
        .find_map(|(albedo, most, salt)| {
            let scene = PathScene::furnace_coloured(albedo, Vec3::ONE);
            let run = trace_furnace(f, &scene, BRIGHT_PATHS, salt ^ crate::run_seed());
            let mean_beta = (run.most_per_sample / albedo.as_dvec3()).max_element();
            (mean_beta > most).then(|| {
                format!(
                    "a furnace of albedo {albedo:.3} and Le = 1, where every light sample brings \
                     β ρ: one of {BRIGHT_PATHS} paths had a mean throughput of {mean_beta:.1} \
                     at its light samples (a survival probability taken from the whole \
                     throughput keeps it below {most})"
                )
            })
        })
}

/// A floor seen from above and, beside it and below its plane, a lamp
/// facing up: from every point of the floor the lamp lies below the
/// horizon (cos θ < 0), and no surface stands in between to stop a
/// shadow ray, so only the path's own test keeps that light out.
fn open_floor() -> String {
    format!(
        r#"
[camera]
eye = [0.0, 3.0, 3.0]
target = [0.0, 0.0, 0.0]
fov = 40.0
width = 24
height = 24
{FLOOR_AND_GLOW}
[[objects]]
shape = "rectangle"
size = [2.0, 2.0]
rotate = {{ axis = [1.0, 0.0, 0.0], degrees = -90.0 }}
material = "floor"

[[objects]]
shape = "rectangle"
size = [1.0, 1.0]
rotate = {{ axis = [1.0, 0.0, 0.0], degrees = -90.0 }}
translate = [2.0, -0.5, 0.0]
material = "glow"
"#
    )
}

/// The materials of [`open_floor`] and [`shaded_lamp_scene`]: a grey
/// floor, and a black lamp that glows.
const FLOOR_AND_GLOW: &str = r#"
[[materials]]
name = "floor"
reflectance = [0.8, 0.8, 0.8]

[[materials]]
name = "glow"
reflectance = [0.0, 0.0, 0.0]
emission = [5.0, 5.0, 5.0]
"#;

/// Whether `f` lets light in from below the surface: in [`open_floor`],
/// every path's radiance is a sum of non-negative terms, so a negative
/// channel means a light sample with cos θ < 0 was counted.
pub fn light_from_behind(f: PathFn) -> Option<String> {
    let scene =
        Scene::from_text(&open_floor(), "open-floor").expect("the open floor is a valid scene");
    let camera = Camera::of(&scene);
    let paths = PathScene::new(&scene);
    let what = "a floor lit only from below its horizon";
    let sample = camera_sample(f, &paths, &camera, 614 ^ crate::run_seed(), what);
    for y in 0..camera.height {
        for x in 0..camera.width {
            let ray = camera.ray(Vec2::new(x as f32 + 0.5, y as f32 + 0.5));
            // Where the camera sees the floor, nothing reaches it: the
            // lamp is below its horizon and its bounces leave the scene.
            let floor = paths
                .first_hit(ray.origin, ray.dir)
                .is_some_and(|h| h.emitted == Vec3::ZERO);
            let l = sample(x, y, 0);
            if l.min_element() < -1e-6 || (floor && l.abs_max() > 1e-6) {
                return Some(format!(
                    "a floor lit by a lamp below its horizon (nothing between them): pixel ({x}, {y}) \
                     got {l}, expected 0; a light sample with cos θ ≤ 0 at the surface \
                     brings nothing"
                ));
            }
        }
    }
    None
}

/// A light sample counted though something blocks it: the shadow ray's
/// answer ignored, or the ray stopped short of its light point so that an
/// occluder near the light is missed.
pub const LIGHT_THROUGH_OCCLUDER: Symptom = Symptom {
    name: "light counted through an occluder",
};

/// A lamp facing down inside a closed box whose floor lies `gap` below
/// it, over a floor: no light leaves the box, so every path gives 0.
fn shaded_lamp_scene(gap: f64) -> String {
    let (height, top) = (gap + 0.1, 1.1);
    format!(
        r#"
[camera]
eye = [0.0, 2.5, 3.0]
target = [0.0, 0.3, 0.0]
fov = 50.0
width = 24
height = 24
{FLOOR_AND_GLOW}
[[objects]]
shape = "rectangle"
size = [4.0, 4.0]
rotate = {{ axis = [1.0, 0.0, 0.0], degrees = -90.0 }}
material = "floor"

[[objects]]
shape = "rectangle"
size = [0.5, 0.5]
rotate = {{ axis = [1.0, 0.0, 0.0], degrees = 90.0 }}
translate = [0.0, 1.0, 0.0]
material = "glow"

[[objects]]
shape = "box"
size = [0.6, {height:?}, 0.6]
translate = [0.0, {:?}, 0.0]
material = "floor"
"#,
        top - height / 2.0
    )
}

/// Whether `f`'s shadow rays stop short of the light: in a scene whose
/// lamp sits in a closed box, the box's floor a drawn 2·10⁻⁴ to 10⁻³ below
/// the lamp (far more than the scene's own stop at the light, about
/// 10⁻⁵ there), nothing is lit, so every path's radiance is 0. A shadow
/// ray cut short by as little as 1 % of its length passes through the
/// box's floor.
pub fn shaded_lamp(f: PathFn) -> Option<String> {
    let gap = f64::from(crate::exercises::draws::Draws::new(615).decades(-3.7, -3.0));
    let scene = Scene::from_text(&shaded_lamp_scene(gap), "shaded-lamp")
        .expect("the shaded lamp is a valid scene");
    let camera = Camera::of(&scene);
    let paths = PathScene::new(&scene);
    let what = "a lamp shut in a box";
    let sample = camera_sample(f, &paths, &camera, 615 ^ crate::run_seed(), what);
    for s in 0..2 {
        for y in 0..camera.height {
            for x in 0..camera.width {
                let l = sample(x, y, s);
                if l.abs_max() > 1e-6 {
                    return Some(format!(
                        "a lamp shut in a closed box whose floor lies {gap:.1e} below it: no \
                         light leaves the box, yet pixel ({x}, {y}) got {l}; a light sample counts \
                         only when its shadow ray, run the whole way to the light's point, is \
                         clear"
                    ));
                }
            }
        }
    }
    None
}
