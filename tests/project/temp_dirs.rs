//! The tests' folders under the system temp dir: a passing test removes
//! its own, so that `cargo test` does not leave a copy of every folder it
//! wrote behind (about 150 folders and 90 MB a run, before); a failing
//! test keeps its folder for inspection.

use crate::common;

#[test]
fn a_test_folder_goes_when_its_test_passes_and_stays_when_it_fails() {
    let passed = common::temp_dir("temp-dirs-passed");
    common::write_files(&passed, &[("a/b.txt", "kept until the end")]);
    let path = passed.to_path_buf();
    assert!(path.join("a/b.txt").is_file());
    drop(passed);
    assert!(!path.exists(), "{} is still there", path.display());

    // A test that fails: its panic unwinds through the folder's owner.
    let dir = common::temp_dir("temp-dirs-failed");
    common::write_files(&dir, &[("out.txt", "what the test wrote")]);
    let failed = dir.to_path_buf();
    let outcome = std::panic::catch_unwind(move || {
        let _dir = dir;
        panic!("a failing test (expected)");
    });
    assert!(outcome.is_err());
    assert!(
        failed.join("out.txt").is_file(),
        "a failing test's folder went"
    );
    std::fs::remove_dir_all(&failed).unwrap();
}
