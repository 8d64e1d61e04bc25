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

/// Every shipped exercise file, in chapter order.
pub const STUBS: &[Stub] = &[
    stub!("ch1-projection", "draw_edges"),
    stub!("ch1-projection", "look_at"),
    stub!("ch1-projection", "project_point"),
    stub!("ch2-rasterization", "barycentric"),
    stub!("ch2-rasterization", "depth_test"),
    stub!("ch2-rasterization", "edge_function"),
    stub!("ch2-rasterization", "rasterize_triangle"),
    stub!("ch3-ray-triangle", "barycentric_inside"),
    stub!("ch3-ray-triangle", "bvh_traversal"),
    stub!("ch3-ray-triangle", "moller_trumbore"),
    stub!("ch3-ray-triangle", "ray_plane"),
    stub!("ch4-sphere-tracing", "gradient_normal"),
    stub!("ch4-sphere-tracing", "sphere_sdf"),
    stub!("ch4-sphere-tracing", "sphere_trace"),
    stub!("ch4-sphere-tracing", "trace_scene"),
    stub!("ch5-reflection", "area_pdf"),
    stub!("ch5-reflection", "cosine_hemisphere"),
    stub!("ch5-reflection", "direct_light"),
    stub!("ch5-reflection", "lambert_brdf"),
    stub!("ch5-reflection", "point_light"),
    stub!("ch6-global-illumination", "mc_integral"),
    stub!("ch6-global-illumination", "mis_weight"),
    stub!("ch6-global-illumination", "path_radiance"),
    stub!("ch6-global-illumination", "russian_roulette"),
];

/// Writes every shipped stub under `dir` (`dir/chN-…/exercises/name.rs`),
/// as a fresh copy of the exercises for a test or a new student; returns
/// `dir`.
pub fn write_all(dir: &Path) -> std::io::Result<PathBuf> {
    for stub in STUBS {
        let path = stub.path_in(dir);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent)?;
        }
        std::fs::write(&path, stub.text)?;
    }
    Ok(dir.to_path_buf())
}

/// The shipped stub of exercise `id` (`chN/name`).
pub fn find(id: &str) -> Option<&'static Stub> {
    STUBS.iter().find(|s| s.id() == id)
}
