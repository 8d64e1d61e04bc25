//! The capstone's check, clause by clause: edges with both ends in front,
//! one end behind (cut exactly at the near plane z = -near), both behind,
//! ends exactly on the near plane, the order of the returned ends; then
//! chapter 1's railroad drawn from between the rails.

use glam::{DVec3, Vec2, Vec3};

use super::{BEHIND_DRAWN, DROPPED, MIRRORED, NOT_CLIPPED, ON_PLANE, ORDER, WRONG_CUT};
use crate::cases::{self, v3, Case, V3};
use crate::ch1_projection::camera::{project_pinhole, Camera, CameraDesc};
use crate::ch1_projection::wireframe::{clip_to_near, NEAR};
use crate::core::draw;
use crate::core::film::Film;
use crate::exercise::{Check, Symptom};
use crate::exercises::draws::{fold_drawn, worst_drawn, Draws};
use crate::exercises::{images, stateless, worse};

/// The capstone's candidate: a world-space edge to its two raster ends.
pub type EdgeFn = fn(&Camera, Vec3, Vec3, f32) -> Option<(Vec2, Vec2)>;

/// raystep's answer to the capstone: chapter 1's clip and projection.
pub fn reference_edge(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (ca, cb) = clip_to_near(camera.to_camera(a), camera.to_camera(b), near)?;
    let (ua, ub) = (project_pinhole(ca)?, project_pinhole(cb)?);
    Some((
        camera.raster_from_image_plane(ua),
        camera.raster_from_image_plane(ub),
    ))
}

/// The capstone: the clauses on a camera at the origin (camera space is
/// world space, so ends on the near plane are exactly on it), then the
/// railroad (whose images a failed clause shows too).
pub fn check_draw_edges(f: EdgeFn) -> Check {
    let clauses = clauses(f);
    if !clauses.passed() {
        // The railroad drawn both ways, to look at (the live view and the
        // failure images show it).
        return Check {
            images: railroad(f).images,
            ..clauses
        };
    }
    stateless::unless_changed(railroad(f), || {
        stateless::probes::draw_edges(f, reference_edge)
    })
}

/// What kind of edge a clause case is.
#[derive(Clone, Copy, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
enum Kind {
    Front,
    Cut,
    Behind,
    OnPlane,
}

/// A clause case (`src/grading/cases.toml`): an edge from `a` to `b`
/// and the near plane.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct ClauseCase {
    kind: Kind,
    a: V3,
    b: V3,
    near: f32,
}

/// A camera at the origin looking down -z, 90° field of view, 200 × 200:
/// raster = (100 (u + 1), 100 (1 - v)), and its camera space is world space.
fn origin_camera() -> Camera {
    Camera::new(CameraDesc {
        eye: DVec3::ZERO,
        target: DVec3::NEG_Z,
        up: DVec3::Y,
        fov_degrees: 90.0,
        width: 200,
        height: 200,
    })
    .expect("a valid camera")
}

/// The relative distance of two raster points (pixels over max(|want|, 1)).
fn rel(p: Vec2, q: Vec2) -> f64 {
    let d = ((p - q).length() / q.length().max(1.0)) as f64;
    if d.is_nan() {
        f64::INFINITY
    } else {
        d
    }
}

