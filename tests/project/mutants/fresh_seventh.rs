//! The seventh fresh set (2026-11-29): plausible wrong solutions written
//! by two more testers from the stubs' contracts before reading the
//! checks, aimed at scale, position, signs of zero, state kept between
//! calls and the statistics of random numbers. The ones the grader let
//! through until this set, now caught: a scene 10⁻⁴ across, an image
//! 10⁻¹² of the depth off the axis, edges from 10⁻⁹ to 10⁶ long, u or v
//! exactly -0, a triangle in the plane z = const 10⁴ sizes out, a leaf that
//! holds more than two triangles, a hit exactly at t_max, N and d 10⁻¹²
//! long, an input repeated with another beside it (the same origin, light
//! point, plane normal or corner), a lookup table of angles, a dim light,
//! a bright furnace. Each must fail under every seed tried; the stateful
//! ones keep their state in a `thread_local`, as the testers wrote, reset
//! before each seed's run (a fresh process's state).

use std::cell::Cell;

use glam::{Mat4, Vec2, Vec3};
use raystep::ch3_ray_triangle::ray::Ray;
use raystep::ch4_implicit_surfaces::march::March;
use raystep::grading::counted::{Hit, ReadableBvh};
use raystep::grading::exercise::Check;
use raystep::grading::exercises::paths::{self, PathScene};
use raystep::grading::exercises::{ch1, ch2, ch3, ch4, ch5};

use super::fails_every;
use super::knobs::{
    self, BvhKnobs, DirectKnobs, InsideKnobs, Knobs, LookKnobs, MollerKnobs, PathKnobs,
    RasterKnobs, SceneKnobs,
};

/// The seeds every mutant must fail under: the testers' two and two more.
const SEEDS: [u64; 4] = [61, 62, 71, 0x2026_1129];

/// The path loop's check traces 200,000 paths per seed: two seeds.
const PATH_SEEDS: &[u64] = &[61, 71];

fn fails(what: &str, check: impl Fn() -> Check) {
    fails_every(&SEEDS, what, None, check);
}

thread_local! {
    static ORIGIN_F: Cell<Option<(Vec3, f32)>> = const { Cell::new(None) };
    static GEOMETRY: Cell<Option<(Vec3, Vec3, f32)>> = const { Cell::new(None) };
    static NORMAL: Cell<Option<(Vec3, Vec3)>> = const { Cell::new(None) };
    static PLANE: Cell<Option<(Vec3, f32)>> = const { Cell::new(None) };
    static LIGHT: Cell<Option<(Vec3, f32)>> = const { Cell::new(None) };
    static SEEN: Cell<Option<(Vec3, bool)>> = const { Cell::new(None) };
}

/// Every cache empty, as in a fresh process.
fn forget() {
    ORIGIN_F.with(|c| c.set(None));
    GEOMETRY.with(|c| c.set(None));
    NORMAL.with(|c| c.set(None));
    PLANE.with(|c| c.set(None));
    LIGHT.with(|c| c.set(None));
    SEEN.with(|c| c.set(None));
}

/// `check` fails under every seed, each run from empty caches.
fn fails_fresh(what: &str, check: impl Fn() -> Check) {
    fails(what, || {
        forget();
        check()
    });
}

// ---- chapter 1 ------------------------------------------------------------------

/// z normalised as v / (|v| + 10⁻⁶) "to avoid dividing by zero".
fn look_at_soft_normalise(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    knobs::look_at(
        LookKnobs::with(|k| k.soft_normalise = Some(1e-6)),
        eye,
        target,
        up,
    )
}

/// |u| or |v| below 10⁻⁶ snapped to 0 ("round-off near the axis").
fn project_snapped(p: Vec3) -> Option<Vec2> {
    if p.z.is_nan() || p.z >= 0.0 {
        return None;
    }
    let t = 1.0 / -p.z;
    let snap = |c: f32| if c.abs() < 1e-6 { 0.0 } else { c };
    Some(Vec2::new(snap(p.x * t), snap(p.y * t)))
}

#[test]
fn projection_mistakes_fail() {
    fails("z softly normalised", || {
        ch1::check_look_at(look_at_soft_normalise)
    });
    fails("images near the axis snapped to 0", || {
        ch1::check_project_point(project_snapped)
    });
}

// ---- chapter 2 ------------------------------------------------------------------

/// 0 for an edge shorter than 10⁻⁶ ("a degenerate edge has no sides").
fn edge_short_is_zero(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    let e = b - a;
    if e.length_squared() < 1e-12 {
        return 0.0;
    }
    e.perp_dot(p - a)
}

