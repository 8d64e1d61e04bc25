//! The fourteenth fresh set (2026-11-29): wrong solutions that keep
//! something between calls (a memo keyed on some of the arguments, a
//! counter of calls, the last ray's hit), or that turn a black colour
//! into 0/0. Of 96 wrong ones, 22 passed; these, written as closures over
//! the course's solutions, now fail under every seed tried (most of them
//! by the probe of `grading/exercises/stateless.rs`).

use std::cell::Cell;

use glam::{Mat4, Vec2, Vec3};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch1, ch3, ch4, ch5};

use super::fails_every;
use super::knobs::{self, DirectKnobs, LookKnobs, MarchKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [141, 142, 147, 0x2026_1129];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// What draw_edges answers.
type Cut = Option<(Vec2, Vec2)>;

thread_local! {
    static LOOK: Cell<Option<((Vec3, Vec3), Mat4)>> = const { Cell::new(None) };
    static PROJECTED: Cell<Option<((f32, f32), Vec2)>> = const { Cell::new(None) };
    static DENSITY: Cell<Option<((Vec3, Vec3), f32)>> = const { Cell::new(None) };
    static LENGTHS: Cell<Option<(Vec3, [f32; 3])>> = const { Cell::new(None) };
    static EDGE: Cell<Option<((Vec3, Vec3), Cut)>> = const { Cell::new(None) };
    static CALLS: Cell<u32> = const { Cell::new(0) };
    static LAST_HIT: Cell<Option<f32>> = const { Cell::new(None) };
}

/// `answer()`, or what `memo` holds for `key`; `memo` then holds `key`'s.
fn memo<K: PartialEq + Copy, V: Copy>(
    memo: &'static std::thread::LocalKey<Cell<Option<(K, V)>>>,
    key: K,
    answer: impl FnOnce() -> V,
) -> V {
    if let Some((k, v)) = memo.with(Cell::get) {
        if k == key {
            return v;
        }
    }
    let v = answer();
    memo.with(|m| m.set(Some((key, v))));
    v
}

/// The solid angle by Van Oosterom and Strackee's formula, with the
/// corners' distances from `lengths`.
fn solid(p: Vec3, tri: [Vec3; 3], lengths: [f32; 3]) -> f32 {
    let [a, b, c] = tri.map(|v| v - p);
    let [la, lb, lc] = lengths;
    let numerator = a.dot(b.cross(c)).abs();
    let denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    2.0 * numerator.atan2(denominator)
}

#[test]
fn answers_kept_between_calls_fail() {
    fails("the view kept for (eye, target), whatever up", || {
        ch1::check_look_at(|eye, target, up| {
            let k = LookKnobs::default();
            memo(&LOOK, (eye, target), || knobs::look_at(k, eye, target, up))
        })
    });
    fails("the projection kept for (x, z), whatever y", || {
        ch1::check_project_point(|p| {
            (p.z < 0.0).then(|| memo(&PROJECTED, (p.x, p.z), || p.truncate() / -p.z))
        })
    });
    fails("the cut kept for the edge, whatever near", || {
        ch1::check_draw_edges(|camera, a, b, near| {
            memo(&EDGE, (a, b), || ch1::reference_edge(camera, a, b, near))
        })
    });
    fails(
        "the density kept for (x, y), whatever the light's normal",
        || {
            ch5::check_area_pdf(|pdf, x, y, n| {
                memo(&DENSITY, (x, y), || {
                    let to = x - y;
                    let d2 = to.length_squared();
                    pdf * d2 / n.dot(to / d2.sqrt()).abs()
                })
            })
        },
    );
    fails("the corners' distances kept for p", || {
        ch5::check_solid_angle(|p, tri| {
            let lengths = memo(&LENGTHS, p, || tri.map(|v| (v - p).length()));
            solid(p, tri, lengths)
        })
    });
    fails("a cheaper length after 2,000 calls", || {
        ch4::check_sphere_sdf(|p, c, r| {
            let calls = CALLS.with(|n| {
                n.set(n.get() + 1);
                n.get()
            });
            let d = p - c;
            match calls > 2048 {
                true => d.length_squared() * (1.001 / d.length()) - r,
                false => d.length() - r,
            }
        })
    });
    fails("a march that starts at 0.9 of the last ray's hit", || {
        ch4::check_sphere_trace(|sdf, o, d, eps, steps, max| {
            let k = MarchKnobs::default();
            let start = LAST_HIT.with(Cell::get).filter(|&t| sdf(o) >= 0.5 * t);
            let hit = match start {
                Some(t) => knobs::sphere_trace(k, sdf, (o + d * 0.9 * t, d), eps, steps, max)
                    .map(|s| s + 0.9 * t),
                None => knobs::sphere_trace(k, sdf, (o, d), eps, steps, max),
            };
            LAST_HIT.with(|h| h.set(hit.or(h.get())));
            hit
        })
    });
}

#[test]
fn black_colours_and_repeated_corners_fail() {
    fails("ρ as its hue times its largest channel", || {
        ch5::check_lambert_brdf(|rho, wo, wi| {
            let m = rho.max_element();
            let same = wo.z * wi.z > 0.0;
            if same {
                rho / m * m / std::f32::consts::PI
            } else {
                Vec3::ZERO
            }
        })
    });
    fails("I as its hue times its largest channel", || {
        ch5::check_point_light(|i, light, p, n| {
            let m = i.max_element();
            let to = light - p;
            let r2 = to.length_squared();
            i / m * m * n.dot(to / r2.sqrt()).max(0.0) / r2
        })
    });
    fails("Le as its hue times its largest channel", || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
            let m = le.max_element();
            knobs::direct(
                DirectKnobs::default(),
                (p, n, rho),
                (y, nl, a, le / m * m),
                v,
            )
        })
    });
    fails(
        "edges made unit first (a corner given twice: NaN, not None)",
        || {
            ch3::check_moller_trumbore(|o, d, tri| {
                let (e1, e2) = ((tri[1] - tri[0]).normalize(), (tri[2] - tri[0]).normalize());
                let (l1, l2) = ((tri[1] - tri[0]).length(), (tri[2] - tri[0]).length());
                let det = e1.dot(e2.cross(-d));
                if det == 0.0 {
                    return None;
                }
                let s = o - tri[0];
                let t = e1.dot(e2.cross(s)) / det;
                let u = s.dot(e2.cross(-d)) / det / l1;
                let v = e1.dot(s.cross(-d)) / det / l2;
                if u < 0.0 || v < 0.0 || u + v > 1.0 || t <= 0.0 {
                    return None;
                }
                Some((t, u, v))
            })
        },
    );
}
