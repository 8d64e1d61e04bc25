//! Scene files → a validated [`Scene`] that holds only what the file uses.
//!
//! Loading happens in three steps: TOML text → serde types ([`file`](mod@file)),
//! checks that name the key that is wrong, then building: meshes are read
//! (OBJ through tobj) or generated, transformed to world space, and bound to
//! materials. Nothing is built for a section the file does not mention.

pub mod camera;
pub mod file;
pub mod mesh;
pub mod obj;
pub mod sdf;
pub mod sdf_parse;

use std::path::{Path, PathBuf};

use glam::{DVec3, Mat4, Quat, Vec3};

use crate::core::error::{Error, Result};
use crate::scene::mesh::Mesh;
use camera::CameraDesc;
use file::{LightSection, MaterialKind, ObjectSection, Scale, SceneFile, Shape};
use sdf::SdfObject;

/// A material, ready to render.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// The name from the scene file.
    pub name: String,
    /// What kind of surface.
    pub kind: MaterialKind,
    /// Diffuse reflectance ρ (linear RGB).
    pub reflectance: Vec3,
    /// Emitted radiance Le (linear RGB); zero for non-emitters.
    pub emission: Vec3,
    /// Whether emission leaves both faces (else the front face only).
    pub two_sided: bool,
    /// Index of refraction inside a glass material (1.5 unless the file
    /// says otherwise; unused by other kinds).
    pub ior: f32,
    /// Lobe sharpness n of glossy, retro-reflective and semi-gloss
    /// materials (chapter 5).
    pub exponent: f32,
    /// Specular fraction k_s of a semi-gloss material (chapter 5).
    pub specular: f32,
}

/// The index of refraction of glass when a scene gives none.
pub const DEFAULT_IOR: f64 = 1.5;
/// The lobe sharpness materials get when the file gives none.
pub const DEFAULT_EXPONENT: f64 = 100.0;
/// The largest lobe sharpness a scene file may ask for.
pub const MAX_EXPONENT: f64 = 1e6;
/// The semi-gloss specular fraction materials get when the file gives none.
pub const DEFAULT_SPECULAR: f64 = 0.1;

impl Material {
    /// The material objects get when they name none: grey, diffuse.
    pub fn default_grey() -> Material {
        Material {
            name: "default".into(),
            kind: MaterialKind::Diffuse,
            reflectance: Vec3::splat(0.8),
            emission: Vec3::ZERO,
            two_sided: false,
            exponent: DEFAULT_EXPONENT as f32,
            specular: DEFAULT_SPECULAR as f32,
            ior: DEFAULT_IOR as f32,
        }
    }

    /// Whether surfaces with this material emit light.
    pub fn is_emissive(&self) -> bool {
        self.emission.max_element() > 0.0
    }
}

/// A validated scene.
#[derive(Clone, Debug)]
pub struct Scene {
    /// Short name used in output file names (the file stem).
    pub name: String,
    /// Where it came from: a path, or `<built-in>`.
    pub source: String,
    /// The camera, as the file describes it (checked: chapter 1 builds a
    /// [`crate::ch1_projection::camera::Camera`] from it).
    pub camera: CameraDesc,
    /// Meshes in world space.
    pub meshes: Vec<Mesh>,
    /// Materials used by at least one mesh or SDF object; unused ones are
    /// dropped.
    pub materials: Vec<Material>,
    /// Non-surface lights, as written (chapter 5 interprets them).
    pub lights: Vec<LightSection>,
    /// Signed distance function objects (chapter 4); empty, and nothing
    /// allocated, when the file has no `[[sdfs]]`.
    pub sdfs: Vec<SdfObject>,
}

