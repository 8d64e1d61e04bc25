//! The `grade` command: builds the exercises crate, leaves out the files
//! that do not compile (naming the compiler's file:line), runs each check
//! in a process of its own under a time limit, prints each result as soon
//! as it is known, and can write Gradescope's `results.json`.

use std::collections::BTreeMap;
use std::io::{IsTerminal, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use clap::Parser;

use crate::grading::exercise::{Exercise, Outcome};
use crate::grading::runner::parse_verdict;
use crate::grading::{all, hints, run, write_failure_images, PROGRESS, PROGRESS_ENV};

/// Grade your solutions to the exercises against raystep's reference.
#[derive(Parser, Debug)]
#[command(name = "grade")]
struct GradeCli {
    /// Chapters (`ch1` or `1`) or single exercises (`ch3/moller_trumbore`)
    /// to grade; all when omitted.
    chapters: Vec<String>,
    /// Grade raystep's reference solutions instead (they must all pass).
    #[arg(long)]
    reference: bool,
    /// Show the next hint for one exercise (`ch3/moller_trumbore`); ask
    /// again for the next tier. Grades nothing.
    #[arg(long, value_name = "EXERCISE")]
    hint: Option<String>,
    /// Also write Gradescope's results.json (to FILE, or `results.json`).
    #[arg(long, value_name = "FILE", num_args = 0..=1, default_missing_value = "results.json")]
    json: Option<PathBuf>,
    /// The time limit of one exercise, in seconds.
    #[arg(long, value_name = "SECONDS", default_value_t = 5.0)]
    timeout: f64,
    /// Where images of failed image checks (and the hints seen) go.
    #[arg(long, value_name = "DIR", default_value = "out/grade")]
    out: PathBuf,
    /// The folder holding the chapters' exercise folders
    /// (`ch1-projection/exercises/…`); `chapters/` of this repository when
    /// omitted.
    #[arg(long, value_name = "DIR", hide = true)]
    exercises: Option<PathBuf>,
}

/// The repository root (where `Cargo.toml` and `chapters/` are).
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The whole `main` of the `grade` binary.
pub fn grade_main() -> ExitCode {
    let cli = GradeCli::parse();
    let catalog = all();
    if let Some(id) = &cli.hint {
        let Some(ex) = catalog.iter().find(|e| &e.id() == id) else {
            eprintln!("error: no exercise `{id}`; expected e.g. `ch3/moller_trumbore`");
            return ExitCode::from(2);
        };
        return match hints::next_hint(ex, &cli.out) {
            Ok(text) => {
                print!("{text}");
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!(
                    "error: could not remember the hint in {}: {e}",
                    cli.out.display()
                );
                ExitCode::from(2)
            }
        };
    }
    let exercises = match select(&catalog, &cli.chapters) {
        Ok(e) => e,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if let Err(e) = std::fs::create_dir_all(&cli.out) {
        eprintln!("error: cannot create {}: {e}", cli.out.display());
        return ExitCode::from(2);
    }
    let mut stdout = std::io::stdout();
    let live = stdout.is_terminal();
    let results = if cli.reference {
        say(
            &mut stdout,
            &format!(
                "grading {} exercises (reference solutions)\n",
                exercises.len()
            ),
        );
        grade_stream(
            &exercises,
            &mut |ex| reference(ex, &cli.out),
            &mut stdout,
            live,
        )
    } else {
        say(
            &mut stdout,
            "building your exercises (the raystep-exercises crate)...\n",
        );
        let dir = cli
            .exercises
            .clone()
            .unwrap_or_else(|| root().join("chapters"));
        let built = match build_exercises(&dir) {
            Ok(b) => b,
            Err(e) => {
                eprintln!("error: could not build the exercises: {e}");
                return ExitCode::from(2);
            }
        };
        say(
            &mut stdout,
            &format!("grading {} exercises (your solutions)\n", exercises.len()),
        );
        let timeout = Duration::from_secs_f64(cli.timeout.max(0.1));
        grade_stream(
            &exercises,
            &mut |ex| match built.broken.get(&ex.id()) {
                Some(message) => (Outcome::DoesNotCompile(message.clone()), Vec::new()),
                None => run_student(&built.runner, ex, &cli.out, timeout),
            },
            &mut stdout,
            live,
        )
    };
    let passed = results.iter().filter(|r| r.1.is_pass()).count();
    let mut end = format!("{passed} of {} passed\n", results.len());
    if results.iter().any(|r| r.2.contains("images: ")) {
        end += "to compare the newest images side by side: open the terminal UI \
                (`cargo run --release`) and press `g`\n";
    }
    say(&mut stdout, &end);
    if let Some(path) = &cli.json {
        if let Err(e) = std::fs::write(path, results_json(&results)) {
            eprintln!("error: cannot write {}: {e}", path.display());
            return ExitCode::from(2);
        }
    }
    if passed == results.len() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

fn say(w: &mut impl Write, text: &str) {
    let _ = w.write_all(text.as_bytes());
    let _ = w.flush();
}

/// The exercises named by `wanted` (`ch1`, `1`, `ch3/moller_trumbore`).
fn select(catalog: &[Exercise], wanted: &[String]) -> Result<Vec<Exercise>, String> {
    let mut out: Vec<Exercise> = Vec::new();
    for w in wanted {
        let found: Vec<Exercise> = if w.contains('/') {
            catalog.iter().filter(|e| &e.id() == w).copied().collect()
        } else {
            match w.trim_start_matches("ch").parse::<u32>() {
                Ok(n) => catalog.iter().filter(|e| e.chapter == n).copied().collect(),
                Err(_) => {
                    return Err(format!(
                        "`{w}` is not a chapter; expected e.g. `ch1`, `1` or `ch3/moller_trumbore`"
                    ))
                }
            }
        };
        if found.is_empty() {
            return Err(format!("no exercises match `{w}`"));
        }
        for e in found {
            if !out.iter().any(|o| o.id() == e.id()) {
                out.push(e);
            }
        }
    }
    Ok(if wanted.is_empty() {
        catalog.to_vec()
    } else {
        out
    })
}

/// Grades each exercise with `grade`, printing each result to `w` as soon
/// as it is known; `grade` returns the outcome and the images it wrote.
/// Returns (exercise, outcome, the printed text).
pub fn grade_stream(
    exercises: &[Exercise],
    grade: &mut dyn FnMut(&Exercise) -> (Outcome, Vec<PathBuf>),
    w: &mut dyn Write,
    live: bool,
) -> Vec<(Exercise, Outcome, String)> {
    let width = exercises.iter().map(|e| e.id().len()).max().unwrap_or(0);
    let mut results = Vec::new();
    for ex in exercises {
        // On a terminal, say what runs before it runs: a slow check is not
        // a silent one (the result overwrites the line).
        if live {
            let _ = write!(w, "  {:width$}  ...", ex.id());
            let _ = w.flush();
        }
        let (outcome, images) = grade(ex);
        let text = describe(ex, &outcome, width, &images);
        let _ = write!(w, "{}{text}", if live { "\r" } else { "" });
        let _ = w.flush();
        results.push((*ex, outcome, text));
    }
    results
}

/// The printed lines for one result (starting with the padded id).
pub fn describe(ex: &Exercise, outcome: &Outcome, width: usize, images: &[PathBuf]) -> String {
    let id = format!("{:width$}", ex.id());
    let pad = format!("  {:width$}        ", "");
    let mut s = match outcome {
        Outcome::Passed(c) => {
            return format!("  {id}  PASS  error {:.3e} within {:.0e}\n", c.error, c.tolerance)
        }
        Outcome::NotImplemented => {
            return format!("  {id}  not started: replace the todo!() in {}\n", ex.file)
        }
        Outcome::Failed(c) => {
            let mut s = format!(
                "  {id}  FAIL  error {:.3e} exceeds {:.0e}: {}\n",
                c.error, c.tolerance, c.detail
            );
            let files: Vec<String> = images.iter().map(|f| f.display().to_string()).collect();
            if !files.is_empty() {
                s += &format!("{pad}images: {}\n", files.join(", "));
            }
            s
        }
        Outcome::Panicked(m) => format!("  {id}  FAIL  panicked: {m}\n"),
        Outcome::TimedOut { seconds, doing } => format!(
            "  {id}  FAIL  timed out after {seconds} s and was stopped, while {}: does a loop never end?\n",
            if doing.is_empty() { "running your code".to_string() } else { doing.clone() }
        ),
        Outcome::DoesNotCompile(m) => {
            let mut s = format!("  {id}  FAIL  does not compile ({}):\n", ex.file);
            for line in m.lines().take(24) {
                s += &format!("{pad}| {line}\n");
            }
            // Fix the compiler's complaint first: no hint yet.
            return s;
        }
    };
    s += &format!("{pad}hint: {}\n", ex.hints[0]);
    s += &format!("{pad}more: grade --hint {}\n", ex.id());
    s
}

/// `chN --student`: builds the exercises, then renders chapter N's
/// capstone scene with the student's code beside the reference and their
/// difference, into `out/student/` (under a one-minute limit).
pub fn student_main(chapter: u32) -> ExitCode {
    let Some((_, name)) = crate::grading::runner::CAPSTONES
        .iter()
        .find(|(c, _)| *c == chapter)
    else {
        eprintln!("chapter {chapter} has no capstone to render yet");
        return ExitCode::from(2);
    };
    eprintln!("building your exercises (the raystep-exercises crate)...");
    let built = match build_exercises(&root().join("chapters")) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error: could not build the exercises: {e}");
            return ExitCode::from(2);
        }
    };
    let id = format!("ch{chapter}/{name}");
    if let Some(m) = built.broken.get(&id) {
        eprintln!("{id} does not compile:\n{m}");
        return ExitCode::from(1);
    }
    let out = PathBuf::from("out/student");
    let mut child = match Command::new(&built.runner)
        .args(["render", &format!("ch{chapter}")])
        .arg(&out)
        .stdin(Stdio::null())
        .spawn()
    {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: could not start {}: {e}", built.runner.display());
            return ExitCode::from(2);
        }
    };
    let start = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(status)) => {
                return ExitCode::from(u8::try_from(status.code().unwrap_or(1)).unwrap_or(1))
            }
            Ok(None) if start.elapsed() > Duration::from_secs(60) => {
                let _ = child.kill();
                let _ = child.wait();
                eprintln!("your {id} ran for a minute and was stopped: does a loop never end?");
                return ExitCode::from(1);
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
}

