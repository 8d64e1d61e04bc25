//! The ninth fresh set (2026-11-29): plausible wrong solutions written by
//! two more testers before reading the checks, half of them from the
//! contract alone (another formula, another representation), aimed also
//! at the clauses beyond the returned value (state, counts, refused
//! inputs, distributions). The ones the grader let through until this
//! set, now caught: an up nearly perpendicular to the view, a buffer
//! holding depths before the first test, f32::MAX on an empty sample, a
//! flat triangle asked at a corner, max_distance short of the origin's
//! distance, irradiance up to 10⁶ m, grazing lights far from the origin,
//! a number given twice, points snapped to a grid, a normal along z, a
//! light sampler that finds nothing, and roulette from one channel. Each
//! must fail under every seed tried.

use std::cell::Cell;
use std::collections::HashMap;

use glam::{Mat4, Vec3};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::refraction::check_refraction;
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5, ch6, paths};

use super::fails_every;
use super::knobs::{self, InsideKnobs, Knobs, LookKnobs, MarchKnobs, PathKnobs, Survival};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [71, 72, 93, 0x2026_1129];

/// The path loop's check traces 200,000 paths per seed: two seeds.
const PATH_SEEDS: &[u64] = &[71, 93];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// `up` itself as the picture's y when it is within 10⁻³ of
/// perpendicular to the view.
fn look_at_perpendicular_shortcut(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    knobs::look_at(
        LookKnobs::with(|k| k.up_as_y_within = Some(1e-3)),
        eye,
        target,
        up,
    )
}

thread_local! {
    static CLEARED: Cell<bool> = const { Cell::new(false) };
}

/// "The buffer starts at infinity": the whole buffer filled with ∞ on
/// the first call.
fn depth_first_fill(depth: &mut [f32], index: usize, z: f32) -> bool {
    if !CLEARED.with(|c| c.replace(true)) {
        depth.fill(f32::INFINITY);
    }
    let nearer = z < depth[index];
    if nearer {
        depth[index] = z;
    }
    nearer
}

/// Anything from f32::MAX up taken for an empty sample, which only a
/// depth below f32::MAX passes.
fn depth_max_sentinel(depth: &mut [f32], index: usize, z: f32) -> bool {
    let stored = depth[index];
    let nearer = if stored >= f32::MAX {
        z < f32::MAX
    } else {
        z < stored
    };
    if nearer {
        depth[index] = z;
    }
    nearer
}

/// A corner's (u, v) returned at once, before the test for no area.
fn inside_corner_first(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    knobs::inside(InsideKnobs::with(|k| k.corners_first = true), p, tri)
}

#[test]
fn geometry_mistakes_fail() {
    fails("up used as y within 10⁻³ of perpendicular", || {
        ch1::check_look_at(look_at_perpendicular_shortcut)
    });
    fails("the buffer filled with ∞ on the first call", || {
        CLEARED.with(|c| c.set(false));
        ch2::check_depth_test(depth_first_fill)
    });
    fails("f32::MAX taken for an empty sample", || {
        ch2::check_depth_test(depth_max_sentinel)
    });
    fails("a corner answered before the area test", || {
        ch3::check_barycentric_inside(inside_corner_first)
    });
    // Gives up when the point is farther than max_distance from the
    // world's origin, not when t is.
    fails("max_distance from the world's origin", || {
        ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
            let k = MarchKnobs::with(|k| k.max_from_origin = true);
            knobs::sphere_trace(k, sdf, (o, d), eps, steps, max)
        })
    });
}

/// No light past 1,000 m.
fn point_range_cut(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let r2 = to.length_squared();
    if r2 > 1e6 {
        return Vec3::ZERO;
    }
    intensity * n.dot(to / r2.sqrt()).max(0.0) / r2
}

/// Behind decided by the planes' offsets n · light ≤ n · p.
fn point_plane_offsets(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    if n.dot(light) <= n.dot(p) {
        return Vec3::ZERO;
    }
    let to = light - p;
    let r2 = to.length_squared();
    intensity * (n.dot(to).abs() / r2.sqrt()) / r2
}

#[test]
fn light_mistakes_fail() {
    fails("no light past 1,000 m", || {
        ch5::check_point_light(point_range_cut)
    });
    fails("behind by the planes' offsets", || {
        ch5::check_point_light(point_plane_offsets)
    });
}

