//! What a stage refuses to render: a scene without what it draws (chapters
//! 1 to 3 draw meshes), or without light (chapters 5 and 6), is an
//! error that says what is missing, not a black picture without a word.

use crate::core::error::Result;
use crate::scene::Scene;

/// Refuses a scene with no triangle meshes, for a stage that draws only
/// meshes: "chapter 1 draws triangle meshes; sdf-shapes has none (it has
/// 3 SDF objects)". Such a stage would otherwise show a black picture
/// without a word.
pub fn require_meshes(chapter: u32, scene: &Scene) -> Result<()> {
    if !scene.meshes.is_empty() {
        return Ok(());
    }
    let has = match scene.sdfs.len() {
        0 => "it is empty".to_string(),
        1 => "it has 1 SDF object: chapter 4 draws it".to_string(),
        n => format!("it has {n} SDF objects: chapter 4 draws them"),
    };
    Err(crate::core::error::Error::Usage(format!(
        "chapter {chapter} draws triangle meshes; {} has none ({has})",
        scene.name
    )))
}

/// Refuses a scene that holds nothing, or no light, for a stage that
/// shades with the scene's lights (chapters 5 and 6 draw meshes and SDFs
/// alike, but without a light or an emitting material every pixel is
/// black): "chapter 5 needs light; sdf-shapes has no lights and no
/// emitting material".
pub fn require_light(chapter: u32, scene: &Scene) -> Result<()> {
    if scene.meshes.is_empty() && scene.sdfs.is_empty() {
        return Err(crate::core::error::Error::Usage(format!(
            "chapter {chapter} needs something to render; {} has no meshes and no SDFs",
            scene.name
        )));
    }
    let emits = scene
        .materials
        .iter()
        .any(|m| m.emission.max_element() > 0.0);
    if scene.lights.is_empty() && !emits {
        return Err(crate::core::error::Error::Usage(format!(
            "chapter {chapter} needs light; {} has no lights and no emitting material \
             (add a [[lights]] entry, or an emission to a material)",
            scene.name
        )));
    }
    Ok(())
}
