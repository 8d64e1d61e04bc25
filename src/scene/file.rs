//! The TOML scene format, as serde types. Every key is optional except what
//! an object needs to say what it is; omitted keys take the defaults below.
//! The book's "Scene files" page shows an example for every key, and a test
//! parses every example there.

use serde::{Deserialize, Deserializer};

/// Arrays of exactly `N` numbers: serde's fixed-size arrays would drop extra
/// elements silently (`eye = [0, 1, 5, 1]`); here they are an error. The
/// TOML error then names the line, and the loader adds the key.
pub mod exact {
    use serde::de::Error;
    use serde::{Deserialize, Deserializer};

    fn exactly<E: Error, const N: usize>(v: Vec<f64>) -> Result<[f64; N], E> {
        let n = v.len();
        v.try_into()
            .map_err(|_| E::custom(format!("expected an array of exactly {N} numbers, got {n}")))
    }

    /// `[x, y, z]` and other fixed-length arrays.
    pub fn array<'de, D: Deserializer<'de>, const N: usize>(d: D) -> Result<[f64; N], D::Error> {
        exactly(Vec::<f64>::deserialize(d)?)
    }

    /// An optional fixed-length array.
    pub fn option<'de, D: Deserializer<'de>, const N: usize>(
        d: D,
    ) -> Result<Option<[f64; N]>, D::Error> {
        Option::<Vec<f64>>::deserialize(d)?.map(exactly).transpose()
    }

    /// Three numbers for the key named `$key`, saying so in the error: for
    /// the lights, whose tagged enum loses the position of the key.
    macro_rules! named {
        ($($name:ident),*) => {$(
            #[doc = concat!("`", stringify!($name), "`: exactly three numbers.")]
            pub fn $name<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 3], D::Error> {
                exactly(Vec::<f64>::deserialize(d)?)
                    .map_err(|e: D::Error| D::Error::custom(format!("`{}`: {e}", stringify!($name))))
            }
        )*};
    }
    named!(position, direction, intensity, irradiance, radiance, zenith, horizon, ground);

    /// An optional 4 x 4 matrix, row by row.
    pub fn matrix<'de, D: Deserializer<'de>>(d: D) -> Result<Option<[[f64; 4]; 4]>, D::Error> {
        let Some(rows) = Option::<Vec<Vec<f64>>>::deserialize(d)? else {
            return Ok(None);
        };
        let n = rows.len();
        let rows: Vec<[f64; 4]> = rows
            .into_iter()
            .enumerate()
            .map(|(i, r)| {
                exactly::<D::Error, 4>(r)
                    .map_err(|e| D::Error::custom(format!("row {}: {e}", i + 1)))
            })
            .collect::<Result<_, _>>()?;
        rows.try_into()
            .map(Some)
            .map_err(|_| D::Error::custom(format!("expected 4 rows of 4 numbers, got {n} rows")))
    }
}

/// A whole scene file.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// The camera; defaults to [`CameraSection::default`].
    #[serde(default)]
    pub camera: CameraSection,
    /// Named materials that objects refer to.
    #[serde(default)]
    pub materials: Vec<MaterialSection>,
    /// Meshes and built-in shapes.
    #[serde(default)]
    pub objects: Vec<ObjectSection>,
    /// Lights that are not surfaces (area lights are emissive materials).
    #[serde(default)]
    pub lights: Vec<LightSection>,
    /// Signed distance function objects (chapter 4), each a table with a
    /// `type`; checked key by key in [`crate::scene::sdf_parse`], so errors name
    /// the key path.
    #[serde(default)]
    pub sdfs: Vec<toml::Table>,
}

/// `[camera]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct CameraSection {
    /// Pinhole position.
    #[serde(deserialize_with = "exact::array")]
    pub eye: [f64; 3],
    /// Point looked at.
    #[serde(deserialize_with = "exact::array")]
    pub target: [f64; 3],
    /// Up hint.
    #[serde(deserialize_with = "exact::array")]
    pub up: [f64; 3],
    /// Full vertical field of view in degrees.
    pub fov: f64,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

