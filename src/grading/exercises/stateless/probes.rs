//! Each exercise's probe: its questions drawn in its domain (the numbers
//! of its arguments in order), and how a question is asked, by the
//! student's function and by the reference. Each asks its questions
//! again after decoys ([`changed_answer`]), then each decoy right after
//! its question ([`same_for_decoy`]), then beside their twins
//! ([`same_for_near`]): which arguments a twin moves (one at a time) and
//! which numbers are lengths.
//! Three have no twins, so no reference either: the statistical exercises
//! (the cosine map, roulette), whose right answers may differ from the
//! reference's at every point, and barycentric_inside, whose points must
//! stay in the triangle's plane. Refraction's probe is beside its check
//! (`refraction.rs`), with the exact answer it needs.

// (`&[3..6]` is a list of the ranges taken whole, with one in it.)
#![allow(clippy::single_range_in_vec_init)]

use std::fmt::Debug;
use std::ops::Range;

use glam::{DVec3, Vec2, Vec3};

use super::super::twins::{same_for_decoy, same_for_near, Twins};
use super::{changed_answer, decoys, nums2, nums3, vec2_at, vec3_at, Questions};
use crate::ch1_projection::camera::{Camera, CameraDesc};
use crate::exercises::draws::Draws;

/// How many questions a probe draws.
const COUNT: usize = 24;

/// [`balanced`] with no pairs moved towards each other: the twins'
/// numbers (nudged, lengths) and salt.
pub(crate) fn both<R: Debug>(
    q: &Questions,
    (nudged, lengths): (&[Range<usize>], &[Range<usize>]),
    salt: u64,
    ask: impl Fn(&[f64]) -> R,
    right: impl Fn(&[f64]) -> R,
) -> Option<String> {
    balanced(q, (nudged, &[], lengths), salt, ask, right)
}

/// A probe's twins: the arguments nudged one at a time, the pairs of them
/// moved towards each other, and the lengths ([`Twins`]'s fields).
type Moves<'a> = (&'a [Range<usize>], &'a [(usize, usize)], &'a [Range<usize>]);

/// [`changed_answer`], then [`same_for_decoy`] and [`same_for_near`],
/// whose twins move the arguments `nudged`, the pairs of points
/// `balanced` (indices into `nudged`) towards each other, and scale the
/// `lengths`.
fn balanced<R: Debug>(
    q: &Questions,
    (nudged, balanced, lengths): Moves,
    salt: u64,
    ask: impl Fn(&[f64]) -> R,
    right: impl Fn(&[f64]) -> R,
) -> Option<String> {
    let twins = Twins {
        nudged,
        balanced,
        lengths,
    };
    changed_answer(q, &ask)
        .or_else(|| same_for_decoy(&q.cases, &decoys(q), &twins, salt + 500, &ask, &right))
        .or_else(|| same_for_near(&q.cases, &twins, salt, &ask, &right))
}

/// Every pair of three arguments, and of four.
const PAIRS_OF_3: [(usize, usize); 3] = [(0, 1), (0, 2), (1, 2)];
const PAIRS_OF_4: [(usize, usize); 6] = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];

pub(crate) fn draw(
    salt: u64,
    whole: &[std::ops::Range<usize>],
    mut one: impl FnMut(&mut Draws) -> Vec<f64>,
) -> Questions {
    let mut d = Draws::new(salt);
    Questions::drawn(COUNT, whole, || {
        d.next_case();
        one(&mut d)
    })
}

/// A point anywhere in a cube of side 20 around the origin.
fn point(d: &mut Draws) -> Vec3 {
    d.in_cube() * 10.0
}

/// The numbers of several vectors, one after another.
pub(crate) fn cat(vs: &[Vec3]) -> Vec<f64> {
    vs.iter().flat_map(|v| nums3(*v)).collect()
}

/// project_point(p), p in front of the camera or not.
pub fn project_point<R: Debug>(
    f: impl Fn(Vec3) -> R,
    reference: impl Fn(Vec3) -> R,
) -> Option<String> {
    let q = draw(91, &[], |d| cat(&[point(d)]));
    let ask = |n: &[f64]| f(vec3_at(n, 0));
    let right = |n: &[f64]| reference(vec3_at(n, 0));
    both(&q, (&[0..3], &[0..3]), 191, ask, right)
}

/// look_at(eye, target, up), up taken whole.
pub fn look_at<R: Debug>(
    f: impl Fn(Vec3, Vec3, Vec3) -> R,
    reference: impl Fn(Vec3, Vec3, Vec3) -> R,
) -> Option<String> {
    let q = draw(92, &[6..9], |d| cat(&[point(d), point(d), d.direction()]));
    let ask = |n: &[f64]| f(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6));
    let right = |n: &[f64]| reference(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6));
    balanced(&q, (&[0..3, 3..6], &[(0, 1)], &[0..6]), 192, ask, right)
}

