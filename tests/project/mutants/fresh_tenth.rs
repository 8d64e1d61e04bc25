//! The tenth fresh set (2026-11-29): plausible wrong solutions written by
//! two more testers before reading the checks, as a student who has read
//! other renderers or who optimises would write them (other conventions,
//! bit-trick reciprocals and square roots, loops unrolled, padding
//! against cracks, weights too small to matter). The ones the grader let
//! through until this set, now caught: a disk radius a few percent off
//! (a grid of u spread over the hemisphere), an ε added to cos θl (a light
//! exactly edge-on but for a hair), an inside test padded by 10⁻³, a slab
//! test with an approximate 1/d (rays aimed just inside triangles' edges),
//! an odd step budget, and MIS weights under 10⁻⁴ dropped. Each must fail
//! under every seed tried.

use glam::{Vec2, Vec3};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::ch6_global_illumination::layers::{
    LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND, SLOT_EMITTED,
};
use raystep::grading::counted::{Hit, ReadableBvh};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::bounce_layers::{check_bounce_layers, Gathered, How};
use raystep::grading::exercises::{ch3, ch4, ch5};

use super::fails_every;
use super::knobs::{self, BvhKnobs, Knobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [81, 82, 97, 0x2026_1129];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// Malley's method with r = √u.x from the exponent-halving bit trick
/// (up to 4% off).
fn cosine_bit_sqrt(u: Vec2) -> (Vec3, f32) {
    let r = f32::from_bits((u.x.to_bits() >> 1) + 0x1fbd_1df5);
    let phi = std::f32::consts::TAU * u.y;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    (Vec3::new(x, y, z), z * std::f32::consts::FRAC_1_PI)
}

/// 10⁻⁶ added to cos θl "against division by 0".
#[allow(clippy::too_many_arguments)]
fn direct_cos_epsilon(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: &dyn Fn(Vec3, Vec3) -> bool,
) -> Vec3 {
    let to = y - p;
    let d2 = to.length_squared();
    let wi = to / d2.sqrt();
    let (cos, cos_light) = (n.dot(wi), n_light.dot(-wi));
    if cos <= 0.0 || cos_light <= 0.0 || !visible(p, y) {
        return Vec3::ZERO;
    }
    let pdf = d2 / ((cos_light + 1e-6) * area);
    rho * std::f32::consts::FRAC_1_PI * le * cos / pdf
}

#[test]
fn light_mistakes_fail() {
    fails("a bit-trick √u.x", || {
        ch5::check_cosine_hemisphere(cosine_bit_sqrt)
    });
    fails("10⁻⁶ added to cos θl", || {
        ch5::check_direct_light(direct_cos_epsilon)
    });
}

/// The inside test padded by 10⁻³ against cracks.
fn moller_padded(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
    let pvec = d.cross(e2);
    let det = e1.dot(pvec);
    if det == 0.0 {
        return None;
    }
    let tvec = o - tri[0];
    let qvec = tvec.cross(e1);
    let (u, v, t) = (tvec.dot(pvec) / det, d.dot(qvec) / det, e2.dot(qvec) / det);
    let pad = 1e-3;
    (u >= -pad && v >= -pad && u + v <= 1.0 + pad && t > 0.0).then_some((t, u, v))
}

/// 1/d from the bit trick in the slab test.
fn bvh_approximate_recip(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    knobs::closest_hit(BvhKnobs::with(|k| k.approx_recip = true), bvh, ray, t_max)
}

/// Two evaluations a turn for max_steps / 2 turns: an odd budget loses its
/// last evaluation.
fn trace_unrolled(
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    epsilon: f32,
    max_steps: u32,
    max_distance: f32,
) -> Option<f32> {
    let mut t = 0.0f32;
    for _ in 0..max_steps / 2 {
        for _ in 0..2 {
            let d = sdf(origin + t * dir);
            if d.abs() < epsilon {
                return Some(t);
            }
            if t > max_distance {
                return None;
            }
            t += d;
        }
    }
    None
}

/// The capstone's march unrolled the same way.
fn scene_unrolled(
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    march: &March,
) -> Option<(f32, Vec3)> {
    let mut t = 0.0;
    let mut hit = None;
    'march: for _ in 0..march.max_steps / 2 {
        for _ in 0..2 {
            let p = origin + t * dir;
            let f = sdf(p);
            if f.abs() < march.epsilon_at(p) {
                hit = Some(p);
                break 'march;
            }
            if t > march.max_distance {
                return None;
            }
            t += f;
        }
    }
    let p = hit?;
    let h = march.epsilon_at(p).max(1e-4);
    let partial = |axis: Vec3| (sdf(p + axis * h) - sdf(p - axis * h)) / (2.0 * h);
    let gradient = Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z));
    let n = gradient.try_normalize().unwrap_or(-dir);
    Some((t, if n.dot(dir) > 0.0 { -n } else { n }))
}

#[test]
fn geometry_mistakes_fail() {
    fails("an inside test padded by 10⁻³", || {
        ch3::check_moller_trumbore(moller_padded)
    });
    fails("an approximate 1/d in the slab test", || {
        ch3::check_bvh_traversal(bvh_approximate_recip)
    });
    fails("sphere tracing unrolled by two", || {
        ch4::check_sphere_trace(trace_unrolled)
    });
    fails("the capstone's march unrolled by two", || {
        ch4::check_trace_scene(scene_unrolled)
    });
}

/// Contributions whose MIS weight is under 10⁻⁴ skipped.
fn layers_skip_small_weights(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    let mut layers = [Vec3::ZERO; LAYER_SLOTS];
    for g in path {
        let k = match g.how {
            How::Found if g.vertex == 0 => None,
            How::Found => Some(g.vertex - 1),
            How::LightSample => Some(g.vertex),
        };
        let slot = match k {
            None => SLOT_EMITTED,
            Some(k) if k <= LAYERS_SHOWN => k as usize + 1,
            Some(_) => SLOT_BEYOND,
        };
        let c = g.value * g.weight;
        if g.weight >= 1e-4 && c.is_finite() {
            layers[slot] += c;
        }
    }
    layers
}

#[test]
fn layer_mistakes_fail() {
    fails("MIS weights under 10⁻⁴ skipped", || {
        check_bounce_layers(layers_skip_small_weights)
    });
}