impl Scene {
    /// Loads a scene file; mesh paths are relative to it.
    pub fn load(path: &Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "scene".into());
        Scene::parse(&text, &name, &path.display().to_string(), &move |rel| {
            let p: PathBuf = base.join(rel);
            std::fs::read_to_string(&p)
                .map_err(|e| (p.display().to_string(), e.to_string()))
                .map(|t| (p.display().to_string(), t))
        })
    }

    /// The built-in default scene: the Cornell box of `scenes/cornell-box.toml`
    /// with its meshes compiled into the binary, so `cargo run` needs no files.
    pub fn builtin() -> Scene {
        Scene::parse(
            include_str!("../../scenes/cornell-box.toml"),
            "cornell-box",
            "<built-in>/cornell-box.toml",
            &|rel| {
                BUILTIN_FILES
                    .iter()
                    .find(|(name, _)| *name == rel)
                    .map(|(name, text)| (format!("<built-in>/{name}"), text.to_string()))
                    .ok_or_else(|| (rel.to_string(), "not built in".to_string()))
            },
        )
        .expect("the built-in scene is valid (tested)")
    }

    /// Parses scene text. `read` returns (display name, text) of a mesh file
    /// named relative to the scene, or (display name, reason) on failure.
    pub fn parse(text: &str, name: &str, source: &str, read: &MeshReader) -> Result<Scene> {
        let file: SceneFile = toml::from_str(text).map_err(|e| toml_error(source, text, &e))?;
        build(file, name, source, read)
    }

    /// The same scene seen at another resolution.
    pub fn with_resolution(mut self, width: u32, height: u32) -> Result<Scene> {
        self.camera = self.camera.with_resolution(width, height)?;
        Ok(self)
    }

    /// Total triangles over all meshes.
    pub fn triangle_count(&self) -> usize {
        self.meshes.iter().map(|m| m.triangles.len()).sum()
    }

    /// Whether any surface emits light.
    pub fn has_emitters(&self) -> bool {
        self.meshes
            .iter()
            .any(|m| self.materials[m.material].is_emissive())
    }
}

/// Reads a mesh file named relative to the scene: `Ok((display, text))` or
/// `Err((display, reason))`.
pub type MeshReader = dyn Fn(&str) -> std::result::Result<(String, String), (String, String)>;

const BUILTIN_FILES: &[(&str, &str)] = &[
    (
        "meshes/cornell-box/floor.obj",
        include_str!("../../scenes/meshes/cornell-box/floor.obj"),
    ),
    (
        "meshes/cornell-box/ceiling.obj",
        include_str!("../../scenes/meshes/cornell-box/ceiling.obj"),
    ),
    (
        "meshes/cornell-box/back.obj",
        include_str!("../../scenes/meshes/cornell-box/back.obj"),
    ),
    (
        "meshes/cornell-box/red-wall.obj",
        include_str!("../../scenes/meshes/cornell-box/red-wall.obj"),
    ),
    (
        "meshes/cornell-box/green-wall.obj",
        include_str!("../../scenes/meshes/cornell-box/green-wall.obj"),
    ),
    (
        "meshes/cornell-box/large-box.obj",
        include_str!("../../scenes/meshes/cornell-box/large-box.obj"),
    ),
    (
        "meshes/cornell-box/small-box.obj",
        include_str!("../../scenes/meshes/cornell-box/small-box.obj"),
    ),
    (
        "meshes/cornell-box/light.obj",
        include_str!("../../scenes/meshes/cornell-box/light.obj"),
    ),
];

/// Turns a TOML or serde error into one that gives the line and, for an
/// unknown key, the closest known one.
fn toml_error(source: &str, text: &str, e: &toml::de::Error) -> Error {
    let at = match e.span() {
        Some(span) => {
            let before = &text[..span.start.min(text.len())];
            let line = before.matches('\n').count() + 1;
            let col = before.len() - before.rfind('\n').map(|i| i + 1).unwrap_or(0) + 1;
            format!("line {line}, column {col}")
        }
        None => "top level".into(),
    };
    let message = e.message().trim().to_string();
    let message = match unknown_key_suggestion(&message) {
        Some(hint) => format!("{message}; {hint}"),
        None => message,
    };
    Error::Scene {
        file: source.to_string(),
        at,
        message,
    }
}

/// From serde's "unknown field `fvo`, expected one of `eye`, ..." (or
/// "unknown variant"), the closest expected name.
fn unknown_key_suggestion(message: &str) -> Option<String> {
    let rest = message
        .strip_prefix("unknown field ")
        .or_else(|| message.strip_prefix("unknown variant "))?;
    let mut names = rest.split('`').skip(1).step_by(2);
    let given = names.next()?;
    let best = names
        .map(|n| (strsim::levenshtein(given, n), n))
        .min_by_key(|(d, _)| *d)?;
    (best.0 <= given.len().max(2) / 2 + 1).then(|| format!("did you mean `{}`?", best.1))
}

