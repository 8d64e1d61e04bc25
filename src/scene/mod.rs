//! Scene files → a validated [`Scene`] that holds only what the file uses.
//!
//! Loading happens in three steps: TOML text → serde types ([`file`](mod@file)),
//! checks that name the key that is wrong, then building: meshes are read
//! (OBJ through tobj) or generated, transformed to world space, and bound to
//! materials. Nothing is built for a section the file does not mention.

mod build;
pub use build::{sdf_nodes, MAX_SDF_NODES};
pub mod camera;
pub mod content;
pub mod file;
pub mod mesh;
pub mod obj;
mod object;
pub mod place;
pub mod sdf;
pub mod sdf_parse;
pub mod validate;

use std::path::{Path, PathBuf};

use glam::Vec3;

use crate::core::error::{Error, Result};
use crate::scene::mesh::Mesh;
use camera::CameraDesc;
use file::{LightSection, MaterialKind, SceneFile};
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
    /// Where this scene's coordinates start, in the file's: every position
    /// above is relative to it. Zero, except for a scene far from the
    /// file's origin, which is kept around its camera
    /// ([`place::origin_for`]).
    pub origin: glam::DVec3,
    /// How long one unit of this scene is in the file's units: 1, except
    /// for a tiny scene, which is scaled up by a power of two
    /// ([`Scene::normalized`]).
    pub unit: f64,
    /// How chapters 5 and 6 sample area lights (`--light-sampling`): not
    /// part of the scene's content, since either way the image converges
    /// to the same one.
    pub light_sampling: LightSampling,
}

/// How area lights are sampled (chapter 5): a point by area, or a
/// direction by the solid angle the light subtends.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum LightSampling {
    /// A uniform point on the light's surface (pdf 1/A).
    #[default]
    Area,
    /// A uniform direction in the solid angle the light covers, where it
    /// can (`crate::ch5_reflection::light::spherical`).
    SolidAngle,
}

impl LightSampling {
    /// What chapters 5 and 6 add to the estimator in their reports: nothing
    /// for the default, else ", area lights by solid angle".
    pub fn note(self) -> &'static str {
        match self {
            LightSampling::Area => "",
            LightSampling::SolidAngle => ", area lights by solid angle",
        }
    }
}

/// Limits on what one load may read and build, so that a huge or endless
/// input is refused with an error naming the bound instead of exhausting
/// memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Largest scene or OBJ file, in bytes (`--max-file-mib`).
    pub max_file_bytes: u64,
    /// Most triangles in the whole scene (`--max-triangles`).
    pub max_triangles: usize,
}

/// The default file size limit: 512 MiB.
pub const DEFAULT_MAX_FILE_BYTES: u64 = 512 << 20;

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_file_bytes: DEFAULT_MAX_FILE_BYTES,
            max_triangles: obj::DEFAULT_MAX_TRIANGLES,
        }
    }
}

/// Reads a text file of at most `max` bytes; larger files (and endless
/// ones such as `/dev/zero`) are refused before they fill memory.
pub fn read_limited(path: &Path, max: u64) -> Result<String> {
    use std::io::Read;
    let too_big = || {
        Error::Usage(format!(
            "{}: the file is larger than the limit of {} MiB (raise it with --max-file-mib)",
            path.display(),
            max >> 20
        ))
    };
    // Only regular files: opening a FIFO waits for a writer for ever, and
    // a device may never end.
    let meta = std::fs::metadata(path).map_err(|e| Error::io(path, e))?;
    if !meta.is_file() {
        return Err(Error::Usage(format!(
            "{}: not a regular file ({}); expected a scene or OBJ file",
            path.display(),
            if meta.is_dir() {
                "a folder"
            } else {
                "a FIFO, socket or device"
            }
        )));
    }
    let file = std::fs::File::open(path).map_err(|e| Error::io(path, e))?;
    if file
        .metadata()
        .map(|m| m.is_file() && m.len() > max)
        .unwrap_or(false)
    {
        return Err(too_big());
    }
    crate::core::memory::check_file(path, meta.len())?;
    // In chunks, so that a binary or endless file (`/dev/zero`) is refused
    // at its first NUL byte instead of after the whole limit.
    let mut bytes = Vec::new();
    let mut reader = file.take(max.saturating_add(1));
    let mut chunk = vec![0u8; 1 << 16];
    loop {
        let n = match reader.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(Error::io(path, e)),
        };
        if chunk[..n].contains(&0) {
            return Err(Error::Usage(format!(
                "{}: not a text file (it contains NUL bytes)",
                path.display()
            )));
        }
        bytes.extend_from_slice(&chunk[..n]);
    }
    if bytes.len() as u64 > max {
        return Err(too_big());
    }
    String::from_utf8(bytes).map_err(|e| {
        Error::io(
            path,
            std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!("not UTF-8 text: {e}"),
            ),
        )
    })
}

