//! Chapter 1's exercises and how each is graded. The capstone's check is
//! in [`edges`].

use glam::{Mat4, Vec2, Vec3};

use crate::ch1_projection::camera::{
    camera_from_world_look_at, project_pinhole, Camera, CameraDesc,
};
use crate::ch1_projection::wireframe::draw_scene;
use crate::exercise::{Check, Exercise, Symptom};
use crate::exercises::draws::Draws;
use crate::exercises::{stateless, AbsMax};
use crate::scene::Material;

pub mod edges;

pub use edges::{check_draw_edges, reference_edge, EdgeFn};

/// The image turned upside down: the sign of the projection.
pub const MIRRORED: Symptom = Symptom {
    name: "mirrored image",
};
/// A point with no image given one.
pub const NO_IMAGE: Symptom = Symptom {
    name: "a point with no image got one",
};
/// world_from_camera returned instead of camera_from_world.
pub const INVERSE: Symptom = Symptom {
    name: "the inverse matrix",
};
/// An axis of the camera's frame with the wrong sign.
pub const AXIS_SIGN: Symptom = Symptom {
    name: "an axis points the wrong way",
};
/// Axes that are not unit length.
pub const NOT_UNIT: Symptom = Symptom {
    name: "axes not unit length",
};
/// Capstone: the ends in the other order.
pub const ORDER: Symptom = Symptom {
    name: "the ends in the other order",
};
/// Capstone: an edge behind the near plane drawn.
pub const BEHIND_DRAWN: Symptom = Symptom {
    name: "an edge behind the near plane drawn",
};
/// Capstone: a partly visible edge dropped.
pub const DROPPED: Symptom = Symptom {
    name: "a visible edge dropped",
};
/// Capstone: the hidden end projected without a cut.
pub const NOT_CLIPPED: Symptom = Symptom {
    name: "the hidden end projected",
};
/// Capstone: the cut not on the near plane.
pub const WRONG_CUT: Symptom = Symptom {
    name: "the cut is not on the near plane",
};
/// Capstone: an end on the near plane treated as behind it.
pub const ON_PLANE: Symptom = Symptom {
    name: "an end on the near plane",
};

/// Chapter 1's exercises, in order.
pub fn exercises() -> Vec<Exercise> {
    vec![
        Exercise {
            chapter: 1,
            name: "project_point",
            file: "chapters/ch1-projection/exercises/project_point.rs",
            symptoms: &[MIRRORED, NO_IMAGE],
            reference: || check_project_point(project_pinhole),
        },
        Exercise {
            chapter: 1,
            name: "look_at",
            file: "chapters/ch1-projection/exercises/look_at.rs",
            symptoms: &[INVERSE, AXIS_SIGN, NOT_UNIT],
            reference: || {
                check_look_at(|e, t, u| camera_from_world_look_at(e, t, u).unwrap_or(Mat4::NAN))
            },
        },
        Exercise {
            chapter: 1,
            name: "draw_edges",
            file: "chapters/ch1-projection/exercises/draw_edges.rs",
            symptoms: &[
                ORDER,
                BEHIND_DRAWN,
                DROPPED,
                NOT_CLIPPED,
                WRONG_CUT,
                ON_PLANE,
                MIRRORED,
            ],
            reference: || check_draw_edges(reference_edge),
        },
    ]
}

/// Compares a pinhole projection with values worked out by hand.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_project_point(f: fn(Vec3) -> Option<Vec2>) -> Check {
    stateless::unless_changed(project_point_values(f), || {
        stateless::probes::project_point(f, project_pinhole)
    })
}

