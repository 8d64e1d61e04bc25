//! The fifteenth fresh set (2026-11-29): wrong solutions in what a
//! function does besides its value (calls, buffers, counters), in integer
//! arithmetic, and in a rare branch of an otherwise right function. Of 77
//! wrong ones, 11 passed; these, written as closures over the course's
//! solutions, now fail under every seed tried.

use glam::{Vec2, Vec3};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch2, ch4, ch6};

use super::fails_every;
use super::knobs::{self, SceneKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [151, 152, 157, 0x2026_1129];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// Twice the signed area of (a, b, c).
fn area2(a: Vec2, b: Vec2, c: Vec2) -> f32 {
    (b - a).perp_dot(c - a)
}

#[test]
fn counters_and_rare_branches_fail() {
    fails("corner pk answered as pj's (a copied shortcut)", || {
        ch2::check_barycentric(|pi, pj, pk, p| {
            let whole = area2(pi, pj, pk);
            if whole == 0.0 {
                return None;
            }
            match p {
                p if p == pi => Some(Vec3::X),
                p if p == pj || p == pk => Some(Vec3::Y),
                _ => Some(Vec3::new(area2(pj, pk, p), area2(pk, pi, p), area2(pi, pj, p)) / whole),
            }
        })
    });
    fails("an edge of no length measured as |p - a|", || {
        ch2::check_edge_function(|a, b, p| match a == b {
            true => (p - a).length(),
            false => (b - a).perp_dot(p - a),
        })
    });
    fails("the evaluations counted in a byte", || {
        ch4::check_trace_scene(|sdf, o, d, m| {
            let byte = raystep::ch4_implicit_surfaces::march::March {
                max_steps: match m.max_steps {
                    // A u8 counter never reaches a budget of 256 or more.
                    256.. => u32::MAX,
                    n => n,
                },
                ..*m
            };
            knobs::trace_scene(SceneKnobs::default(), sdf, o, d, &byte)
        })
    });
    fails("the count of numbers as a u16", || {
        ch6::check_mc_integral(|f, a, b, u| {
            let sum: f64 = u.iter().map(|&v| f(a + v * (b - a))).sum();
            (b - a) * sum / f64::from(u.len() as u16)
        })
    });
    fails("survival when u > 1 - q (u = 0 dies at q = 1)", || {
        ch6::check_russian_roulette(|value, q, u| match u > 1.0 - q {
            true => value / q,
            false => 0.0,
        })
    });
}
