//! The stiff and extreme cases of chapter 1 (requirement 2): points behind
//! and on the camera plane, edges crossing it, NaN ends, fields of view near
//! 0° and 180°, coordinates far from the origin.

use glam::{DVec3, Vec2, Vec3};

use super::camera::{project_pinhole, Camera};
use super::studies::points_at_depth;
use super::wireframe::{project_edge, NEAR};
use crate::core::draw;
use crate::core::film::Film;
use crate::core::format::{format_number, format_vec2};
use crate::core::report::StabilityCase;

/// Requirement 2 for chapter 1: the named stiff and extreme cases.
pub fn stability_cases(cam: &Camera) -> Vec<StabilityCase> {
    let mut cases = Vec::new();
    let mut case = |name: &str, expected: &str, measured: String, ok: bool| {
        cases.push(StabilityCase::new(name, expected, measured, ok))
    };
    let shown = |r: Option<Vec2>| r.map(format_vec2).unwrap_or_else(|| "culled".into());

    let r = project_pinhole(Vec3::new(0.5, 0.5, 1.0));
    case(
        "point behind the camera (z = +1)",
        "culled",
        shown(r),
        r.is_none(),
    );
    let r = project_pinhole(Vec3::new(0.5, 0.5, 0.0));
    case(
        "point on the camera plane (z = 0)",
        "culled, no division by zero",
        shown(r),
        r.is_none(),
    );
    let r = project_pinhole(Vec3::new(1.0, 1.0, -1e-40));
    case(
        "point 1e-40 in front of the pinhole",
        "culled, no Inf",
        shown(r),
        r.is_none(),
    );
    let r = project_pinhole(Vec3::new(0.0, 0.0, -1e7));
    case(
        "point 1e7 away on the axis",
        "(0, 0)",
        shown(r),
        r == Some(Vec2::ZERO),
    );

    // Edges through the whole pipeline: clip, project, draw.
    let draw_edge = |a: Vec3, b: Vec3| {
        let mut film = Film::new(cam.width, cam.height);
        let e = project_edge(cam, a, b);
        let lit = e.map_or(0, |e| draw::line(&mut film, e.a, e.b, Vec3::ONE, Vec3::ONE));
        (e, lit, film)
    };
    let (a, b) = (Vec3::new(-0.2, -0.1, -2.0), Vec3::new(0.3, -0.1, 2.0));
    let (e, lit, mut film) = draw_edge(a, b);
    let front = cam.raster_from_image_plane(project_pinhole(a).unwrap_or_default());
    let front_lit = film.get(
        (front.x as u32).min(cam.width - 1),
        (front.y as u32).min(cam.height - 1),
    ) != Vec3::ZERO;
    let cut_depth = e.map_or(f32::NAN, |e| e.depth[1]);
    let nan = film.scrub_nonfinite();
    case(
        "edge crossing the camera plane",
        "cut at depth = near; the visible part drawn from its front end",
        format!(
            "cut at depth {cut_depth}, {lit} samples drawn, front end lit: {front_lit}, NaN: {nan}"
        ),
        cut_depth == NEAR && lit > 0 && front_lit && nan == 0,
    );
    let (_, lit, _) = draw_edge(Vec3::new(0.0, 0.0, 1.0), Vec3::new(1.0, 1.0, 3.0));
    case(
        "edge entirely behind the camera",
        "nothing drawn",
        format!("{lit} samples drawn"),
        lit == 0,
    );
    let (_, lit, _) = draw_edge(
        Vec3::new(f32::NAN, 0.0, -1.0),
        Vec3::new(0.0, f32::NAN, f32::NAN),
    );
    case(
        "edge with NaN ends",
        "nothing drawn",
        format!("{lit} samples drawn"),
        lit == 0,
    );

    // Extreme fields of view and far-off coordinates: the f32 camera against
    // exact pixel positions.
    let extreme = |fov: f64, eye: DVec3, depth: f64| -> (f64, bool) {
        let desc = crate::scene::camera::CameraDesc {
            fov_degrees: fov,
            eye,
            target: eye + DVec3::new(0.0, 0.0, -10.0),
            up: DVec3::Y,
            ..cam.desc
        };
        let Ok(c) = Camera::new(desc) else {
            return (f64::NAN, false);
        };
        let mut worst: f64 = 0.0;
        let mut finite = true;
        for (w, r) in points_at_depth(&c, depth) {
            match c.project(w.as_vec3()) {
                Some(p) if p.is_finite() => worst = worst.max((p.as_dvec2() - r).length()),
                _ => finite = false,
            }
        }
        (worst, finite)
    };
    for fov in [0.01, 179.99] {
        let (e, fin) = extreme(fov, DVec3::ZERO, 10.0);
        case(
            &format!("fov {fov}°"),
            "finite, within 0.5 px",
            format!("max error {} px", format_number(e)),
            fin && e < 0.5,
        );
    }
    let (e, fin) = extreme(cam.desc.fov_degrees, DVec3::splat(1e7), 10.0);
    case(
        "camera and points at coordinates 1e7",
        "finite; f32 spacing there is 1.0, so large error is expected and reported",
        format!("max error {} px", format_number(e)),
        fin,
    );
    cases
}
