//! The third fresh set (2026-11-29): plausible wrong solutions written by
//! testers from the stubs' contracts before reading the checks, each the
//! course's solution (`tests/project/solutions/`) with one change, mostly
//! a threshold where the contract has none (an absolute or a relative ε,
//! a strict comparison, a t_min) or a step left out. The grader now
//! catches each: it must fail under every seed tried, naming its symptom
//! where the grader names one. The testers' correct alternatives that no
//! other test covers must pass under every seed. Where one copies a long
//! solution body, it is a one-line call of that solution written once with
//! knobs ([`super::knobs`]), its change a knob turned.

use std::f32::consts::PI;

use glam::{Mat4, Vec2, Vec3, Vec4};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::grading::counted::{Hit, ReadableBvh};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::paths::{self, PathScene};
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5, ch6, refraction};

use super::knobs::{
    self, BvhKnobs, Knobs, LightCos, MarchKnobs, MollerKnobs, NormalStep, PathKnobs, SahKnobs,
    SceneKnobs, Singular, Survival, TMin,
};
use super::{fails_every, passes_every};

/// The seeds every mutant must fail under (and every alternative pass
/// under): the testers' three and one more.
const SEEDS: [u64; 4] = [11, 22, 33, 0x2026_1129];

/// The path loop's check traces 200,000 paths in a furnace per seed: its
/// mutants and alternative are tried under the first two seeds only.
const PATH_SEEDS: &[u64] = &[11, 22];

fn fails(what: &str, symptom: Option<&str>, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, symptom, check);
}

fn passes(what: &str, check: impl Fn() -> Check) {
    passes_every(&SEEDS, what, check);
}

// ---- 1.1 project_point -------------------------------------------------------

/// An absolute ε: a point less than a micrometre in front has no image.
fn project_abs_eps(p: Vec3) -> Option<Vec2> {
    if p.z.is_nan() || p.z >= -1e-6 {
        return None;
    }
    let t = 1.0 / -p.z;
    Some(Vec2::new(p.x * t, p.y * t))
}

/// f32::EPSILON as the ε: nothing nearer than 1.2e-7 has an image.
fn project_f32_eps(p: Vec3) -> Option<Vec2> {
    if p.z.is_nan() || p.z >= -f32::EPSILON {
        return None;
    }
    let t = 1.0 / -p.z;
    Some(Vec2::new(p.x * t, p.y * t))
}

#[test]
fn project_point_mistakes_fail() {
    fails("an absolute ε of 1e-6", None, || {
        ch1::check_project_point(project_abs_eps)
    });
    fails("f32::EPSILON for ε", None, || {
        ch1::check_project_point(project_f32_eps)
    });
}

// ---- 1.2 look_at --------------------------------------------------------------

/// Correct: the matrix's rows written out, the translation -axis · eye.
fn look_at_rows(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    let f = (target - eye).normalize();
    let r = f.cross(up).normalize();
    let u = r.cross(f);
    let b = -f;
    Mat4::from_cols(
        Vec4::new(r.x, u.x, b.x, 0.0),
        Vec4::new(r.y, u.y, b.y, 0.0),
        Vec4::new(r.z, u.z, b.z, 0.0),
        Vec4::new(-r.dot(eye), -u.dot(eye), -b.dot(eye), 1.0),
    )
}

#[test]
fn look_at_alternative_passes() {
    passes("the rows written out", || ch1::check_look_at(look_at_rows));
}

// ---- 2.1 edge_function ----------------------------------------------------------

/// Correct: the formula written out in f64, then rounded once.
fn edge_f64(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    let (a, b, p) = (a.as_dvec2(), b.as_dvec2(), p.as_dvec2());
    ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) as f32
}

#[test]
fn edge_function_alternative_passes() {
    passes("in f64", || ch2::check_edge_function(edge_f64));
}

// ---- 2.2 barycentric ------------------------------------------------------------

/// Correct: Cramer's rule on p - pi = s (pj - pi) + t (pk - pi), φi = 1 - s - t.
fn barycentric_cramer(pi: Vec2, pj: Vec2, pk: Vec2, p: Vec2) -> Option<Vec3> {
    let (e1, e2, q) = (pj - pi, pk - pi, p - pi);
    let det = e1.perp_dot(e2);
    if det == 0.0 {
        return None;
    }
    let s = q.perp_dot(e2) / det;
    let t = e1.perp_dot(q) / det;
    Some(Vec3::new(1.0 - s - t, s, t))
}

