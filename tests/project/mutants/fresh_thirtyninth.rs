//! The thirty-ninth fresh set (2026-12-01), three testers who read the
//! stubs, the book and the course's solutions but not the grader: H,
//! right solutions that cost far more than the course's (recursion,
//! allocation, brute force, f64, compensated sums) and the shortcuts that
//! make them cheap (33 wrong, 29 right); I, clause by clause, chapters 1,
//! 4 and 5 (53 wrong, 17 right); J, clause by clause, chapters 2, 3 and 6
//! (74 wrong, 22 right). Every right one passes. With the grader of
//! d347320, 3 of the 160 wrong ones passed under at least one of seeds
//! 51 to 53. The one here now fails under seeds 51 to 55 (a fifth of
//! Möller–Trumbore's drawn triangles now sit 10^4.5 to 10^5 sizes from
//! the origin). The other two are outside the roulette's contract, which
//! lets no survivor be below q = 10⁻¹⁵: u and q compared in f32 (nothing
//! survives below 10⁻⁴⁵) and survivors worth 0 where 1/q passes 10¹⁰⁰.

use glam::Vec3;
use raystep::grading::exercise::Check;
use raystep::grading::exercises::ch3;

use super::fails_every;

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [51, 52, 53, 0x2026_1207];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

/// The course's u and v, but t from the plane through p0 written in the
/// world's coordinates, n·p0 − n·o: both terms as large as the
/// coordinates, their difference as small as the distance.
fn moller_t_in_world_coordinates(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
    let n = e1.cross(e2);
    if n.dot(d) == 0.0 {
        return None;
    }
    let t = (n.dot(tri[0]) - n.dot(o)) / n.dot(d);
    let (s, q) = (o - tri[0], d.cross(e2));
    let det = e1.dot(q);
    let (u, v) = (s.dot(q) / det, d.dot(s.cross(e1)) / det);
    (t > 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.0).then_some((t, u, v))
}

#[test]
fn t_from_the_plane_in_world_coordinates_fails() {
    fails("moller_trumbore: t = (n·p0 − n·o) / n·d", || {
        ch3::check_moller_trumbore(moller_t_in_world_coordinates)
    });
}