fn build(file: SceneFile, name: &str, source: &str, read: &MeshReader) -> Result<Scene> {
    let scene_err = |at: String, message: String| Error::Scene {
        file: source.to_string(),
        at,
        message,
    };

    // Camera.
    let c = &file.camera;
    let camera = CameraDesc {
        eye: DVec3::from(c.eye),
        target: DVec3::from(c.target),
        up: DVec3::from(c.up),
        fov_degrees: c.fov,
        width: c.width,
        height: c.height,
    };
    camera.check().map_err(|e| {
        scene_err(
            "[camera]".into(),
            e.to_string().trim_start_matches("camera: ").into(),
        )
    })?;

    // Materials: checked, then kept only if an object uses them.
    let mut declared = Vec::new();
    for (i, m) in file.materials.iter().enumerate() {
        let at = format!("materials[{i}] (\"{}\")", m.name);
        if declared.iter().any(|d: &Material| d.name == m.name) {
            return Err(scene_err(
                at,
                format!("material name `{}` is used twice", m.name),
            ));
        }
        check_finite(&m.reflectance)
            .and_then(|_| {
                m.reflectance
                    .iter()
                    .all(|r| (0.0..=1.0).contains(r))
                    .then_some(())
                    .ok_or("must lie in [0, 1] (a surface cannot reflect more than arrives)")
            })
            .map_err(|why| {
                scene_err(
                    format!("{at}.reflectance"),
                    format!("{:?} {why}", m.reflectance),
                )
            })?;
        check_finite(&m.emission)
            .and_then(|_| {
                m.emission
                    .iter()
                    .all(|r| *r >= 0.0)
                    .then_some(())
                    .ok_or("must not be negative")
            })
            .map_err(|why| {
                scene_err(format!("{at}.emission"), format!("{:?} {why}", m.emission))
            })?;
        let (exponent, specular) =
            lobe_keys(m).map_err(|(key, why)| scene_err(format!("{at}.{key}"), why))?;
        let ior = match (m.kind, m.ior) {
            (MaterialKind::Glass, None) => DEFAULT_IOR,
            (MaterialKind::Glass, Some(ior)) if ior.is_finite() && (1.0..=10.0).contains(&ior) => {
                ior
            }
            (MaterialKind::Glass, Some(ior)) => {
                return Err(scene_err(
                    format!("{at}.ior"),
                    format!(
                        "{ior} must be a finite index of refraction in [1, 10] (1 is vacuum, 1.5 glass)"
                    ),
                ))
            }
            (_, Some(_)) => {
                return Err(scene_err(
                    format!("{at}.ior"),
                    "`ior` applies only to type = \"glass\"".into(),
                ))
            }
            (_, None) => DEFAULT_IOR,
        };
        declared.push(Material {
            name: m.name.clone(),
            kind: m.kind,
            reflectance: DVec3::from(m.reflectance).as_vec3(),
            emission: DVec3::from(m.emission).as_vec3(),
            two_sided: m.two_sided,
            exponent,
            specular,
            ior: ior as f32,
        });
    }

    let mut materials: Vec<Material> = Vec::new();
    let mut meshes = Vec::new();
    for (i, o) in file.objects.iter().enumerate() {
        let at = format!("objects[{i}]");
        let mut mesh = build_object(o, &at, source, read)?;
        mesh.material = use_material(&declared, &mut materials, o.material.as_deref(), &at)
            .map_err(|(a, m)| scene_err(a, m))?;
        if let Some(n) = &o.name {
            mesh.name = n.clone();
        }
        meshes.push(mesh);
    }

    let sdfs = build_sdfs(&file.sdfs, &declared, &mut materials, source)?;

    let mut environment: Option<usize> = None;
    for (i, l) in file.lights.iter().enumerate() {
        if matches!(
            l,
            LightSection::Environment { .. } | LightSection::Sky { .. }
        ) {
            if let Some(first) = environment {
                return Err(scene_err(
                    format!("lights[{i}]"),
                    format!(
                        "a scene has at most one environment (\"environment\" or \"sky\"); lights[{first}] is one already"
                    ),
                ));
            }
            environment = Some(i);
        }
        let numbers: Vec<f64> = match l {
            LightSection::Point {
                position,
                intensity,
            } => [position.as_slice(), intensity].concat(),
            LightSection::Directional {
                direction,
                irradiance,
            } => [direction.as_slice(), irradiance].concat(),
            LightSection::Spot {
                position,
                direction,
                intensity,
                cone_degrees,
                falloff_degrees,
            } => [
                position.as_slice(),
                direction,
                intensity,
                &[*cone_degrees, *falloff_degrees],
            ]
            .concat(),
            LightSection::Environment { radiance } => radiance.to_vec(),
            LightSection::Sky {
                zenith,
                horizon,
                ground,
            } => [zenith.as_slice(), horizon, ground].concat(),
        };
        check_finite(&numbers)
            .map_err(|why| scene_err(format!("lights[{i}]"), format!("a value {why}")))?;
    }

    Ok(Scene {
        name: name.to_string(),
        source: source.to_string(),
        camera,
        meshes,
        materials,
        lights: file.lights,
        sdfs,
    })
}

