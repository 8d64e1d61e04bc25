//! The exercise files as shipped: every stub, embedded in the library.
//! Students edit their copies under `chapters/chN-…/exercises/`; the
//! grader's own tests and `grade --restore` use these, so a student's work
//! never changes what the project's tests see. `.ci/run` checks that the
//! working copies in a clean clone are these files.

use std::path::{Path, PathBuf};

/// One shipped exercise file.
#[derive(Clone, Copy, Debug)]
pub struct Stub {
    /// The chapter folder under `chapters/` (`ch3-ray-triangle`).
    pub folder: &'static str,
    /// The file stem, the exercise's name (`bvh_traversal`).
    pub name: &'static str,
    /// The file as shipped.
    pub text: &'static str,
}

impl Stub {
    /// `chN/name`, the exercise's id.
    pub fn id(&self) -> String {
        let chapter = self.folder.split('-').next().unwrap_or(self.folder);
        format!("{chapter}/{}", self.name)
    }

    /// Where this file lives under a folder of chapter folders.
    pub fn path_in(&self, chapters: &Path) -> PathBuf {
        chapters
            .join(self.folder)
            .join("exercises")
            .join(format!("{}.rs", self.name))
    }
}

macro_rules! stub {
    ($folder:literal, $name:literal) => {
        Stub {
            folder: $folder,
            name: $name,
            text: include_str!(concat!("shipped/", $folder, "/", $name, ".rs")),
        }
    };
}

/// Every exercise file, as `$make!(folder, name)` for each, in chapter
/// order: the one list the shipped stubs ([`STUBS`]) and the solutions
/// ([`crate::solutions::SOLUTIONS`]) are made from.
macro_rules! exercise_files {
    ($make:ident) => {
        &[
            $make!("ch1-projection", "draw_edges"),
            $make!("ch1-projection", "look_at"),
            $make!("ch1-projection", "project_point"),
            $make!("ch2-rasterization", "barycentric"),
            $make!("ch2-rasterization", "depth_test"),
            $make!("ch2-rasterization", "edge_function"),
            $make!("ch2-rasterization", "manifold"),
            $make!("ch2-rasterization", "rasterize_triangle"),
            $make!("ch3-ray-triangle", "barycentric_inside"),
            $make!("ch3-ray-triangle", "bvh_traversal"),
            $make!("ch3-ray-triangle", "moller_trumbore"),
            $make!("ch3-ray-triangle", "ray_plane"),
            $make!("ch3-ray-triangle", "sah"),
            $make!("ch4-sphere-tracing", "gradient_normal"),
            $make!("ch4-sphere-tracing", "sphere_sdf"),
            $make!("ch4-sphere-tracing", "sphere_trace"),
            $make!("ch4-sphere-tracing", "trace_scene"),
            $make!("ch5-reflection", "area_pdf"),
            $make!("ch5-reflection", "cosine_hemisphere"),
            $make!("ch5-reflection", "direct_light"),
            $make!("ch5-reflection", "lambert_brdf"),
            $make!("ch5-reflection", "point_light"),
            $make!("ch5-reflection", "solid_angle"),
            $make!("ch5-reflection", "spot"),
            $make!("ch6-global-illumination", "bounce_layers"),
            $make!("ch6-global-illumination", "mc_integral"),
            $make!("ch6-global-illumination", "mis_weight"),
            $make!("ch6-global-illumination", "path_radiance"),
            $make!("ch6-global-illumination", "refraction"),
            $make!("ch6-global-illumination", "russian_roulette"),
        ]
    };
}
pub(crate) use exercise_files;

/// Every shipped exercise file, in chapter order.
pub const STUBS: &[Stub] = exercise_files!(stub);

/// Writes every shipped stub under `dir` (`dir/chN-…/exercises/name.rs`),
/// and the blank predict sheet (`dir/predictions.toml`), as a fresh copy of the exercises for a test or a new student; returns
/// `dir`.
pub fn write_all(dir: &Path) -> std::io::Result<PathBuf> {
    for stub in STUBS {
        let path = stub.path_in(dir);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent)?;
        }
        std::fs::write(&path, stub.text)?;
    }
    std::fs::write(dir.join(super::predict::SHEET), super::predict::SHIPPED)?;
    Ok(dir.to_path_buf())
}

/// The shipped stub of exercise `id` (`chN/name`).
pub fn find(id: &str) -> Option<&'static Stub> {
    STUBS.iter().find(|s| s.id() == id)
}
