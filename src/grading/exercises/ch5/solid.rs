//! Exercise 5.6, the solid angle of a triangle: checked against the exact
//! value of the inputs as given (in f64), to 10⁻⁴ relative, widened by
//! what f32 rounding alone can do to the answer (see [`f32_spread`]).

use glam::{DQuat, DVec3, Vec3};

use super::{SOLID_ABOVE_PI, SOLID_FAR_LIMIT, SOLID_PRECISION, SOLID_SIGNED};
use crate::cases::{self, v3, V3};
use crate::ch5_reflection::radiometry::triangle_solid_angle;
use crate::exercise::{Check, Symptom};
use crate::exercises::draws::{fold_drawn, worst_drawn, Draws};
use crate::exercises::stateless;

type SolidFn = fn(Vec3, [Vec3; 3]) -> f32;

/// The exact solid angle of `tri` at `p`, in f64.
fn exact(p: DVec3, tri: [DVec3; 3]) -> f64 {
    triangle_solid_angle(tri[0] - p, tri[1] - p, tri[2] - p)
}

fn wide(p: Vec3, tri: [Vec3; 3]) -> (DVec3, [DVec3; 3]) {
    (p.as_dvec3(), tri.map(|v| v.as_dvec3()))
}

/// How far the exact solid angle moves when the inputs move by what f32
/// rounding of a solution's vectors can do: a corner by 10⁻⁶ ℓ (ℓ the
/// longest edge), p by 10⁻⁶ of its distance to the farthest corner, or the
/// plane tilting (about any corner) by 10⁻⁶ ℓ₁ℓ₂/(2A), the error of an f32
/// cross product of the two longest edges relative to its length.
fn f32_spread(p: DVec3, tri: [DVec3; 3]) -> f64 {
    let base = exact(p, tri);
    let edges = [tri[1] - tri[0], tri[2] - tri[1], tri[0] - tri[2]];
    let mut lengths = edges.map(|e| e.length());
    let longest = edges[(0..3).fold(0, |m, i| if lengths[i] > lengths[m] { i } else { m })];
    lengths.sort_by(f64::total_cmp);
    let far = tri.iter().map(|v| v.distance(p)).fold(0.0, f64::max);
    let normal = edges[0].cross(edges[2]);
    let mut moved = Vec::new();
    for axis in [
        DVec3::X,
        DVec3::Y,
        DVec3::Z,
        -DVec3::X,
        -DVec3::Y,
        -DVec3::Z,
    ] {
        moved.push((p + axis * 1e-6 * far, tri));
        for i in 0..3 {
            let mut t = tri;
            t[i] += axis * 1e-6 * lengths[2];
            moved.push((p, t));
        }
    }
    let tilt = (1e-6 * lengths[2] * lengths[1] / normal.length()).min(0.1);
    if tilt.is_finite() && longest.length() > 0.0 {
        let u = longest.normalize();
        for axis in [u, normal.normalize().cross(u)] {
            for angle in [-tilt, tilt] {
                let turn = DQuat::from_axis_angle(axis, angle);
                for pivot in tri {
                    moved.push((p, tri.map(|v| pivot + turn * (v - pivot))));
                }
            }
        }
    }
    moved
        .into_iter()
        .map(|(q, t)| (exact(q, t) - base).abs())
        .fold(0.0, f64::max)
        .max(f32_sum_spread(p, tri))
}

/// What f32 rounding of Van Oosterom and Strackee's denominator alone can
/// do to 2 atan2(N, D): the sum rounded to about 8 f32 steps of its terms'
/// magnitudes, moved through atan2's derivative in D, 2|N|/(N² + D²). It
/// matters only where the four terms cancel to almost nothing (D small
/// beside them, N small too), which moving the inputs by 10⁻⁶ does not
/// always reach; elsewhere it is a few f32 steps of Ω.
fn f32_sum_spread(p: DVec3, tri: [DVec3; 3]) -> f64 {
    let [a, b, c] = tri.map(|v| v - p);
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let n = a.dot(b.cross(c));
    let terms = [la * lb * lc, a.dot(b) * lc, a.dot(c) * lb, b.dot(c) * la];
    let d: f64 = terms.iter().sum();
    let dd = 8.0 * f64::from(f32::EPSILON) * terms.iter().map(|t| t.abs()).sum::<f64>();
    let r2 = n * n + d * d;
    match r2 > 0.0 {
        true => 2.0 * n.abs() * dd / r2,
        false => 0.0,
    }
}