/// Clauses on hand-made edges (camera space = world space).
// Tolerance: 1e-5 relative per end. The correct alternatives of
// `tests/project/mutants/ch1.rs` (the cut from the other end, the cut
// projected as x / near, a parametric clip of both ends) agree with the
// reference within 6.1e-7 here; a cut at the wrong plane or parameter is
// off by more than 1.
fn clauses(f: EdgeFn) -> Check {
    let camera = origin_camera();
    let cases: Vec<Case<ClauseCase>> = match cases::of("ch1/draw_edges") {
        Ok(c) => c,
        Err(e) => return cases::unreadable(e),
    };
    for (k, Case { why: what, case }) in cases.iter().enumerate() {
        let (kind, a, b, near) = (case.kind, v3(case.a), v3(case.b), case.near);
        crate::progress(format_args!(
            "calling draw_edges on clause case {k}: {a} to {b}, near {near}"
        ));
        let got = f(&camera, a, b, near);
        let want = reference_edge(&camera, a, b, near);
        let err = match (got, want) {
            (Some(g), Some(w)) => rel(g.0, w.0).max(rel(g.1, w.1)),
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        if err <= 1e-5 {
            continue;
        }
        let detail = format!(
            "{what} (camera at the origin looking down -z, 200 x 200 pixels, near = {near}): the edge \
             from {a} to {b} gave {}, the reference {} (raster pixels)",
            show(got),
            show(want)
        );
        let (why, symptom) = diagnose(&camera, kind, a, b, near, got, want);
        let detail = if why.is_empty() {
            detail
        } else {
            format!("{why}: {detail}")
        };
        return Check {
            error: err,
            tolerance: 1e-5,
            detail,
            images: None,
            symptom,
        };
    }
    // Drawn edges: near planes from 10⁻⁶ to 3 (a fifth, from a stream of
    // their own, 10⁻¹⁰ to 10⁻⁶: every length scales with near), ends from
    // the pinhole to 100 times the near distance in front or behind, in
    // every combination; left out are ends within 10⁻³ of the plane,
    // where rounding decides the side, and edges almost parallel to it.
    let mut draws = Draws::new(13);
    let mut tiny = Draws::new(113);
    let drawn = worst_drawn((0..draws.count(200, 800)).filter_map(|_| {
        draws.next_case();
        tiny.next_case();
        let near = draws.decades(-6.0, 0.5);
        let near = match tiny.unit() < 0.2 {
            true => tiny.decades(-10.0, -6.0),
            false => near,
        };
        let end = |d: &mut Draws| {
            let z = -near * d.sign() * d.decades(-1.0, 2.0);
            let side = d.in_square() * z.abs() * d.range(0.0, 1.5);
            Vec3::new(side.x, side.y, z)
        };
        let (a, b) = (end(&mut draws), end(&mut draws));
        let (da, db) = (a.z + near, b.z + near);
        if da.abs().min(db.abs()) < 1e-3 * near || (da - db).abs() < 0.2 * da.abs().max(db.abs()) {
            return None;
        }
        let (got, want) = (f(&camera, a, b, near), reference_edge(&camera, a, b, near));
        // A cut's rounding grows with the edge's length over the near
        // distance (100 pixels per unit of the image plane): within a few
        // f32 roundings of that, or 1e-5 relative, whichever is larger.
        let rounding =
            100.0 * 4.0 * f32::EPSILON as f64 * (a.length() + b.length()) as f64 / near as f64;
        let off = |g: Vec2, w: Vec2| {
            let d = (g - w).length() as f64;
            let allowed = 1e-5 * (w.length() as f64).max(1.0) + rounding;
            if d.is_nan() {
                f64::INFINITY
            } else {
                d / allowed * 1e-5
            }
        };
        let err = match (got, want) {
            (Some(g), Some(w)) => off(g.0, w.0).max(off(g.1, w.1)),
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        Some((
            err,
            format!(
                "the edge from {a} to {b}, near = {near} (camera at the origin looking down -z, \
                 200 x 200 pixels): gave {}, the reference {}",
                show(got),
                show(want)
            ),
        ))
    }));
    let (mut error, mut detail) = (0.0, "every clause case matches".to_string());
    fold_drawn(&mut error, &mut detail, drawn);
    Check {
        error,
        tolerance: 1e-5,
        detail,
        images: None,
        symptom: None,
    }
}

/// An answer, with non-finite coordinates as `inf` or `NaN`.
fn show(r: Option<(Vec2, Vec2)>) -> String {
    match r {
        None => "None".into(),
        Some((p, q)) => format!("Some(({}, {}), ({}, {}))", p.x, p.y, q.x, q.y),
    }
}

/// What went wrong in a clause case, in words, and its symptom.
fn diagnose(
    camera: &Camera,
    kind: Kind,
    a: Vec3,
    b: Vec3,
    near: f32,
    got: Option<(Vec2, Vec2)>,
    want: Option<(Vec2, Vec2)>,
) -> (String, Option<Symptom>) {
    let close = |p: Vec2, q: Vec2| rel(p, q) <= 1e-3;
    let (w, h) = (camera.width as f32, camera.height as f32);
    let mirror = |p: Vec2| Vec2::new(w - p.x, h - p.y);
    // The raster image of a camera-space point, behind or not.
    let naive = |p: Vec3| camera.raster_from_image_plane(p.truncate() / -p.z);
    match (kind, got, want) {
        (Kind::Behind, Some(_), None) => {
            let between = a.z <= 0.0 && b.z <= 0.0;
            let why = if between {
                "both ends lie between the pinhole and the near plane (-near < z <= 0): nothing is in front of the near plane"
            } else {
                "nothing of this edge is in front of the near plane"
            };
            (why.into(), Some(BEHIND_DRAWN))
        }
        (Kind::Front, None, Some(_)) => (
            "both ends are in front of the near plane: the whole edge is visible".into(),
            Some(DROPPED),
        ),
        (Kind::Cut, None, Some(_)) => (
            "this edge is partly in front of the near plane: its front part must be drawn".into(),
            Some(DROPPED),
        ),
        (Kind::OnPlane, None, Some(_)) | (Kind::OnPlane, Some(_), Some(_)) => (
            "an end exactly on the near plane (z = -near) is in front of it, and stays as it is".into(),
            Some(ON_PLANE),
        ),
        (_, Some(g), Some(r)) if close(g.0, mirror(r.0)) && close(g.1, mirror(r.1)) => (
            "your picture is the reference turned upside down (mirrored through the centre)".into(),
            Some(MIRRORED),
        ),
        (_, Some(g), Some(r)) if close(g.0, r.1) && close(g.1, r.0) => (
            "your ends come back in the other order: the first must be a's (or its cut), the second b's".into(),
            Some(ORDER),
        ),
        (Kind::Cut, Some(g), Some(r)) => {
            // Which end was cut, and where the candidate put it.
            let (cut_is_a, gc, rc) = if a.z > -near { (true, g.0, r.0) } else { (false, g.1, r.1) };
            let (hidden, kept) = if cut_is_a { (a, b) } else { (b, a) };
            if hidden.z > 0.0 && close(gc, naive(hidden)) {
                return (
                    "the end behind the camera was projected as it is (through the pinhole it lands mirrored)".into(),
                    Some(NOT_CLIPPED),
                );
            }
            if !close(gc, rc) {
                let z = depth_along(camera, kept, hidden, gc);
                let why = format!(
                    "your cut end is the image of the edge's point at z = {z:.4} m; the cut belongs on the near \
                     plane, z = -near = {:.4} m",
                    -near
                );
                return (why, Some(WRONG_CUT));
            }
            (String::new(), None)
        }
        _ => (String::new(), None),
    }
}

/// The depth z of the point of the camera-space segment kept→hidden whose
/// image is the raster point `r` (NaN when the point is not on its line).
fn depth_along(camera: &Camera, kept: Vec3, hidden: Vec3, r: Vec2) -> f32 {
    let uv = camera.image_plane_from_raster(r);
    let d = hidden - kept;
    // u (-(kz + s dz)) = kx + s dx  =>  s = (-u kz - kx) / (dx + u dz); the same for v.
    let su = (-uv.x * kept.z - kept.x, d.x + uv.x * d.z);
    let sv = (-uv.y * kept.z - kept.y, d.y + uv.y * d.z);
    let (num, den) = if su.1.abs() >= sv.1.abs() { su } else { sv };
    kept.z + num / den * d.z
}

/// The railroad (`railroad.toml`, 160 × 120), seen from 3 m further down
/// the track so that the rails run past the camera and cross its near
/// plane, drawn edge by edge through the candidate and through the
/// reference.
// Tolerances: the line images must match but for 2e-3 of the pixels
// (where rounding decides a line's pixel); a whole edge's ends within
// 1e-4 (relative); a clipped edge's direction within 5e-3 rad and its
// uncut end within 0.05 pixel: its cut end, 1 mm before the pinhole, lies
// thousands of pixels off the image, where the f32 rounding of the cut
// point moves it by several pixels. Measured on the alternatives of the
// mutant tests: up to 0.49 of 1e-3 rad or of 0.01 pixel, the worse of the
// two; the clauses above already hold the cut exactly.
fn railroad(f: EdgeFn) -> Check {
    let scene = images::scene("railroad.toml");
    let mut desc = scene.camera;
    desc.eye.z -= 3.0;
    desc.target.z -= 3.0;
    desc.width = 160;
    desc.height = 120;
    let camera = Camera::new(desc).expect("a valid camera");
    // The same view at another size: each edge is asked through both, one
    // after the other (a raster point kept for a world point would be the
    // other camera's).
    let wide = Camera::new(CameraDesc {
        width: 224,
        height: 96,
        ..desc
    })
    .expect("a valid camera");
    let edges: Vec<(Vec3, Vec3)> = scene
        .meshes
        .iter()
        .flat_map(|m| {
            m.edges()
                .into_iter()
                .map(|[i, j]| (m.positions[i as usize], m.positions[j as usize]))
        })
        .collect();
    let draw = |g: EdgeFn| {
        let mut film = Film::new(camera.width, camera.height);
        for (k, (a, b)) in edges.iter().enumerate() {
            crate::progress(format_args!(
                "calling draw_edges on railroad edge {k}, {a} to {b}"
            ));
            if let Some((ra, rb)) = g(&camera, *a, *b, NEAR) {
                draw::line(&mut film, ra, rb, Vec3::ONE, Vec3::ONE);
            }
        }
        film
    };
    let mut worst = (0.0f64, String::new());
    for ((a, b), camera) in edges.iter().flat_map(|e| [(e, &camera), (e, &wide)]) {
        let got = f(camera, *a, *b, NEAR);
        let want = reference_edge(camera, *a, *b, NEAR);
        let (ca, cb) = (camera.to_camera(*a), camera.to_camera(*b));
        let clipped = ca.z > -NEAR || cb.z > -NEAR;
        let err = match (got, want) {
            (Some(g), Some(w)) if clipped => {
                let (dg, dw) = ((g.1 - g.0).normalize(), (w.1 - w.0).normalize());
                let angle = dg.dot(dw).clamp(-1.0, 1.0).acos() as f64;
                let end = (g.0 - w.0).length().min((g.1 - w.1).length());
                let end = if (g.0 - w.0).is_nan() || (g.1 - w.1).is_nan() {
                    f32::NAN
                } else {
                    end
                };
                worse(angle / 5e-3, end as f64 / 5e-2)
            }
            (Some(g), Some(w)) => worse(rel(g.0, w.0), rel(g.1, w.1)) / 1e-4,
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            worst = (
                err,
                format!(
                    "the railroad edge from {a} to {b} (camera space z = {} m and {} m) on a {}×{} \
                     image: yours gave {}, the reference {} (raster pixels)",
                    ca.z,
                    cb.z,
                    camera.width,
                    camera.height,
                    show(got),
                    show(want)
                ),
            );
        }
    }
    let explain = |_: u32, _: u32| worst.1.clone();
    let check = images::compare(
        draw(f),
        draw(reference_edge),
        0.05,
        2e-3,
        "wireframe",
        &explain,
    );
    if check.passed() && worst.0 > 1.0 {
        return Check {
            error: 1.0 + check.tolerance,
            detail: format!("the picture matches, but {}", worst.1),
            ..check
        };
    }
    check
}
