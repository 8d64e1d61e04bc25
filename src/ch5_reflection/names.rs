//! Names of a scene's surfaces and lights for tables and inspect panels:
//! "mesh 3 \"floor\"", "0 area, mesh 5 \"light\"".

pub use crate::ch4_implicit_surfaces::hit::surface_name;
use crate::ch4_implicit_surfaces::hit::Surface;
use crate::ch5_reflection::light::Light;
use crate::ch5_reflection::world::World;
use crate::scene::Scene;

/// A light's name for a table: its kind, and for an area light its mesh.
pub fn light_name(scene: &Scene, world: &World, index: usize) -> String {
    match world.lights.lights.get(index) {
        Some(Light::Area(a)) => {
            format!(
                "{index} area, {}",
                surface_name(scene, Surface::Mesh(a.mesh))
            )
        }
        Some(Light::Point { .. }) => format!("{index} point"),
        Some(Light::Directional { .. }) => format!("{index} directional"),
        Some(Light::Environment { .. }) => format!("{index} environment"),
        Some(Light::Spot(_)) => format!("{index} spot"),
        Some(Light::Sky(_)) => format!("{index} sky"),
        None => format!("{index}"),
    }
}