/// draw_edges(camera, a, b, near), the camera (its eye and target)
/// taken whole: a memo keyed on the world points alone answers another
/// camera's question with the first camera's raster points.
pub fn draw_edges<R: Debug>(
    f: impl Fn(&Camera, Vec3, Vec3, f32) -> R,
    reference: impl Fn(&Camera, Vec3, Vec3, f32) -> R,
) -> Option<String> {
    let q = draw(109, &[0..6], |d| {
        let eye = point(d);
        // Never straight up or down (up is +y).
        let ahead = d.direction();
        let ahead = match ahead.y.abs() > 0.9 {
            true => Vec3::new(ahead.x + 0.5, 0.0, ahead.z).normalize(),
            false => ahead,
        };
        let mut v = cat(&[eye, eye + ahead * d.range(1.0, 5.0), point(d), point(d)]);
        v.push(d.range(0.01, 2.0) as f64);
        v
    });
    let camera = |n: &[f64]| {
        Camera::new(CameraDesc {
            eye: vec3_at(n, 0).as_dvec3(),
            target: vec3_at(n, 3).as_dvec3(),
            up: DVec3::Y,
            fov_degrees: 70.0,
            width: 320,
            height: 200,
        })
        .ok()
    };
    // (A camera that cannot be made, which the draws avoid, asks nothing.)
    let ask = |n: &[f64]| camera(n).map(|c| f(&c, vec3_at(n, 6), vec3_at(n, 9), n[12] as f32));
    let right =
        |n: &[f64]| camera(n).map(|c| reference(&c, vec3_at(n, 6), vec3_at(n, 9), n[12] as f32));
    balanced(
        &q,
        (&[6..9, 9..12, 12..13], &[(0, 1)], &[0..13]),
        209,
        ask,
        right,
    )
}

/// edge_function(a, b, p).
pub fn edge_function<R: Debug>(
    f: impl Fn(Vec2, Vec2, Vec2) -> R,
    reference: impl Fn(Vec2, Vec2, Vec2) -> R,
) -> Option<String> {
    let q = draw(93, &[], |d| {
        [point(d), point(d), point(d)]
            .iter()
            .flat_map(|v| nums2(v.truncate()))
            .collect()
    });
    let ask = |n: &[f64]| f(vec2_at(n, 0), vec2_at(n, 2), vec2_at(n, 4));
    let right = |n: &[f64]| reference(vec2_at(n, 0), vec2_at(n, 2), vec2_at(n, 4));
    balanced(
        &q,
        (&[0..2, 2..4, 4..6], &PAIRS_OF_3, &[0..6]),
        193,
        ask,
        right,
    )
}

/// barycentric(pi, pj, pk, p).
pub fn barycentric<R: Debug>(
    f: impl Fn(Vec2, Vec2, Vec2, Vec2) -> R,
    reference: impl Fn(Vec2, Vec2, Vec2, Vec2) -> R,
) -> Option<String> {
    let q = draw(94, &[], |d| {
        (0..4).flat_map(|_| nums2(point(d).truncate())).collect()
    });
    let ask = |n: &[f64]| f(vec2_at(n, 0), vec2_at(n, 2), vec2_at(n, 4), vec2_at(n, 6));
    let right = |n: &[f64]| reference(vec2_at(n, 0), vec2_at(n, 2), vec2_at(n, 4), vec2_at(n, 6));
    balanced(
        &q,
        (&[0..2, 2..4, 4..6, 6..8], &PAIRS_OF_4, &[0..8]),
        194,
        ask,
        right,
    )
}

/// ray_plane(o, d, n, c), the direction and the normal taken whole.
pub fn ray_plane<R: Debug>(
    f: impl Fn(Vec3, Vec3, Vec3, f32) -> R,
    reference: impl Fn(Vec3, Vec3, Vec3, f32) -> R,
) -> Option<String> {
    let q = draw(95, &[3..6, 6..9], |d| {
        let mut v = cat(&[point(d), d.direction(), d.direction()]);
        v.push(d.range(-5.0, 5.0) as f64);
        v
    });
    let ask = |n: &[f64]| f(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6), n[9] as f32);
    let right = |n: &[f64]| reference(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6), n[9] as f32);
    both(&q, (&[0..3, 9..10], &[0..3, 9..10]), 195, ask, right)
}