impl Scene {
    /// Loads a scene file; mesh paths are relative to it.
    pub fn load(path: &Path) -> Result<Scene> {
        Scene::load_with(path, &Limits::default())
    }

    /// [`Scene::load`] within `limits`.
    pub fn load_with(path: &Path, limits: &Limits) -> Result<Scene> {
        let max = limits.max_file_bytes;
        let text = read_limited(path, max)?;
        let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "scene".into());
        let read = move |rel: &str| {
            let p: PathBuf = base.join(rel);
            read_limited(&p, max)
                .map_err(|e| (p.display().to_string(), e.to_string()))
                .map(|t| (p.display().to_string(), t))
        };
        Scene::parse_with(&text, &name, &path.display().to_string(), &read, limits)
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
        Scene::parse_with(text, name, source, read, &Limits::default())
    }

    /// [`Scene::parse`] within `limits`.
    pub fn parse_with(
        text: &str,
        name: &str,
        source: &str,
        read: &MeshReader,
        limits: &Limits,
    ) -> Result<Scene> {
        let file: SceneFile =
            toml::from_str(text).map_err(|e| build::toml_error(source, text, &e))?;
        build::build(file, name, source, read, limits)
    }

    /// Parses a scene given as text that uses built-in shapes only (no mesh
    /// files): the one way studies, stiff cases and tests build a scene from
    /// TOML, so what they check is exactly what a user could write. Errors
    /// name `<name>.toml`.
    pub fn from_text(text: &str, name: &str) -> Result<Scene> {
        Scene::parse(text, name, &format!("{name}.toml"), &|rel| {
            Err((
                rel.to_string(),
                "mesh files cannot be read here".to_string(),
            ))
        })
    }

    /// The same scene seen at another resolution.
    pub fn with_resolution(mut self, width: u32, height: u32) -> Result<Scene> {
        self.camera = self.camera.with_resolution(width, height)?;
        Ok(self)
    }

    /// The hash of everything in the scene that changes its picture, as
    /// 16 hex digits ([`content::content_hash`]): stored references are
    /// matched by it.
    pub fn content_hash(&self) -> String {
        content::content_hash(self)
    }

    /// Total triangles over all meshes.
    pub fn triangle_count(&self) -> usize {
        self.meshes.iter().map(|m| m.triangles.len()).sum()
    }

    /// The scene's lights in words, the same in every chapter's report:
    /// "1 area light", "2 point lights, 1 sky", or "no lights". Area
    /// lights are emissive meshes; emissive SDFs count apart.
    pub fn describe_lights(&self) -> String {
        let emissive = |m: usize| self.materials[m].is_emissive();
        let mut kinds: Vec<(&str, usize)> = vec![
            (
                "area light",
                self.meshes.iter().filter(|m| emissive(m.material)).count(),
            ),
            (
                "emissive SDF",
                self.sdfs.iter().filter(|o| emissive(o.material)).count(),
            ),
        ];
        for l in &self.lights {
            let kind = match l {
                file::LightSection::Point { .. } => "point light",
                file::LightSection::Directional { .. } => "directional light",
                file::LightSection::Spot { .. } => "spot light",
                file::LightSection::Environment { .. } => "environment",
                file::LightSection::Sky { .. } => "sky",
            };
            match kinds.iter_mut().find(|(k, _)| *k == kind) {
                Some((_, n)) => *n += 1,
                None => kinds.push((kind, 1)),
            }
        }
        let parts: Vec<String> = kinds
            .iter()
            .filter(|(_, n)| *n > 0)
            .map(|(k, n)| match (*n, *k) {
                (1, k) => format!("1 {k}"),
                (n, "sky") => format!("{n} skies"),
                (n, k) => format!("{n} {k}s"),
            })
            .collect();
        if parts.is_empty() {
            "no lights".into()
        } else {
            parts.join(", ")
        }
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