#[test]
fn barycentric_alternative_passes() {
    passes("Cramer's rule", || {
        ch2::check_barycentric(barycentric_cramer)
    });
}

// ---- 2.3 depth_test -------------------------------------------------------------

/// An absolute bias: nearer by less than 1e-6 counts as behind.
fn depth_abs_eps(depth: &mut [f32], index: usize, z: f32) -> bool {
    let nearer = z < depth[index] - 1e-6;
    if nearer {
        depth[index] = z;
    }
    nearer
}

/// A relative bias: nearer by less than a millionth counts as behind.
fn depth_rel_eps(depth: &mut [f32], index: usize, z: f32) -> bool {
    let nearer = z < depth[index] * (1.0 - 1e-6);
    if nearer {
        depth[index] = z;
    }
    nearer
}

/// Correct: `partial_cmp` is `Less`.
fn depth_cmp(depth: &mut [f32], index: usize, z: f32) -> bool {
    match z.partial_cmp(&depth[index]) {
        Some(std::cmp::Ordering::Less) => {
            depth[index] = z;
            true
        }
        _ => false,
    }
}

#[test]
fn depth_test_mistakes_fail() {
    fails("an absolute bias of 1e-6", None, || {
        ch2::check_depth_test(depth_abs_eps)
    });
    fails("a relative bias of 1e-6", None, || {
        ch2::check_depth_test(depth_rel_eps)
    });
    passes("partial_cmp", || ch2::check_depth_test(depth_cmp));
}

// ---- 3.1 ray_plane --------------------------------------------------------------

/// A relative ε: a ray at less than 1e-6 rad to the plane called parallel.
fn plane_rel_eps(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let denom = n.dot(d);
    if denom.abs() < 1e-6 * n.length() * d.length() {
        return None;
    }
    Some((c - n.dot(o)) / denom)
}

/// Correct: through the plane's point n c / |n|², in f64.
fn plane_through_point(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let (o, d, n, c) = (o.as_dvec3(), d.as_dvec3(), n.as_dvec3(), c as f64);
    let nd = n.dot(d);
    if nd == 0.0 {
        return None;
    }
    let p0 = n * (c / n.dot(n));
    Some((n.dot(p0 - o) / nd) as f32)
}

#[test]
fn ray_plane_mistake_fails() {
    fails("a relative ε for parallel", None, || {
        ch3::check_ray_plane(plane_rel_eps)
    });
    passes("through the plane's point, in f64", || {
        ch3::check_ray_plane(plane_through_point)
    });
}

// ---- 3.2 barycentric_inside -----------------------------------------------------

/// A fat ε: up to 1e-3 outside each edge counts as inside.
fn inside_fat_eps(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    let (e1, e2, q) = (tri[1] - tri[0], tri[2] - tri[0], p - tri[0]);
    let n = e1.cross(e2);
    let nn = n.dot(n);
    if nn == 0.0 {
        return None;
    }
    let u = n.dot(q.cross(e2)) / nn;
    let v = n.dot(e1.cross(q)) / nn;
    (u >= -1e-3 && v >= -1e-3 && u + v <= 1.0 + 1e-3).then_some((u, v))
}

/// Ericson's normal equations from dot products, in f32: right but for
/// slivers, whose determinant (their thinness squared) rounds to 0.
fn inside_ericson(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    let (v0, v1, v2) = (tri[1] - tri[0], tri[2] - tri[0], p - tri[0]);
    let (d00, d01, d11) = (v0.dot(v0), v0.dot(v1), v1.dot(v1));
    let (d20, d21) = (v2.dot(v0), v2.dot(v1));
    let den = d00 * d11 - d01 * d01;
    if den.is_nan() || den <= 0.0 {
        return None;
    }
    let u = (d11 * d20 - d01 * d21) / den;
    let v = (d00 * d21 - d01 * d20) / den;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0).then_some((u, v))
}

#[test]
fn barycentric_inside_mistake_fails() {
    fails("a fat ε of 1e-3", None, || {
        ch3::check_barycentric_inside(inside_fat_eps)
    });
    // Right for most triangles, and once counted right here; but a sliver
    // 1 : 8192 thin has an inside, and in f32 the normal equations'
    // determinant (the thinness squared) rounds to 0 there (the stub says
    // so since the seventeenth set).
    fails("Ericson's normal equations in f32", None, || {
        ch3::check_barycentric_inside(inside_ericson)
    });
}

