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

/// At the documented coordinate bound (1e12) a triangle is hit at a finite
/// t by the readable watertight test (chapters 3 and 4) and by the wide BVH
/// (chapters 5 and 6); at 1e13 the readable test's products overflowed and
/// chapter 4 drew the hits as NaN. A scene past the bound is refused.
#[test]
fn triangles_at_the_coordinate_bound_are_hit_at_a_finite_distance() {
    use glam::Vec3;
    use raystep::ch3_ray_triangle::ray::Ray;
    use raystep::ch3_ray_triangle::triangle::intersect_watertight;
    use raystep::ch3_ray_triangle::wide_bvh::WideBvh;
    use raystep::scene::validate::MAX_COORDINATE;
    let b = MAX_COORDINATE as f32;
    let tri = [
        Vec3::new(-b, -b, -b),
        Vec3::new(b, -b, -b),
        Vec3::new(0.0, b, -b),
    ];
    let ray = Ray::new(Vec3::new(0.0, 0.0, b), Vec3::new(0.01, 0.02, -1.0)).unwrap();
    let hit = intersect_watertight(&ray, tri, 0.0, f32::INFINITY).expect("a hit");
    assert!(
        hit.t.is_finite() && (hit.t / (2.0 * b) - 1.0).abs() < 1e-3,
        "{hit:?}"
    );
    let wide = WideBvh::build(&[tri]).expect("a tree");
    let t = wide.closest(&ray, f32::INFINITY).expect("a hit").t;
    assert!((t / hit.t - 1.0).abs() < 1e-5, "{t} vs {}", hit.t);
    let far = format!("[camera]\neye = [0, 0, 4e13]\n\n{LAMP}\n[[objects]]\nmesh = \"tri.obj\"\nmaterial = \"lamp\"\n");
    let m = load(&far).unwrap_err();
    assert!(m.contains("eye") && m.contains("1e12"), "{m}");
}

/// SDF numbers are bounded like a mesh's: a subnormal scale (it made a
/// plane vanish), a scale past 1e6, a radius past the coordinate bound
/// (its Eikonal check printed NaN beside "≈ 1") are refused naming the key.
#[test]
fn sdf_numbers_are_bounded_like_mesh_values() {
    for (body, key) in [
        ("type = \"plane\"\nscale = 1e-40\n", "sdfs[0].scale"),
        ("type = \"sphere\"\nscale = 1e7\n", "sdfs[0].scale"),
        ("type = \"sphere\"\nscale = [1, 1e-9, 1]\n", "sdfs[0].scale"),
        ("type = \"sphere\"\nradius = 1e30\n", "sdfs[0].radius"),
        (
            "type = \"sphere\"\ntranslate = [0, 1e13, 0]\n",
            "sdfs[0].translate",
        ),
    ] {
        let text = format!("{LAMP}\n[[sdfs]]\n{body}material = \"lamp\"\n");
        let m = load(&text).unwrap_err();
        assert!(m.contains(key), "{key}: {m}");
    }
    let fine = format!("{LAMP}\n[[sdfs]]\ntype = \"sphere\"\nscale = 1e-3\nmaterial = \"lamp\"\n");
    assert!(load(&fine).is_ok(), "{:?}", load(&fine).err());
}

/// A small file cannot ask for unbounded work: a scene of 20,000 SDFs (a
/// 1.4 MB file took 232 s in chapter 4) is refused naming the limit.
#[test]
fn too_many_sdf_shapes_are_refused() {
    use raystep::scene::MAX_SDF_NODES;
    let one = "[[sdfs]]\ntype = \"sphere\"\nradius = 0.1\nmaterial = \"lamp\"\n";
    let text = format!("{LAMP}\n{}", one.repeat(MAX_SDF_NODES + 1));
    let m = load(&text).unwrap_err();
    assert!(
        m.contains(&format!("sdfs[{MAX_SDF_NODES}]")) && m.contains(&MAX_SDF_NODES.to_string()),
        "{m}"
    );
    let text = format!("{LAMP}\n{}", one.repeat(MAX_SDF_NODES));
    assert!(load(&text).is_ok());
}
