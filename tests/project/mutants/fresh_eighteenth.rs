//! The eighteenth fresh set (2026-11-30): clauses read another way, and
//! the exact ends of each stated domain. Of 41 wrong ones, 8 passed under
//! at least one of three seeds; these five, written as closures over the
//! course's solutions, now fail under every seed tried.

use glam::{Vec2, Vec3};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch1, ch2, ch3};

use super::fails_every;
use super::knobs::{self, InsideKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [181, 182, 187, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// Whether two edges from one corner point the same way or opposite
/// ways, by the cosine of their unit vectors (1 for a sliver too).
fn unit_cosine_is_one(e1: Vec3, e2: Vec3) -> bool {
    e1.normalize().dot(e2.normalize()).abs() >= 1.0
}

#[test]
fn misread_clauses_and_domain_ends_fail() {
    fails(
        "a depth past -f32::MIN_POSITIVE taken as on the camera's plane",
        || {
            ch1::check_project_point(|p| {
                (p.z < -f32::MIN_POSITIVE).then(|| Vec2::new(p.x / -p.z, p.y / -p.z))
            })
        },
    );
    fails(
        "a triangle whose unit edges' cosine rounds to 1 taken as flat",
        || {
            ch2::check_barycentric(|pi, pj, pk, p| {
                let area = (pj - pi).perp_dot(pk - pi);
                if area == 0.0 || unit_cosine_is_one((pj - pi).extend(0.0), (pk - pi).extend(0.0)) {
                    return None;
                }
                let e = |a: Vec2, b: Vec2| (b - a).perp_dot(p - a);
                Some(Vec3::new(e(pj, pk), e(pk, pi), e(pi, pj)) / area)
            })
        },
    );
    fails("the edge function scaled by 1/|b - a| and back", || {
        ch2::check_edge_function(|a, b, p| {
            let (e, q) = (b - a, p - a);
            let l = e.length();
            match l == 0.0 {
                true => 0.0,
                false => (e / l).perp_dot(q / l) * (l * l),
            }
        })
    });
    fails("a sliver taken as flat by its unit edges' cosine", || {
        ch3::check_barycentric_inside(|p, tri| {
            match unit_cosine_is_one(tri[1] - tri[0], tri[2] - tri[0]) {
                true => None,
                false => knobs::inside(InsideKnobs::default(), p, tri),
            }
        })
    });
    fails("parallel where |N . d| < 1e-30", || {
        ch3::check_ray_plane(|o, d, n, c| {
            let den = n.dot(d);
            (den.abs() >= 1e-30).then(|| (c - n.dot(o)) / den)
        })
    });
}