/// What building the exercises crate gave.
#[derive(Debug)]
pub struct Built {
    /// The `grade-student` binary.
    pub runner: PathBuf,
    /// Exercises left out because they do not compile, with the
    /// compiler's messages about them.
    pub broken: BTreeMap<String, String>,
}

/// Builds `raystep-exercises` with the exercise files under `dir`; an
/// exercise whose file (or whose call in the crate's table) draws a
/// compiler error is left out (`RAYSTEP_BROKEN`) and the crate rebuilt.
pub fn build_exercises(dir: &Path) -> Result<Built, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let bin_dir = exe
        .parent()
        .ok_or("no folder for the grader")?
        .to_path_buf();
    // `grade` lives in <target>/<profile>/: build beside it, same profile.
    let target = bin_dir.parent().ok_or("no target folder")?.to_path_buf();
    let release = !cfg!(debug_assertions);
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let dir = dir
        .canonicalize()
        .map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut broken: BTreeMap<String, String> = BTreeMap::new();
    for _round in 0..6 {
        let mut cmd = Command::new(&cargo);
        cmd.args([
            "build",
            "--quiet",
            "--color",
            "never",
            "-p",
            "raystep-exercises",
        ])
        .args(["--bin", "grade-student", "--manifest-path"])
        .arg(root().join("Cargo.toml"))
        .arg("--target-dir")
        .arg(&target)
        .env("RAYSTEP_EXERCISES_DIR", &dir)
        .env(
            "RAYSTEP_BROKEN",
            broken.keys().cloned().collect::<Vec<_>>().join(","),
        )
        .stdin(Stdio::null());
        if release {
            cmd.arg("--release");
        }
        let output = cmd.output().map_err(|e| format!("cannot run cargo: {e}"))?;
        let runner = bin_dir.join(format!("grade-student{}", std::env::consts::EXE_SUFFIX));
        if output.status.success() {
            return Ok(Built { runner, broken });
        }
        let stderr = String::from_utf8_lossy(&output.stderr);
        let (found, other) = attribute_errors(&stderr);
        let new: Vec<_> = found
            .into_iter()
            .filter(|(id, _)| !broken.contains_key(id))
            .collect();
        if new.is_empty() {
            return Err(format!(
                "cargo build failed and no exercise file is to blame:\n{}",
                if other.is_empty() {
                    stderr.to_string()
                } else {
                    other.join("\n")
                }
            ));
        }
        broken.extend(new);
    }
    Err("the exercises still do not compile after leaving out the broken files".into())
}

