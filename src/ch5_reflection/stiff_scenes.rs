//! The scenes of chapter 5's stiff cases ([`super::stability`]): a floor,
//! the point on it that is shaded, point lights and emitting rectangles,
//! as scene text.

use glam::Vec3;

use crate::ch4_implicit_surfaces::hit::Surface;
use crate::ch5_reflection::world::{Interaction, World};
use crate::scene::Scene;

/// The world of a stiff case's scene text (TOML).
pub(super) fn world(text: &str) -> World {
    let scene = Scene::from_text(text, "stiff").expect("stability scenes are valid (tested)");
    World::new(&scene)
}

/// The centre of [`FLOOR`], facing up.
pub(super) fn floor_point(world: &World) -> Interaction {
    Interaction {
        t: 1.0,
        p: Vec3::ZERO,
        n: Vec3::Z,
        material: world.mesh_material[0],
        surface: Surface::Mesh(0),
    }
}

/// A 4 x 4 floor of albedo 0.5 in the plane z = 0.
pub(super) const FLOOR: &str = r#"
[[materials]]
name = "floor"
reflectance = [0.5, 0.5, 0.5]
[[objects]]
shape = "rectangle"
size = [4, 4]
material = "floor"
"#;

/// A point light of intensity 1 at `position` (TOML, `[x, y, z]`).
pub(super) fn point_light(position: &str) -> String {
    format!("\n[[lights]]\ntype = \"point\"\nposition = {position}\nintensity = [1, 1, 1]\n")
}

/// A black rectangle emitting `emission` (TOML), one-sided unless
/// `two_sided`, of `size`, placed by the TOML lines `placement`.
pub(super) fn lamp(emission: &str, two_sided: bool, size: &str, placement: &str) -> String {
    let sides = if two_sided { "two_sided = true\n" } else { "" };
    format!(
        "[[materials]]
name = \"lamp\"
reflectance = [0, 0, 0]
emission = {emission}
{sides}[[objects]]
shape = \"rectangle\"
size = {size}
material = \"lamp\"
{placement}"
    )
}
