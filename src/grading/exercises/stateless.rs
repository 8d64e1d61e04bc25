//! The same question gets the same answer, whatever was asked before: a
//! probe for the exercises whose answer is a function of their arguments
//! alone. A cache or memo keyed on some of the arguments (the last eye and
//! target without up, a point without its sphere), a table kept from the
//! first call, or a counter of calls, all answer a question again
//! differently once something else was asked in between.
//!
//! The probe draws questions in the exercise's domain, asks each once,
//! then asks it again right after a decoy: the same question with one
//! argument, or one number of an argument, taken from another question
//! (a whole argument where the contract constrains it as a whole, such as
//! a unit direction). The second answer must be the first, bit for bit.

use std::fmt::Debug;
use std::ops::Range;

use glam::{Vec2, Vec3};

use crate::exercise::Check;

/// A question as its numbers (f64 holds every f32 exactly), and the
/// groups of numbers a decoy takes together from another question.
pub struct Questions {
    /// The drawn questions.
    pub cases: Vec<Vec<f64>>,
    /// The groups: each a range of a question's numbers.
    pub groups: Vec<Range<usize>>,
}

impl Questions {
    /// `count` questions drawn by `draw`, with one group per number but
    /// for the ranges in `whole`, each a group of its own.
    pub fn drawn(count: usize, whole: &[Range<usize>], mut draw: impl FnMut() -> Vec<f64>) -> Self {
        let cases: Vec<Vec<f64>> = (0..count).map(|_| draw()).collect();
        let n = cases.first().map_or(0, Vec::len);
        let mut groups: Vec<Range<usize>> = whole.to_vec();
        groups.extend(
            (0..n)
                .filter(|i| !whole.iter().any(|r| r.contains(i)))
                .map(|i| i..i + 1),
        );
        Questions { cases, groups }
    }
}

/// The numbers of a `Vec3`.
pub fn nums3(v: Vec3) -> [f64; 3] {
    v.as_dvec3().to_array()
}

/// The numbers of a `Vec2`.
pub fn nums2(v: Vec2) -> [f64; 2] {
    v.as_dvec2().to_array()
}

/// The `Vec3` at numbers `at..at + 3`.
pub fn vec3_at(n: &[f64], at: usize) -> Vec3 {
    Vec3::new(n[at] as f32, n[at + 1] as f32, n[at + 2] as f32)
}

/// The `Vec2` at numbers `at..at + 2`.
pub fn vec2_at(n: &[f64], at: usize) -> Vec2 {
    Vec2::new(n[at] as f32, n[at + 1] as f32)
}

/// Asks every question, then each again right after each of its decoys,
/// and each decoy once after an unrelated question and once right after
/// its question: `None` if every answer came back the same, else what
/// changed. (A memo keyed on part of the arguments answers whichever of
/// the two comes second with the other's answer.)
pub fn changed_answer<R: Debug>(q: &Questions, ask: impl Fn(&[f64]) -> R) -> Option<String> {
    let first: Vec<String> = q.cases.iter().map(|c| format!("{:?}", ask(c))).collect();
    let n = q.cases.len();
    let changed = |what: &[f64], before: &str, then: &str, after: &[f64]| {
        format!(
            "the arguments {what:?}: answered {before} the first time, and {then} when asked \
             again right after {after:?}: an answer must depend on its arguments alone, never on \
             what was asked before"
        )
    };
    for (k, case) in q.cases.iter().enumerate() {
        let (other, unrelated) = (&q.cases[(k + 1) % n], &q.cases[(k + 2) % n]);
        for g in &q.groups {
            let mut decoy = case.clone();
            decoy[g.clone()].copy_from_slice(&other[g.clone()]);
            if decoy == *case {
                continue;
            }
            ask(unrelated);
            let cold = format!("{:?}", ask(&decoy));
            let again = format!("{:?}", ask(case));
            if again != first[k] {
                return Some(changed(case, &first[k], &again, &decoy));
            }
            let warm = format!("{:?}", ask(&decoy));
            if warm != cold {
                return Some(changed(&decoy, &cold, &warm, case));
            }
        }
    }
    None
}

/// `check`, failed with the probe's finding if it passed and an answer
/// changed.
pub fn unless_changed(check: Check, found: impl FnOnce() -> Option<String>) -> Check {
    if !check.passed() {
        return check;
    }
    match found() {
        Some(detail) => Check {
            error: f64::INFINITY,
            detail,
            symptom: None,
            ..check
        },
        None => check,
    }
}

/// Each exercise's probe: its questions drawn in its domain (the numbers
/// of its arguments in order), and how a question is asked.
// (`&[3..6]` is a list of the ranges taken whole, with one in it.)
#[allow(clippy::single_range_in_vec_init)]
pub mod probes {
    use std::fmt::Debug;

