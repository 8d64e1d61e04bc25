//! Declares the exercise modules from the files under
//! `$RAYSTEP_EXERCISES_DIR` (this folder when unset), one `pub mod chN {…}`
//! per chapter folder, and leaves out the exercises named in
//! `$RAYSTEP_BROKEN` (`ch1/look_at,…`: files the grader found not to
//! compile) by setting `broken_ch1_look_at`, so the others still build.

use std::fmt::Write;
use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-env-changed=RAYSTEP_EXERCISES_DIR");
    println!("cargo:rerun-if-env-changed=RAYSTEP_BROKEN");
    let here = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap());
    let dir = std::env::var_os("RAYSTEP_EXERCISES_DIR")
        .map(PathBuf::from)
        .unwrap_or(here);
    let broken = std::env::var("RAYSTEP_BROKEN").unwrap_or_default();
    let broken: Vec<&str> = broken.split(',').filter(|s| !s.is_empty()).collect();
    let mut chapters: Vec<(String, PathBuf)> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .flatten()
        .filter_map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            let ch = name.split('-').next()?.to_string();
            let ex = e.path().join("exercises");
            (ch.starts_with("ch") && ex.is_dir()).then_some((ch, ex))
        })
        .collect();
    chapters.sort();
    let mut code = String::new();
    for (ch, ex) in &chapters {
        println!("cargo:rerun-if-changed={}", ex.display());
        let mut files: Vec<String> = std::fs::read_dir(ex)
            .unwrap()
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".rs") && n != "mod.rs")
            .map(|n| n.trim_end_matches(".rs").to_string())
            .collect();
        files.sort();
        writeln!(
            code,
            "/// Chapter {}'s exercises.\npub mod {ch} {{",
            &ch[2..]
        )
        .unwrap();
        for name in files {
            let cfg = format!("broken_{ch}_{name}");
            println!("cargo::rustc-check-cfg=cfg({cfg})");
            if broken.contains(&format!("{ch}/{name}").as_str()) {
                println!("cargo::rustc-cfg={cfg}");
            }
            let path = ex.join(format!("{name}.rs"));
            writeln!(
                code,
                "    #[cfg(not({cfg}))]\n    #[path = {:?}]\n    pub mod {name};",
                path.display().to_string()
            )
            .unwrap();
        }
        code += "}\n";
    }
    let out = PathBuf::from(std::env::var("OUT_DIR").unwrap()).join("exercises.rs");
    std::fs::write(out, code).unwrap();
}
