//! Every kind of bad input gets a clear error that names the file, the key
//! or line, and what was expected, and the chapter binary exits non-zero
//! without writing any image.

use crate::common;
use raystep::scene::Scene;

const CUBE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";

/// Loads `scene` (with `files` beside it) and returns the error text.
fn load_error(name: &str, scene: &str, files: &[(&str, &str)]) -> String {
    let dir = common::temp_dir(name);
    let mut all = vec![("scene.toml", scene)];
    all.extend_from_slice(files);
    common::write_files(&dir, &all);
    match Scene::load(&dir.join("scene.toml")) {
        Ok(_) => panic!("scene `{name}` loaded but should not have"),
        Err(e) => e.to_string(),
    }
}

fn assert_mentions(message: &str, parts: &[&str]) {
    for p in parts {
        assert!(
            message.contains(p),
            "error `{message}` does not mention `{p}`"
        );
    }
}

#[test]
fn malformed_toml_gives_the_line() {
    let m = load_error("malformed", "[camera]\nfov = = 40\n", &[]);
    assert_mentions(&m, &["scene.toml", "line 2, column 7"]);
    // An unclosed array is noticed where the next line starts.
    let m = load_error("unclosed", "[camera]\neye = [0, 0, 5\nfov = 40\n", &[]);
    assert_mentions(&m, &["scene.toml", "line 3", "expected `,`"]);
}

#[test]
fn unknown_key_suggests_the_closest_known_one() {
    let m = load_error("unknown", "[camera]\nfvo = 40\n", &[]);
    assert_mentions(
        &m,
        &[
            "scene.toml",
            "line 2",
            "unknown field `fvo`",
            "did you mean `fov`?",
        ],
    );
    let m = load_error(
        "unknown-obj",
        "[[objects]]\nshape = \"sphere\"\nradus = 2\n",
        &[],
    );
    assert_mentions(&m, &["line 3", "`radus`", "did you mean `radius`?"]);
    let m = load_error(
        "unknown-shape",
        "[[objects]]\nshape = \"tetrahedorn\"\n",
        &[],
    );
    assert_mentions(&m, &["line 2", "did you mean `tetrahedron`?"]);
}

#[test]
fn missing_mesh_names_the_object_and_the_path() {
    let m = load_error("missing", "[[objects]]\nmesh = \"meshes/nope.obj\"\n", &[]);
    assert_mentions(
        &m,
        &["scene.toml", "objects[0].mesh", "nope.obj", "cannot read"],
    );
}

#[test]
fn unreadable_mesh_is_reported() {
    // A directory where a file should be cannot be read as text.
    let dir = common::temp_dir("unreadable");
    std::fs::create_dir_all(dir.join("meshes/dir.obj")).unwrap();
    common::write_files(
        &dir,
        &[("scene.toml", "[[objects]]\nmesh = \"meshes/dir.obj\"\n")],
    );
    let m = Scene::load(&dir.join("scene.toml"))
        .unwrap_err()
        .to_string();
    assert_mentions(&m, &["objects[0].mesh", "dir.obj", "cannot read"]);
}

#[test]
fn out_of_range_obj_index_gives_file_and_line() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n";
    let m = load_error(
        "range",
        "[[objects]]\nmesh = \"bad.obj\"\n",
        &[("bad.obj", obj)],
    );
    assert_mentions(&m, &["bad.obj:5", "vertex 9", "only 3 vertices"]);
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n";
    let m = load_error(
        "range-neg",
        "[[objects]]\nmesh = \"bad.obj\"\n",
        &[("bad.obj", obj)],
    );
    assert_mentions(&m, &["bad.obj:4", "vertex -4"]);
}

#[test]
fn empty_mesh_is_refused() {
    let m = load_error(
        "empty",
        "[[objects]]\nmesh = \"empty.obj\"\n",
        &[("empty.obj", "# nothing\nv 0 0 0\n")],
    );
    assert_mentions(&m, &["empty.obj", "no triangles"]);
}

