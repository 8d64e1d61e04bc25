//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// A fresh empty folder under the system temp dir, unique to this test.
pub fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raystep-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
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
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}
pub mod chi2;

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
