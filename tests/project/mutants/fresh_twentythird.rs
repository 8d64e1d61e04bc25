//! The twenty-third fresh set (2026-11-30), four testers who read the
//! stubs, the book and the course's solutions but not the grader, each
//! from an angle: precision in f32 (I, 64 wrong), placement, frames and
//! scale (J, 64), the patch a tired student commits after a failing test
//! (K, 69), and approximations (L, 62, and one meant as right that is
//! not: a solid angle of 0/0 at an edge's middle); 87 right alternatives,
//! all of which pass. With the grader as it stood before (16d2c4a), 23 of
//! the 260 wrong ones passed under seed 51 or 52; the fifteen that now
//! fail under seeds 51 to 55 are here as the mistakes they share (a path
//! ended for being dim came three times, a slack on the inside test
//! twice).

use glam::{Vec2, Vec3};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5, ch6, paths};

use super::fails_every;
use super::knobs::{self, EdgeKnobs, Knobs, MarchKnobs, PathKnobs, RasterKnobs, SceneKnobs};

/// The seeds every mutant must fail under.
const SEEDS: [u64; 4] = [231, 232, 237, 0x2026_1130];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

#[test]
fn precision_mistakes_fail() {
    fails(
        "sphere_trace: ε raised to 4 ulps of t far along the ray",
        || {
            ch4::check_sphere_trace(|sdf, o, d, eps, steps, far| {
                let k = MarchKnobs::with(|k| k.eps_ulps_of_t = Some(4.0));
                knobs::sphere_trace(k, sdf, (o, d), eps, steps, far)
            })
        },
    );
    fails(
        "sphere_trace: a march that stands still taken as a hit",
        || {
            ch4::check_sphere_trace(|sdf, o, d, eps, steps, far| {
                let k = MarchKnobs::with(|k| k.stall_hit = true);
                knobs::sphere_trace(k, sdf, (o, d), eps, steps, far)
            })
        },
    );
    fails("moller_trumbore: d normalised, t divided by |d|", || {
        ch3::check_moller_trumbore(|o, d, tri| {
            let len = d.length();
            let dir = d / len;
            let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
            let p = dir.cross(e2);
            let det = e1.dot(p);
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let s = o - tri[0];
            let u = s.dot(p) / det;
            let q = s.cross(e1);
            let v = dir.dot(q) / det;
            let t = e2.dot(q) / det / len;
            (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0).then_some((t, u, v))
        })
    });
    fails("area_pdf: pdf · d · d · d / |n · to| in f32", || {
        ch5::check_area_pdf(|pdf, x, y, n| {
            let to = y - x;
            let d = to.length();
            let dot = n.dot(to).abs();
            if dot == 0.0 {
                return 0.0;
            }
            pdf * d * d * d / dot
        })
    });
    fails("mc_integral: the sum taken in f32", || {
        ch6::check_mc_integral(|f, a, b, u| {
            if u.is_empty() {
                return 0.0;
            }
            let sum: f32 = u.iter().map(|u| f(a + u * (b - a)) as f32).sum();
            (sum / u.len() as f32 * (b - a) as f32) as f64
        })
    });
}

#[test]
fn tolerances_and_patches_fail() {
    fails(
        "barycentric_inside: 10⁻⁴ of slack outside every edge",
        || {
            ch3::check_barycentric_inside(|p, tri| {
                let (e1, e2, q) = (tri[1] - tri[0], tri[2] - tri[0], p - tri[0]);
                let n = e1.cross(e2);
                let nn = n.dot(n);
                if nn == 0.0 {
                    return None;
                }
                let (u, v) = (n.dot(q.cross(e2)) / nn, n.dot(e1.cross(q)) / nn);
                (u >= -1e-4 && v >= -1e-4 && u + v <= 1.0 + 1e-4).then_some((u, v))
            })
        },
    );
    fails(
        "rasterize_triangle: within 10⁻⁵ of the area taken as on the edge",
        || {
            ch2::check_rasterize_triangle(|v, c, w, h, depth, image| {
                let k = RasterKnobs::with(|k| k.relative_slack = 1e-5);
                knobs::rasterize(k, v, c, (w, h), depth, image)
            })
        },
    );
    fails(
        "draw_edges: cut at the middle where the ends' distances differ by under 10⁻⁶",
        || {
            ch1::check_draw_edges(|camera, a, b, near| {
                let k = EdgeKnobs::with(|k| k.parallel_below = Some(1e-6));
                knobs::draw_edges(k, camera, a, b, near)
            })
        },
    );
    fails("cosine_hemisphere: the radius kept below 0.999", || {
        ch5::check_cosine_hemisphere(|u: Vec2| {
            let r = u.x.sqrt().min(0.999);
            let phi = std::f32::consts::TAU * u.y;
            let z = (1.0 - r * r).sqrt();
            (
                Vec3::new(r * phi.cos(), r * phi.sin(), z),
                z * std::f32::consts::FRAC_1_PI,
            )
        })
    });
}

#[test]
fn dim_paths_ended_fail() {
    fails(
        "path_radiance: a path ended where roulette's q is below 0.05",
        || {
            paths::check_path_radiance(|scene, o, d, rng| {
                let k = PathKnobs::with(|k| k.dim_below = Some(0.05));
                knobs::path(k, scene, o, d, rng)
            })
        },
    );
}

#[test]
fn approximations_fail() {
    fails(
        "trace_scene: the normal by differences forwards from the hit",
        || {
            ch4::check_trace_scene(|sdf, o, d, m| {
                let k = SceneKnobs::with(|k| k.forward = true);
                knobs::trace_scene(k, sdf, o, d, m)
            })
        },
    );
}
