//! Exercise 6.6: one path's light filed by bounce count, the layers the
//! chapter's strip of 1, 2, 4, 8 and 16 bounces is summed from. Checked
//! on paths drawn from the run's seed against the convention worked out
//! here in f64, and on real paths of the Cornell box traced by the
//! render's own loop ([`record_path`]) against what the render filed.

use glam::{DVec3, Vec3};

use super::draws::{fold_drawn, worst_drawn, Draws};
use super::worst_of;
use crate::ch1_projection::camera::Camera;
use crate::ch5_reflection::world::World;
use crate::ch6_global_illumination::integrator::{PathSettings, Strategy};
use crate::ch6_global_illumination::layers::{
    slot_of, Contributions, LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND, SLOT_EMITTED,
};
use crate::ch6_global_illumination::path_record::{record_path, PathRecord};
use crate::ch6_global_illumination::sampler::SamplerKind;
use crate::exercise::{Check, Symptom};
use crate::exercises::AbsMax;
use crate::wire::Wire;

/// How a contribution was gathered at its vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum How {
    /// Emission that the ray arriving at the vertex found: the surface
    /// there emits, or the ray left the scene where that vertex would have
    /// been and found the sky.
    Found,
    /// Next-event estimation at the vertex: a light sample and its shadow
    /// ray.
    LightSample,
}

/// One contribution of a path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gathered {
    /// The vertex: 0 is the first surface the camera ray reaches, 1 the
    /// surface the next ray reaches, and so on.
    pub vertex: u32,
    /// How it was gathered there.
    pub how: How,
    /// What it brings before its MIS weight (β · Le for emission, β · f ·
    /// Li · cos θ / pdf for a light sample).
    pub value: Vec3,
    /// Its MIS weight, in [0, 1].
    pub weight: f32,
}

impl Wire for Gathered {
    fn put(&self, out: &mut Vec<u8>) {
        let how = u8::from(self.how == How::LightSample);
        (self.vertex, how, self.value, self.weight).put(out);
    }
    fn get(input: &mut &[u8]) -> Option<Self> {
        let (vertex, how, value, weight) = <(u32, u8, Vec3, f32)>::get(input)?;
        let how = match how {
            0 => How::Found,
            1 => How::LightSample,
            _ => return None,
        };
        Some(Gathered {
            vertex,
            how,
            value,
            weight,
        })
    }
}

/// The candidate: a path's contributions to its layer slots.
pub type LayersFn = fn(&[Gathered]) -> [Vec3; LAYER_SLOTS];

/// Emitters the camera sees directly not in slot E.
pub const LAYERS_EMITTED: Symptom = Symptom {
    name: "emitters seen directly not in layer E",
};
/// A light sample or found emission one slot off.
pub const LAYERS_OFF_BY_ONE: Symptom = Symptom {
    name: "a bounce filed one layer off",
};
/// Bounce counts past [`LAYERS_SHOWN`] not in [`SLOT_BEYOND`].
pub const LAYERS_CAP: Symptom = Symptom {
    name: "long paths not in the last slot",
};
/// The MIS weight not applied.
pub const LAYERS_WEIGHT: Symptom = Symptom {
    name: "the MIS weight left out",
};
/// A NaN or infinite contribution let into the layers.
pub const LAYERS_NOT_FINITE: Symptom = Symptom {
    name: "a NaN or infinite contribution let through",
};

/// The symptoms of [`check_bounce_layers`].
pub const SYMPTOMS: [Symptom; 5] = [
    LAYERS_EMITTED,
    LAYERS_OFF_BY_ONE,
    LAYERS_CAP,
    LAYERS_WEIGHT,
    LAYERS_NOT_FINITE,
];

/// raystep's answer: the render's own [`slot_of`] and [`Contributions`].
// ANCHOR: bounce_layers
pub fn reference_layers(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    let mut layers = [Vec3::ZERO; LAYER_SLOTS];
    for g in path {
        // Light found at vertex i scattered at i surfaces before it.
        let k = match g.how {
            How::Found => g.vertex.checked_sub(1),
            How::LightSample => Some(g.vertex),
        };
        let c = g.value * g.weight;
        if c.is_finite() {
            layers.add_to(slot_of(k), c);
        }
    }
    layers
}
// ANCHOR_END: bounce_layers

