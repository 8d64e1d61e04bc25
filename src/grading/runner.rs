//! The child side of grading: the `grade-student` binary of the exercises
//! crate (`chapters/runner.rs`) runs one check on the student's code and
//! prints its verdict for the grader ([`crate::grading::driver`]), which
//! runs it under a time limit. One process per exercise: a loop that never
//! ends, a stack overflow or an abort stops that exercise, not the grader.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use serde::{Deserialize, Serialize};

use crate::grading::exercise::{Check, Exercise, Outcome};
use crate::grading::sandbox::Limits;
use crate::grading::{run_check, write_failure_images};

/// The student's checks, by exercise id (`chN/name`): what the exercises
/// crate compiled (an exercise that does not compile is left out).
pub type Registry = Vec<(&'static str, fn() -> Check)>;

/// The student's sampling routines the warp view can test, by exercise id.
pub type Warps = Vec<(&'static str, crate::core::warp_test::WarpRoutine)>;

/// The first line `grade-student warp` prints before the draws
/// ([`crate::core::warp_test::Drawn::to_text`]); `not_implemented` or
/// `panicked: …` instead when the routine could not draw.
pub const WARP_HEADER: &str = "raystep-warp";

/// What the grader hands a `grade-student` process on its standard input,
/// read before any student code runs: a secret that marks the verdict, and
/// the time limit (for the process's CPU limit). The student's code cannot
/// read it again (standard input is drained and closed), so a verdict it
/// prints itself lacks the secret and is ignored.
#[derive(Clone, Debug, PartialEq)]
pub struct Handshake {
    /// 32 hex digits, new for every process.
    pub secret: String,
    /// The time limit, seconds.
    pub timeout: f64,
}

impl Handshake {
    /// A new secret for a process with time limit `timeout`.
    pub fn new(timeout: Duration) -> Handshake {
        use std::hash::{BuildHasher, Hasher};
        let word = |salt: u64| {
            let mut h = std::collections::hash_map::RandomState::new().build_hasher();
            h.write_u64(salt);
            h.write_u128(
                std::time::SystemTime::now()
                    .duration_since(std::time::UNIX_EPOCH)
                    .map_or(0, |d| d.as_nanos()),
            );
            h.write_u32(std::process::id());
            h.finish()
        };
        Handshake {
            secret: format!("{:016x}{:016x}", word(1), word(2)),
            timeout: timeout.as_secs_f64(),
        }
    }

    /// The line written to the child's standard input.
    pub fn line(&self) -> Vec<u8> {
        format!("{} {}\n", self.secret, self.timeout).into_bytes()
    }

    /// Reads the handshake from standard input: `None` when there is none
    /// (the binary run by hand).
    pub fn read() -> Option<Handshake> {
        let mut text = String::new();
        std::io::stdin().read_to_string(&mut text).ok()?;
        let (secret, timeout) = text.trim().split_once(' ')?;
        Some(Handshake {
            secret: secret.to_string(),
            timeout: timeout.parse().ok()?,
        })
    }

    fn open(&self) -> String {
        format!("@@raystep-verdict {}@@", self.secret)
    }

    fn close(&self) -> String {
        format!("@@raystep-verdict-end {}@@", self.secret)
    }

    /// Prints `verdict` between the two marked lines.
    pub fn print(&self, verdict: &Verdict) {
        match toml::to_string(verdict) {
            Ok(text) => {
                let mut out = std::io::stdout().lock();
                let _ = write!(out, "\n{}\n{text}\n{}\n", self.open(), self.close());
                let _ = out.flush();
            }
            Err(e) => eprintln!("error: could not write the verdict: {e}"),
        }
    }

    /// The verdict in a child's standard output: the text between the two
    /// lines that carry this secret.
    pub fn verdict_in(&self, stdout: &str) -> Option<Verdict> {
        let (_, rest) = stdout.split_once(&self.open())?;
        let (text, _) = rest.split_once(&self.close())?;
        toml::from_str(text).ok()
    }
}

/// One exercise's result, as the child prints it.
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
pub struct Verdict {
    /// `passed`, `failed`, `not_implemented`, `panicked` or `missing`.
    pub outcome: String,
    /// The measured error.
    pub error: f64,
    /// The tolerance.
    pub tolerance: f64,
    /// The worst case, or the panic message.
    pub detail: String,
    /// Images written for a failed image check.
    pub images: Vec<PathBuf>,
    /// The symptom the check named (one of the exercise's), or empty.
    #[serde(default)]
    pub symptom: String,
}

impl Verdict {
    /// The verdict `outcome` (`passed` or `failed`) for a check's result,
    /// with the images it wrote.
    fn of_check(outcome: &str, c: Check, images: Vec<PathBuf>) -> Verdict {
        Verdict {
            outcome: outcome.into(),
            error: c.error,
            tolerance: c.tolerance,
            symptom: c.symptom.map(|s| s.name.to_string()).unwrap_or_default(),
            detail: c.detail,
            images,
        }
    }

    /// The outcome this verdict stands for, with its images' paths (the
    /// images themselves stay on disk).
    pub fn outcome(&self, ex: &Exercise) -> Outcome {
        let symptom = ex.symptoms.iter().find(|s| s.name == self.symptom).copied();
        let check = || Check {
            error: self.error,
            tolerance: self.tolerance,
            detail: self.detail.clone(),
            images: None,
            symptom,
        };
        match self.outcome.as_str() {
            "passed" => Outcome::Passed(check()),
            "failed" => Outcome::Failed(check()),
            "not_implemented" => Outcome::NotImplemented,
            "missing" => Outcome::DoesNotCompile(self.detail.clone()),
            _ => Outcome::Panicked(self.detail.clone()),
        }
    }
}

/// Runs the check of `ex` from `registry` and returns its verdict; images
/// of a failed image check go to `out`.
pub fn verdict(registry: &Registry, ex: &Exercise, out: &Path) -> Verdict {
    let id = ex.id();
    let Some((_, check)) = registry.iter().find(|(n, _)| *n == id) else {
        return Verdict {
            outcome: "missing".into(),
            detail: format!("{id} is not in the exercises crate that was built"),
            ..Verdict::default()
        };
    };
    match run_check(*check) {
        Outcome::Passed(c) => Verdict::of_check("passed", c, Vec::new()),
        Outcome::Failed(c) => {
            let (images, note) = match write_failure_images(ex, &c, out) {
                Ok(files) => (files, String::new()),
                Err(e) => (Vec::new(), format!(" (could not write images: {e})")),
            };
            let mut v = Verdict::of_check("failed", c, images);
            v.detail += &note;
            v
        }
        Outcome::NotImplemented => Verdict {
            outcome: "not_implemented".into(),
            ..Verdict::default()
        },
        Outcome::Panicked(m) | Outcome::DoesNotCompile(m) => Verdict {
            outcome: "panicked".into(),
            detail: m,
            ..Verdict::default()
        },
        Outcome::TimedOut { doing, .. } => Verdict {
            outcome: "panicked".into(),
            detail: doing,
            ..Verdict::default()
        },
    }
}

/// The argument that makes `grade-student` report which sandbox limits
/// this system cannot set, instead of grading.
pub const SANDBOX_CHECK: &str = "--sandbox-check";

/// Each chapter's capstone, the exercise that renders the chapter's scene.
pub const CAPSTONES: [(u32, &str); 6] = [
    (1, "draw_edges"),
    (2, "rasterize_triangle"),
    (3, "bvh_traversal"),
    (4, "trace_scene"),
    (5, "direct_light"),
    (6, "path_radiance"),
];

/// `grade-student render <N> <out>`: renders chapter N's capstone scene
/// with the student's code and with the reference, writes both and their
/// difference to `out`, and says how they compare. When the grader runs it
/// (with a [`Handshake`]: the TUI's student mode), the verdict follows, as
/// for a check, with the three images' paths.
fn render(
    registry: &Registry,
    chapter: &str,
    out: &Path,
    handshake: Option<&Handshake>,
) -> ExitCode {
    let n: u32 = chapter.trim_start_matches("ch").parse().unwrap_or(0);
    let Some((_, name)) = CAPSTONES.iter().find(|(c, _)| *c == n) else {
        eprintln!("chapter {chapter} has no capstone to render yet");
        return ExitCode::from(2);
    };
    let Some(ex) = crate::grading::all()
        .into_iter()
        .find(|e| e.chapter == n && e.name == *name)
    else {
        eprintln!("error: no exercise ch{n}/{name}");
        return ExitCode::from(2);
    };
    let Some((_, check)) = registry.iter().find(|(id, _)| *id == ex.id()) else {
        eprintln!(
            "error: {} is not in the exercises crate that was built",
            ex.id()
        );
        return ExitCode::from(2);
    };
    let (code, verdict) = render_check(&ex, *check, out);
    if let Some(handshake) = handshake {
        handshake.print(&verdict);
    }
    code
}

/// Runs the capstone's check, prints what it found and writes its images.
fn render_check(ex: &Exercise, check: fn() -> Check, out: &Path) -> (ExitCode, Verdict) {
    let fail = |outcome: &str, detail: String| Verdict {
        outcome: outcome.into(),
        detail,
        ..Verdict::default()
    };
    let c = match run_check(check) {
        Outcome::Passed(c) | Outcome::Failed(c) => c,
        Outcome::NotImplemented => {
            println!(
                "{} is not started: replace the todo!() in {}",
                ex.id(),
                ex.file
            );
            return (ExitCode::from(1), fail("not_implemented", String::new()));
        }
        other => {
            println!("{}: {other:?}", ex.id());
            let detail = match other {
                Outcome::Panicked(m) | Outcome::DoesNotCompile(m) => m,
                other => format!("{other:?}"),
            };
            return (ExitCode::from(1), fail("panicked", detail));
        }
    };
    let passed = c.passed();
    let verdict = if passed {
        "matches the reference"
    } else {
        "differs from the reference"
    };
    println!("your {} {verdict}: {}", ex.id(), c.detail);
    match write_failure_images(ex, &c, out) {
        Ok(files) => {
            for f in &files {
                println!("wrote {}", f.display());
            }
            let outcome = if passed { "passed" } else { "failed" };
            (ExitCode::SUCCESS, Verdict::of_check(outcome, c, files))
        }
        Err(e) => {
            eprintln!("error: {e}");
            let detail = format!("could not write the images: {e}");
            (ExitCode::from(2), fail("panicked", detail))
        }
    }
}

/// The whole `main` of `grade-student`: `grade-student <chN/name> <out>`
/// prints the verdict of one exercise, marked with the secret of the
/// [`Handshake`] on standard input; `grade-student render <chN> <out>`
/// renders a chapter's capstone. Before any student code runs, the process
/// limits itself ([`Limits`]) and may write only under `out`.
pub fn runner_main(registry: Registry, warps: Warps) -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    // `grade-student --sandbox-check <dir>`: which limits this system
    // cannot set, one per line (the grader says so before grading).
    if let [flag, dir] = args.as_slice() {
        if flag == SANDBOX_CHECK {
            for missing in Limits::for_timeout(1.0).apply(Path::new(dir)) {
                println!("{missing}");
            }
            return ExitCode::SUCCESS;
        }
    }
    if let [cmd, id, out, draws, seed] = args.as_slice() {
        if cmd == "warp" {
            return warp(&warps, id, Path::new(out), draws, seed);
        }
    }
    let handshake = Handshake::read();
    let (render_chapter, id, out) = match args.as_slice() {
        [cmd, chapter, out] if cmd == "render" => (Some(chapter.clone()), None, out),
        [id, out] => (None, Some(id.clone()), out),
        _ => {
            eprintln!("usage: grade-student <chN/name> <out dir> (run by `grade`)");
            return ExitCode::from(2);
        }
    };
    let out = Path::new(out);
    if let Err(e) = std::fs::create_dir_all(out) {
        eprintln!("error: cannot create {}: {e}", out.display());
        return ExitCode::from(2);
    }
    let timeout = handshake.as_ref().map_or(60.0, |h| h.timeout);
    for missing in Limits::for_timeout(timeout).apply(out) {
        eprintln!("note: the grader's sandbox could not set {missing}");
    }
    if let Some(chapter) = render_chapter {
        return render(&registry, &chapter, out, handshake.as_ref());
    }
    let id = id.unwrap_or_default();
    let Some(ex) = crate::grading::all().into_iter().find(|e| e.id() == id) else {
        eprintln!("error: no exercise `{id}`");
        return ExitCode::from(2);
    };
    let Some(handshake) = handshake else {
        eprintln!("error: grade-student is run by `grade` (cargo grade), which hands it a secret");
        return ExitCode::from(2);
    };
    handshake.print(&verdict(&registry, &ex, out));
    ExitCode::SUCCESS
}

/// `grade-student warp <id> <out> <draws> <seed>`: the student's routine
/// `id` draws `draws` directions in the sandbox (it may write only under
/// `out`), and the counts are printed after [`WARP_HEADER`]; the test
/// against the pdf is the caller's.
fn warp(warps: &Warps, id: &str, out: &Path, draws: &str, seed: &str) -> ExitCode {
    let (Ok(draws), Ok(seed)) = (draws.parse::<usize>(), seed.parse::<u64>()) else {
        eprintln!("usage: grade-student warp <chN/name> <out dir> <draws> <seed>");
        return ExitCode::from(2);
    };
    let Some((_, routine)) = warps.iter().find(|(w, _)| *w == id) else {
        eprintln!("error: no sampling routine `{id}` in the exercises crate that was built");
        return ExitCode::from(2);
    };
    if let Err(e) = std::fs::create_dir_all(out) {
        eprintln!("error: cannot create {}: {e}", out.display());
        return ExitCode::from(2);
    }
    for missing in Limits::for_timeout(60.0).apply(out) {
        eprintln!("note: the grader's sandbox could not set {missing}");
    }
    let sample = routine.sample;
    let drawn = std::panic::catch_unwind(|| {
        crate::core::warp_test::draw(&sample, draws.min(1 << 22), seed)
    });
    match drawn {
        Ok(d) => println!("{WARP_HEADER}\n{}", d.to_text()),
        Err(payload) => {
            let message = crate::grading::panic_text(&*payload);
            if message.starts_with("not yet implemented") {
                println!("not_implemented");
            } else {
                println!("panicked: {}", message.replace('\n', " "));
            }
        }
    }
    ExitCode::SUCCESS
}