/// The edge function as a shoelace sum of the corners' products: it
/// cancels near an edge away from the image's corner.
fn raster_shoelace(v: [Vec3; 3], c: [Vec3; 3], w: u32, h: u32, d: &mut [f32], i: &mut [Vec3]) {
    knobs::rasterize(RasterKnobs::with(|k| k.shoelace = true), v, c, (w, h), d, i);
}

/// Clamped to ±10⁹ "to keep it finite".
fn edge_saturated(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    (b - a).perp_dot(p - a).clamp(-1e9, 1e9)
}

#[test]
fn edge_function_scale_mistakes_fail() {
    fails("short edges give 0", || {
        ch2::check_edge_function(edge_short_is_zero)
    });
    fails("clamped to 10⁹", || {
        ch2::check_edge_function(edge_saturated)
    });
    fails("a shoelace edge function", || {
        ch2::check_rasterize_triangle(raster_shoelace)
    });
}

// ---- chapter 3 ------------------------------------------------------------------

/// u, v tested with `is_sign_positive`: a -0 is outside.
fn inside_sign_bits(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    knobs::inside(InsideKnobs::with(|k| k.sign_bits = true), p, tri)
}

/// The cross products from absolute positions, p × e2 − p0 × e2: they
/// cancel far from the origin.
fn inside_absolute(p: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32)> {
    knobs::inside(InsideKnobs::with(|k| k.absolute = true), p, tri)
}

/// Only a leaf's first four triangles tested.
fn bvh_leaf_of_four(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    knobs::closest_hit(BvhKnobs::with(|k| k.leaf_cap = Some(4)), bvh, ray, t_max)
}

/// Triangles asked for hits before t_best·(1 − 10⁻⁶) ("so equal hits do
/// not replace it"): a hit at exactly t_max is lost.
fn bvh_shrunk_t_max(bvh: &ReadableBvh, ray: &Ray, t_max: f32) -> Option<Hit> {
    knobs::closest_hit(BvhKnobs::default(), bvh, ray, t_max * (1.0 - 1e-6))
}

/// u, v tested with `is_sign_negative`: a -0 is outside.
fn moller_sign_bits(o: Vec3, d: Vec3, tri: [Vec3; 3]) -> Option<(f32, f32, f32)> {
    knobs::moller(MollerKnobs::with(|k| k.sign_bits = true), o, d, tri)
}

/// c remembered by N ("the same plane again").
fn plane_cached(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let c = PLANE.with(|cell| match cell.get() {
        Some((m, c)) if m == n => c,
        _ => {
            cell.set(Some((n, c)));
            c
        }
    });
    let denom = n.dot(d);
    (denom != 0.0).then(|| (c - n.dot(o)) / denom)
}

/// Parallel when (Nᵀd)² is 0: it underflows for Nᵀd under 10⁻²³.
fn plane_squared_test(o: Vec3, d: Vec3, n: Vec3, c: f32) -> Option<f32> {
    let denom = n.dot(d);
    (denom * denom != 0.0).then(|| (c - n.dot(o)) / denom)
}

#[test]
fn ray_triangle_mistakes_fail() {
    fails("-0 outside (barycentric)", || {
        ch3::check_barycentric_inside(inside_sign_bits)
    });
    fails("absolute cross products", || {
        ch3::check_barycentric_inside(inside_absolute)
    });
    fails("leaves of four", || {
        ch3::check_bvh_traversal(bvh_leaf_of_four)
    });
    fails("t_max shrunk by 10⁻⁶", || {
        ch3::check_bvh_traversal(bvh_shrunk_t_max)
    });
    fails("-0 outside (Moller-Trumbore)", || {
        ch3::check_moller_trumbore(moller_sign_bits)
    });
    fails_fresh("c remembered by N", || ch3::check_ray_plane(plane_cached));
    fails("(Nᵀd)² = 0", || ch3::check_ray_plane(plane_squared_test));
}

// ---- chapter 4 ------------------------------------------------------------------

/// f at the ray's origin remembered by the origin alone: another scene
/// from the same eye takes a stale first step.
fn scene_origin_cached(
    sdf: &dyn Fn(Vec3) -> f32,
    o: Vec3,
    d: Vec3,
    m: &March,
) -> Option<(f32, Vec3)> {
    let cached = |p: Vec3| {
        if p != o {
            return sdf(p);
        }
        ORIGIN_F.with(|c| match c.get() {
            Some((at, f)) if at == o => f,
            _ => {
                let f = sdf(p);
                c.set(Some((o, f)));
                f
            }
        })
    };
    knobs::trace_scene(SceneKnobs::default(), &cached, o, d, m)
}