/// The slot the contract files `g` into, worked out apart from the
/// render's code.
fn slot(g: &Gathered) -> usize {
    let scatterings = match g.how {
        How::Found if g.vertex == 0 => return SLOT_EMITTED,
        How::Found => g.vertex as usize,
        How::LightSample => g.vertex as usize + 1,
    };
    // Bounce count k = scatterings − 1 has slot k + 1.
    scatterings.min(SLOT_BEYOND)
}

/// Per slot, the f64 sum of the finite contributions and of their
/// magnitudes.
fn expected(path: &[Gathered]) -> [(DVec3, DVec3); LAYER_SLOTS] {
    let mut out = [(DVec3::ZERO, DVec3::ZERO); LAYER_SLOTS];
    for g in path {
        let c = g.value.as_dvec3() * f64::from(g.weight);
        if (g.value * g.weight).is_finite() {
            out[slot(g)].0 += c;
            out[slot(g)].1 += c.abs();
        }
    }
    out
}

/// The worst slot's error: its difference from `want` relative to the
/// magnitudes filed there (a slot nothing is filed into must be 0).
fn slots_error(got: &[Vec3; LAYER_SLOTS], want: &[(DVec3, DVec3); LAYER_SLOTS]) -> (f64, usize) {
    let mut worst = (0.0, 0);
    for (s, (g, (w, mag))) in got.iter().zip(want).enumerate() {
        for c in 0..3 {
            let diff = (f64::from(g[c]) - w[c]).abs();
            let e = match mag[c] > 0.0 {
                true => diff / mag[c],
                false if diff == 0.0 => 0.0,
                false => f64::INFINITY,
            };
            let e = if e.is_nan() { f64::INFINITY } else { e };
            if e > worst.0 {
                worst = (e, s);
            }
        }
    }
    worst
}

/// A drawn contribution's value: channels over six decades, now and then
/// up to 10²⁵, NaN, or infinite of either sign.
fn drawn_value(draws: &mut Draws) -> Vec3 {
    // Now and then huge (up to 10²⁵: finite, though its length is not).
    let size = if draws.unit() < 0.05 {
        draws.decades(15.0, 25.0)
    } else {
        draws.decades(-3.0, 3.0)
    };
    let mut v = Vec3::new(draws.unit(), draws.unit(), draws.unit()) * size;
    if draws.unit() < 0.03 {
        v[draws.count(0, 2)] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY][draws.count(0, 2)];
    }
    v
}

/// A drawn path of up to 40 vertices (past [`LAYERS_SHOWN`] in over half
/// of them), in the order its contributions were gathered.
fn drawn_path(draws: &mut Draws) -> Vec<Gathered> {
    let vertices = draws.count(0, 40) as u32;
    let mut path = Vec::new();
    let mut add = |draws: &mut Draws, vertex, how| {
        let value = drawn_value(draws);
        // Now and then a weight that is not finite (0/0 in a pdf): the
        // product is what must be finite. And some tiny (10⁻⁸ to 10⁻⁴),
        // which still count.
        let weight = match draws.count(0, 60) {
            0 => [f32::NAN, f32::INFINITY][draws.count(0, 1)],
            1..=6 => 0.0,
            7..=24 => 1.0,
            25..=28 => draws.decades(-8.0, -4.0),
            _ => draws.unit(),
        };
        path.push(Gathered {
            vertex,
            how,
            value,
            weight,
        });
    };
    for i in 0..=vertices {
        // Emission the ray to vertex i found (the sky past the last).
        if draws.unit() < if i == 0 { 0.6 } else { 0.3 } {
            add(draws, i, How::Found);
        }
        if i < vertices && draws.unit() < 0.8 {
            add(draws, i, How::LightSample);
            // Now and then a second light sample at the same vertex (one
            // per light, say): both count.
            if draws.unit() < 0.1 {
                add(draws, i, How::LightSample);
            }
        }
    }
    // Now and then one contribution near f32's largest number in every
    // channel (weight 1): finite, though the sum of its channels is not.
    if !path.is_empty() && draws.unit() < 0.1 {
        let k = draws.count(0, path.len() - 1);
        path[k].value = Vec3::new(
            draws.range(0.4, 1.0),
            draws.range(0.4, 1.0),
            draws.range(0.4, 1.0),
        ) * 3.0e38;
        path[k].weight = 1.0;
    }
    path
}

