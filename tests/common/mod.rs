//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use glam::Vec3;

/// A fresh empty folder under the system temp dir, unique to this test,
/// removed with everything in it when the value is dropped: when the test
/// passes. A failing test leaves it for inspection (its path is in the
/// panic's output).
pub fn temp_dir(name: &str) -> TempDir {
    let dir = std::env::temp_dir().join(format!("raystep-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    TempDir(dir)
}

/// A test's folder from [`temp_dir`]: a path, and its removal.
#[derive(Debug)]
pub struct TempDir(PathBuf);

impl std::ops::Deref for TempDir {
    type Target = PathBuf;
    fn deref(&self) -> &PathBuf {
        &self.0
    }
}

impl AsRef<Path> for TempDir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<std::ffi::OsStr> for TempDir {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.0.as_os_str()
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        if std::thread::panicking() {
            eprintln!("kept for inspection: {}", self.0.display());
        } else {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

/// Writes `files` (relative path, contents) into `dir`.
pub fn write_files(dir: &Path, files: &[(&str, &str)]) {
    for (rel, text) in files {
        let p = dir.join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    }
}

/// The repository root.
/// The chapters' folders under `src/`, in lecture order (each a module of
/// the lessons' crate).
pub const CHAPTER_MODULES: [&str; 6] = [
    "ch1_projection",
    "ch2_rasterization",
    "ch3_ray_triangle",
    "ch4_implicit_surfaces",
    "ch5_reflection",
    "ch6_global_illumination",
];

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The shipped scene `scenes/<name>.toml` at `w` x `h` pixels.
pub fn shipped_scene(name: &str, w: u32, h: u32) -> raystep::scene::Scene {
    raystep::scene::Scene::load(&root().join(format!("scenes/{name}.toml")))
        .unwrap()
        .with_resolution(w, h)
        .unwrap()
}
pub mod chi2;

/// The cell of `row` (an index into `table.rows`) under the column headed
/// `header`: tests read report tables by what a column means, not by where
/// it sits, so a column added or moved does not make them read the wrong
/// one. Panics, naming the headers there are, when `header` is not one.
pub fn cell<'a>(table: &'a raystep::core::table::Table, row: usize, header: &str) -> &'a str {
    let Some(col) = table.columns.iter().position(|c| c == header) else {
        panic!(
            "table \"{}\" has no column \"{header}\"; its columns: {:?}",
            table.title, table.columns
        );
    };
    &table.rows[row][col]
}

/// Every exercise of `chapter` (there must be `count`): its file exists
/// and its reference solution passes. (That every shipped stub fails
/// cleanly is checked through the grader itself, which builds the
/// exercises crate: `tests/project/grading.rs`.)
pub fn references_pass(chapter: u32, count: usize) {
    use raystep::grading;
    let exercises: Vec<_> = grading::all()
        .into_iter()
        .filter(|e| e.chapter == chapter)
        .collect();
    assert_eq!(exercises.len(), count);
    for ex in &exercises {
        assert!(root().join(ex.file).is_file(), "{}", ex.file);
        let outcome = grading::run(ex);
        assert!(outcome.is_pass(), "{}: {outcome:?}", ex.id());
    }
}

/// Per-pixel mean and variance of the mean of `spp` samples of
/// `radiance`, each sample's camera ray jittered inside its pixel (as the
/// shading chapters' render passes do), every number from
/// (seed, pixel, sample). The estimator ladders' tests compare such images.
pub fn mean_and_variance(
    scene: &raystep::scene::Scene,
    spp: u32,
    seed: u64,
    radiance: &dyn Fn(
        &raystep::ch5_reflection::world::World,
        raystep::ch3_ray_triangle::ray::Ray,
        &mut raystep::core::sampling::Sampler,
    ) -> glam::Vec3,
) -> (raystep::core::film::Film, raystep::core::film::Film) {
    use glam::Vec3;
    use raystep::ch3_ray_triangle::render::camera_sample;
    use raystep::core::film::Film;
    let world = raystep::ch5_reflection::world::World::new(scene);
    let cam = raystep::ch1_projection::camera::Camera::of(scene);
    let (mut mean, mut var) = (
        Film::new(cam.width, cam.height),
        Film::new(cam.width, cam.height),
    );
    for y in 0..cam.height {
        for x in 0..cam.width {
            let pixel = (y * cam.width + x) as u64;
            let (mut sum, mut sum_sq) = (Vec3::ZERO, Vec3::ZERO);
            for sample in 0..spp {
                let (mut s, ray) = camera_sample(&cam, (x, y), |p| {
                    raystep::core::sampling::Sampler::new(seed, p, sample as u64)
                });
                let l = radiance(&world, ray, &mut s);
                assert!(l.is_finite(), "pixel ({x}, {y}): {l}");
                sum += l;
                sum_sq += l * l;
            }
            let n = spp as f32;
            let m = sum / n;
            mean.pixels[pixel as usize] = m;
            // The sample variance, divided by n: the variance of the mean.
            var.pixels[pixel as usize] = (sum_sq - n * m * m).max(Vec3::ZERO) / (n - 1.0) / n;
        }
    }
    (mean, var)
}

/// A xorshift64 stream from `seed` (not 0): the tests' cheap, repeatable
/// source of bits.
pub fn xorshift(seed: u64) -> impl FnMut() -> u64 {
    let mut h = seed;
    move || {
        h ^= h << 13;
        h ^= h >> 7;
        h ^= h << 17;
        h
    }
}

/// [`xorshift`]'s top 24 bits as numbers in [0, 1).
pub fn unit_stream(seed: u64) -> impl FnMut() -> f32 {
    let mut bits = xorshift(seed);
    move || (bits() >> 40) as f32 / (1u64 << 24) as f32
}

/// The twelve triangles of the box `lo`..`hi`'s six faces (corner i has
/// bit 0, 1, 2 of i choosing hi's x, y, z), two per face.
pub fn box_faces(lo: Vec3, hi: Vec3) -> Vec<[Vec3; 3]> {
    let c = |i: usize| {
        Vec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        )
    };
    let quads = [
        [0, 1, 3, 2],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 3, 7, 5],
    ];
    quads
        .iter()
        .flat_map(|q| [[c(q[0]), c(q[1]), c(q[2])], [c(q[0]), c(q[2]), c(q[3])]])
        .collect()
}

/// Every file under `dir` whose name ends in `.{ext}`, sorted.
pub fn files_under(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let p = entry.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == ext) {
                found.push(p);
            }
        }
    }
    found.sort();
    found
}