/// Splits cargo's error output into messages and assigns each to the
/// exercise it is about: by the file it points at
/// (`chN-…/exercises/<name>.rs`), or by the exercise's path in the crate's
/// table (`chN::<name>::`). Returns (by exercise id, the rest).
pub fn attribute_errors(stderr: &str) -> (BTreeMap<String, String>, Vec<String>) {
    let mut blocks: Vec<String> = Vec::new();
    for line in stderr.lines() {
        let starts = line.starts_with("error") || line.starts_with("warning");
        if starts || blocks.is_empty() {
            blocks.push(String::new());
        }
        let b = blocks.last_mut().expect("one block");
        b.push_str(line);
        b.push('\n');
    }
    let mut found: BTreeMap<String, String> = BTreeMap::new();
    let mut other = Vec::new();
    for b in blocks.into_iter().filter(|b| b.starts_with("error")) {
        if b.starts_with("error: could not compile") || b.starts_with("error: aborting") {
            continue;
        }
        match blame(&b) {
            Some((id, false)) => found.entry(id).or_default().push_str(&b),
            Some((id, true)) => {
                let text = found.entry(id).or_default();
                if text.is_empty() {
                    text.push_str(
                        "the signature of your function does not match the one shipped \
                         (keep its name, argument and return types); the grader calls it here:\n",
                    );
                }
                text.push_str(&b);
            }
            None => other.push(b),
        }
    }
    (found, other)
}

