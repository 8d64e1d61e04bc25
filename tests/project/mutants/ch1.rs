//! Chapter 1's graders against plausible wrong solutions (each must fail
//! and name its mistake) and correct alternatives (each must pass).

use glam::{Mat4, Vec2, Vec3};
use raystep::ch1_projection::camera::{camera_from_world_look_at, Camera};
use raystep::grading::exercise::{Check, Symptom};
use raystep::grading::exercises::ch1;

fn expect(check: Check, symptom: Symptom, what: &str) {
    super::fails_naming(check, symptom, &ch1::exercises(), what);
}

fn raster(camera: &Camera, p: Vec3) -> Vec2 {
    camera.raster_from_image_plane(Vec2::new(p.x / -p.z, p.y / -p.z))
}

/// The capstone as a student writes it from the book: cut the end behind
/// the near plane, from the end in front.
fn book(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (mut a, mut b) = (camera.to_camera(a), camera.to_camera(b));
    let (da, db) = (a.z + near, b.z + near);
    if da > 0.0 && db > 0.0 {
        return None;
    }
    if da > 0.0 {
        a = b.lerp(a, db / (db - da)).with_z(-near);
    } else if db > 0.0 {
        b = a.lerp(b, da / (da - db)).with_z(-near);
    }
    Some((raster(camera, a), raster(camera, b)))
}

/// Correct, another formulation: the cut computed from the end behind,
/// and projected as (x / near, y / near) since it lies on the plane.
fn alternative_from_behind(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (a, b) = (camera.to_camera(a), camera.to_camera(b));
    let behind = |p: Vec3| p.z > -near;
    let cut = |from: Vec3, to: Vec3| {
        let s = (from.z + near) / (from.z - to.z);
        let p = from + (to - from) * s;
        camera.raster_from_image_plane(Vec2::new(p.x / near, p.y / near))
    };
    match (behind(a), behind(b)) {
        (true, true) => None,
        (false, false) => Some((raster(camera, a), raster(camera, b))),
        (true, false) => Some((cut(a, b), raster(camera, b))),
        (false, true) => Some((raster(camera, a), cut(b, a))),
    }
}

/// Correct, another formulation: the parametric clip (Liang–Barsky) of
/// p(t) = a + t (b - a), t in [0, 1], to the half-space z <= -near.
fn alternative_parametric(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (a, b) = (camera.to_camera(a), camera.to_camera(b));
    let d = b - a;
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    // a.z + t d.z <= -near
    let limit = -near - a.z;
    if d.z == 0.0 {
        if limit < 0.0 {
            return None;
        }
    } else if d.z > 0.0 {
        t1 = t1.min(limit / d.z);
    } else {
        t0 = t0.max(limit / d.z);
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f32| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            // A cut: on the plane, as the contract says.
            (a + d * t).with_z(-near)
        }
    };
    Some((raster(camera, at(t0)), raster(camera, at(t1))))
}

/// The slide's u = x / z: the picture upside down.
fn mirrored(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let flip = |p: Vec2| camera.raster_from_image_plane(-camera.image_plane_from_raster(p));
    book(camera, a, b, near).map(|(p, q)| (flip(p), flip(q)))
}

/// The ends returned as (b, a).
fn swapped(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    book(camera, a, b, near).map(|(p, q)| (q, p))
}

/// The cut end always returned first, whichever end was cut.
fn cut_first(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (ca, cb) = (camera.to_camera(a), camera.to_camera(b));
    let r = book(camera, a, b, near)?;
    Some(if cb.z > -near && ca.z <= -near {
        (r.1, r.0)
    } else {
        r
    })
}

/// No clipping: both ends projected, also one behind the camera (an edge
/// wholly behind is still dropped).
fn unclipped(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (ca, cb) = (camera.to_camera(a), camera.to_camera(b));
    if ca.z > -near && cb.z > -near {
        return None;
    }
    Some((raster(camera, ca), raster(camera, cb)))
}

/// An edge that crosses the near plane dropped as a whole.
fn dropped(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (ca, cb) = (camera.to_camera(a), camera.to_camera(b));
    if ca.z > -near || cb.z > -near {
        return None;
    }
    book(camera, a, b, near)
}

/// The chapter's constant NEAR used instead of the `near` given.
fn constant_near(camera: &Camera, a: Vec3, b: Vec3, _near: f32) -> Option<(Vec2, Vec2)> {
    book(camera, a, b, raystep::ch1_projection::wireframe::NEAR)
}

/// The cut parameter measured from the wrong end: s = db / (db - da)
/// applied from a.
fn wrong_parameter(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (mut a, mut b) = (camera.to_camera(a), camera.to_camera(b));
    let (da, db) = (a.z + near, b.z + near);
    if da > 0.0 && db > 0.0 {
        return None;
    }
    let s = db / (db - da);
    if da > 0.0 {
        a = a.lerp(b, s);
    } else if db > 0.0 {
        b = a.lerp(b, s);
    }
    Some((raster(camera, a), raster(camera, b)))
}