/// barycentric_inside(p, tri), p in the triangle's plane.
pub fn barycentric_inside<R: Debug>(f: impl Fn(Vec3, [Vec3; 3]) -> R) -> Option<String> {
    let q = draw(96, &[], |d| {
        let t = [point(d), point(d), point(d)];
        let (u, v) = (d.unit(), d.unit());
        cat(&[
            t[0] + (t[1] - t[0]) * u + (t[2] - t[0]) * v,
            t[0],
            t[1],
            t[2],
        ])
    });
    let ask = |n: &[f64]| f(vec3_at(n, 0), [vec3_at(n, 3), vec3_at(n, 6), vec3_at(n, 9)]);
    changed_answer(&q, ask)
}

/// moller_trumbore(o, d, tri), d taken whole.
pub fn moller_trumbore<R: Debug>(
    f: impl Fn(Vec3, Vec3, [Vec3; 3]) -> R,
    reference: impl Fn(Vec3, Vec3, [Vec3; 3]) -> R,
) -> Option<String> {
    let q = draw(97, &[3..6], |d| {
        let t = [point(d), point(d), point(d)];
        let o = point(d);
        let at = (t[0] + t[1] + t[2]) / 3.0 + point(d) * 0.05;
        cat(&[o, (at - o).normalize_or(Vec3::Z), t[0], t[1], t[2]])
    });
    let ask = |n: &[f64]| {
        f(
            vec3_at(n, 0),
            vec3_at(n, 3),
            [vec3_at(n, 6), vec3_at(n, 9), vec3_at(n, 12)],
        )
    };
    let right = |n: &[f64]| {
        reference(
            vec3_at(n, 0),
            vec3_at(n, 3),
            [vec3_at(n, 6), vec3_at(n, 9), vec3_at(n, 12)],
        )
    };
    let triangle = [(1, 2), (1, 3), (2, 3)];
    balanced(
        &q,
        (&[0..3, 6..9, 9..12, 12..15], &triangle, &[0..3, 6..15]),
        197,
        ask,
        right,
    )
}

/// sphere_sdf(p, centre, radius).
pub fn sphere_sdf<R: Debug>(
    f: impl Fn(Vec3, Vec3, f32) -> R,
    reference: impl Fn(Vec3, Vec3, f32) -> R,
) -> Option<String> {
    let q = draw(98, &[], |d| {
        let mut v = cat(&[point(d), point(d)]);
        v.push(d.decades(-1.0, 1.0) as f64);
        v
    });
    let ask = |n: &[f64]| f(vec3_at(n, 0), vec3_at(n, 3), n[6] as f32);
    let right = |n: &[f64]| reference(vec3_at(n, 0), vec3_at(n, 3), n[6] as f32);
    balanced(
        &q,
        (&[0..3, 3..6, 6..7], &[(0, 1)], &[0..7]),
        198,
        ask,
        right,
    )
}

/// gradient_normal(sdf, p, h) on a box and a ball, h from 10⁻⁴ to 10⁻².
pub fn gradient_normal<R: Debug>(
    f: impl Fn(&dyn Fn(Vec3) -> f32, Vec3, f32) -> R,
    reference: impl Fn(&dyn Fn(Vec3) -> f32, Vec3, f32) -> R,
) -> Option<String> {
    let shape =
        |p: Vec3| crate::ch4_implicit_surfaces::primitives::sd_box(p, Vec3::new(1.0, 2.0, 3.0));
    let q = draw(99, &[], |d| {
        let mut v = cat(&[point(d) * 0.5]);
        v.push(d.decades(-4.0, -2.0) as f64);
        v
    });
    let ask = |n: &[f64]| f(&shape, vec3_at(n, 0), n[3] as f32);
    let right = |n: &[f64]| reference(&shape, vec3_at(n, 0), n[3] as f32);
    both(&q, (&[0..3], &[]), 199, ask, right)
}

/// lambert_brdf(rho, wo, wi), the directions taken whole.
pub fn lambert_brdf<R: Debug>(
    f: impl Fn(Vec3, Vec3, Vec3) -> R,
    reference: impl Fn(Vec3, Vec3, Vec3) -> R,
) -> Option<String> {
    let q = draw(100, &[3..6, 6..9], |d| {
        cat(&[
            Vec3::new(d.unit(), d.unit(), d.unit()),
            d.direction(),
            d.direction(),
        ])
    });
    let ask = |n: &[f64]| f(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6));
    let right = |n: &[f64]| reference(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6));
    both(&q, (&[0..3], &[]), 200, ask, right)
}

/// cosine_hemisphere(u).
pub fn cosine_hemisphere<R: Debug>(f: impl Fn(Vec2) -> R) -> Option<String> {
    let q = draw(101, &[], |d| vec![d.unit() as f64, d.unit() as f64]);
    let ask = |n: &[f64]| f(vec2_at(n, 0));
    changed_answer(&q, ask)
}