    use glam::{Vec2, Vec3};

    use super::{changed_answer, nums2, nums3, vec2_at, vec3_at, Questions};
    use crate::exercises::draws::Draws;

    /// How many questions a probe draws.
    const COUNT: usize = 24;

    fn draw(
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
    fn cat(vs: &[Vec3]) -> Vec<f64> {
        vs.iter().flat_map(|v| nums3(*v)).collect()
    }

    /// project_point(p), p in front of the camera or not.
    pub fn project_point<R: Debug>(f: impl Fn(Vec3) -> R) -> Option<String> {
        let q = draw(91, &[], |d| cat(&[point(d)]));
        changed_answer(&q, |n| f(vec3_at(n, 0)))
    }

    /// look_at(eye, target, up), up taken whole.
    pub fn look_at<R: Debug>(f: impl Fn(Vec3, Vec3, Vec3) -> R) -> Option<String> {
        let q = draw(92, &[6..9], |d| cat(&[point(d), point(d), d.direction()]));
        changed_answer(&q, |n| f(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6)))
    }

    /// draw_edges(camera, a, b, near) with one camera.
    pub fn draw_edges<R: Debug>(f: impl Fn(Vec3, Vec3, f32) -> R) -> Option<String> {
        let q = draw(109, &[], |d| {
            let mut v = cat(&[point(d), point(d)]);
            v.push(d.range(0.01, 2.0) as f64);
            v
        });
        changed_answer(&q, |n| f(vec3_at(n, 0), vec3_at(n, 3), n[6] as f32))
    }

    /// edge_function(a, b, p).
    pub fn edge_function<R: Debug>(f: impl Fn(Vec2, Vec2, Vec2) -> R) -> Option<String> {
        let q = draw(93, &[], |d| {
            [point(d), point(d), point(d)]
                .iter()
                .flat_map(|v| nums2(v.truncate()))
                .collect()
        });
        changed_answer(&q, |n| f(vec2_at(n, 0), vec2_at(n, 2), vec2_at(n, 4)))
    }

    /// barycentric(pi, pj, pk, p).
    pub fn barycentric<R: Debug>(f: impl Fn(Vec2, Vec2, Vec2, Vec2) -> R) -> Option<String> {
        let q = draw(94, &[], |d| {
            (0..4).flat_map(|_| nums2(point(d).truncate())).collect()
        });
        changed_answer(&q, |n| {
            f(vec2_at(n, 0), vec2_at(n, 2), vec2_at(n, 4), vec2_at(n, 6))
        })
    }

