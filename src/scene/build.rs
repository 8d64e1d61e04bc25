//! The building step of loading a scene: the parsed file checked section
//! by section (each error names the key and what was expected), meshes
//! read or generated and moved to world space, materials bound, and the
//! SDF tree assembled. Nothing is built for a section the file leaves out.

use glam::DVec3;

use super::camera::CameraDesc;
use super::file::{self, LightSection, MaterialKind, SceneFile};
use super::object::{build_object, check_finite};
use super::sdf::SdfObject;
use super::validate;
use super::{
    LightSampling, Limits, Material, MeshReader, Scene, DEFAULT_EXPONENT, DEFAULT_IOR,
    DEFAULT_SPECULAR, MAX_EXPONENT,
};
use crate::core::error::{Error, Result};
use crate::core::text::{shorten, NAME_CHARS};

/// Turns a TOML or serde error into one that gives the line and, for an
/// unknown key, the closest known one.
pub(super) fn toml_error(source: &str, text: &str, e: &toml::de::Error) -> Error {
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
    let message = match (
        e.span(),
        message.starts_with("expected an array of exactly")
            || message.starts_with("expected a number or exactly")
            || message.starts_with("row ")
            || message.starts_with("expected 4 rows"),
    ) {
        (Some(span), true) => format!("`{}`: {message}", key_on_line(text, span.start)),
        _ => message,
    };
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

/// The key written before the `=` on the line where `offset` lies (or
/// before the last `=` ahead of it, for an inline table).
fn key_on_line(text: &str, offset: usize) -> String {
    let offset = offset.min(text.len());
    let start = text[..offset].rfind('\n').map(|i| i + 1).unwrap_or(0);
    let before = &text[start..offset];
    let Some(eq) = before.rfind('=') else {
        return "?".into();
    };
    let key = before[..eq].trim_end();
    let key = key
        .rsplit(|c: char| c == '{' || c == ',' || c.is_whitespace())
        .next()
        .unwrap_or(key);
    key.chars().take(64).collect()
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

pub(super) fn build(
    file: SceneFile,
    name: &str,
    source: &str,
    read: &MeshReader,
    limits: &Limits,
) -> Result<Scene> {
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
    let camera_err = |e: Error| {
        scene_err(
            "[camera]".into(),
            e.to_string().trim_start_matches("camera: ").into(),
        )
    };
    for (name, v) in [("eye", camera.eye), ("target", camera.target)] {
        validate::position(&v.to_array())
            .map_err(|why| camera_err(Error::Usage(format!("`{name}` {why}"))))?;
    }
    // A scene far from its file's origin is built around its camera, and
    // its camera checked there (at 1e12, f32 cannot tell eye and target
    // apart; 5 units from the camera it can).
    let origin = super::place::origin_for(camera.eye, camera.target);
    CameraDesc {
        eye: camera.eye - origin,
        target: camera.target - origin,
        ..camera
    }
    .check()
    .map_err(camera_err)?;

    // Materials: checked, then kept only if an object uses them.
    let mut declared = Vec::new();
    for (i, m) in file.materials.iter().enumerate() {
        check_name(&m.name, &format!("materials[{i}].name")).map_err(|(a, m)| scene_err(a, m))?;
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
        validate::light(&m.emission).map_err(|why| scene_err(format!("{at}.emission"), why))?;
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
    let mut triangles = 0usize;
    for (i, o) in file.objects.iter().enumerate() {
        let at = format!("objects[{i}]");
        let mut mesh = build_object(
            o,
            (&at, source, origin),
            read,
            limits.max_triangles - triangles,
        )?;
        triangles += mesh.triangles.len();
        mesh.material = use_material(&declared, &mut materials, o.material.as_deref(), &at)
            .map_err(|(a, m)| scene_err(a, m))?;
        if let Some(n) = &o.name {
            check_name(n, &format!("{at}.name")).map_err(|(a, m)| scene_err(a, m))?;
            mesh.name = n.clone();
        }
        // An area light needs an area: the lights would sample a density
        // of 1/0, and the reports would count a light that gives none.
        let area = emitting_area(&mesh);
        if materials[mesh.material].is_emissive() && (area.is_nan() || area <= 0.0) {
            return Err(scene_err(
                at,
                format!(
                    "`{}` emits light but its triangles have no area (every one is degenerate in f32); \
                     give it area or a material that does not emit",
                    mesh.name
                ),
            ));
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
        validate::check_light(l)
            .map_err(|(key, why)| scene_err(format!("lights[{i}].{key}"), why))?;
    }

    Ok(Scene {
        name: name.to_string(),
        source: source.to_string(),
        camera,
        meshes,
        materials,
        lights: file.lights,
        sdfs,
        origin: glam::DVec3::ZERO,
        unit: 1.0,
        light_sampling: LightSampling::Area,
    }
    .moved_to(origin)
    .normalized())
}

/// The most SDF shapes and operations (CSG, transforms) a scene may hold:
/// sphere tracing evaluates all of them at every step of every ray.
pub const MAX_SDF_NODES: usize = 1024;

/// The shapes and operations in one SDF tree.
pub fn sdf_nodes(sdf: &crate::scene::sdf::Sdf) -> usize {
    use crate::scene::sdf::Sdf;
    1 + match sdf {
        Sdf::Union(of) | Sdf::Intersection(of) | Sdf::SmoothUnion { of, .. } => {
            of.iter().map(sdf_nodes).sum()
        }
        Sdf::Difference(a, b) => sdf_nodes(a) + sdf_nodes(b),
        Sdf::Translate { of, .. }
        | Sdf::Rotate { of, .. }
        | Sdf::Scale { of, .. }
        | Sdf::ScaleAxes { of, .. } => sdf_nodes(of),
        _ => 0,
    }
}

/// The total area of a mesh's triangles, as the renderer computes it (f32).
fn emitting_area(mesh: &crate::scene::mesh::Mesh) -> f32 {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            0.5 * (b - a).cross(c - a).length()
        })
        .sum()
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
    let mut out = Vec::with_capacity(tables.len().min(MAX_SDF_NODES));
    let mut nodes = 0usize;
    for (i, t) in tables.iter().enumerate() {
        let at = format!("sdfs[{i}]");
        let sdf =
            crate::scene::sdf_parse::parse_node(t, &at, true).map_err(|(a, m)| scene_err(a, m))?;
        let name = match t.get("name") {
            None => format!("{} {i}", t["type"].as_str().unwrap_or("sdf")),
            Some(toml::Value::String(n)) => {
                check_name(n, &format!("{at}.name")).map_err(|(a, m)| scene_err(a, m))?;
                n.clone()
            }
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
        nodes += sdf_nodes(&sdf);
        if nodes > MAX_SDF_NODES {
            return Err(scene_err(
                at,
                format!(
                    "more than {MAX_SDF_NODES} SDF shapes and operations in the scene: every step \
                     of every ray evaluates them all (20,000 took minutes per image); build a \
                     large shape from triangles instead"
                ),
            ));
        }
        out.push(SdfObject {
            name,
            sdf,
            material: index,
        });
    }
    Ok(out)
}

/// The most characters a name (of a material, an object or an SDF) may
/// have: reports and messages print names in full.
pub const MAX_NAME_CHARS: usize = 256;

/// Refuses a name longer than [`MAX_NAME_CHARS`]: the key `at` and the
/// message.
fn check_name(name: &str, at: &str) -> std::result::Result<(), (String, String)> {
    let n = name.chars().count();
    if n > MAX_NAME_CHARS {
        return Err((
            at.to_string(),
            format!(
                "`{}`: a name may have at most {MAX_NAME_CHARS} characters",
                shorten(name, 40)
            ),
        ));
    }
    Ok(())
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
                    format!(
                        "no material named `{}`; declared: {known:?}",
                        shorten(wanted, NAME_CHARS)
                    ),
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
