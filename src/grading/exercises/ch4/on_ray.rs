//! Sphere tracing's long marches: every point where the march evaluates
//! the distance function lies on the ray o + t·d (the contract's "march
//! along the ray"), however many steps it takes and however far the ray
//! lies from the world's origin.

use std::cell::RefCell;

use glam::{DVec3, Vec3};

use super::TraceFn;
use crate::exercises::draws::{worst_drawn, Draws};

/// How far a point the march evaluated may lie off the ray, in units of
/// f32's ε times |o| + t + |p|: one rounding of o + t·d (with t·d
/// rounded too) is at most half that, whatever the order of the sums
/// (so four allows any right way of forming the point, and a direction
/// normalized again).
const OFF_RAY: f64 = 4.0;

/// Rays parallel to a plane 1 to 10⁴·h above it (h = 10⁻² to 10²), their
/// origins 10² to 10⁴ h from the world's origin, with max_distance a
/// thousand h: the march takes about a thousand steps of h and ends
/// without a hit. Each point it evaluates must lie on the ray: within
/// [`OFF_RAY`] of the rounding of o + t·d (t the point's distance along
/// the ray). A march that advances its point by p += d·dir instead of
/// forming o + t·d adds a rounding at every step, and after a thousand
/// of them the point has left the ray.
pub(super) fn long_marches(f: TraceFn) -> (f64, String) {
    let mut draws = Draws::new(543);
    worst_drawn((0..draws.count(4, 8)).map(|_| {
        draws.next_case();
        let h = draws.decades(-2.0, 2.0);
        let n = draws.direction();
        let c = draws.direction() * h * draws.decades(2.0, 4.0);
        let along = n
            .cross(draws.direction())
            .normalize_or(n.any_orthonormal_vector());
        let origin = c + n * h;
        let max_distance = 1000.0 * h;
        let (cd, nd) = (c.as_dvec3(), n.as_dvec3());
        let points = RefCell::new(Vec::new());
        let sdf = |p: Vec3| {
            points.borrow_mut().push(p);
            (p.as_dvec3() - cd).dot(nd) as f32
        };
        let got = f(&sdf, origin, along, h * 1e-3, 4096, max_distance);
        let (off, at) = worst_off_ray(origin, along, &points.borrow());
        let error = if got.is_some() { f64::INFINITY } else { off };
        (
            error,
            format!(
                "a ray from {origin} along {along}, parallel to a plane {h} below it (ε = {}, \
                 max_distance = {max_distance}): got {got:?}, expected None; {at}",
                h * 1e-3
            ),
        )
    }))
}

/// The largest distance from the ray (`o`, `d`) of the `points`, over
/// f32's ε times |o| + t + |p| (t how far along the ray the point lies),
/// as an error that passes up to 10⁻⁵ (the check's tolerance), and what
/// it says.
fn worst_off_ray(o: Vec3, d: Vec3, points: &[Vec3]) -> (f64, String) {
    let (od, dd) = (o.as_dvec3(), d.as_dvec3().normalize());
    let mut worst = (0.0, String::from("every evaluated point lies on the ray"));
    for (k, p) in points.iter().enumerate() {
        let rel: DVec3 = p.as_dvec3() - od;
        let t = rel.dot(dd);
        let off = (rel - dd * t).length();
        let scale = f32::EPSILON as f64 * (od.length() + t.abs() + p.as_dvec3().length());
        let units = off / scale;
        if units > worst.0 {
            worst = (
                units,
                format!(
                    "evaluation {} was at {p}, {off:.3e} off the ray at t = {t:.6e} \
                     ({units:.1} times f32's ε · (|o| + t + |p|), at most {OFF_RAY}): march \
                     along the ray, forming each point as o + t·d",
                    k + 1
                ),
            );
        }
    }
    // Within OFF_RAY: no error; past it, a multiple of the tolerance.
    let error = if worst.0 <= OFF_RAY {
        0.0
    } else {
        1e-5 * worst.0 / OFF_RAY * 10.0
    };
    (error, worst.1)
}
