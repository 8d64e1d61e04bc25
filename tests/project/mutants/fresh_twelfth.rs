//! The twelfth fresh set (2026-11-29): wrong solutions that treat an
//! exact special value by accident (a view straight down an axis, a point
//! on the line of an edge, a normal along an axis but not unit, a point
//! on a sphere's axis, a budget of u32::MAX or of one evaluation, a zero
//! density edge-on, a direction straight down, a number exactly 0). Of 63
//! wrong ones, 23 passed; these, written as closures over the course's
//! solutions, now fail under every seed tried.

use glam::{Mat4, Vec3};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch1, ch3, ch4, ch5, ch6};

use raystep::grading::exercises::bounce_layers::{check_bounce_layers, Gathered};

use super::fails_every;
use super::knobs::{self, DirectKnobs, InsideKnobs, LayersKnobs, LookKnobs, MarchKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [111, 112, 117, 0x2026_1129];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn exact_special_values_fail() {
    fails("a view straight down -z taken as no turn", || {
        ch1::check_look_at(|eye, target, up| {
            let back = eye - target;
            match back.x == 0.0 && back.y == 0.0 && back.z > 0.0 {
                true => Mat4::from_translation(-eye),
                false => knobs::look_at(LookKnobs::default(), eye, target, up),
            }
        })
    });
    fails("v = 0 answered without u", || {
        ch3::check_barycentric_inside(|p, tri| {
            let got = knobs::inside(InsideKnobs::default(), p, tri);
            let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
            let n = e1.cross(e2);
            let v = n.dot(e1.cross(p - tri[0])) / n.dot(n);
            match v == 0.0 {
                true => Some((n.dot((p - tri[0]).cross(e2)) / n.dot(n), 0.0)),
                false => got,
            }
        })
    });
    fails("an axis normal taken as unit", || {
        ch3::check_ray_plane(|o, d, n, c| {
            let denom = n.dot(d);
            if denom == 0.0 {
                return None;
            }
            match (n.y, n.z) {
                (0.0, 0.0) => Some((c - o.x) / d.x),
                _ => Some((c - n.dot(o)) / denom),
            }
        })
    });
    fails(
        "on the x axis through the centre, no absolute value",
        || {
            ch4::check_sphere_sdf(|p, c, r| {
                let d = p - c;
                match d.y == 0.0 && d.z == 0.0 {
                    true => d.x - r,
                    false => d.length() - r,
                }
            })
        },
    );
    fails("the budget as an i32", || {
        ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
            let steps = (steps as i32).max(0) as u32;
            knobs::sphere_trace(MarchKnobs::default(), sdf, (o, d), eps, steps, max)
        })
    });
    fails("no march on a budget of one", || {
        ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
            let k = MarchKnobs::default();
            (steps > 1)
                .then(|| knobs::sphere_trace(k, sdf, (o, d), eps, steps, max))
                .flatten()
        })
    });
}

#[test]
fn exact_special_values_of_light_fail() {
    fails("only an infinite density made 0", || {
        ch5::check_area_pdf(|pdf, x, y, n| {
            let to = x - y;
            let d2 = to.length_squared();
            let v = pdf * d2 / n.dot(to / d2.sqrt()).abs();
            if v.is_infinite() {
                0.0
            } else {
                v
            }
        })
    });
    fails("the side by ceil(z)", || {
        ch5::check_lambert_brdf(|rho, wo, wi| {
            let same = wo.z != 0.0 && wi.z != 0.0 && wo.z.ceil() == wi.z.ceil();
            if same {
                rho / std::f32::consts::PI
            } else {
                Vec3::ZERO
            }
        })
    });
    fails("numbers exactly 0 skipped", || {
        ch6::check_mc_integral(|f, a, b, u| {
            let used: Vec<f64> = u.iter().copied().filter(|&v| v != 0.0).collect();
            let sum: f64 = used.iter().map(|&v| f(a + v * (b - a))).sum();
            (b - a) * sum / used.len() as f64
        })
    });
}

/// Two of the set's wrong solutions that the checks added for it catch as
/// well (direct_light's distances to 10⁴ sizes, bounce_layers' two light
/// samples at one vertex), kept here so that they stay caught.
#[test]
fn exact_special_values_caught_by_the_same_checks_fail() {
    fails("lights beyond 1000 m cut off", || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
            match (y - p).length_squared() > 1.0e6 {
                true => Vec3::ZERO,
                false => knobs::direct(DirectKnobs::default(), (p, n, rho), (y, nl, a, le), v),
            }
        })
    });
    fails("a repeated (vertex, how) dropped as a duplicate", || {
        check_bounce_layers(|path| {
            let mut kept: Vec<Gathered> = Vec::new();
            for g in path {
                if !kept.iter().any(|k| k.vertex == g.vertex && k.how == g.how) {
                    kept.push(*g);
                }
            }
            knobs::layers(LayersKnobs::default(), &kept)
        })
    });
}