// ---- 3.3 moller_trumbore --------------------------------------------------------

/// t = 0 accepted: the ray's own origin on the triangle is a hit.
fn moller_t_zero(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    knobs::moller(MollerKnobs::with(|k| k.t_zero = true), o, d, tri)
}

/// Strict comparisons: the edges and corners are outside.
fn moller_strict(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    knobs::moller(MollerKnobs::with(|k| k.strict_edges = true), o, d, tri)
}

/// A relative ε on the determinant against |e1| |e2| |d|.
fn moller_rel_eps(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let k = MollerKnobs::with(|k| k.singular = Singular::Relative(1e-6));
    knobs::moller(k, o, d, tri)
}

/// Correct: the classic pvec, tvec, qvec form, with early outs.
fn moller_classic(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    let (e1, e2) = (tri[1] - tri[0], tri[2] - tri[0]);
    let pvec = d.cross(e2);
    let det = e1.dot(pvec);
    if det == 0.0 {
        return None;
    }
    let inv = 1.0 / det;
    let tvec = o - tri[0];
    let u = tvec.dot(pvec) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let qvec = tvec.cross(e1);
    let v = d.dot(qvec) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(qvec) * inv;
    (t > 0.0).then_some((t, u, v))
}

#[test]
fn moller_trumbore_mistakes_fail() {
    fails("t = 0 accepted", Some("hit behind the origin"), || {
        ch3::check_moller_trumbore(moller_t_zero)
    });
    fails("strict comparisons", None, || {
        ch3::check_moller_trumbore(moller_strict)
    });
    fails("a relative ε on the determinant", None, || {
        ch3::check_moller_trumbore(moller_rel_eps)
    });
    passes("the classic form", || {
        ch3::check_moller_trumbore(moller_classic)
    });
}

// ---- 3.4 bvh_traversal ----------------------------------------------------------

/// t_min 1e-4 for 0: a hit nearer than 1e-4 along the ray is missed.
fn bvh_t_min_eps(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    let k = BvhKnobs::with(|k| k.t_min = TMin::Fixed(1e-4));
    knobs::closest_hit(k, bvh, ray, t_max)
}

#[test]
fn bvh_traversal_mistake_fails() {
    fails("t_min = 1e-4", Some("not the closest hit"), || {
        ch3::check_bvh_traversal(bvh_t_min_eps)
    });
}

// ---- 3.5 sah --------------------------------------------------------------------

/// The traversal's cost left out: a split's cost is its children's alone.
fn sah_no_traversal(b: &[[Vec3; 2]], c: &[Vec3]) -> Option<(usize, f32)> {
    knobs::sah_sweep(SahKnobs::with(|k| k.trav_cost = 0.0), b, c)
}

#[test]
fn sah_mistake_fails() {
    fails(
        "no traversal cost",
        Some("a split where a leaf is cheaper"),
        || ch3::check_sah(sah_no_traversal),
    );
}

// ---- 4.2 sphere_trace -----------------------------------------------------------

/// f < ε for |f| < ε: a point inside the surface is a hit.
fn trace_no_abs(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, e: f32, n: u32, m: f32) -> Option<f32> {
    let k = MarchKnobs::with(|k| k.signed_hit = true);
    knobs::sphere_trace(k, f, (o, d), e, n, m)
}

#[test]
fn sphere_trace_mistake_fails() {
    fails(
        "f < ε, not |f| < ε",
        Some("inside taken for a hit"),
        || ch4::check_sphere_trace(trace_no_abs),
    );
}

// ---- 4.3 gradient_normal --------------------------------------------------------

/// The gradient returned as it is, not normalised.
fn normal_not_normalised(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let partial = |axis: Vec3| (sdf(p + axis * h) - sdf(p - axis * h)) / (2.0 * h);
    Vec3::new(partial(Vec3::X), partial(Vec3::Y), partial(Vec3::Z))
}

/// Correct: the differences not divided by 2h (normalising drops it).
fn normal_unscaled(sdf: &dyn Fn(Vec3) -> f32, p: Vec3, h: f32) -> Vec3 {
    let e = |v: Vec3| sdf(p + v) - sdf(p - v);
    let g = Vec3::new(e(Vec3::X * h), e(Vec3::Y * h), e(Vec3::Z * h));
    g / g.length()
}

#[test]
fn gradient_normal_mistake_fails() {
    fails("not normalised", Some("normal not unit length"), || {
        ch4::check_gradient_normal(normal_not_normalised)
    });
    passes("the differences unscaled", || {
        ch4::check_gradient_normal(normal_unscaled)
    });
}

