//! Issue 20: the fuzz harness in CI. A thousand mutated scene and OBJ
//! files, each loaded and (when it loads) rendered at 16x16: none may
//! panic, none may hang. `cargo run --release --bin fuzz -- --cases
//! 1000000` runs the long version and also counts cases over one second.

use raystep::fuzz::{case, run_range};

/// Cases run by `cargo test`: a thousand, a few seconds in a debug build.
/// The million-case run is `cargo run --release --bin fuzz` (see
/// book/src/running.md); this one keeps every mutation kind exercised.
const CI_CASES: u64 = 1000;

#[test]
fn mutated_inputs_give_errors_or_images_never_panics() {
    let tally = run_range(20, 0..CI_CASES);
    eprintln!("{tally:?}");
    assert_eq!(tally.cases, CI_CASES);
    assert_eq!(tally.panics, 0, "panicking cases: {:?}", tally.bad);
    // The mutations must exercise both paths: many inputs still load and
    // render, many are refused.
    assert!(tally.successes > CI_CASES / 10, "{tally:?}");
    assert!(tally.errors > CI_CASES / 10, "{tally:?}");
    // A debug build on a loaded machine is slower than the release run the
    // one-second rule is for: here only "does not hang".
    assert!(
        tally.slowest.0 < 20.0,
        "case {} took {:.1} s",
        tally.slowest.1,
        tally.slowest.0
    );
}

#[test]
fn cases_are_reproducible() {
    for i in [0, 1, 17, 999_999] {
        let (a, b) = (case(7, i), case(7, i));
        assert_eq!((a.scene, a.obj, a.chapter), (b.scene, b.obj, b.chapter));
    }
    assert_ne!(case(7, 1).scene, case(7, 2).scene);
}