/// point_light(I, light, p, n), the normal taken whole.
pub fn point_light<R: Debug>(
    f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> R,
    reference: impl Fn(Vec3, Vec3, Vec3, Vec3) -> R,
) -> Option<String> {
    let q = draw(102, &[9..12], |d| {
        let i = Vec3::new(d.unit(), d.unit(), d.unit()) * 10.0;
        cat(&[i, point(d), point(d), d.direction()])
    });
    let ask = |n: &[f64]| f(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6), vec3_at(n, 9));
    let right = |n: &[f64]| reference(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6), vec3_at(n, 9));
    balanced(
        &q,
        (&[0..3, 3..6, 6..9], &[(1, 2)], &[3..9]),
        202,
        ask,
        right,
    )
}

/// area_to_solid_angle(pdf_area, x, y, n_light), the normal taken whole.
pub fn area_pdf<R: Debug>(
    f: impl Fn(f32, Vec3, Vec3, Vec3) -> R,
    reference: impl Fn(f32, Vec3, Vec3, Vec3) -> R,
) -> Option<String> {
    let q = draw(103, &[7..10], |d| {
        let mut v = vec![d.decades(-2.0, 2.0) as f64];
        v.extend(cat(&[point(d), point(d), d.direction()]));
        v
    });
    let ask = |n: &[f64]| f(n[0] as f32, vec3_at(n, 1), vec3_at(n, 4), vec3_at(n, 7));
    let right = |n: &[f64]| reference(n[0] as f32, vec3_at(n, 1), vec3_at(n, 4), vec3_at(n, 7));
    balanced(
        &q,
        (&[0..1, 1..4, 4..7], &[(1, 2)], &[1..7]),
        203,
        ask,
        right,
    )
}

/// solid_angle(p, tri).
pub fn solid_angle<R: Debug>(
    f: impl Fn(Vec3, [Vec3; 3]) -> R,
    reference: impl Fn(Vec3, [Vec3; 3]) -> R,
) -> Option<String> {
    let q = draw(104, &[], |d| cat(&[point(d), point(d), point(d), point(d)]));
    let ask = |n: &[f64]| f(vec3_at(n, 0), [vec3_at(n, 3), vec3_at(n, 6), vec3_at(n, 9)]);
    let right = |n: &[f64]| reference(vec3_at(n, 0), [vec3_at(n, 3), vec3_at(n, 6), vec3_at(n, 9)]);
    balanced(
        &q,
        (&[0..3, 3..6, 6..9, 9..12], &PAIRS_OF_4, &[0..12]),
        204,
        ask,
        right,
    )
}

/// spot_power(I, inner, outer), the two angles taken together (inner
/// ≤ outer).
pub fn spot<R: Debug>(
    f: impl Fn(Vec3, f32, f32) -> R,
    reference: impl Fn(Vec3, f32, f32) -> R,
) -> Option<String> {
    let q = draw(105, &[3..5], |d| {
        let i = Vec3::new(d.unit(), d.unit(), d.unit()) * 10.0;
        let outer = d.range(0.01, 3.0);
        let mut v = cat(&[i]);
        v.extend([(outer * d.unit()) as f64, outer as f64]);
        v
    });
    let ask = |n: &[f64]| f(vec3_at(n, 0), n[3] as f32, n[4] as f32);
    let right = |n: &[f64]| reference(vec3_at(n, 0), n[3] as f32, n[4] as f32);
    both(&q, (&[0..3, 3..4], &[]), 205, ask, right)
}

/// mis_weight(pdf_f, pdf_g).
pub fn mis_weight<R: Debug>(
    f: impl Fn(f64, f64) -> R,
    reference: impl Fn(f64, f64) -> R,
) -> Option<String> {
    let q = draw(106, &[], |d| {
        vec![d.decades(-3.0, 3.0) as f64, d.decades(-3.0, 3.0) as f64]
    });
    let ask = |n: &[f64]| f(n[0], n[1]);
    let right = |n: &[f64]| reference(n[0], n[1]);
    both(&q, (&[0..1, 1..2], &[]), 206, ask, right)
}

/// russian_roulette(value, q, u).
pub fn russian_roulette<R: Debug>(f: impl Fn(f64, f64, f64) -> R) -> Option<String> {
    let q = draw(107, &[], |d| {
        vec![
            d.range(-5.0, 5.0) as f64,
            d.range(0.05, 1.0) as f64,
            d.unit() as f64,
        ]
    });
    let ask = |n: &[f64]| f(n[0], n[1], n[2]);
    changed_answer(&q, ask)
}
