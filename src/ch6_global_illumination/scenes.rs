//! Scenes with known answers, for the tests, the report's studies and the
//! stiff cases. Each is a scene file as text, so what is tested is exactly
//! what a user could write.

use crate::scene::Scene;

/// Parses one of these scenes (they use built-in shapes only).
pub fn parse(text: &str, name: &str) -> Scene {
    Scene::from_text(text, name).expect("the chapter's own test scenes are valid")
}

/// The closed furnace: the camera inside a sphere whose inside is
/// Lambertian of albedo ρ and emits Le from both faces, and a second sphere
/// of the same material inside it, which must be invisible. Every pixel
/// of layer E is Le, of layer k is Le·ρ^(k+1), of the unlimited image
/// Le / (1 - ρ).
pub fn closed_furnace(rho: f64, le: f64, size: u32) -> Scene {
    parse(
        &format!(
            r#"
[camera]
eye = [0.0, 0.0, 0.0]
target = [0.0, 0.0, -1.0]
fov = 70.0
width = {size}
height = {size}

[[materials]]
name = "furnace"
reflectance = [{rho}, {rho}, {rho}]
emission = [{le}, {le}, {le}]
two_sided = true

[[objects]]
shape = "sphere"
radius = 3.0
subdivisions = 2
material = "furnace"

[[objects]]
shape = "sphere"
radius = 0.6
center = [0.4, 0.2, -1.6]
subdivisions = 2
material = "furnace"
"#
        ),
        "closed-furnace",
    )
}

/// The open furnace: a Lambertian sphere of albedo ρ under a constant
/// environment of radiance 1, filling the middle of the image. Its pixels
/// are exactly ρ for any bounce limit (a convex object sees only the
/// sky); the background is 1. With `glass_ior`, a glass shell of that
/// index surrounds the sphere (with index 1 it must change nothing).
pub fn open_furnace(rho: f64, size: u32, glass_ior: Option<f64>) -> Scene {
    let glass = match glass_ior {
        None => String::new(),
        Some(ior) => format!(
            r#"
[[materials]]
name = "glass"
type = "glass"
ior = {ior}

[[objects]]
shape = "sphere"
radius = 1.4
subdivisions = 3
material = "glass"
"#
        ),
    };
    parse(
        &format!(
            r#"
[camera]
eye = [0.0, 0.0, 4.0]
target = [0.0, 0.0, 0.0]
fov = 30.0
width = {size}
height = {size}

[[lights]]
type = "environment"
radiance = [1.0, 1.0, 1.0]

[[materials]]
name = "ball"
reflectance = [{rho}, {rho}, {rho}]

[[objects]]
shape = "sphere"
radius = 1.0
subdivisions = 3
material = "ball"
{glass}"#
        ),
        "open-furnace",
    )
}

/// A camera inside glass: at the centre of a glass sphere of index `ior`
/// under a sky of radiance 1. Every ray meets the surface head-on, so what
/// arrives is η² (radiance/η² is what a lossless path keeps; the Fresnel
/// reflections all escape in the end).
pub fn inside_glass(ior: f64, size: u32) -> Scene {
    parse(
        &format!(
            r#"
[camera]
eye = [0.0, 0.0, 0.0]
target = [0.0, 0.0, -1.0]
fov = 60.0
width = {size}
height = {size}

[[lights]]
type = "environment"
radiance = [1.0, 1.0, 1.0]

[[materials]]
name = "glass"
type = "glass"
ior = {ior}

[[objects]]
shape = "sphere"
radius = 1.0
subdivisions = 4
material = "glass"
"#
        ),
        "inside-glass",
    )
}

/// Total internal reflection: a camera at the centre of a glass cube
/// (η = 1.5) under a sky of radiance 1, looking at `target`. Inside a cube,
/// reflections only flip the signs of a direction's components, so a ray
/// whose components are all below cos θc = √(1 - 1/η²) ≈ 0.745 in size
/// (the cube's diagonal) is reflected totally at every face forever and
/// sees nothing (exactly 0); along an axis it sees η².
pub fn glass_cube(target: [f64; 3], size: u32) -> Scene {
    let [x, y, z] = target;
    parse(
        &format!(
            r#"
[camera]
eye = [0.0, 0.0, 0.0]
target = [{x}, {y}, {z}]
up = [0.0, 1.0, 0.5]
fov = 6.0
width = {size}
height = {size}

[[lights]]
type = "environment"
radiance = [1.0, 1.0, 1.0]

[[materials]]
name = "glass"
type = "glass"
ior = 1.5

[[objects]]
shape = "box"
size = [2.0, 2.0, 2.0]
material = "glass"
"#
        ),
        "glass-cube",
    )
}

/// A tiny, very bright light: a square of side `side` and radiance `le`
/// facing down 1 unit above a Lambertian floor of albedo 0.5, the camera
/// looking straight down at the floor below it through a narrow (0.2°)
/// field of view. The irradiance at the point below the light is
/// Le ∫∫ dx dy / (1 + x² + y²)² = Le·side²·(1 - side²/3 + O(side⁴)), so the
/// pixels show 0.5/π times that (to 1e-6 relative over the field of view).
pub fn tiny_light(side: f64, le: f64, size: u32) -> Scene {
    parse(
        &format!(
            r#"
[camera]
eye = [0.0, 0.5, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
fov = 0.2
width = {size}
height = {size}

[[materials]]
name = "floor"
reflectance = [0.5, 0.5, 0.5]

[[materials]]
name = "light"
reflectance = [0.0, 0.0, 0.0]
emission = [{le}, {le}, {le}]

[[objects]]
shape = "rectangle"
size = [20.0, 20.0]
rotate = {{ axis = [1.0, 0.0, 0.0], degrees = -90.0 }}
material = "floor"

[[objects]]
shape = "rectangle"
size = [{side}, {side}]
rotate = {{ axis = [1.0, 0.0, 0.0], degrees = 90.0 }}
translate = [0.0, 1.0, 0.0]
material = "light"
"#
        ),
        "tiny-light",
    )
}
