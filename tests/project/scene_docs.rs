//! The "Scene files" page of the book: every example on it is a complete
//! scene that loads, every key of the format is shown in an example, and the
//! error messages it quotes are the ones raystep prints.

use crate::common;
use raystep::scene::Scene;

fn page() -> String {
    std::fs::read_to_string(common::root().join("book/src/scene-files.md")).unwrap()
}

/// The bodies of the ```toml blocks.
fn toml_examples(text: &str) -> Vec<String> {
    text.split("```toml\n")
        .skip(1)
        .map(|rest| rest.split("```").next().unwrap().to_string())
        .collect()
}

fn parse(example: &str) -> raystep::Result<Scene> {
    let scenes = common::root().join("scenes");
    Scene::parse(example, "example", "scene-files.md", &move |rel| {
        let p = scenes.join(rel);
        std::fs::read_to_string(&p)
            .map(|t| (p.display().to_string(), t))
            .map_err(|e| (p.display().to_string(), e.to_string()))
    })
}

#[test]
fn every_example_on_the_page_loads() {
    let examples = toml_examples(&page());
    assert!(examples.len() >= 8, "only {} examples", examples.len());
    for (i, ex) in examples.iter().enumerate() {
        if let Err(e) = parse(ex) {
            panic!("example {} does not load: {e}\n{ex}", i + 1);
        }
    }
}

#[test]
fn every_key_of_the_format_has_an_example() {
    let examples = toml_examples(&page()).join("\n");
    let keys = [
        "[camera]",
        "eye",
        "target",
        "up",
        "fov",
        "width",
        "height",
        "[[materials]]",
        "name",
        "type",
        "reflectance",
        "emission",
        "[[objects]]",
        "mesh",
        "shape",
        "material",
        "radius",
        "center",
        "subdivisions",
        "size",
        "scale",
        "rotate",
        "axis",
        "degrees",
        "translate",
        "matrix",
        "[[lights]]",
        "\"point\"",
        "\"directional\"",
        "\"spot\"",
        "\"environment\"",
        "position",
        "intensity",
        "direction",
        "irradiance",
        "cone_degrees",
        "falloff_degrees",
        "radiance",
        "\"tetrahedron\"",
        "\"sphere\"",
        "\"rectangle\"",
        "\"box\"",
        "\"diffuse\"",
        "\"mirror\"",
        "\"glossy\"",
        "\"retroreflective\"",
        "\"semigloss\"",
        "exponent",
        "specular",
        "two_sided",
        "\"sky\"",
        "zenith",
        "horizon",
        "ground",
        "\"glass\"",
        "ior",
    ];
    for key in keys {
        let as_key = format!("{key} =");
        assert!(
            examples.contains(&as_key) || (key.starts_with(['[', '"']) && examples.contains(key)),
            "no example shows `{key}`"
        );
    }
}

#[test]
fn an_empty_file_is_the_default_scene() {
    let s = parse("").unwrap();
    assert!(s.meshes.is_empty() && s.lights.is_empty() && s.materials.is_empty());
    assert_eq!((s.camera.width, s.camera.height), (320, 240));
    assert_eq!(s.camera.fov_degrees, 45.0);
}

#[test]
fn unused_materials_are_not_kept() {
    let s = parse(
        "[[materials]]\nname = \"a\"\n[[materials]]\nname = \"b\"\n[[objects]]\nshape = \"box\"\nmaterial = \"b\"\n",
    )
    .unwrap();
    assert_eq!(s.materials.len(), 1);
    assert_eq!(s.materials[0].name, "b");
}

#[test]
fn the_quoted_unknown_key_message_is_the_real_one() {
    let err = parse("[camera]\nfvo = 40\n").unwrap_err().to_string();
    let quoted = "unknown field `fvo`, expected one of `eye`, `target`, `up`, `fov`, `width`, `height`; did you mean `fov`?";
    assert!(err.contains(quoted), "{err}");
    assert!(page().contains(quoted));
}

#[test]
fn transforms_apply_scale_then_rotate_then_translate() {
    let s = parse(
        "[[objects]]\nshape = \"box\"\nscale = [2.0, 1.0, 1.0]\nrotate = { axis = [0, 0, 1], degrees = 90 }\ntranslate = [0, 0, -3]\n",
    )
    .unwrap();
    // The box's +x corner (1, 0.5, 0.5) after scale is (1, .5, .5) → rotate
    // 90° about z → (-0.5, 1, 0.5) → translate → (-0.5, 1, -2.5).
    let p = &s.meshes[0].positions;
    let has = |q: glam::Vec3| p.iter().any(|v| v.distance(q) < 1e-5);
    assert!(has(glam::Vec3::new(-0.5, 1.0, -2.5)), "{p:?}");
    let m = parse(
        "[[objects]]\nshape = \"tetrahedron\"\nmatrix = [[1,0,0,0.5],[0,1,0,0],[0,0,1,-2],[0,0,0,1]]\n",
    )
    .unwrap();
    assert_eq!(m.meshes[0].positions[0], glam::Vec3::new(-0.5, -1.0, -3.0));
}
