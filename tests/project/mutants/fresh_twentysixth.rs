//! The twenty-sixth fresh set (2026-11-30), three testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: state, order and reuse (U, 59 wrong), units and
//! conventions (V, 75), and code transplanted from other renderers and
//! tutorials (W, 65); 79 right alternatives, all of which pass. With the
//! grader as it stood before (07a1f70), 9 of the 199 wrong ones passed
//! under seed 51 or 52. Six kept an answer from an earlier question (a
//! memo keyed on some of the arguments, or on rounded ones, or a march
//! that starts where the last one from the same eye stopped); they fail
//! now under seeds 51 to 53 and are here. Of the other three, two decide
//! roulette's survival by u ≥ 1 − q (right, as the earlier sets rule),
//! and one multiplies trace_scene's steps by `march.step_factor`, which
//! is 1 in every march the grader passes (the stub now says so).

use std::cell::{Cell, RefCell};
use std::collections::HashMap;

use glam::{Mat4, Vec3};
use raystep::ch1_projection::camera::project_pinhole;
use raystep::ch1_projection::wireframe::clip_to_near;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch5::reference_lambert;
use raystep::grading::exercises::refraction::{check_refraction, reference_refract};
use raystep::grading::exercises::{ch1, ch4, ch5, ch6};

use super::fails_every;
use super::knobs::{self, LookKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// Bits of a point, for keys.
fn bits(v: Vec3) -> [u32; 3] {
    v.to_array().map(f32::to_bits)
}

thread_local! {
    static LOOK: RefCell<HashMap<[u32; 6], Mat4>> = RefCell::new(HashMap::new());
    static RHO: RefCell<HashMap<[u8; 3], Vec3>> = RefCell::new(HashMap::new());
    static CAMERA_SPACE: RefCell<HashMap<[u32; 3], Vec3>> = RefCell::new(HashMap::new());
    static LAST_HIT: Cell<Option<(Vec3, f32)>> = const { Cell::new(None) };
    static INVERSE_Q: RefCell<HashMap<u32, f64>> = RefCell::new(HashMap::new());
    static FRESNEL: RefCell<HashMap<(u32, u32, u32), f32>> = RefCell::new(HashMap::new());
}

#[test]
fn look_at_kept_without_up_fails() {
    fails(
        "look_at: the matrix kept by eye and target, up left out",
        || {
            LOOK.with(|m| m.borrow_mut().clear());
            ch1::check_look_at(|e, t, u| {
                let key = [bits(e), bits(t)].concat().try_into().expect("six");
                LOOK.with(|m| {
                    *m.borrow_mut()
                        .entry(key)
                        .or_insert_with(|| knobs::look_at(LookKnobs::default(), e, t, u))
                })
            })
        },
    );
}

#[test]
fn lambert_kept_by_an_8_bit_albedo_fails() {
    fails(
        "lambert_brdf: ρ/π kept by the albedo as 8-bit colour",
        || {
            RHO.with(|m| m.borrow_mut().clear());
            ch5::check_lambert_brdf(|rho, wo, wi| {
                if wo.z * wi.z <= 0.0 {
                    return Vec3::ZERO;
                }
                let key = rho
                    .to_array()
                    .map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
                RHO.with(|m| {
                    *m.borrow_mut()
                        .entry(key)
                        .or_insert_with(|| reference_lambert(rho, Vec3::Z, Vec3::Z))
                })
            })
        },
    );
}

#[test]
fn draw_edges_kept_without_the_camera_fails() {
    fails(
        "draw_edges: camera-space points kept by world point, the camera left out",
        || {
            CAMERA_SPACE.with(|m| m.borrow_mut().clear());
            ch1::check_draw_edges(|camera, a, b, near| {
                let to_camera = |p: Vec3| {
                    CAMERA_SPACE.with(|m| {
                        *m.borrow_mut()
                            .entry(bits(p))
                            .or_insert_with(|| camera.to_camera(p))
                    })
                };
                let (ca, cb) = clip_to_near(to_camera(a), to_camera(b), near)?;
                let (ua, ub) = (project_pinhole(ca)?, project_pinhole(cb)?);
                Some((
                    camera.raster_from_image_plane(ua),
                    camera.raster_from_image_plane(ub),
                ))
            })
        },
    );
}

#[test]
fn sphere_trace_from_the_last_hit_fails() {
    fails(
        "sphere_trace: a march from the same origin starts at half the last hit's t",
        || {
            LAST_HIT.with(|c| c.set(None));
            ch4::check_sphere_trace(|sdf, origin, dir, eps, max_steps, max_distance| {
                let mut t = match LAST_HIT.with(Cell::get) {
                    Some((o, t_hit)) if o == origin => 0.5 * t_hit,
                    _ => 0.0,
                };
                for _ in 0..max_steps {
                    let d = sdf(origin + t * dir);
                    if d.abs() < eps {
                        LAST_HIT.with(|c| c.set(Some((origin, t))));
                        return Some(t);
                    }
                    if t > max_distance {
                        return None;
                    }
                    t += d;
                }
                None
            })
        },
    );
}

#[test]
fn roulette_inverse_kept_by_an_f32_q_fails() {
    fails(
        "russian_roulette: 1/q kept by q rounded to f32 (every q below f32's range shares one)",
        || {
            INVERSE_Q.with(|m| m.borrow_mut().clear());
            ch6::check_russian_roulette(|value, q, u| {
                if u >= q {
                    return 0.0;
                }
                let inverse = INVERSE_Q.with(|m| {
                    *m.borrow_mut()
                        .entry((q as f32).to_bits())
                        .or_insert(1.0 / q)
                });
                value * inverse
            })
        },
    );
}

#[test]
fn refraction_kept_by_a_rounded_cosine_fails() {
    fails(
        "refraction: the reflectance kept by the indices and cos θ to 1/4096",
        || {
            FRESNEL.with(|m| m.borrow_mut().clear());
            check_refraction(|d, n, outside, inside| {
                let (t, f) = reference_refract(d, n, outside, inside)?;
                let (eta_i, eta_t) = match d.dot(n) < 0.0 {
                    true => (outside, inside),
                    false => (inside, outside),
                };
                let key = (
                    eta_i.to_bits(),
                    eta_t.to_bits(),
                    (d.dot(n).abs() * 4096.0) as u32,
                );
                Some((t, FRESNEL.with(|m| *m.borrow_mut().entry(key).or_insert(f))))
            })
        },
    );
}