#[test]
fn nan_and_infinite_coordinates_are_refused() {
    let obj = "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n";
    let m = load_error(
        "nan-obj",
        "[[objects]]\nmesh = \"n.obj\"\n",
        &[("n.obj", obj)],
    );
    assert_mentions(&m, &["n.obj:2", "`nan`", "not a finite number"]);
    let obj = "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n";
    let m = load_error(
        "inf-obj",
        "[[objects]]\nmesh = \"i.obj\"\n",
        &[("i.obj", obj)],
    );
    assert_mentions(&m, &["i.obj:3", "not a finite number"]);
    let m = load_error("nan-eye", "[camera]\neye = [0, nan, 5]\n", &[]);
    assert_mentions(&m, &["scene.toml", "[camera]", "`eye` must be finite"]);
    let m = load_error(
        "inf-translate",
        "[[objects]]\nshape = \"box\"\ntranslate = [0, inf, 0]\n",
        &[],
    );
    assert_mentions(&m, &["objects[0].translate", "finite"]);
}

#[test]
fn zero_and_absurd_resolutions_are_refused() {
    let m = load_error("zero", "[camera]\nwidth = 0\n", &[]);
    assert_mentions(
        &m,
        &["scene.toml", "`width` must be between 1 and 16384", "got 0"],
    );
    let m = load_error("huge", "[camera]\nheight = 100000\n", &[]);
    assert_mentions(&m, &["`height` must be between 1 and 16384", "got 100000"]);
    let m = load_error("negative", "[camera]\nwidth = -3\n", &[]);
    assert_mentions(&m, &["scene.toml", "line 2"]);
}

#[test]
fn field_of_view_must_lie_between_0_01_and_180() {
    for fov in ["0", "180", "-5", "360", "nan", "1e-300"] {
        let m = load_error(
            &format!("fov{fov}"),
            &format!("[camera]\nfov = {fov}\n"),
            &[],
        );
        assert_mentions(&m, &["scene.toml", "`fov`", "from 0.01 to below 180"]);
    }
}

#[test]
fn objects_must_say_what_they_are_and_keys_must_fit_the_shape() {
    let m = load_error("neither", "[[objects]]\nmaterial = \"x\"\n", &[]);
    assert_mentions(&m, &["objects[0]", "needs `mesh", "or `shape`"]);
    let m = load_error(
        "both",
        "[[objects]]\nshape = \"box\"\nmesh = \"m.obj\"\n",
        &[("m.obj", CUBE_OBJ)],
    );
    assert_mentions(&m, &["objects[0]", "either `mesh` or `shape`"]);
    let m = load_error("stray", "[[objects]]\nshape = \"box\"\nradius = 2\n", &[]);
    assert_mentions(&m, &["objects[0].radius", "applies only to shape"]);
    let m = load_error(
        "material",
        "[[objects]]\nshape = \"box\"\nmaterial = \"gold\"\n",
        &[],
    );
    assert_mentions(&m, &["objects[0].material", "no material named `gold`"]);
    let m = load_error(
        "reflectance",
        "[[materials]]\nname = \"a\"\nreflectance = [1.5, 0, 0]\n[[objects]]\nshape = \"box\"\nmaterial = \"a\"\n",
        &[],
    );
    assert_mentions(&m, &["materials[0]", "reflectance", "[0, 1]"]);
    let m = load_error("scale0", "[[objects]]\nshape = \"box\"\nscale = 0\n", &[]);
    assert_mentions(&m, &["objects[0].scale", "non-zero"]);
    let m = load_error(
        "axis0",
        "[[objects]]\nshape = \"box\"\nrotate = { axis = [0, 0, 0], degrees = 3 }\n",
        &[],
    );
    assert_mentions(&m, &["objects[0].rotate.axis", "zero vector"]);
}

#[test]
fn a_glass_index_of_refraction_must_be_sensible_and_only_on_glass() {
    let glass = |ior: &str| {
        format!(
            "[[materials]]\nname = \"g\"\ntype = \"glass\"\nior = {ior}\n[[objects]]\nshape = \"box\"\nmaterial = \"g\"\n"
        )
    };
    for (name, ior) in [("ior-low", "0.5"), ("ior-nan", "nan"), ("ior-huge", "1e9")] {
        let m = load_error(name, &glass(ior), &[]);
        assert_mentions(&m, &["scene.toml", "materials[0] (\"g\").ior", "[1, 10]"]);
    }
    let m = load_error(
        "ior-diffuse",
        "[[materials]]\nname = \"d\"\nior = 1.5\n[[objects]]\nshape = \"box\"\nmaterial = \"d\"\n",
        &[],
    );
    assert_mentions(
        &m,
        &["materials[0] (\"d\").ior", "only to type = \"glass\""],
    );
    let m = load_error("ior-string", &glass("\"high\""), &[]);
    assert_mentions(&m, &["scene.toml", "line 4"]);
    let m = load_error(
        "glas",
        "[[materials]]\nname = \"g\"\ntype = \"glas\"\n",
        &[],
    );
    assert_mentions(&m, &["did you mean `glass`?"]);
}

