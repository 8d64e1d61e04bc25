//! One `[[objects]]` entry built into a mesh in world space: read from an
//! OBJ file or generated (plane, box, sphere), then placed by its
//! transform (a matrix, or scale, rotations and translation in that order).

use glam::{DVec3, Mat4, Quat, Vec3};

use super::file::{ObjectSection, Scale, Shape};
use super::obj;
use super::validate::{self, MAX_COORDINATE, MIN_LENGTH};
use super::MeshReader;
use crate::core::error::{Error, Result};
use crate::scene::mesh::Mesh;

pub(super) fn check_finite(values: &[f64]) -> std::result::Result<(), &'static str> {
    values
        .iter()
        .all(|v| v.is_finite())
        .then_some(())
        .ok_or("must be finite numbers (no nan or inf)")
}

/// One object: its mesh, generated or read, in world space.
/// Positions are relative to `origin` (computed in f64, rounded once).
pub(super) fn build_object(
    o: &ObjectSection,
    (at, source, origin): (&str, &str, DVec3),
    read: &MeshReader,
    max_triangles: usize,
) -> Result<Mesh> {
    let err = |key: &str, message: String| Error::Scene {
        file: source.to_string(),
        at: if key.is_empty() {
            at.to_string()
        } else {
            format!("{at}.{key}")
        },
        message,
    };
    // Which keys apply to which shape, so a stray one is reported, not ignored.
    let shape_keys: [(&str, bool, &[Shape]); 4] = [
        ("radius", o.radius.is_some(), &[Shape::Sphere]),
        ("center", o.center.is_some(), &[Shape::Sphere]),
        ("subdivisions", o.subdivisions.is_some(), &[Shape::Sphere]),
        ("size", o.size.is_some(), &[Shape::Rectangle, Shape::Box]),
    ];
    for (key, present, shapes) in shape_keys {
        if present && !o.shape.is_some_and(|s| shapes.contains(&s)) {
            return Err(err(
                key,
                format!("`{key}` applies only to shape = {shapes:?}"),
            ));
        }
    }
    let mut mesh = match (&o.mesh, o.shape) {
        (Some(_), Some(_)) => return Err(err("", "give either `mesh` or `shape`, not both".into())),
        (None, None) => {
            return Err(err(
                "",
                "an object needs `mesh = \"path.obj\"` or `shape` (tetrahedron, sphere, rectangle, box)".into(),
            ))
        }
        (Some(path), None) => {
            let (display, text) = read(path).map_err(|(display, why)| {
                err("mesh", format!("cannot read mesh `{display}`: {why}"))
            })?;
            obj::parse_obj_limited(&text, &display, max_triangles)?
        }
        (None, Some(shape)) => match shape {
            Shape::Tetrahedron => Mesh::tetrahedron(),
            Shape::Sphere => {
                let radius = o.radius.unwrap_or(1.0);
                if !(radius.is_finite() && (MIN_LENGTH..=MAX_COORDINATE).contains(&radius)) {
                    return Err(err(
                        "radius",
                        format!("must be a number in [{MIN_LENGTH:e}, {MAX_COORDINATE:e}] (f32 lengths), got {radius}"),
                    ));
                }
                let subdivisions = o.subdivisions.unwrap_or(3);
                if subdivisions > 7 {
                    return Err(err(
                        "subdivisions",
                        format!("at most 7 (327,680 triangles), got {subdivisions}"),
                    ));
                }
                let center = o.center.unwrap_or([0.0; 3]);
                validate::position(&center).map_err(|why| err("center", why))?;
                let mut m = Mesh::icosphere(subdivisions);
                m.transform(&Mat4::from_scale_rotation_translation(
                    Vec3::splat(radius as f32),
                    Quat::IDENTITY,
                    DVec3::from(center).as_vec3(),
                ));
                m
            }
            Shape::Rectangle | Shape::Box => {
                let dims = if shape == Shape::Rectangle { 2 } else { 3 };
                let size = o.size.clone().unwrap_or_else(|| vec![1.0; dims]);
                let length = |s: &f64| (MIN_LENGTH..=MAX_COORDINATE).contains(s);
                if size.len() != dims || !size.iter().all(length) {
                    return Err(err(
                        "size",
                        format!(
                            "expected exactly {dims} numbers in [{MIN_LENGTH:e}, {MAX_COORDINATE:e}], got {size:?}"
                        ),
                    ));
                }
                if shape == Shape::Rectangle {
                    Mesh::rectangle(size[0] as f32, size[1] as f32)
                } else {
                    Mesh::cuboid(DVec3::new(size[0], size[1], size[2]).as_vec3())
                }
            }
        },
    };
    if mesh.triangles.len() > max_triangles {
        return Err(err(
            "",
            format!(
                "{} triangles would pass the scene's limit (at most {max_triangles} more; raise it with --max-triangles)",
                mesh.triangles.len()
            ),
        ));
    }
    let (m, translate) = object_transform(o, &err)?;
    if origin == DVec3::ZERO {
        mesh.transform(&m);
    } else {
        // The linear part in f32 as always, the move to `origin` in f64.
        let shift = translate - origin;
        for p in &mut mesh.positions {
            *p = (m.transform_vector3(*p).as_dvec3() + shift).as_vec3();
        }
    }
    let limit = MAX_COORDINATE as f32;
    let outside = |p: &Vec3| !(p.is_finite() && p.abs().max_element() <= limit);
    if let Some(i) = mesh.positions.iter().position(outside) {
        return Err(err(
            "",
            format!(
                "vertex {i} lies at {} after the transform, outside ±{MAX_COORDINATE:e} (the triangle test multiplies three coordinates in f32)",
                mesh.positions[i]
            ),
        ));
    }
    Ok(mesh)
}