thread_local! {
    static MEMO: std::cell::RefCell<HashMap<u64, f64>> = std::cell::RefCell::new(HashMap::new());
}

/// f evaluated once per different number.
fn integral_memo(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.is_empty() {
        return 0.0;
    }
    MEMO.with(|m| m.borrow_mut().clear());
    let sum: f64 = u
        .iter()
        .map(|&x| {
            MEMO.with(|m| {
                *m.borrow_mut()
                    .entry(x.to_bits())
                    .or_insert_with(|| f(a + x * (b - a)))
            })
        })
        .sum();
    (b - a) * sum / u.len() as f64
}

/// Points snapped to the centres of 1,024 cells.
fn integral_snapped(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.is_empty() {
        return 0.0;
    }
    let s: f64 = u
        .iter()
        .map(|&v| f(a + ((v * 1024.0).floor() + 0.5) / 1024.0 * (b - a)))
        .sum();
    (b - a) * s / u.len() as f64
}

/// A frame from n × z, which has none where n is along z.
fn refract_frame_from_z(
    d: Vec3,
    n: Vec3,
    eta_outside: f32,
    eta_inside: f32,
) -> Option<(Vec3, f32)> {
    let (m, ei, et) = if d.dot(n) < 0.0 {
        (n, eta_outside, eta_inside)
    } else {
        (-n, eta_inside, eta_outside)
    };
    let tx = m.cross(Vec3::Z).normalize();
    let ty = m.cross(tx);
    let wo = -d;
    let lo = Vec3::new(wo.dot(tx), wo.dot(ty), wo.dot(m));
    let eta = ei / et;
    let s2 = eta * eta * (1.0 - lo.z * lo.z).max(0.0);
    if s2 >= 1.0 {
        return None;
    }
    let ct = (1.0 - s2).sqrt();
    let t = (tx * (-eta * lo.x) + ty * (-eta * lo.y) - m * ct).normalize();
    let rs = (ei * lo.z - et * ct) / (ei * lo.z + et * ct);
    let rp = (et * lo.z - ei * ct) / (et * lo.z + ei * ct);
    Some((t, 0.5 * (rs * rs + rp * rp)))
}

#[test]
fn sampling_mistakes_fail() {
    fails("f evaluated once per different number", || {
        ch6::check_mc_integral(integral_memo)
    });
    fails("points snapped to 1,024 cells", || {
        ch6::check_mc_integral(integral_snapped)
    });
    fails("a frame from n × z", || {
        check_refraction(refract_frame_from_z)
    });
}

#[test]
fn path_radiance_emission_without_a_light_sample_fails() {
    fails_every(
        PATH_SEEDS,
        "the emission found where no light sample was",
        Some("emission a bounce finds added"),
        || {
            paths::check_path_radiance(|s, o, d, rng| {
                let k = PathKnobs::with(|k| k.found_emission_without_light = true);
                knobs::path(k, s, o, d, rng)
            })
        },
    );
}

/// q from channel `C` of β alone.
fn path_one_channel<const C: usize>(
    scene: &paths::PathScene,
    o: Vec3,
    d: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    knobs::path(
        PathKnobs::with(|k| k.q = Survival::Channel(C)),
        scene,
        o,
        d,
        rng,
    )
}

#[test]
fn path_radiance_roulette_from_one_channel_fails() {
    for f in [
        path_one_channel::<0>,
        path_one_channel::<1>,
        path_one_channel::<2>,
    ] {
        fails_every(PATH_SEEDS, "roulette from one channel", None, || {
            paths::check_path_radiance(f)
        });
    }
}

/// Right: each point shifted by its number's place in `u` (a Weyl
/// sequence), which leaves it uniform when the number is.
fn integral_shifted_by_place(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.is_empty() {
        return 0.0;
    }
    let golden = 0.618_033_988_749_894_9;
    let sum: f64 = u
        .iter()
        .enumerate()
        .map(|(i, &v)| f(a + (v + i as f64 * golden).fract() * (b - a)))
        .sum();
    (b - a) * sum / u.len() as f64
}

#[test]
fn a_point_shifted_by_its_place_passes() {
    super::passes_every(&SEEDS, "points shifted by their place", || {
        ch6::check_mc_integral(integral_shifted_by_place)
    });
}