/// The exercise one compiler message is about, and whether it was found
/// through the crate's table (a changed signature) rather than its file.
fn blame(block: &str) -> Option<(String, bool)> {
    for line in block.lines() {
        let Some(at) = line.trim_start().strip_prefix("--> ") else {
            continue;
        };
        let path = at.replace('\\', "/");
        if let Some((before, after)) = path.split_once("/exercises/") {
            let chapter = before.rsplit('/').next()?.split('-').next()?;
            let name = after.split(".rs").next()?;
            if chapter.starts_with("ch") {
                return Some((format!("{chapter}/{name}"), false));
            }
        }
    }
    // A call in the crate's table: `chN::name::function`.
    let bytes = block.as_bytes();
    for (i, _) in block.match_indices("ch") {
        if i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_') {
            continue;
        }
        let rest = &block[i + 2..];
        let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
        let Some(tail) = rest[digits.len()..].strip_prefix("::") else {
            continue;
        };
        let name: String = tail
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if !digits.is_empty() && tail[name.len()..].starts_with("::") {
            return Some((format!("ch{digits}/{name}"), true));
        }
    }
    None
}

/// Grades raystep's reference solution of `ex` in this process; images of
/// a failed image check go to `out`.
pub fn reference(ex: &Exercise, out: &Path) -> (Outcome, Vec<PathBuf>) {
    let outcome = run(ex);
    let images = match &outcome {
        Outcome::Failed(c) => write_failure_images(ex, c, out).unwrap_or_default(),
        _ => Vec::new(),
    };
    (outcome, images)
}