/// world_from_object = translate · rotate · scale, or the given matrix.
/// The object's transform, and its translation in f64 as written.
fn object_transform(
    o: &ObjectSection,
    err: &dyn Fn(&str, String) -> Error,
) -> Result<(Mat4, DVec3)> {
    if let Some(rows) = o.matrix {
        if o.scale.is_some() || o.rotate.is_some() || o.translate.is_some() {
            return Err(err(
                "matrix",
                "`matrix` replaces `scale`, `rotate` and `translate`; give one or the others"
                    .into(),
            ));
        }
        let flat: Vec<f64> = rows.iter().flatten().copied().collect();
        validate::position(&flat).map_err(|why| err("matrix", why))?;
        // Rows as written; glam stores columns.
        let m = glam::DMat4::from_cols_array_2d(&rows).transpose().as_mat4();
        if m.determinant().abs() < 1e-12 {
            return Err(err("matrix", "is singular (it flattens the object)".into()));
        }
        let translate = DVec3::new(rows[0][3], rows[1][3], rows[2][3]);
        return Ok((m, translate));
    }
    let scale = match o.scale {
        None => Vec3::ONE,
        Some(Scale::Uniform(s)) => Vec3::splat(s as f32),
        Some(Scale::PerAxis(s)) => DVec3::from(s).as_vec3(),
    };
    let given = match o.scale {
        None => vec![1.0],
        Some(Scale::Uniform(s)) => vec![s],
        Some(Scale::PerAxis(s)) => s.to_vec(),
    };
    validate::position(&given).map_err(|why| err("scale", why))?;
    if scale.abs().min_element() < MIN_LENGTH as f32 {
        return Err(err(
            "scale",
            format!("{given:?} must be non-zero, at least {MIN_LENGTH:e} in size (f32)"),
        ));
    }
    let rotation = match o.rotate {
        None => Quat::IDENTITY,
        Some(r) => {
            validate::within(&[r.degrees], 1e6).map_err(|why| err("rotate.degrees", why))?;
            validate::direction(&r.axis).map_err(|why| err("rotate.axis", why))?;
            let axis = DVec3::from(r.axis).normalize();
            Quat::from_axis_angle(axis.as_vec3(), (r.degrees as f32).to_radians())
        }
    };
    let translate = o.translate.unwrap_or([0.0; 3]);
    validate::position(&translate).map_err(|why| err("translate", why))?;
    Ok((
        Mat4::from_scale_rotation_translation(scale, rotation, DVec3::from(translate).as_vec3()),
        DVec3::from(translate),
    ))
}