// ---- 4.4 trace_scene ------------------------------------------------------------

/// The normal's step the fixed ε, not scaled to the hit point.
fn scene_h_fixed_eps(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    let k = SceneKnobs::with(|k| (k.h, k.h_floor) = (NormalStep::Fixed, None));
    knobs::trace_scene(k, f, o, d, m)
}

/// The normal's step ε at the point, without the floor of 1e-4.
fn scene_h_no_floor(f: &dyn Fn(Vec3) -> f32, o: Vec3, d: Vec3, m: &March) -> Option<(f32, Vec3)> {
    knobs::trace_scene(SceneKnobs::with(|k| k.h_floor = None), f, o, d, m)
}

/// Correct: a for loop over the budget, the hit kept, then the normal.
fn scene_structured(
    sdf: &dyn Fn(Vec3) -> f32,
    origin: Vec3,
    dir: Vec3,
    march: &March,
) -> Option<(f32, Vec3)> {
    let mut t = 0.0f32;
    let mut hit = None;
    for _ in 0..march.max_steps {
        let p = origin + dir * t;
        let f = sdf(p);
        if f.abs() < march.epsilon_at(p) {
            hit = Some(p);
            break;
        }
        if t > march.max_distance {
            return None;
        }
        t += f;
    }
    let p = hit?;
    let h = march.epsilon_at(p).max(1e-4);
    let g = Vec3::new(
        sdf(p + Vec3::X * h) - sdf(p - Vec3::X * h),
        sdf(p + Vec3::Y * h) - sdf(p - Vec3::Y * h),
        sdf(p + Vec3::Z * h) - sdf(p - Vec3::Z * h),
    );
    let n = if g.length_squared() > 0.0 {
        g.normalize()
    } else {
        -dir
    };
    Some((t, if n.dot(dir) > 0.0 { -n } else { n }))
}

#[test]
fn trace_scene_mistakes_fail() {
    fails("the normal's step the fixed ε", None, || {
        ch4::check_trace_scene(scene_h_fixed_eps)
    });
    fails("the normal's step ε at p, no floor", None, || {
        ch4::check_trace_scene(scene_h_no_floor)
    });
    passes("structured: hit first, normal after", || {
        ch4::check_trace_scene(scene_structured)
    });
}

// ---- 5.1 lambert_brdf -----------------------------------------------------------

/// Correct: same side, and neither direction in the surface.
fn lambert_signs(rho: Vec3, wo: Vec3, wi: Vec3) -> Vec3 {
    if (wo.z > 0.0) == (wi.z > 0.0) && wo.z != 0.0 && wi.z != 0.0 {
        rho * std::f32::consts::FRAC_1_PI
    } else {
        Vec3::ZERO
    }
}

#[test]
fn lambert_brdf_alternative_passes() {
    passes("by the signs of z", || {
        ch5::check_lambert_brdf(lambert_signs)
    });
}

// ---- 5.2 cosine_hemisphere ------------------------------------------------------

/// Correct: Shirley's concentric disc, lifted to the hemisphere.
fn cosine_concentric(u: Vec2) -> (Vec3, f32) {
    let a = 2.0 * u - Vec2::ONE;
    let (r, phi) = if a == Vec2::ZERO {
        (0.0, 0.0)
    } else if a.x.abs() > a.y.abs() {
        (a.x, PI / 4.0 * (a.y / a.x))
    } else {
        (a.y, PI / 2.0 - PI / 4.0 * (a.x / a.y))
    };
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    (Vec3::new(x, y, z), z / PI)
}

#[test]
fn cosine_hemisphere_alternative_passes() {
    passes("the concentric disc", || {
        ch5::check_cosine_hemisphere(cosine_concentric)
    });
}

// ---- 5.3 point_light ------------------------------------------------------------

/// n · to / r³, no normalised direction (wrong for far lights: below).
fn point_light_cube(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let r = to.length();
    let ndotl = n.dot(to);
    if ndotl <= 0.0 {
        return Vec3::ZERO;
    }
    intensity * (ndotl / (r * r * r))
}

/// Once counted right, n · to / r³ is wrong (since the nineteenth set):
/// r³ leaves f32's range for lights past 7·10¹² m, where r² does not, and
/// the irradiance comes out 0.
#[test]
fn point_light_cube_fails_for_far_lights() {
    fails("n · to / r³", None, || {
        ch5::check_point_light(point_light_cube)
    });
}