/// Behind means z > 0 (the pinhole) rather than z > -near.
fn pinhole_plane(camera: &Camera, a: Vec3, b: Vec3, _near: f32) -> Option<(Vec2, Vec2)> {
    let (ca, cb) = (camera.to_camera(a), camera.to_camera(b));
    if ca.z >= 0.0 && cb.z >= 0.0 {
        return None;
    }
    book(camera, a, b, 1e-6)
}

/// An end exactly on the near plane counted as behind it (z < -near to be
/// in front).
fn strict_plane(camera: &Camera, a: Vec3, b: Vec3, near: f32) -> Option<(Vec2, Vec2)> {
    let (ca, cb) = (camera.to_camera(a), camera.to_camera(b));
    if ca.z >= -near && cb.z >= -near {
        return None;
    }
    book(camera, a, b, near)
}

#[test]
fn edge_mutants_fail_with_their_symptom() {
    let cases: [(ch1::EdgeFn, Symptom, &str); 10] = [
        (mirrored, ch1::MIRRORED, "mirrored"),
        (swapped, ch1::ORDER, "(b, a)"),
        (cut_first, ch1::ORDER, "the cut end first"),
        (unclipped, ch1::NOT_CLIPPED, "no clipping"),
        (dropped, ch1::DROPPED, "crossing edges dropped"),
        (constant_near, ch1::WRONG_CUT, "NEAR instead of near"),
        (
            wrong_parameter,
            ch1::WRONG_CUT,
            "the parameter from the wrong end",
        ),
        (pinhole_plane, ch1::WRONG_CUT, "the pinhole's plane"),
        (
            strict_plane,
            ch1::ON_PLANE,
            "the near plane counted as behind",
        ),
        (|_, _, _, _| None, ch1::DROPPED, "nothing drawn"),
    ];
    for (f, symptom, what) in cases {
        expect(ch1::check_draw_edges(f), symptom, what);
    }
}

#[test]
fn edge_alternatives_pass() {
    for (f, what) in [
        (book as ch1::EdgeFn, "the book's recipe"),
        (
            alternative_from_behind,
            "the cut from the end behind, x / near",
        ),
        (alternative_parametric, "the parametric clip"),
        (ch1::reference_edge, "the reference"),
    ] {
        let check = ch1::check_draw_edges(f);
        assert!(check.passed(), "{what}: {}", check.detail);
    }
}

#[test]
fn projection_and_look_at_mutants_name_their_mistake() {
    // The slide's u = x / z.
    let check = ch1::check_project_point(|p| (p.z < 0.0).then(|| Vec2::new(p.x / p.z, p.y / p.z)));
    expect(check, ch1::MIRRORED, "u = x / z");
    // Points behind the camera projected too.
    let check =
        ch1::check_project_point(|p| (p.z != 0.0).then(|| Vec2::new(p.x / -p.z, p.y / -p.z)));
    expect(check, ch1::NO_IMAGE, "points behind");
    let look = |e: Vec3, t: Vec3, u: Vec3| camera_from_world_look_at(e, t, u).unwrap();
    // world_from_camera returned.
    let check = ch1::check_look_at(|e, t, u| camera_from_world_look_at(e, t, u).unwrap().inverse());
    expect(check, ch1::INVERSE, "the inverse");
    // +z towards the target: the camera looks the other way.
    let check = ch1::check_look_at(|e, t, u| {
        let back = (t - e).normalize();
        let right = u.cross(back).normalize();
        Mat4::from_cols(
            right.extend(0.0),
            back.cross(right).extend(0.0),
            back.extend(0.0),
            e.extend(1.0),
        )
        .inverse()
    });
    expect(check, ch1::AXIS_SIGN, "looking backwards");
    // right = back × up: the x axis flipped.
    let check = ch1::check_look_at(|e, t, u| {
        let back = (e - t).normalize();
        let right = back.cross(u).normalize();
        Mat4::from_cols(
            right.extend(0.0),
            back.cross(right).extend(0.0),
            back.extend(0.0),
            e.extend(1.0),
        )
        .inverse()
    });
    expect(check, ch1::AXIS_SIGN, "x flipped");
    // Axes not normalised.
    let check = ch1::check_look_at(|e, t, u| {
        let back = e - t;
        let right = u.cross(back);
        Mat4::from_cols(
            right.extend(0.0),
            back.cross(right).extend(0.0),
            back.extend(0.0),
            e.extend(1.0),
        )
        .inverse()
    });
    expect(check, ch1::NOT_UNIT, "not unit");
    assert!(ch1::check_look_at(look).passed());
}