/// The path `r` recorded, as the exercise is handed it.
fn gathered_of(r: &PathRecord) -> Vec<Gathered> {
    let mut out = Vec::new();
    for (i, v) in r.vertices.iter().enumerate() {
        let vertex = i as u32;
        if let Some(e) = v.emission {
            let (value, weight) = (v.beta * e.le, e.weight);
            out.push(Gathered {
                vertex,
                how: How::Found,
                value,
                weight,
            });
        }
        if let Some(l) = v.light {
            let value = match l.visible {
                true => v.beta * l.f * l.li * l.cos / l.pdf,
                false => Vec3::ZERO,
            };
            let (how, weight) = (How::LightSample, l.weight);
            out.push(Gathered {
                vertex,
                how,
                value,
                weight,
            });
        }
    }
    if let Some((_, e)) = r.escaped {
        let vertex = r.vertices.len() as u32;
        let (how, value, weight) = (How::Found, e.contribution, 1.0);
        out.push(Gathered {
            vertex,
            how,
            value,
            weight,
        });
    }
    out
}

/// Real paths: the Cornell box at 12 × 12, one path per pixel traced by
/// the render's loop with roulette held off to 40 bounces, so most
/// paths reach past [`LAYERS_SHOWN`]; the layers must be what the render
/// filed.
fn real_paths(f: LayersFn) -> (f64, String) {
    let scene = super::images::scene("cornell-box.toml");
    let world = World::new(&scene);
    let camera = Camera::of(&scene)
        .with_resolution(12, 12)
        .expect("a valid camera");
    let settings = PathSettings {
        strategy: Strategy::Mis,
        max_bounces: Some(40),
        rr_min_bounce: 40,
        rr_scale: None,
    };
    let seed = 66 ^ crate::run_seed();
    worst_of((0..camera.width * camera.height).map(|p| {
        let pixel = (p % camera.width, p / camera.width);
        let r = record_path(
            &world,
            &camera,
            &settings,
            SamplerKind::Independent,
            seed,
            pixel,
            0,
        );
        let path = gathered_of(&r);
        let got = f(&path);
        let mut want = expected(&path);
        for (w, filed) in want.iter_mut().zip(r.layers) {
            w.0 = filed.as_dvec3();
        }
        let (e, s) = slots_error(&got, &want);
        (
            e,
            format!(
                "a path of the Cornell box ({} vertices), slot {s}: got {}, the render filed {}",
                r.vertices.len(),
                got[s],
                r.layers[s]
            ),
        )
    }))
}

/// Every contribution in the slot of its bounce count, times its weight,
/// non-finite ones left out: on probes, drawn paths and real ones (see
/// the stub's contract). Tolerance 10⁻⁵ of the magnitudes in a slot.
pub fn check_bounce_layers(f: LayersFn) -> Check {
    let tol = 1e-5;
    let (mut error, mut detail) = match probe(f) {
        Some((what, _)) => (1.0, what),
        None => (0.0, "all cases match".to_string()),
    };
    let mut draws = Draws::new(66);
    // A stream of its own: a channel set to 0 or -0 (what a black channel
    // of an albedo gives) in a tenth of the contributions; they still
    // count. (Not a subnormal: value · weight in f32 keeps few of its
    // digits, so no f32 product is within 10⁻⁵ of the f64 one there.)
    let mut dark = Draws::new(67);
    // And another: a twentieth of the contributions 10³⁰ bright with a
    // weight of 10⁹ to 10¹⁰, whose product in f32 (as the render forms it)
    // is infinite, though in f64 it is not: left out.
    let mut blinding = Draws::new(167);
    let drawn = worst_drawn((0..draws.count(300, 800)).map(|_| {
        draws.next_case();
        dark.next_case();
        blinding.next_case();
        let mut path = drawn_path(&mut draws);
        for g in &mut path {
            if dark.unit() < 0.1 {
                let c = dark.count(0, 2);
                g.value[c] = [0.0, -0.0][dark.count(0, 1)];
            }
            if blinding.unit() < 0.05 {
                g.value = Vec3::splat(blinding.range(0.4, 1.0) * 1e30);
                g.weight = blinding.decades(9.0, 10.0);
            }
        }
        let got = f(&path);
        let (e, s) = slots_error(&got, &expected(&path));
        let want = expected(&path)[s].0.as_vec3();
        let filed: Vec<String> = path
            .iter()
            .filter(|g| slot(g) == s)
            .map(|g| format!("{:?} at {} {} × {}", g.how, g.vertex, g.value, g.weight))
            .collect();
        (
            e,
            format!(
                "slot {s}: got {}, expected {want} from [{}]",
                got[s],
                filed.join(", ")
            ),
        )
    }));
    fold_drawn(&mut error, &mut detail, drawn);
    let real = real_paths(f);
    if real.0 > error {
        (error, detail) = real;
    }
    Check {
        error,
        tolerance: tol,
        detail,
        images: None,
        symptom: (error > tol).then(|| probe(f).map(|p| p.1)).flatten(),
    }
}

