//! Plausible wrong solutions of the capstones (and common mistakes of the
//! other exercises) that the grader must fail, naming the symptom, and
//! correct alternatives it must pass.

use raystep::grading::{Check, Exercise, Symptom};

pub mod ch1;
pub mod ch2;
pub mod ch3;
pub mod ch4;
pub mod ch5;
pub mod ch6;
pub mod fresh;

/// Runs `check` once under each of `seeds` (the seed of the inputs the
/// checks draw, as a grading run sets it), on this thread; each seed with
/// what the check found.
pub fn under_seeds(seeds: &[u64], check: impl Fn() -> Check) -> Vec<(u64, Check)> {
    let found = seeds
        .iter()
        .map(|&seed| {
            raystep::grading::set_run_seed(seed);
            (seed, check())
        })
        .collect();
    raystep::grading::set_run_seed(0);
    found
}

/// Runs `f` in a child process (this test binary again, running only the
/// test `name`), for tests that trip raystep's reference guard: what the
/// guard records is process-wide and sticky, and would fail every later
/// check in this process. Returns the child's stdout and stderr; panics
/// when it fails.
pub fn in_child(name: &str, f: impl FnOnce()) -> String {
    const CHILD: &str = "RAYSTEP_MUTANTS_CHILD";
    // A test's name as the harness knows it (`module_path!()` starts with
    // the test crate's name).
    let name = name
        .strip_prefix(concat!(env!("CARGO_CRATE_NAME"), "::"))
        .unwrap_or(name);
    if std::env::var_os(CHILD).is_some() {
        f();
        return String::new();
    }
    let out = std::process::Command::new(std::env::current_exe().expect("the test binary"))
        .args([name, "--exact", "--nocapture", "--test-threads=1"])
        .env(CHILD, "1")
        .output()
        .expect("runs the test binary");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "the child failed:\n{text}");
    assert!(text.contains("1 passed"), "the child ran no test:\n{text}");
    text
}

/// Each of `calls` calls raystep's own solution of the exercise it names
/// as if from inside a student's function; in a child process (see
/// [`in_child`], which runs the test `test` again) every one must be
/// refused with the guard's message naming that exercise.
pub fn refused_in_a_child(test: &str, calls: &[(&str, &dyn Fn())]) {
    use raystep::core::guard;
    use std::panic::{catch_unwind, AssertUnwindSafe};
    in_child(test, || {
        for (id, call) in calls {
            let got = catch_unwind(AssertUnwindSafe(|| guard::student(call)));
            let message = got
                .err()
                .and_then(|p| p.downcast::<String>().ok())
                .map_or_else(|| "nothing".to_string(), |m| *m);
            assert_eq!(message, guard::message(id), "{id}");
        }
    });
}

/// `check` failed, naming `symptom`, which its chapter's `exercises` list;
/// returns the check's detail. `what` names the mistake in a failure.
pub fn fails_naming(check: Check, symptom: Symptom, exercises: &[Exercise], what: &str) -> String {
    assert!(!check.passed(), "{what} passed: {}", check.detail);
    assert_eq!(check.symptom, Some(symptom), "{what}: {}", check.detail);
    assert!(
        exercises.iter().any(|e| e.symptoms.contains(&symptom)),
        "{what}: {} is not listed",
        symptom.name
    );
    check.detail
}