// ---- 5.4 area_pdf ---------------------------------------------------------------

/// A threshold on the cosine: below 1e-3, a grazing light's pdf is 0.
fn area_pdf_threshold(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    let to = x - y;
    let d2 = to.length_squared();
    let cos = n_light.dot(to / d2.sqrt()).abs();
    if cos < 1e-3 {
        0.0
    } else {
        pdf_area * d2 / cos
    }
}

/// Counted right until the twenty-third set: d³ / |n · to|, no normalised
/// direction (d³ overflows where the answer does not).
fn area_pdf_cube(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    let to = y - x;
    let d = to.length();
    let nd = n_light.dot(to).abs();
    if nd > 0.0 {
        pdf_area * d * d * d / nd
    } else {
        0.0
    }
}

/// Correct: the quotient as it comes, 0 where it is not finite.
fn area_pdf_if_finite(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    let d = x.distance(y);
    let v = pdf_area * d * d / n_light.dot((x - y) / d).abs();
    if v.is_finite() {
        v
    } else {
        0.0
    }
}

#[test]
fn area_pdf_mistake_fails() {
    fails("a cosine threshold of 1e-3", None, || {
        ch5::check_area_pdf(area_pdf_threshold)
    });
    // Counted right until the twenty-third set: d³ leaves f32's range
    // for a small light far away (10¹⁴ and more), whose density does not.
    fails("d³ / |n · to|", None, || {
        ch5::check_area_pdf(area_pdf_cube)
    });
    passes("0 where not finite", || {
        ch5::check_area_pdf(area_pdf_if_finite)
    });
}

// ---- 5.5 direct_light -----------------------------------------------------------

/// Correct: the light's cosine clamped to 0, its infinite pdf giving 0.
#[allow(clippy::too_many_arguments)]
fn direct_clamped_to_infinity(
    p: Vec3,
    n: Vec3,
    rho: Vec3,
    y: Vec3,
    n_light: Vec3,
    area: f32,
    le: Vec3,
    visible: &dyn Fn(Vec3, Vec3) -> bool,
) -> Vec3 {
    let to = y - p;
    let d2 = to.length_squared();
    let wi = to / d2.sqrt();
    let cos_light = n_light.dot(-wi).max(0.0);
    if !visible(p, y) {
        return Vec3::ZERO;
    }
    let pdf = d2 / (cos_light * area);
    rho / PI * le * n.dot(wi).max(0.0) / pdf
}

#[test]
fn direct_light_alternative_passes() {
    passes("the pdf infinite behind the light", || {
        ch5::check_direct_light(direct_clamped_to_infinity)
    });
}

// ---- 5.7 spot -------------------------------------------------------------------

/// Correct: 1 - cos θ as sin² θ / (1 + cos θ) below π/2.
fn spot_sin2(intensity: Vec3, inner: f32, outer: f32) -> Vec3 {
    let one_minus_cos = |t: f32| {
        let (s, c) = t.sin_cos();
        if c > 0.0 {
            s * s / (1.0 + c)
        } else {
            1.0 - c
        }
    };
    intensity * (PI * (one_minus_cos(inner) + one_minus_cos(outer)))
}

#[test]
fn spot_alternative_passes() {
    passes("sin² θ / (1 + cos θ)", || ch5::check_spot(spot_sin2));
}

// ---- 6.1 mc_integral ------------------------------------------------------------

/// Correct: x from b down, b - u (b - a).
fn mc_reversed(f: &dyn Fn(f64) -> f64, a: f64, b: f64, u: &[f64]) -> f64 {
    if u.is_empty() {
        return 0.0;
    }
    let w = b - a;
    w * u.iter().map(|x| f(b - x * w)).sum::<f64>() / u.len() as f64
}

#[test]
fn mc_integral_alternative_passes() {
    passes("from b down", || ch6::check_mc_integral(mc_reversed));
}

// ---- 6.2 russian_roulette -------------------------------------------------------

/// Correct: survival on the upper end, u ≥ 1 - q.
fn roulette_upper(value: f64, q: f64, u: f64) -> f64 {
    if u >= 1.0 - q {
        value / q
    } else {
        0.0
    }
}

#[test]
fn russian_roulette_alternative_passes() {
    passes("u ≥ 1 - q", || {
        ch6::check_russian_roulette(roulette_upper)
    });
}

// ---- 6.3 mis_weight -------------------------------------------------------------