/// Runs the student's check of `ex` in a `grade-student` process, stopping
/// it after `timeout`; the outcome and the images the check wrote.
pub fn run_student(
    runner: &Path,
    ex: &Exercise,
    out: &Path,
    timeout: Duration,
) -> (Outcome, Vec<PathBuf>) {
    let none = Vec::new;
    let mut child = match Command::new(runner)
        .arg(ex.id())
        .arg(out)
        .env(PROGRESS_ENV, "1")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
    {
        Ok(c) => c,
        Err(e) => {
            let m = format!("could not start {}: {e}", runner.display());
            return (Outcome::Panicked(m), none());
        }
    };
    let read = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            let _ = r.read_to_end(&mut buf);
            String::from_utf8_lossy(&buf).into_owned()
        })
    };
    let stdout = read(Box::new(child.stdout.take().expect("piped")));
    let stderr = read(Box::new(child.stderr.take().expect("piped")));
    let start = Instant::now();
    let mut timed_out = false;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if start.elapsed() >= timeout => {
                let _ = child.kill();
                let _ = child.wait();
                timed_out = true;
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => {
                return (
                    Outcome::Panicked(format!("lost the check's process: {e}")),
                    none(),
                )
            }
        }
    };
    let stdout = stdout.join().unwrap_or_default();
    let stderr = stderr.join().unwrap_or_default();
    let doing = stderr
        .lines()
        .filter_map(|l| l.strip_prefix(PROGRESS))
        .last()
        .unwrap_or_default()
        .to_string();
    if timed_out {
        let seconds = timeout.as_secs_f64();
        return (Outcome::TimedOut { seconds, doing }, none());
    }
    match parse_verdict(&stdout) {
        Some(v) => (v.outcome(), v.images),
        None => {
            let tail: Vec<&str> = stderr
                .lines()
                .filter(|l| !l.starts_with(PROGRESS))
                .collect();
            let tail = tail[tail.len().saturating_sub(3)..].join(" / ");
            let m = format!(
                "the check's process crashed ({}){}{}",
                status.map(|s| s.to_string()).unwrap_or_default(),
                if doing.is_empty() {
                    String::new()
                } else {
                    format!(" while {doing}")
                },
                if tail.is_empty() {
                    String::new()
                } else {
                    format!(": {tail}")
                }
            );
            (Outcome::Panicked(m), none())
        }
    }
}

/// Gradescope's `results.json`: one test per exercise (name, score,
/// max_score, status, output) and the total score.
pub fn results_json(results: &[(Exercise, Outcome, String)]) -> String {
    let mut tests = Vec::new();
    for (ex, outcome, text) in results {
        let score = if outcome.is_pass() { 1 } else { 0 };
        tests.push(format!(
            "    {{\"name\": {}, \"score\": {score}, \"max_score\": 1, \"status\": \"{}\", \"output\": {}}}",
            json_string(&ex.id()),
            if score == 1 { "passed" } else { "failed" },
            json_string(text.trim_end())
        ));
    }
    let score = results.iter().filter(|r| r.1.is_pass()).count();
    format!(
        "{{\n  \"score\": {score},\n  \"max_score\": {},\n  \"tests\": [\n{}\n  ]\n}}\n",
        results.len(),
        tests.join(",\n")
    )
}

/// A JSON string literal.
fn json_string(s: &str) -> String {
    let mut o = String::with_capacity(s.len() + 2);
    o.push('"');
    for c in s.chars() {
        match c {
            '"' => o.push_str("\\\""),
            '\\' => o.push_str("\\\\"),
            '\n' => o.push_str("\\n"),
            '\r' => o.push_str("\\r"),
            '\t' => o.push_str("\\t"),
            c if (c as u32) < 0x20 => o.push_str(&format!("\\u{:04x}", c as u32)),
            c => o.push(c),
        }
    }
    o.push('"');
    o
}
