//! Numbers at the edge of what a scene may say: a field of view too narrow
//! for f32 to tell the rays apart, and an emitter with no area (it used to
//! be accepted, and the report said both "1 area light" and none), are
//! refused naming the key.

use raystep::scene::Scene;

fn load(text: &str) -> Result<Scene, String> {
    let read = |rel: &str| -> Result<(String, String), (String, String)> {
        match rel {
            "flat.obj" => Ok((
                "flat.obj".into(),
                "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n".into(),
            )),
            "tri.obj" => Ok((
                "tri.obj".into(),
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".into(),
            )),
            _ => Err((rel.into(), "not found".into())),
        }
    };
    Scene::parse(text, "t", "t.toml", &read).map_err(|e| e.to_string())
}

const LAMP: &str =
    "[[materials]]\nname = \"lamp\"\nreflectance = [0, 0, 0]\nemission = [1, 1, 1]\n";

#[test]
fn a_field_of_view_too_narrow_for_f32_is_refused() {
    for fov in ["1e-300", "0.001"] {
        let text = format!("[camera]\nfov = {fov}\n\n{LAMP}\n[[objects]]\nmesh = \"tri.obj\"\nmaterial = \"lamp\"\n");
        let m = load(&text).unwrap_err();
        assert!(m.contains("fov") && m.contains("0.01"), "{m}");
    }
    let ok = format!(
        "[camera]\nfov = 0.5\n\n{LAMP}\n[[objects]]\nmesh = \"tri.obj\"\nmaterial = \"lamp\"\n"
    );
    assert!(load(&ok).is_ok());
}

#[test]
fn an_emitter_with_no_area_is_refused() {
    let text = format!("{LAMP}\n[[objects]]\nmesh = \"flat.obj\"\nmaterial = \"lamp\"\n");
    let m = load(&text).unwrap_err();
    assert!(m.contains("objects[0]") && m.contains("no area"), "{m}");
    // The same degenerate triangle is fine when it does not emit.
    let grey = "[[materials]]\nname = \"grey\"\nreflectance = [0.5, 0.5, 0.5]\n\n[[objects]]\nmesh = \"flat.obj\"\nmaterial = \"grey\"\n";
    assert!(load(grey).is_ok(), "{:?}", load(grey).err());
}