/// The first of the one-contribution probes `f` gets wrong, and the
/// symptom it shows: a non-finite slot, a wrong total (the weight), or the
/// right total in the wrong slot.
fn probe(f: LayersFn) -> Option<(String, Symptom)> {
    let v = Vec3::new(1.0, 2.0, 3.0);
    let one = |vertex, how, value, weight| {
        [Gathered {
            vertex,
            how,
            value,
            weight,
        }]
    };
    use How::{Found, LightSample as Light};
    let nan = Vec3::new(f32::NAN, 1.0, 1.0);
    let inf = Vec3::new(1.0, f32::INFINITY, 1.0);
    let neg_inf = Vec3::new(1.0, 1.0, f32::NEG_INFINITY);
    let max = LAYERS_SHOWN;
    let probes = [
        (one(0, Light, nan, 1.0), LAYERS_NOT_FINITE),
        (one(3, Found, inf, 0.0), LAYERS_NOT_FINITE),
        (one(2, Light, inf, 0.5), LAYERS_NOT_FINITE),
        (one(1, Found, neg_inf, 1.0), LAYERS_NOT_FINITE),
        (one(0, Light, v, 0.5), LAYERS_WEIGHT),
        (one(4, Found, v, 0.25), LAYERS_WEIGHT),
        (one(0, Found, v, 1.0), LAYERS_EMITTED),
        (one(0, Light, v, 1.0), LAYERS_OFF_BY_ONE),
        (one(1, Found, v, 1.0), LAYERS_OFF_BY_ONE),
        (one(2, Light, v, 1.0), LAYERS_OFF_BY_ONE),
        (one(5, Found, v, 1.0), LAYERS_OFF_BY_ONE),
        (one(max, Light, v, 1.0), LAYERS_CAP),
        (one(max + 1, Found, v, 1.0), LAYERS_CAP),
        (one(max + 1, Light, v, 1.0), LAYERS_CAP),
        (one(max + 2, Found, v, 1.0), LAYERS_CAP),
        (one(39, Light, v, 1.0), LAYERS_CAP),
        (one(1000, Found, v, 1.0), LAYERS_CAP),
    ];
    probes.into_iter().find_map(|(path, symptom)| {
        let got = f(&path);
        let want = expected(&path);
        let total = |l: &[Vec3]| l.iter().map(|c| c.as_dvec3()).sum::<DVec3>();
        let wrong = match symptom {
            LAYERS_NOT_FINITE => got.iter().any(|c| !c.is_finite()),
            LAYERS_WEIGHT => {
                let want = path[0].value.as_dvec3() * f64::from(path[0].weight);
                let off = (total(&got) - want).abs_max();
                off.is_nan() || off > 1e-6 * want.max_element()
            }
            _ => slots_error(&got, &want).0 > 1e-5,
        };
        let g = &path[0];
        wrong.then(|| {
            let (e, s) = slots_error(&got, &want);
            let s = if e > 0.0 { s } else { slot(g) };
            let what = format!(
                "{:?} at vertex {}, {} × {}: slot {s} got {}, expected it all in slot {}",
                g.how,
                g.vertex,
                g.value,
                g.weight,
                got[s],
                slot(g)
            );
            (what, symptom)
        })
    })
}