/// [`check_project_point`]'s checks of the values.
fn project_point_values(f: fn(Vec3) -> Option<Vec2>) -> Check {
    // (point, expected image): first one behind the camera (a side taken
    // from the first point asked would be the wrong one), then in front of
    // it, worked out by hand...
    let mut cases: Vec<(Vec3, Option<Vec2>)> = vec![
        (Vec3::new(0.5, -1.0, 2.0), None),
        (Vec3::new(1.0, 2.0, -2.0), Some(Vec2::new(0.5, 1.0))),
        (Vec3::new(-3.0, 0.0, -1.0), Some(Vec2::new(-3.0, 0.0))),
        (Vec3::new(0.2, -0.4, -4.0), Some(Vec2::new(0.05, -0.1))),
        (Vec3::new(0.0, 0.0, -1e6), Some(Vec2::ZERO)),
        // A subnormal depth, z < 0 all the same: (2⁻¹²⁶, -2⁻¹²⁵, -2⁻¹²⁷)
        // (1/z, 2¹²⁷, is still finite).
        (
            Vec3::new(2f32.powi(-126), -(2f32.powi(-125)), -(2f32.powi(-127))),
            Some(Vec2::new(2.0, -4.0)),
        ),
        // ... and points with no image.
        (Vec3::new(0.0, 0.0, 1.0), None),
        (Vec3::new(1.0, 1.0, 0.0), None),
    ];
    // A grid of points at several depths: x/(-z), y/(-z).
    for k in 1..=4 {
        let z = -(k as f32) * 1.5;
        for x in [-2.0f32, 0.5, 3.0] {
            cases.push((
                Vec3::new(x, 1.0 - x, z),
                Some(Vec2::new(x / -z, (1.0 - x) / -z)),
            ));
        }
    }
    // Drawn points: depths from 10⁻³ to 10⁴ in front, and now and then
    // from 10⁻³⁰ or up to 10³⁰ (a scene's units are its own: a point just
    // in front of the pinhole still has an image), sideways up to ten
    // times the depth, and points on or behind the camera's plane; the
    // image worked out in f64.
    let mut draws = Draws::new(11);
    for _ in 0..draws.count(200, 1000) {
        draws.next_case();
        let depth = match draws.count(0, 9) {
            0 => draws.decades(-30.0, -3.0),
            1 => draws.decades(4.0, 30.0),
            _ => draws.decades(-3.0, 4.0),
        };
        // Sideways up to ten times the depth, a tenth from 10⁻¹² up to 10⁷
        // times (within 10⁻⁵ rad of the camera's plane: still an image).
        // A tenth near the view axis, 10⁻¹² to 10⁻⁶ of the depth.
        let (narrow, wide) = match draws.count(0, 9) {
            0 => (-12.0, 7.0),
            1 => (-12.0, -6.0),
            _ => (-2.0, 1.0),
        };
        let side = draws.in_square() * depth * draws.decades(narrow, wide);
        let p = match draws.count(0, 9) {
            // On the camera's plane, z = +0 or -0 (no image either way).
            0 => Vec3::new(side.x, side.y, draws.sign() * 0.0),
            1 => Vec3::new(side.x, side.y, depth),
            _ => Vec3::new(side.x, side.y, -depth),
        };
        let want = (p.z < 0.0).then(|| {
            let (x, y, z) = (p.x as f64, p.y as f64, p.z as f64);
            Vec2::new((x / -z) as f32, (y / -z) as f32)
        });
        cases.push((p, want));
    }
    let mut worst = (0.0f64, String::from("all cases match"));
    // The mistakes it can name: every image the negative of the right one
    // (the slide's sign), or an image for a point that has none.
    let (mut mirrored, mut no_image) = (true, false);
    for (p, want) in cases {
        let got = f(p);
        match (got, want) {
            (Some(g), Some(w)) => mirrored &= (g + w).length() <= 1e-5 * w.length().max(1.0),
            (Some(_), None) => no_image = true,
            (None, None) => {}
            (None, Some(_)) => mirrored = false,
        }
        let err = match (got, want) {
            // Each coordinate relative to itself: one division makes it.
            (Some(g), Some(w)) => ((g - w) / w.abs().max(Vec2::splat(1e-30))).abs_max() as f64,
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        // A NaN (from a NaN answer) counts as infinitely wrong.
        let err = if err.is_nan() { f64::INFINITY } else { err };
        if err > worst.0 {
            worst = (
                err,
                format!("p = {p}: got {}, expected {}", show(got), show(want)),
            );
        }
    }
    let check = Check {
        error: worst.0,
        tolerance: 1e-5,
        detail: worst.1,
        images: None,
        symptom: None,
    };
    if check.passed() {
        check
    } else if mirrored {
        check.with_symptom(MIRRORED)
    } else if no_image {
        check.with_symptom(NO_IMAGE)
    } else {
        check
    }
}

/// An image point, with non-finite coordinates as `inf` or `NaN`.
fn show(p: Option<Vec2>) -> String {
    p.map_or("None".into(), |p| format!("Some(({}, {}))", p.x, p.y))
}

/// Compares a look-at matrix with the reference on several cameras, then
/// renders the lecture's tetrahedron through it.
/// Then, asked again after other questions, the same answers ([`stateless`]).
pub fn check_look_at(f: fn(Vec3, Vec3, Vec3) -> Mat4) -> Check {
    stateless::unless_changed(look_at_values(f), || {
        stateless::probes::look_at(f, |e, t, u| {
            camera_from_world_look_at(e, t, u).unwrap_or(Mat4::NAN)
        })
    })
}

/// [`check_look_at`]'s checks of the values.
fn look_at_values(f: fn(Vec3, Vec3, Vec3) -> Mat4) -> Check {
    let cameras = [
        (Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y),
        (Vec3::new(3.0, 2.0, 4.0), Vec3::new(0.0, 0.5, 0.0), Vec3::Y),
        (
            Vec3::new(-2.0, 5.0, 1.0),
            Vec3::new(1.0, 0.0, -1.0),
            Vec3::new(0.0, 0.0, -1.0),
        ),
        (
            Vec3::new(10.0, -3.0, 0.5),
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(0.3, 1.0, 0.1),
        ),
    ];
    let mut worst = (0.0f64, String::from("all matrices match"));
    for (eye, target, up) in cameras {
        let want = camera_from_world_look_at(eye, target, up).expect("proper frames");
        let got = f(eye, target, up);
        // The camera must send the eye to the origin and the target onto -z.
        let err = (got - want)
            .to_cols_array()
            .iter()
            .map(|d| match d.is_nan() {
                // (f64::max passes over a NaN: one NaN entry is infinitely off.)
                true => f64::INFINITY,
                false => d.abs() as f64,
            })
            .fold(0.0, f64::max);
        if err > worst.0 {
            worst = (
                err,
                format!(
                    "eye {eye}, target {target}, up {up}: eye maps to {}, target to {}",
                    got.transform_point3(eye),
                    got.transform_point3(target)
                ),
            );
        }
    }
    // Drawn cameras: scenes from 10⁻⁴ to 10² across, up to 100 times that
    // from the origin, `up` of any length (10⁻⁶ to 10², so that a guard on
    // the length of up × view is not taken for the degenerate case it is
    // not: the contract's up has no length) and at least 17° from the view
    // (a fifth 0.3° to 8° from it; some 10⁻⁴ to 10^-2.5 rad short of
    // perpendicular to it, where up itself is nearly, not quite, the
    // picture's y).
    // The axes to 1e-4; the translation to 1e-4 of the eye's distance
    // from the origin (what rounding allows there).
    // A third of them keep the last camera's eye, or its up: the matrix
    // depends on all three inputs, whichever stayed the same.
    let mut draws = Draws::new(12);
    let up_length = |d: &mut Draws| d.decades(-6.0, 2.0);
    let mut last: Option<(Vec3, Vec3, f32)> = None;
    for _ in 0..draws.count(50, 200) {
        draws.next_case();
        let mut size = draws.decades(-4.0, 2.0);
        let mut eye = draws.place_for(size, 2.0) + draws.in_cube() * size;
        let mut view = draws.direction();
        let mut up = draws.direction() * up_length(&mut draws);
        match (last, draws.count(0, 5)) {
            (Some((e, _, s)), 0 | 1) => (eye, size) = (e, s),
            (Some((_, u, _)), 2) => up = u,
            _ => {}
        }
        // A fifth with `up` 0.3° to 8° from the view (either way along
        // it; evenly in the angle's decades), the eye near the origin so
        // that no other rounding is magnified: up is still not parallel,
        // and it still points up (a "nearly parallel" cut-off is wrong).
        let near_parallel = draws.unit() < 0.2;
        if near_parallel {
            eye = draws.in_cube() * size;
            let (a, b) = view.any_orthonormal_pair();
            let (s, c) = draws.range(0.0, std::f32::consts::TAU).sin_cos();
            let side = a * c + b * s;
            let (sin, cos) = draws.decades(-2.3, -0.85).sin_cos();
            up = (view * cos * draws.sign() + side * sin) * up_length(&mut draws);
        } else if draws.unit() < 0.3 {
            // Exactly along an axis, up along another (a view straight
            // down z is no special case).
            let axis = draws.count(0, 2);
            view = Vec3::AXES[axis] * draws.sign();
            up = Vec3::AXES[(axis + 1 + draws.count(0, 1)) % 3]
                * draws.sign()
                * up_length(&mut draws);
        } else if draws.unit() < 0.15 {
            let (a, b) = view.any_orthonormal_pair();
            let (s, c) = draws.range(0.0, std::f32::consts::TAU).sin_cos();
            let tilt = draws.sign() * draws.decades(-4.0, -2.5);
            up = ((a * c + b * s) + view * tilt) * up_length(&mut draws);
        }
        let target = eye + view * size * draws.range(0.5, 3.0);
        last = Some((eye, up, size));
        if !near_parallel && up.normalize().cross(view).length() < 0.3 {
            continue;
        }
        let Some(want) = camera_from_world_look_at(eye, target, up) else {
            continue;
        };
        let got = f(eye, target, up);
        let scale = eye.length().max(1.0) as f64;
        let (g, w) = (got.to_cols_array(), want.to_cols_array());
        let err = (0..16)
            .map(|k| {
                let d = (g[k] - w[k]).abs() as f64;
                // Entries 12..15 are the translation column.
                if (12..15).contains(&k) {
                    d / scale
                } else {
                    d
                }
            })
            .fold(
                0.0,
                |a: f64, d| if d.is_nan() { f64::INFINITY } else { a.max(d) },
            );
        if err > worst.0 {
            worst = (
                err,
                format!(
                    "eye {eye}, target {target}, up {up} (a drawn camera): got {got:?}, expected {want:?}"
                ),
            );
        }
    }
    // The picture: the tetrahedron through the candidate and the reference.
    let desc = CameraDesc {
        eye: glam::DVec3::new(3.0, 2.0, 4.0),
        target: glam::DVec3::ZERO,
        up: glam::DVec3::Y,
        fov_degrees: 45.0,
        width: 160,
        height: 120,
    };
    let reference = Camera::new(desc).expect("valid camera");
    let mut candidate = reference.clone();
    candidate.camera_from_world = f(desc.eye.as_vec3(), desc.target.as_vec3(), desc.up.as_vec3());
    let mesh = [crate::scene::mesh::Mesh::tetrahedron()];
    let materials = [Material::default_grey()];
    let (ref_films, _) = draw_scene(&reference, &mesh, &materials, 0..reference.height);
    let (cand_films, _) = draw_scene(&candidate, &mesh, &materials, 0..candidate.height);
    let check = Check {
        error: worst.0,
        tolerance: 1e-4,
        detail: worst.1,
        images: Some((cand_films[0].clone(), ref_films[0].clone())),
        symptom: None,
    };
    match look_at_mistake(f, &cameras) {
        Some(symptom) if !check.passed() => check.with_symptom(symptom),
        _ => check,
    }
}

/// The mistake a look-at matrix makes on every camera, if one: the
/// inverse returned, an axis flipped, axes not unit length.
fn look_at_mistake(
    f: fn(Vec3, Vec3, Vec3) -> Mat4,
    cameras: &[(Vec3, Vec3, Vec3)],
) -> Option<Symptom> {
    let close = |a: Mat4, b: Mat4| (a - b).to_cols_array().iter().all(|d| d.abs() <= 1e-3);
    let all = |test: &dyn Fn(Mat4, Mat4) -> bool| {
        cameras.iter().all(|&(eye, target, up)| {
            let want = camera_from_world_look_at(eye, target, up).expect("proper frames");
            test(f(eye, target, up), want)
        })
    };
    // got = S · want for a sign matrix S: an axis (or two) flipped.
    let flipped = |got: Mat4, want: Mat4| {
        let s = got * want.inverse();
        let diag = Vec3::new(s.x_axis.x, s.y_axis.y, s.z_axis.z);
        diag.abs().cmpge(Vec3::splat(0.999)).all()
            && diag.cmplt(Vec3::ZERO).any()
            && close(s, Mat4::from_scale(diag.signum()))
    };
    let not_unit = |got: Mat4, _: Mat4| {
        let r = glam::Mat3::from_mat4(got).transpose();
        [r.x_axis, r.y_axis, r.z_axis]
            .iter()
            .any(|c| (c.length() - 1.0).abs() > 1e-3)
    };
    if all(&|got, want| close(got, want.inverse())) {
        Some(INVERSE)
    } else if all(&flipped) {
        Some(AXIS_SIGN)
    } else if all(&not_unit) {
        Some(NOT_UNIT)
    } else {
        None
    }
}