impl Default for CameraSection {
    fn default() -> Self {
        CameraSection {
            eye: [0.0, 0.0, 5.0],
            target: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            fov: 45.0,
            width: 320,
            height: 240,
        }
    }
}

/// One `[[materials]]` entry.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSection {
    /// The name objects use to refer to it.
    pub name: String,
    /// The kind of surface; chapter 5 adds more.
    #[serde(rename = "type", default)]
    pub kind: MaterialKind,
    /// Diffuse reflectance ρ in linear RGB, each in [0, 1].
    #[serde(default = "default_reflectance", deserialize_with = "exact::array")]
    pub reflectance: [f64; 3],
    /// Emitted radiance Le (W/(m²·sr)) in linear RGB; non-zero makes every
    /// surface with this material an area light.
    #[serde(default, deserialize_with = "exact::array")]
    pub emission: [f64; 3],
    /// Whether an emissive surface emits from both faces; by default only
    /// the front face (the side its triangles wind counter-clockwise
    /// towards, or an SDF's outside) emits.
    #[serde(default)]
    pub two_sided: bool,
    /// Sharpness n of a glossy, retro-reflective or semi-gloss lobe
    /// (chapter 5; default 100). Larger is sharper.
    pub exponent: Option<f64>,
    /// The specular fraction k_s of a semi-gloss material, in [0, 1]
    /// (chapter 5; default 0.1): f = (1 - k_s) ρ/π + k_s · glossy lobe.
    pub specular: Option<f64>,
    /// Index of refraction of a `type = "glass"` material (default 1.5);
    /// only glass takes it.
    #[serde(default)]
    pub ior: Option<f64>,
}

fn default_reflectance() -> [f64; 3] {
    [0.8, 0.8, 0.8]
}

/// Material kinds known to the format.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum MaterialKind {
    /// Lambertian: BRDF = ρ/π.
    #[default]
    Diffuse,
    /// Ideal mirror reflecting the fraction `reflectance`.
    Mirror,
    /// Glossy specular: a normalised Phong lobe of sharpness `exponent`
    /// around the mirror direction, reflecting at most `reflectance`.
    Glossy,
    /// Retro-reflective: a normalised lobe of sharpness `exponent` around
    /// the direction back towards the viewer (and so towards the light).
    Retroreflective,
    /// The lecture's semi-gloss paint: a diffuse base of `reflectance` under
    /// a white glossy coat that takes the fraction `specular`.
    Semigloss,
    /// Smooth glass (chapter 6): Fresnel reflection and refraction with
    /// index `ior`, no absorption; `reflectance` is not used.
    Glass,
}

/// One `[[objects]]` entry: exactly one of `mesh` or `shape`, then an
/// optional transform (scale, then rotate, then translate; or `matrix`).
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectSection {
    /// A name for reports; defaults to the file stem or the shape.
    pub name: Option<String>,
    /// An OBJ file, relative to the scene file.
    pub mesh: Option<String>,
    /// A built-in shape.
    pub shape: Option<Shape>,
    /// The material's name; defaults to a grey diffuse surface.
    pub material: Option<String>,
    /// Sphere radius (default 1).
    pub radius: Option<f64>,
    /// Sphere centre (default the origin), applied before the transform.
    #[serde(default, deserialize_with = "exact::option")]
    pub center: Option<[f64; 3]>,
    /// Icosphere subdivisions (default 3, at most 7).
    pub subdivisions: Option<u32>,
    /// Rectangle `[w, h]` or box `[x, y, z]` size.
    pub size: Option<Vec<f64>>,
    /// Scale: one number or `[x, y, z]`.
    pub scale: Option<Scale>,
    /// Rotation about an axis through the origin.
    pub rotate: Option<Rotate>,
    /// Translation.
    #[serde(default, deserialize_with = "exact::option")]
    pub translate: Option<[f64; 3]>,
    /// A full world-from-object matrix, four rows of four; excludes the
    /// other transform keys.
    #[serde(default, deserialize_with = "exact::matrix")]
    pub matrix: Option<[[f64; 4]; 4]>,
}

