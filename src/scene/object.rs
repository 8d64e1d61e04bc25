//! One `[[objects]]` entry built into a mesh in world space: read from an
//! OBJ file or generated (plane, box, sphere), then placed by its
//! transform (a matrix, or scale, rotations and translation in that order).

use glam::{DVec3, Mat4, Quat, Vec3};

use super::file::{ObjectSection, Scale, Shape};
use super::obj;
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
pub(super) fn build_object(
    o: &ObjectSection,
    at: &str,
    source: &str,
    read: &MeshReader,
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
            obj::parse_obj(&text, &display)?
        }
        (None, Some(shape)) => match shape {
            Shape::Tetrahedron => Mesh::tetrahedron(),
            Shape::Sphere => {
                let radius = o.radius.unwrap_or(1.0);
                if !(radius.is_finite() && radius > 0.0) {
                    return Err(err("radius", format!("must be a positive number, got {radius}")));
                }
                let subdivisions = o.subdivisions.unwrap_or(3);
                if subdivisions > 7 {
                    return Err(err(
                        "subdivisions",
                        format!("at most 7 (327,680 triangles), got {subdivisions}"),
                    ));
                }
                let center = o.center.unwrap_or([0.0; 3]);
                check_finite(&center).map_err(|why| err("center", why.into()))?;
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
                if size.len() != dims || !size.iter().all(|s| s.is_finite() && *s > 0.0) {
                    return Err(err(
                        "size",
                        format!("expected {dims} positive numbers, got {size:?}"),
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
    mesh.transform(&object_transform(o, &err)?);
    if let Some(i) = mesh.positions.iter().position(|p| !p.is_finite()) {
        return Err(err(
            "",
            format!(
                "vertex {i} is not finite after the transform ({})",
                mesh.positions[i]
            ),
        ));
    }
    Ok(mesh)
}

/// world_from_object = translate · rotate · scale, or the given matrix.
fn object_transform(o: &ObjectSection, err: &dyn Fn(&str, String) -> Error) -> Result<Mat4> {
    if let Some(rows) = o.matrix {
        if o.scale.is_some() || o.rotate.is_some() || o.translate.is_some() {
            return Err(err(
                "matrix",
                "`matrix` replaces `scale`, `rotate` and `translate`; give one or the others"
                    .into(),
            ));
        }
        let flat: Vec<f64> = rows.iter().flatten().copied().collect();
        check_finite(&flat).map_err(|why| err("matrix", why.into()))?;
        // Rows as written; glam stores columns.
        let m = glam::DMat4::from_cols_array_2d(&rows).transpose().as_mat4();
        if m.determinant().abs() < 1e-12 {
            return Err(err("matrix", "is singular (it flattens the object)".into()));
        }
        return Ok(m);
    }
    let scale = match o.scale {
        None => Vec3::ONE,
        Some(Scale::Uniform(s)) => Vec3::splat(s as f32),
        Some(Scale::PerAxis(s)) => DVec3::from(s).as_vec3(),
    };
    if !scale.is_finite() || scale.abs().min_element() == 0.0 {
        return Err(err(
            "scale",
            format!("must be finite and non-zero, got {scale}"),
        ));
    }
    let rotation = match o.rotate {
        None => Quat::IDENTITY,
        Some(r) => {
            check_finite(&[r.axis[0], r.axis[1], r.axis[2], r.degrees])
                .map_err(|why| err("rotate", why.into()))?;
            let axis = DVec3::from(r.axis)
                .try_normalize()
                .ok_or_else(|| err("rotate.axis", "must not be the zero vector".into()))?;
            Quat::from_axis_angle(axis.as_vec3(), (r.degrees as f32).to_radians())
        }
    };
    let translate = o.translate.unwrap_or([0.0; 3]);
    check_finite(&translate).map_err(|why| err("translate", why.into()))?;
    Ok(Mat4::from_scale_rotation_translation(
        scale,
        rotation,
        DVec3::from(translate).as_vec3(),
    ))
}