    /// ray_plane(o, d, n, c), the direction and the normal taken whole.
    pub fn ray_plane<R: Debug>(f: impl Fn(Vec3, Vec3, Vec3, f32) -> R) -> Option<String> {
        let q = draw(95, &[3..6, 6..9], |d| {
            let mut v = cat(&[point(d), d.direction(), d.direction()]);
            v.push(d.range(-5.0, 5.0) as f64);
            v
        });
        changed_answer(&q, |n| {
            f(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6), n[9] as f32)
        })
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
        changed_answer(&q, |n| {
            f(vec3_at(n, 0), [vec3_at(n, 3), vec3_at(n, 6), vec3_at(n, 9)])
        })
    }

    /// moller_trumbore(o, d, tri), d taken whole.
    pub fn moller_trumbore<R: Debug>(f: impl Fn(Vec3, Vec3, [Vec3; 3]) -> R) -> Option<String> {
        let q = draw(97, &[3..6], |d| {
            let t = [point(d), point(d), point(d)];
            let o = point(d);
            let at = (t[0] + t[1] + t[2]) / 3.0 + point(d) * 0.05;
            cat(&[o, (at - o).normalize_or(Vec3::Z), t[0], t[1], t[2]])
        });
        changed_answer(&q, |n| {
            f(
                vec3_at(n, 0),
                vec3_at(n, 3),
                [vec3_at(n, 6), vec3_at(n, 9), vec3_at(n, 12)],
            )
        })
    }

    /// sphere_sdf(p, centre, radius).
    pub fn sphere_sdf<R: Debug>(f: impl Fn(Vec3, Vec3, f32) -> R) -> Option<String> {
        let q = draw(98, &[], |d| {
            let mut v = cat(&[point(d), point(d)]);
            v.push(d.decades(-1.0, 1.0) as f64);
            v
        });
        changed_answer(&q, |n| f(vec3_at(n, 0), vec3_at(n, 3), n[6] as f32))
    }

    /// gradient_normal(sdf, p, h) on a box and a ball, h from 10⁻⁴ to 10⁻².
    pub fn gradient_normal<R: Debug>(
        f: impl Fn(&dyn Fn(Vec3) -> f32, Vec3, f32) -> R,
    ) -> Option<String> {
        let shape =
            |p: Vec3| crate::ch4_implicit_surfaces::primitives::sd_box(p, Vec3::new(1.0, 2.0, 3.0));
        let q = draw(99, &[], |d| {
            let mut v = cat(&[point(d) * 0.5]);
            v.push(d.decades(-4.0, -2.0) as f64);
            v
        });
        changed_answer(&q, |n| f(&shape, vec3_at(n, 0), n[3] as f32))
    }

    /// lambert_brdf(rho, wo, wi), the directions taken whole.
    pub fn lambert_brdf<R: Debug>(f: impl Fn(Vec3, Vec3, Vec3) -> R) -> Option<String> {
        let q = draw(100, &[3..6, 6..9], |d| {
            cat(&[
                Vec3::new(d.unit(), d.unit(), d.unit()),
                d.direction(),
                d.direction(),
            ])
        });
        changed_answer(&q, |n| f(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6)))
    }

    /// cosine_hemisphere(u).
    pub fn cosine_hemisphere<R: Debug>(f: impl Fn(Vec2) -> R) -> Option<String> {
        let q = draw(101, &[], |d| vec![d.unit() as f64, d.unit() as f64]);
        changed_answer(&q, |n| f(vec2_at(n, 0)))
    }

    /// point_light(I, light, p, n), the normal taken whole.
    pub fn point_light<R: Debug>(f: impl Fn(Vec3, Vec3, Vec3, Vec3) -> R) -> Option<String> {
        let q = draw(102, &[9..12], |d| {
            let i = Vec3::new(d.unit(), d.unit(), d.unit()) * 10.0;
            cat(&[i, point(d), point(d), d.direction()])
        });
        changed_answer(&q, |n| {
            f(vec3_at(n, 0), vec3_at(n, 3), vec3_at(n, 6), vec3_at(n, 9))
        })
    }

    /// area_to_solid_angle(pdf_area, x, y, n_light), the normal taken whole.
    pub fn area_pdf<R: Debug>(f: impl Fn(f32, Vec3, Vec3, Vec3) -> R) -> Option<String> {
        let q = draw(103, &[7..10], |d| {
            let mut v = vec![d.decades(-2.0, 2.0) as f64];
            v.extend(cat(&[point(d), point(d), d.direction()]));
            v
        });
        changed_answer(&q, |n| {
            f(n[0] as f32, vec3_at(n, 1), vec3_at(n, 4), vec3_at(n, 7))
        })
    }

    /// solid_angle(p, tri).
    pub fn solid_angle<R: Debug>(f: impl Fn(Vec3, [Vec3; 3]) -> R) -> Option<String> {
        let q = draw(104, &[], |d| cat(&[point(d), point(d), point(d), point(d)]));
        changed_answer(&q, |n| {
            f(vec3_at(n, 0), [vec3_at(n, 3), vec3_at(n, 6), vec3_at(n, 9)])
        })
    }

    /// spot_power(I, inner, outer), the two angles taken together (inner
    /// ≤ outer).
    pub fn spot<R: Debug>(f: impl Fn(Vec3, f32, f32) -> R) -> Option<String> {
        let q = draw(105, &[3..5], |d| {
            let i = Vec3::new(d.unit(), d.unit(), d.unit()) * 10.0;
            let outer = d.range(0.01, 3.0);
            let mut v = cat(&[i]);
            v.extend([(outer * d.unit()) as f64, outer as f64]);
            v
        });
        changed_answer(&q, |n| f(vec3_at(n, 0), n[3] as f32, n[4] as f32))
    }

    /// mis_weight(pdf_f, pdf_g).
    pub fn mis_weight<R: Debug>(f: impl Fn(f64, f64) -> R) -> Option<String> {
        let q = draw(106, &[], |d| {
            vec![d.decades(-3.0, 3.0) as f64, d.decades(-3.0, 3.0) as f64]
        });
        changed_answer(&q, |n| f(n[0], n[1]))
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
        changed_answer(&q, |n| f(n[0], n[1], n[2]))
    }

    /// refract(d, n, η outside, η inside), the directions taken whole.
    pub fn refraction<R: Debug>(f: impl Fn(Vec3, Vec3, f32, f32) -> R) -> Option<String> {
        let q = draw(108, &[0..3, 3..6], |d| {
            let mut v = cat(&[d.direction(), d.direction()]);
            v.extend([d.range(1.0, 2.5) as f64, d.range(1.0, 2.5) as f64]);
            v
        });
        changed_answer(&q, |n| {
            f(vec3_at(n, 0), vec3_at(n, 3), n[6] as f32, n[7] as f32)
        })
    }
}