/// The error of `got` for the triangle `tri` seen from `p`: relative to
/// the exact Ω plus 10⁴ times the f32 spread (so within 10⁻⁴ is a pass).
fn error(got: f32, p: Vec3, tri: [Vec3; 3]) -> (f64, String) {
    let (pd, td) = wide(p, tri);
    let want = exact(pd, td);
    let scale = (want + 1e4 * f32_spread(pd, td)).max(f64::MIN_POSITIVE);
    let e = (f64::from(got) - want).abs() / scale;
    (
        if e.is_nan() { f64::INFINITY } else { e },
        format!("p {p}, triangle {tri:?}: got {got}, expected {want:.7e}"),
    )
}

/// A hand-made triangle (`src/grading/cases.toml`).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct SolidCase {
    p: V3,
    triangle: [V3; 3],
}

/// Hand-made triangles, one per clause, then drawn ones over the whole
/// domain.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_solid_angle(f: SolidFn) -> Check {
    stateless::unless_changed(solid_angle_values(f), || {
        stateless::probes::solid_angle(f, super::reference_solid_angle)
    })
}

/// [`check_solid_angle`]'s checks of the values.
fn solid_angle_values(f: SolidFn) -> Check {
    let hand = cases::worst("ch5/solid_angle", |c: &SolidCase| {
        let (p, t) = (v3(c.p), c.triangle.map(v3));
        error(f(p, t), p, t)
    });
    let (mut worst, mut detail) = match hand {
        Ok(w) => w,
        Err(check) => return check,
    };
    fold_drawn(&mut worst, &mut detail, drawn(f));
    let check = Check {
        error: worst,
        tolerance: 1e-4,
        detail,
        images: None,
        symptom: None,
    };
    match check.passed() {
        true => check,
        false => match solid_symptom(f) {
            Some(symptom) => check.with_symptom(symptom),
            None => check,
        },
    }
}

