//! Exercise 3.4's hand-built trees and rays: a shuffled stack of
//! triangles, one flat triangle (a box of no thickness), and rays from
//! inside the Cornell box.

use glam::Vec3;

use crate::ch3_ray_triangle::ray::Ray;
use crate::core::sampling::random;
use crate::counted::ReadableBvh;
use crate::exercises::draws::Draws;

/// The hand-built cases: a stack of sixteen small triangles along z,
/// shuffled so that the list order is not the depth order, seen from
/// above, from below, cut short by t_max (before, at and past a hit),
/// beside it and slanted; and a thin stack beside it.
pub(super) fn stack_cases() -> (ReadableBvh, Vec<(Ray, f32, &'static str)>) {
    let stack: Vec<[Vec3; 3]> = (0..16)
        .map(|i| {
            let z = -1.0 - ((i * 7) % 16) as f32;
            let o = Vec3::new(0.1 * i as f32, 0.0, z);
            [
                o + Vec3::new(-2.0, -1.0, 0.0),
                o + Vec3::new(2.0, -1.0, 0.0),
                o + Vec3::new(0.0, 2.0, 0.0),
            ]
        })
        .chain((0..6).map(|k| {
            // A thin stack beside it, 3·10⁻⁵ apart, farthest first in the
            // list: the nearest is nearer by less than 10⁻⁴.
            let o = Vec3::new(10.0, 0.0, -1.0 - (5 - k) as f32 * 3e-5);
            [
                o + Vec3::new(-1.0, -1.0, 0.0),
                o + Vec3::new(1.0, -1.0, 0.0),
                o + Vec3::new(0.0, 1.0, 0.0),
            ]
        }))
        .collect();
    let down = |x: f32, y: f32| Ray::new(Vec3::new(x, y, 1.0), -Vec3::Z).expect("a ray");
    let up = Ray::new(Vec3::new(0.5, 0.0, -30.0), Vec3::Z).expect("a ray");
    let slant = Ray::new(Vec3::new(0.5, 0.0, 1.0), Vec3::new(0.05, 0.02, -1.0)).expect("a ray");
    let inf = f32::INFINITY;
    let cases = vec![
        (down(0.5, 0.0), inf, "straight down a stack of 16 triangles"),
        (up, inf, "straight up the same stack from below"),
        (
            down(0.5, 0.0),
            1.5,
            "down the stack, t_max before the first hit",
        ),
        (
            down(0.5, 0.0),
            2.5,
            "down the stack, t_max just past the first hit",
        ),
        (
            down(0.5, 0.0),
            2.0,
            "down the stack, t_max exactly at the first hit (the interval (0, t_max] keeps it)",
        ),
        (up, 20.0, "up the stack, t_max = 20 past several hits"),
        (
            down(10.0, 0.0),
            inf,
            "down a thin stack of 6 triangles 3·10⁻⁵ apart, the farthest listed first",
        ),
        (down(50.0, 0.0), inf, "beside the stack: a miss"),
        (slant, inf, "slanted through the stack"),
        (
            {
                // A hit at t from 10⁻⁶ to 10⁻⁴, drawn for the run: the
                // interval is (0, t_max), with no margin at its start.
                let h = Draws::new(39).decades(-6.0, -4.0);
                Ray::new(Vec3::new(0.5, 0.0, -1.0 + h), -Vec3::Z).expect("a ray")
            },
            inf,
            "from just above the top triangle, a hit closer than 10⁻⁴",
        ),
        (
            Ray::new(Vec3::new(0.5, 0.0, -1.0 + 2e-5), -Vec3::Z).expect("a ray"),
            5e-5,
            "from 2·10⁻⁵ above the top triangle, t_max = 5·10⁻⁵: a hit however short the interval",
        ),
    ];
    (ReadableBvh::build(&stack), cases)
}

/// One flat triangle (its box has no thickness: the box is entered where
/// the triangle is hit, to rounding), and 500 rays from anywhere at drawn
/// points of it: the hit is in (0, t_max), wherever the box starts.
/// `far`: the triangle 10^3.5 to 10^4 of its size from the origin, the rays
/// from 0.05 to 1 of its size away and aimed a hair off their drawn
/// points, so that a hit point rounds by far more than 10⁻⁵ of t (a t
/// measured back from that point is not the test's).
pub(super) fn flat_triangle(far: bool) -> (ReadableBvh, Vec<(Ray, String)>) {
    let mut d = Draws::new(if far { 37 } else { 36 });
    let z = d.range(-2.0, 2.0);
    let shift = match far {
        true => d.direction() * d.decades(3.5, 4.0),
        false => Vec3::ZERO,
    };
    let flat = [
        Vec3::new(d.range(-1.0, 0.0), d.range(-1.0, 0.0), z),
        Vec3::new(d.range(0.0, 1.0), d.range(-1.0, 0.0), z),
        Vec3::new(d.range(-1.0, 1.0), d.range(0.0, 1.0), z),
    ]
    .map(|p| p + shift);
    let rays = (0..500)
        .filter_map(|_| {
            d.next_case();
            let (u, v) = (d.range(0.05, 0.45), d.range(0.05, 0.45));
            let target = flat[0] + u * (flat[1] - flat[0]) + v * (flat[2] - flat[0]);
            let away = match far {
                true => d.range(0.05, 1.0),
                false => d.range(1.0, 10.0),
            };
            let origin = target + d.direction() * away;
            // Far, a hair off the drawn point: the hit is then where the
            // line meets the plane, not a point f32 holds exactly.
            let tilt = match far {
                true => d.in_cube() * 0.01 * away,
                false => Vec3::ZERO,
            };
            let ray = Ray::new(origin, target - origin + tilt).ok()?;
            Some((
                ray,
                format!("a flat triangle {flat:?}, a ray from {origin} at {target}"),
            ))
        })
        .collect();
    (ReadableBvh::build(&[flat]), rays)
}

/// `rays` again, cut short: t_max 0.05 to 1.2 times the distance
/// `hit_t(ray)` to the ray's closest hit, or (two thirds of them)
/// 10^-5.5 to 10⁻² of it short of the hit or past it (drawn for the run;
/// rays that hit nothing are left out). Every box the ray enters before
/// t_max is then searched, and a hit found there beyond t_max is no
/// answer. (Not closer: within a few ulps of the hit, the watertight
/// test's own rounding decides, ts ≤ t_max · det.)
pub(super) fn cut_short(
    rays: &[(Ray, String)],
    hit_t: impl Fn(&Ray) -> Option<f32>,
) -> Vec<(Ray, f32, String)> {
    let rays = rays.iter().enumerate();
    rays.filter_map(|(i, (ray, what))| {
        let r = |d| random(36 ^ crate::run_seed(), i as u64, 0, d);
        let near = 10f32.powf(-5.5 + 3.5 * r(1));
        let share = match i % 3 {
            0 => 1.0 - near,
            1 => 1.0 + near,
            _ => 0.05 + 1.15 * r(0),
        };
        let t_max = hit_t(ray)? * share;
        Some((*ray, t_max, format!("{what}, cut short at t_max = {t_max}")))
    })
    .collect()
}

/// Rays from inside the Cornell box (`tris`), new for every grading run:
/// 2,000 along drawn directions, and 2,000 aimed at points 10⁻⁵ to 10⁻³
/// of an edge's length inside a triangle's edge, where a wall's box has
/// its side (a slab test a hair off, an approximate 1/d, loses those
/// hits).
pub(super) fn cornell_inside_rays(tris: &[[Vec3; 3]]) -> Vec<(Ray, String)> {
    let (lo, hi) = tris
        .iter()
        .flatten()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    let mut rays = Vec::new();
    for i in 0..2000u64 {
        let r = |d| random(34 ^ crate::run_seed(), i, 0, d);
        let origin = lo + (hi - lo) * Vec3::new(r(0), r(1), r(2));
        if let Ok(ray) = Ray::new(origin, Vec3::new(r(3), r(4), r(5)) * 2.0 - 1.0) {
            let what = format!(
                "a ray inside the Cornell box from {origin} along {}",
                ray.dir
            );
            rays.push((ray, what));
        }
    }
    for i in 0..2000u64 {
        let r = |d| random(35 ^ crate::run_seed(), i, 0, d);
        let origin = lo + (hi - lo) * Vec3::new(r(0), r(1), r(2));
        let tri = tris[((r(3) * tris.len() as f32) as usize).min(tris.len() - 1)];
        let k = ((r(4) * 3.0) as usize).min(2);
        let (a, b, c) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
        let inward = 10f32.powf(-5.0 + 2.0 * r(5));
        let at = a + (b - a) * r(6) + (c - a) * inward * 0.5;
        if let Ok(ray) = Ray::new(origin, at - origin) {
            let what = format!(
                "a ray inside the Cornell box from {origin} along {}, aimed just inside a \
                 triangle's edge",
                ray.dir
            );
            rays.push((ray, what));
        }
    }
    rays
}

/// Rays along -z from 10,000 away, 10⁻⁶ inside two sides of the box of
/// [`check_bvh_traversal`](super::check_bvh_traversal)'s wall (its
/// direction's zeros of both signs: +0 towards the side x = 10, -0
/// towards y = -10; a zero stands for no drift at all, however far the
/// ray goes, and a tiny stand-in for it drifts out of the box before the
/// hit).
pub(super) fn side_rays() -> Vec<(Ray, String)> {
    [
        (
            Vec3::new(10.0 - 1e-6, 0.0, 1e4),
            Vec3::new(0.0, 0.0, -1.0),
            "x = 10",
        ),
        (
            Vec3::new(0.0, -10.0 + 1e-6, 1e4),
            Vec3::new(-0.0, -0.0, -1.0),
            "y = -10",
        ),
    ]
    .into_iter()
    .map(|(origin, dir, side)| {
        let ray = Ray::new(origin, dir).expect("a ray");
        let what = format!(
            "a ray along {} 10⁻⁶ inside its box's side {side}, the hit 10,000 away",
            ray.dir
        );
        (ray, what)
    })
    .collect()
}

/// A triangle 2·10⁶ to 3·10⁷ away and rays at it, for t_max infinite (no
/// distance is too far).
pub(super) fn far_triangle() -> (ReadableBvh, Vec<(Ray, String)>) {
    let mut afar = Draws::new(236);
    let d = afar.decades(6.3, 7.5);
    let far_wall = ReadableBvh::build(&[[
        Vec3::new(-0.25 * d, -0.25 * d, -d),
        Vec3::new(0.25 * d, -0.25 * d, -d),
        Vec3::new(0.0, 0.25 * d, -d),
    ]]);
    let rays = (0..4)
        .map(|_| {
            afar.next_case();
            let dir = Vec3::new(afar.range(-0.1, 0.1), afar.range(-0.1, 0.1), -1.0);
            let ray = Ray::new(Vec3::ZERO, dir).expect("a ray");
            let what = format!("a triangle {d:e} away, along {}", ray.dir);
            (ray, what)
        })
        .collect();
    (far_wall, rays)
}