/// Correct: both pdfs scaled by the larger before squaring.
fn mis_scaled(pdf_f: f64, pdf_g: f64) -> f64 {
    let m = pdf_f.max(pdf_g);
    if pdf_f.is_nan() || pdf_f <= 0.0 || m <= 0.0 {
        return 0.0;
    }
    let (f, g) = (pdf_f / m, pdf_g / m);
    f * f / (f * f + g * g)
}

#[test]
fn mis_weight_alternative_passes() {
    passes("scaled by the larger pdf", || {
        ch6::check_mis_weight(mis_scaled)
    });
}

// ---- 6.4 path_radiance ----------------------------------------------------------

/// Roulette at a fixed q = 0.8, not taken from the throughput.
fn path_fixed_q(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    let k = PathKnobs::with(|k| k.q = Survival::Fixed(0.8));
    knobs::path(k, scene, o, d, rng)
}

/// A light sample's cosine not clamped: light from behind subtracted.
fn path_nee_unclamped(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    let k = PathKnobs::with(|k| k.light_cos = LightCos::Unclamped);
    knobs::path(k, scene, o, d, rng)
}

/// Correct: roulette from the first bounce on β's mean, in [0.05, 1].
fn path_mean_roulette(
    scene: &PathScene,
    origin: Vec3,
    dir: Vec3,
    rng: &mut dyn FnMut() -> f32,
) -> Vec3 {
    let Some(mut hit) = scene.first_hit(origin, dir) else {
        return Vec3::ZERO;
    };
    let (mut l, mut beta) = (hit.emitted, Vec3::ONE);
    loop {
        let brdf = hit.albedo * std::f32::consts::FRAC_1_PI;
        if let Some(ls) = scene.sample_light(&hit, Vec2::new(rng(), rng())) {
            let c = hit.n.dot(ls.wi);
            if c > 0.0 && ls.pdf > 0.0 && scene.unoccluded(&hit, ls.wi, ls.dist) {
                l += beta * brdf * ls.li * (c / ls.pdf);
            }
        }
        let (wi, pdf) = scene.sample_cosine(&hit, Vec2::new(rng(), rng()));
        if pdf.is_nan() || pdf <= 0.0 {
            break;
        }
        beta *= brdf * (hit.n.dot(wi) / pdf);
        let q = ((beta.x + beta.y + beta.z) / 3.0).clamp(0.05, 1.0);
        if rng() >= q {
            break;
        }
        beta /= q;
        match scene.next_hit(&hit, wi) {
            Some(next) => hit = next,
            None => break,
        }
    }
    l
}

#[test]
fn path_radiance_fixed_q_fails() {
    fails_every(
        PATH_SEEDS,
        "q = 0.8",
        Some("survival not taken from the throughput"),
        || paths::check_path_radiance(path_fixed_q),
    );
}

#[test]
fn path_radiance_unclamped_light_sample_fails() {
    fails_every(
        PATH_SEEDS,
        "the light sample's cosine not clamped",
        Some("a light sample from behind the surface counted"),
        || paths::check_path_radiance(path_nee_unclamped),
    );
}

#[test]
fn path_radiance_mean_roulette_passes() {
    passes_every(PATH_SEEDS, "roulette on β's mean", || {
        paths::check_path_radiance(path_mean_roulette)
    });
}

// ---- 6.5 refraction -------------------------------------------------------------

/// Correct: the tangential part scaled by η, Fresnel by Walter's g.
fn refract_tangent(d: Vec3, n: Vec3, eta_outside: f32, eta_inside: f32) -> Option<(Vec3, f32)> {
    let outside = d.dot(n) < 0.0;
    let m = if outside { n } else { -n };
    let (ei, et) = if outside {
        (eta_outside, eta_inside)
    } else {
        (eta_inside, eta_outside)
    };
    let eta = ei / et;
    let c = -d.dot(m);
    let t_tan = eta * (d + c * m);
    let s2 = t_tan.length_squared();
    if s2 >= 1.0 {
        return None;
    }
    let t = (t_tan - (1.0 - s2).sqrt() * m).normalize();
    let nr = et / ei;
    let g = (nr * nr - 1.0 + c * c).sqrt();
    let a = (g - c) / (g + c);
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    Some((t, 0.5 * a * a * (1.0 + b * b)))
}

#[test]
fn refraction_alternative_passes() {
    passes("by the tangent, Walter's Fresnel", || {
        refraction::check_refraction(refract_tangent)
    });
}