#[test]
fn trace_scene_origin_cached_fails() {
    fails_fresh("f(origin) remembered", || {
        ch4::check_trace_scene(scene_origin_cached)
    });
}

// ---- chapter 5 ------------------------------------------------------------------

/// φ from a table of 256 angles.
fn cosine_table(u: Vec2) -> (Vec3, f32) {
    let r = u.x.sqrt();
    let phi = std::f32::consts::TAU * ((u.y * 256.0) as u32).min(255) as f32 / 256.0;
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    (Vec3::new(x, y, z), z * std::f32::consts::FRAC_1_PI)
}

/// d²/|cos| remembered by the light point and its normal, whatever x.
fn pdf_cached(pdf_area: f32, x: Vec3, y: Vec3, n_light: Vec3) -> f32 {
    let geometry = GEOMETRY.with(|c| match c.get() {
        Some((at, n, g)) if at == y && n == n_light => g,
        _ => {
            let to = x - y;
            let d2 = to.length_squared();
            let cos = n_light.dot(to / d2.sqrt()).abs();
            let g = if cos == 0.0 { 0.0 } else { d2 / cos };
            c.set(Some((y, n_light, g)));
            g
        }
    });
    pdf_area * geometry
}

/// The triangle's normal remembered by its first corner.
fn solid_angle_cached(p: Vec3, tri: [Vec3; 3]) -> f32 {
    let (a, b, c) = (tri[0] - p, tri[1] - p, tri[2] - p);
    let normal = NORMAL.with(|cell| match cell.get() {
        Some((k, n)) if k == tri[0] => n,
        _ => {
            let n = (tri[1] - tri[0]).cross(tri[2] - tri[0]);
            cell.set(Some((tri[0], n)));
            n
        }
    });
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    2.0 * a.dot(normal).abs().atan2(den)
}

/// r² remembered by the light's position, whatever p.
fn point_cached(intensity: Vec3, light: Vec3, p: Vec3, n: Vec3) -> Vec3 {
    let to = light - p;
    let r2 = LIGHT.with(|c| match c.get() {
        Some((at, r2)) if at == light => r2,
        _ => {
            let r2 = to.length_squared();
            c.set(Some((light, r2)));
            r2
        }
    });
    intensity * n.dot(to / r2.sqrt()).max(0.0) / r2
}

#[test]
fn reflection_mistakes_fail() {
    fails("φ from a table", || {
        ch5::check_cosine_hemisphere(cosine_table)
    });
    fails_fresh("d²/|cos| remembered by y", || {
        ch5::check_area_pdf(pdf_cached)
    });
    fails_fresh("the normal remembered by a corner", || {
        ch5::check_solid_angle(solid_angle_cached)
    });
    fails_fresh("r² remembered by the light", || {
        ch5::check_point_light(point_cached)
    });
    fails("dim samples culled", || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, v| {
            let k = DirectKnobs::with(|k| k.cull_below = Some(1e-6));
            knobs::direct(k, (p, n, rho), (y, nl, a, le), v)
        })
    });
    // Visibility remembered by the light point, whatever p.
    fails_fresh("visibility remembered by y", || {
        ch5::check_direct_light(|p, n, rho, y, nl, a, le, visible| {
            let remembered = |p: Vec3, y: Vec3| {
                SEEN.with(|c| match c.get() {
                    Some((at, seen)) if at == y => seen,
                    _ => {
                        let seen = visible(p, y);
                        c.set(Some((y, seen)));
                        seen
                    }
                })
            };
            knobs::direct(
                DirectKnobs::default(),
                (p, n, rho),
                (y, nl, a, le),
                &remembered,
            )
        })
    });
}

// ---- chapter 6 ------------------------------------------------------------------

/// What one light sample brings clamped to 4 per channel ("fireflies").
fn path_clamped(scene: &PathScene, o: Vec3, d: Vec3, rng: &mut dyn FnMut() -> f32) -> Vec3 {
    knobs::path(
        PathKnobs::with(|k| k.light_clamp = Some(4.0)),
        scene,
        o,
        d,
        rng,
    )
}

#[test]
fn path_radiance_clamped_fails() {
    fails_every(PATH_SEEDS, "light samples clamped to 4", None, || {
        paths::check_path_radiance(path_clamped)
    });
}