#[test]
fn the_binary_exits_nonzero_and_writes_nothing() {
    let dir = common::temp_dir("binary");
    common::write_files(&dir, &[("scene.toml", "[camera]\nfvo = 40\n")]);
    let out = dir.join("out");
    let result = std::process::Command::new(env!("CARGO_BIN_EXE_ch1"))
        .args([
            "--scene",
            dir.join("scene.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(result.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(stderr.contains("did you mean `fov`?"), "stderr: {stderr}");
    assert!(!stderr.contains("panicked"), "stderr: {stderr}");
    assert!(
        !out.exists(),
        "an output folder was created for a failed run"
    );

    // Absurd sizes from the command line too.
    let result = std::process::Command::new(env!("CARGO_BIN_EXE_ch1"))
        .args(["--width", "20000", "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(result.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&result.stderr).contains("between 1 and 16384"));
    assert!(!out.exists());
}

#[test]
fn chapter_5_material_keys_are_checked_by_name() {
    let obj = "[[objects]]\nshape = \"sphere\"\nmaterial = \"m\"\n";
    let m = load_error(
        "exponent-on-diffuse",
        &format!("[[materials]]\nname = \"m\"\nexponent = 10\n{obj}"),
        &[],
    );
    assert_mentions(&m, &["scene.toml", "materials[0]", "exponent", "glossy"]);
    let m = load_error(
        "negative-exponent",
        &format!("[[materials]]\nname = \"m\"\ntype = \"glossy\"\nexponent = -1\n{obj}"),
        &[],
    );
    assert_mentions(&m, &["materials[0] (\"m\").exponent", "got -1"]);
    let m = load_error(
        "specular-too-big",
        &format!("[[materials]]\nname = \"m\"\ntype = \"semigloss\"\nspecular = 1.5\n{obj}"),
        &[],
    );
    assert_mentions(&m, &["materials[0] (\"m\").specular", "[0, 1]", "1.5"]);
    let m = load_error(
        "specular-on-glossy",
        &format!("[[materials]]\nname = \"m\"\ntype = \"glossy\"\nspecular = 0.5\n{obj}"),
        &[],
    );
    assert_mentions(&m, &["specular", "semigloss"]);
    let m = load_error(
        "unknown-type",
        &format!("[[materials]]\nname = \"m\"\ntype = \"glosy\"\n{obj}"),
        &[],
    );
    assert_mentions(&m, &["line 3", "did you mean `glossy`?"]);
}

#[test]
fn chapter_5_sky_keys_are_checked() {
    let m = load_error(
        "sky-missing-zenith",
        "[[lights]]\ntype = \"sky\"\nhorizon = [1, 1, 1]\n",
        &[],
    );
    assert_mentions(&m, &["scene.toml", "missing field `zenith`"]);
    let m = load_error(
        "sky-nan",
        "[[lights]]\ntype = \"sky\"\nzenith = [1, nan, 1]\nhorizon = [1, 1, 1]\n",
        &[],
    );
    assert_mentions(&m, &["lights[0]", "finite"]);
    let m = load_error(
        "sky-typo",
        "[[lights]]\ntype = \"sky\"\nzenith = [1, 1, 1]\nhorizon = [1, 1, 1]\ngrund = [0, 0, 0]\n",
        &[],
    );
    assert_mentions(&m, &["`grund`", "did you mean `ground`?"]);
    let m = load_error(
        "two-environments",
        "[[lights]]\ntype = \"environment\"\nradiance = [1, 1, 1]\n[[lights]]\ntype = \"sky\"\nzenith = [1, 1, 1]\nhorizon = [1, 1, 1]\n",
        &[],
    );
    assert_mentions(&m, &["lights[1]", "at most one environment", "lights[0]"]);
}

#[test]
fn zero_samples_or_preview_width_is_a_usage_error_in_every_chapter() {
    let chapters = [
        ("ch1", env!("CARGO_BIN_EXE_ch1")),
        ("ch2", env!("CARGO_BIN_EXE_ch2")),
        ("ch3", env!("CARGO_BIN_EXE_ch3")),
        ("ch4", env!("CARGO_BIN_EXE_ch4")),
        ("ch5", env!("CARGO_BIN_EXE_ch5")),
        ("ch6", env!("CARGO_BIN_EXE_ch6")),
    ];
    let parent = common::temp_dir("zero-flags");
    let out = parent.join("out");
    for (name, exe) in chapters {
        for flag in ["--spp", "--preview-width"] {
            let result = std::process::Command::new(exe)
                .args([flag, "0", "--out", out.to_str().unwrap()])
                .output()
                .unwrap();
            let stderr = String::from_utf8_lossy(&result.stderr);
            // Refused by the flag parser (clap's usage errors exit with 2),
            // naming the flag, before anything renders.
            assert_eq!(result.status.code(), Some(2), "{name} {flag} 0: {stderr}");
            assert!(stderr.contains(flag), "{name} {flag} 0: {stderr}");
            assert!(stderr.contains("0 is not in 1.."), "{name}: {stderr}");
            assert!(!out.exists(), "{name} {flag} 0 wrote {}", out.display());
        }
    }
}

/// Round 4's misleading messages: a direction that is not zero but too
/// short for f32 is not called the zero vector, and an eye and a target
/// that differ only beyond f32's precision are not told to differ.
#[test]
fn short_directions_and_f32_equal_cameras_are_named_for_what_they_are() {
    let m = load_error(
        "short-axis",
        "[[objects]]\nshape = \"box\"\nrotate = { axis = [1e-30, 0, 0], degrees = 3 }\n",
        &[],
    );
    assert_mentions(&m, &["objects[0].rotate.axis", "too short", "1e-30"]);
    assert!(!m.contains("zero vector"), "{m}");
    let m = load_error(
        "short-normal",
        "[[sdfs]]\ntype = \"plane\"\nnormal = [0, 1e-30, 0]\n[[lights]]\ntype = \"point\"\nposition = [0, 2, 0]\nintensity = [1, 1, 1]\n",
        &[],
    );
    assert_mentions(&m, &["normal", "too short"]);
    let camera = |eye: &str, target: &str, up: &str| {
        format!(
            "[camera]\neye = {eye}\ntarget = {target}\nup = {up}\n[[objects]]\nshape = \"box\"\n"
        )
    };
    let m = load_error(
        "same-eye",
        &camera("[0, 0, 1]", "[0, 0, 1]", "[0, 1, 0]"),
        &[],
    );
    assert_mentions(&m, &["`eye` and `target` must differ"]);
    // Apart in f64, not in f32 (the difference underflows).
    let m = load_error(
        "f32-eye",
        &camera("[0, 0, 0]", "[0, 0, 1e-40]", "[0, 1, 0]"),
        &[],
    );
    assert_mentions(&m, &["too close to tell apart in f32"]);
    assert!(!m.contains("must differ"), "{m}");
    // 1 and 1.00000001 are one number in f32, but the camera is then far
    // from the origin for its viewing distance: the scene is kept around
    // it, where the two are 1e-8 apart, and loads.
    let dir = common::temp_dir("f64-eye");
    common::write_files(
        &dir,
        &[(
            "scene.toml",
            &camera("[0, 0, 1]", "[0, 0, 1.00000001]", "[0, 1, 0]"),
        )],
    );
    let scene = Scene::load(&dir.join("scene.toml")).unwrap();
    assert_eq!(scene.origin, glam::DVec3::Z);
    let m = load_error(
        "parallel-up",
        &camera("[0, 0, 1]", "[0, 0, 0]", "[0, 0, 2]"),
        &[],
    );
    assert_mentions(&m, &["`up`", "parallel"]);
    assert!(!m.contains("must differ"), "{m}");
}