/// Triangles of any shape (slivers down to 1:1000) from 10⁻³·⁵ to 10³ m,
/// up to 10⁴ sizes from the origin, seen from anywhere: 0.3 to 1000 sizes
/// away, just above (10⁻⁴·⁵ to 10⁻¹ sizes, a third of those about as near
/// an edge), grazing, and in their plane; a tenth with the last one's
/// first corner.
fn drawn(f: SolidFn) -> (f64, String) {
    let mut d = Draws::new(56);
    let mut last_corner: Option<Vec3> = None;
    worst_drawn((0..d.count(300, 800)).map(|_| {
        d.next_case();
        let s = d.triangle_scale();
        let kind = d.unit();
        // Points just above stay near the origin, so that rounding p
        // cannot put it on the triangle.
        let at = d.place_for(s, if kind < 0.2 { 2.0 } else { 4.0 });
        let mut tri = [0; 3].map(|_| at + d.in_cube() * s);
        if d.unit() < 0.2 {
            let k = d.unit();
            tri[2] = tri[0] + (tri[1] - tri[0]) * k + d.direction() * s * d.decades(-3.0, -1.0);
        }
        // A tenth of those not seen from just above share their first
        // corner with the last triangle: Ω depends on all three corners.
        if let Some(corner) = last_corner.filter(|_| kind >= 0.2 && d.unit() < 0.1) {
            let shift = corner - tri[0];
            tri = tri.map(|v| v + shift);
            tri[0] = corner;
        }
        last_corner = Some(tri[0]);
        let centre = (tri[0] + tri[1] + tri[2]) / 3.0;
        let n = (tri[1] - tri[0])
            .cross(tri[2] - tri[0])
            .normalize_or(Vec3::Z);
        let along = d
            .direction()
            .cross(n)
            .normalize_or(n.any_orthonormal_vector());
        let p = if kind < 0.2 {
            let (u, w) = (d.unit(), d.unit());
            let (u, w) = if u + w > 1.0 {
                (1.0 - u, 1.0 - w)
            } else {
                (u, w)
            };
            let inside = tri[0] + (tri[1] - tri[0]) * u + (tri[2] - tri[0]) * w;
            let height = s * d.decades(-4.5, -1.0);
            // A third of them over a point as near the edge (p0, p1) as
            // they are high, or up to 30 times nearer or farther: there Ω
            // is far from 2π however close to the plane p is.
            let under = match d.unit() < 1.0 / 3.0 {
                true => {
                    let edge = tri[1] - tri[0];
                    let mut inward = n.cross(edge).normalize_or_zero();
                    if inward.dot(tri[2] - tri[0]) < 0.0 {
                        inward = -inward;
                    }
                    tri[0] + edge * d.range(0.1, 0.9) + inward * height * d.decades(-1.5, 1.5)
                }
                false => inside,
            };
            under + n * d.sign() * height
        } else if kind < 0.45 {
            centre + d.direction() * s * d.decades(-0.5, 3.0)
        } else if kind < 0.8 {
            let lift = n * d.sign() * d.decades(-4.0, -1.0);
            centre + (along + lift).normalize() * s * d.decades(0.0, 3.0)
        } else {
            centre + along * s * d.decades(0.5, 3.0)
        };
        let t = if d.unit() < 0.5 {
            tri
        } else {
            [tri[0], tri[2], tri[1]]
        };
        error(f(p, t), p, t)
    }))
}

/// What a failing solid angle got wrong, from four probes.
fn solid_symptom(f: SolidFn) -> Option<Symptom> {
    let rel = |p: Vec3, t: [Vec3; 3]| {
        let (pd, td) = wide(p, t);
        let want = exact(pd, td);
        (f64::from(f(p, t)) - want).abs() / want
    };
    let octant = [Vec3::X, Vec3::Y, Vec3::Z];
    let (a, b) = (
        f(Vec3::ZERO, octant),
        f(Vec3::ZERO, [Vec3::X, Vec3::Z, Vec3::Y]),
    );
    let big = [
        Vec3::new(-10.0, -10.0, 0.0),
        Vec3::new(20.0, -10.0, 0.0),
        Vec3::new(-10.0, 20.0, 0.0),
    ];
    let near = rel(Vec3::new(0.1, 0.2, 1e-2), big);
    let at = Vec3::new(0.0, 0.0, 300.0);
    let face_on = rel(at, [Vec3::ZERO, Vec3::X, Vec3::Y]);
    // 1000 sizes away, 10⁴ from the origin.
    let (o, far) = (Vec3::new(5e3, -3e3, 7e3), Vec3::new(811.3, -437.9, 389.1));
    let corners = [
        Vec3::new(0.013, 0.317, 0.109),
        Vec3::new(0.533, 0.871, 0.437),
        Vec3::new(-0.219, 0.127, 0.991),
    ];
    let oblique = rel(o + far, corners.map(|c| o + c));
    let octant_off = rel(Vec3::ZERO, octant);
    if !(a >= 0.0 && b >= 0.0 && (a - b).abs() <= 1e-3 * a.abs()) {
        Some(SOLID_SIGNED)
    } else if octant_off > 1e-2 && face_on < 1e-2 {
        Some(SOLID_FAR_LIMIT)
    } else if octant_off < 1e-3 && near > 1e-3 {
        Some(SOLID_ABOVE_PI)
    } else if octant_off < 1e-3 && near < 1e-3 && oblique > 1e-3 {
        Some(SOLID_PRECISION)
    } else {
        None
    }
}