/// Built-in shapes.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum Shape {
    /// The lecture's tetrahedron table.
    Tetrahedron,
    /// An icosphere.
    Sphere,
    /// A rectangle in z = 0 facing +z.
    Rectangle,
    /// An axis-aligned box centred at the origin.
    Box,
}

/// `scale = 2.0` or `scale = [1, 2, 1]`.
#[derive(Clone, Copy, Debug)]
pub enum Scale {
    /// The same factor on every axis.
    Uniform(f64),
    /// One factor per axis.
    PerAxis([f64; 3]),
}

impl<'de> Deserialize<'de> for Scale {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Scale, D::Error> {
        use serde::de::Error;
        #[derive(Deserialize)]
        #[serde(untagged, expecting = "a number or an array of three numbers")]
        enum Either {
            Uniform(f64),
            PerAxis(Vec<f64>),
        }
        match Either::deserialize(d)? {
            Either::Uniform(s) => Ok(Scale::Uniform(s)),
            Either::PerAxis(v) => {
                let n = v.len();
                v.try_into().map(Scale::PerAxis).map_err(|_| {
                    D::Error::custom(format!("expected a number or exactly 3 numbers, got {n}"))
                })
            }
        }
    }
}

/// `rotate = { axis = [0, 1, 0], degrees = 30 }`.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rotate {
    /// The axis (need not be unit length).
    #[serde(deserialize_with = "exact::array")]
    pub axis: [f64; 3],
    /// Counter-clockwise angle looking down the axis, in degrees.
    pub degrees: f64,
}

/// One `[[lights]]` entry: lights that are not surfaces. Chapter 5 gives
/// them meaning; earlier chapters parse, check and ignore them.
#[derive(Clone, Debug, Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
pub enum LightSection {
    /// An isotropic point light of intensity I (W/sr).
    Point {
        /// Position.
        #[serde(deserialize_with = "exact::position")]
        position: [f64; 3],
        /// Intensity, linear RGB.
        #[serde(deserialize_with = "exact::intensity")]
        intensity: [f64; 3],
    },
    /// Light from infinitely far away along `direction`.
    Directional {
        /// Direction the light travels.
        #[serde(deserialize_with = "exact::direction")]
        direction: [f64; 3],
        /// Irradiance at normal incidence (W/m²), linear RGB.
        #[serde(deserialize_with = "exact::irradiance")]
        irradiance: [f64; 3],
    },
    /// A point light limited to a cone with a smooth edge.
    Spot {
        /// Position.
        #[serde(deserialize_with = "exact::position")]
        position: [f64; 3],
        /// Cone axis, the direction light travels.
        #[serde(deserialize_with = "exact::direction")]
        direction: [f64; 3],
        /// Intensity on the axis (W/sr), linear RGB.
        #[serde(deserialize_with = "exact::intensity")]
        intensity: [f64; 3],
        /// Half-angle of the cone in degrees.
        cone_degrees: f64,
        /// Width of the smooth edge inside the cone, in degrees.
        #[serde(default)]
        falloff_degrees: f64,
    },
    /// Constant radiance from every direction.
    Environment {
        /// Radiance (W/(m²·sr)), linear RGB.
        #[serde(deserialize_with = "exact::radiance")]
        radiance: [f64; 3],
    },
    /// A sky (chapter 5): radiance blends linearly in the height of the
    /// direction, from `horizon` (horizontal) to `zenith` (straight up,
    /// world +y); below the horizon every direction sees `ground`.
    Sky {
        /// Radiance straight up (W/(m²·sr)), linear RGB.
        #[serde(deserialize_with = "exact::zenith")]
        zenith: [f64; 3],
        /// Radiance along the horizon, linear RGB.
        #[serde(deserialize_with = "exact::horizon")]
        horizon: [f64; 3],
        /// Radiance from below the horizon (default black).
        #[serde(default, deserialize_with = "exact::ground")]
        ground: [f64; 3],
    },
}