/// The `[[sdfs]]` entries: each parsed into an SDF tree, named, and bound
/// to a material (added to `materials` if no mesh uses it yet).
fn build_sdfs(
    tables: &[toml::Table],
    declared: &[Material],
    materials: &mut Vec<Material>,
    source: &str,
) -> Result<Vec<SdfObject>> {
    let scene_err = |at: String, message: String| Error::Scene {
        file: source.to_string(),
        at,
        message,
    };
    let mut out = Vec::with_capacity(tables.len());
    for (i, t) in tables.iter().enumerate() {
        let at = format!("sdfs[{i}]");
        let sdf =
            crate::scene::sdf_parse::parse_node(t, &at, true).map_err(|(a, m)| scene_err(a, m))?;
        let name = match t.get("name") {
            None => format!("{} {i}", t["type"].as_str().unwrap_or("sdf")),
            Some(toml::Value::String(n)) => n.clone(),
            Some(v) => {
                return Err(scene_err(
                    format!("{at}.name"),
                    format!("expected a string, got {v}"),
                ))
            }
        };
        let wanted = match t.get("material") {
            None => None,
            Some(toml::Value::String(wanted)) => Some(wanted.as_str()),
            Some(v) => {
                return Err(scene_err(
                    format!("{at}.material"),
                    format!("expected a material's name, got {v}"),
                ))
            }
        };
        let index =
            use_material(declared, materials, wanted, &at).map_err(|(a, m)| scene_err(a, m))?;
        out.push(SdfObject {
            name,
            sdf,
            material: index,
        });
    }
    Ok(out)
}

/// The index in `used` of the material an object names (the default grey
/// when it names none), adding it to `used` the first time it is used; or
/// the key and message of the error when no material has that name.
fn use_material(
    declared: &[Material],
    used: &mut Vec<Material>,
    wanted: Option<&str>,
    at: &str,
) -> std::result::Result<usize, (String, String)> {
    let material = match wanted {
        None => Material::default_grey(),
        Some(wanted) => declared
            .iter()
            .find(|m| m.name == wanted)
            .cloned()
            .ok_or_else(|| {
                let known: Vec<&str> = declared.iter().map(|m| m.name.as_str()).collect();
                (
                    format!("{at}.material"),
                    format!("no material named `{wanted}`; declared: {known:?}"),
                )
            })?,
    };
    Ok(match used.iter().position(|m| m.name == material.name) {
        Some(k) => k,
        None => {
            used.push(material);
            used.len() - 1
        }
    })
}

/// The `exponent` and `specular` of a material, checked: each only on the
/// kinds that use it, in range, with defaults when omitted.
fn lobe_keys(m: &file::MaterialSection) -> std::result::Result<(f32, f32), (String, String)> {
    use MaterialKind::*;
    let lobed = matches!(m.kind, Glossy | Retroreflective | Semigloss);
    let exponent = match m.exponent {
        Some(_) if !lobed => return Err((
            "exponent".into(),
            "`exponent` applies only to type = \"glossy\", \"retroreflective\" or \"semigloss\""
                .into(),
        )),
        Some(n) if !(n.is_finite() && (0.0..=MAX_EXPONENT).contains(&n)) => {
            return Err((
                "exponent".into(),
                format!("must be a number in [0, {MAX_EXPONENT:e}], got {n}"),
            ))
        }
        Some(n) => n,
        None => DEFAULT_EXPONENT,
    };
    let specular = match m.specular {
        Some(_) if m.kind != Semigloss => {
            return Err((
                "specular".into(),
                "`specular` applies only to type = \"semigloss\"".into(),
            ))
        }
        Some(k) if !(k.is_finite() && (0.0..=1.0).contains(&k)) => {
            return Err((
                "specular".into(),
                format!("must be a number in [0, 1] (a fraction of the light), got {k}"),
            ))
        }
        Some(k) => k,
        None => DEFAULT_SPECULAR,
    };
    Ok((exponent as f32, specular as f32))
}

fn check_finite(values: &[f64]) -> std::result::Result<(), &'static str> {
    values
        .iter()
        .all(|v| v.is_finite())
        .then_some(())
        .ok_or("must be finite numbers (no nan or inf)")
}

/// One object: its mesh, generated or read, in world space.
fn build_object(o: &ObjectSection, at: &str, source: &str, read: &MeshReader) -> Result<Mesh> {
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
