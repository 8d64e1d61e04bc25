//! Plausible wrong solutions of the capstones (and common mistakes of the
//! other exercises) that the grader must fail, naming the symptom, and
//! correct alternatives it must pass.

pub mod ch1;
pub mod ch2;
pub mod ch3;
pub mod ch4;
pub mod ch5;
pub mod ch6;

/// Runs `f` in a child process (this test binary again, running only the
/// test `name`), for tests that trip raystep's reference guard: what the
/// guard records is process-wide and sticky, and would fail every later
/// check in this process. Returns the child's stdout and stderr; panics
/// when it fails.
pub fn in_child(name: &str, f: impl FnOnce()) -> String {
    const CHILD: &str = "RAYSTEP_MUTANTS_CHILD";
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
