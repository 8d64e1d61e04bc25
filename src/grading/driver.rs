//! The `grade` command: builds the exercises crate, leaves out the files
//! that do not compile (naming the compiler's file:line), runs each check
//! in a process of its own under a time limit, prints each result as soon
//! as it is known, and can write Gradescope's `results.json`.

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use clap::Parser;

use crate::build::{build_exercises, exercises_dir};
use crate::core::format::format_count;
use crate::course;
use crate::exercise::{Exercise, Outcome};
use crate::predict;
use crate::process::{fresh_seed, reference, run_student, sandbox_gaps};
use crate::sandbox::{become_subreaper, kill_orphans};
pub use crate::stream::{describe, grade_parallel, grade_stream};
use crate::{all, hints};
use crate::{remove_failure_images, shipped};

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
    /// Also write Gradescope's results.json (to FILE, or `results.json` in
    /// the output folder).
    #[arg(long, value_name = "FILE", num_args = 0..=1)]
    json: Option<Option<PathBuf>>,
    /// Show a solution of one exercise (`ch3/moller_trumbore`) once yours
    /// has passed. Grades nothing.
    #[arg(long, value_name = "EXERCISE")]
    solution: Option<String>,
    /// Mark the answers to the predict questions
    /// (`chapters/predictions.toml`) and explain each one answered.
    /// Grades nothing.
    #[arg(long)]
    predict: bool,
    /// Put one exercise's file back as shipped (`ch3/bvh_traversal`); your
    /// version is kept beside it as `<name>.rs.orig`. Grades nothing.
    #[arg(long, value_name = "EXERCISE")]
    restore: Option<String>,
    /// The time limit of one exercise: seconds of CPU time (a check that
    /// waits without computing is stopped after four times as many
    /// seconds; ch6/path_radiance, whose check traces over a million
    /// paths, gets three times as long).
    #[arg(long, value_name = "SECONDS", default_value_t = 5.0, value_parser = parse_timeout)]
    timeout: f64,
    /// The seed of the inputs the checks draw: a new one every run unless
    /// given (to replay a run exactly).
    #[arg(long, value_name = "N")]
    seed: Option<u64>,
    /// Where images of failed image checks (and the hints seen) go.
    #[arg(long, value_name = "DIR", default_value = "out/grade")]
    out: PathBuf,
    /// The folder holding the chapters' exercise folders
    /// (`ch1-projection/exercises/…`); `chapters/` of this repository when
    /// omitted.
    #[arg(long, value_name = "DIR", hide = true)]
    exercises: Option<PathBuf>,
}

/// `--timeout`: seconds from 0.1 to 3600 (an hour), a clear error
/// otherwise (a NaN used to panic).
fn parse_timeout(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if (0.1..=3600.0).contains(&s) => Ok(s),
        _ => Err(format!("expected seconds from 0.1 to 3600, got `{text}`")),
    }
}

/// The whole `main` of the `grade` binary.
pub fn grade_main() -> ExitCode {
    let cli: GradeCli = crate::core::run::parse_args();
    let catalog = all();
    // The hints and the hand-worked cases are a teacher's to edit: a
    // mistake in them is named before anything is graded.
    let mut problems = match super::manifest::manifest() {
        Ok(m) => super::manifest::problems(m, &catalog),
        Err(e) => vec![e.to_string()],
    };
    let ids: Vec<String> = catalog.iter().map(|e| e.id()).collect();
    problems.extend(super::cases::problems(&ids));
    if !problems.is_empty() {
        eprintln!("error: {}", problems.join("\nerror: "));
        return ExitCode::from(2);
    }
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
    if let Some(id) = &cli.solution {
        let Some(ex) = catalog.iter().find(|e| &e.id() == id) else {
            eprintln!("error: no exercise `{id}`; expected e.g. `ch3/moller_trumbore`");
            return ExitCode::from(2);
        };
        return match crate::solutions::show(ex, &cli.out) {
            Ok(text) => {
                print!("{text}");
                ExitCode::SUCCESS
            }
            Err(why) => {
                eprintln!("{why}");
                ExitCode::from(1)
            }
        };
    }
    if cli.predict {
        let dir = cli.exercises.clone().unwrap_or_else(exercises_dir);
        return predict_main(&dir, &cli.chapters);
    }
    if let Some(id) = &cli.restore {
        return restore(id, &cli.exercises.clone().unwrap_or_else(exercises_dir));
    }
    let exercises = match select(&catalog, &cli.chapters) {
        Ok(e) => e,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if let Err(e) = crate::safe_out::ensure_dir(&cli.out) {
        eprintln!("error: {e}");
        return ExitCode::from(2);
    }
    let mut stdout = std::io::stdout();
    let live = stdout.is_terminal();
    let seed = cli.seed.unwrap_or_else(fresh_seed);
    let results = if cli.reference {
        say(
            &mut stdout,
            &format!(
                "grading {} (reference solutions)\n",
                format_count(exercises.len(), "exercise")
            ),
        );
        grade_stream(
            &exercises,
            &mut |ex| reference(ex, &cli.out, seed),
            &mut stdout,
            live,
        )
    } else {
        say(&mut stdout, "building your exercises...\n");
        let dir = cli.exercises.clone().unwrap_or_else(exercises_dir);
        let built = match build_exercises(&dir) {
            Ok(b) => b,
            Err(e) => {
                eprintln!("error: could not build the exercises: {e}");
                return ExitCode::from(2);
            }
        };
        say(
            &mut stdout,
            &format!(
                "grading {} (your solutions)\n",
                format_count(exercises.len(), "exercise")
            ),
        );
        let gaps = sandbox_gaps(&built.runner);
        if !gaps.is_empty() {
            say(
                &mut stdout,
                &format!(
                    "note: this system cannot give your code's process {}: it is graded \
                     with the limits that hold\n",
                    gaps.join(", ")
                ),
            );
        }
        let timeout = Duration::from_secs_f64(cli.timeout);
        // What a student's code starts and detaches comes back to us when
        // its parent dies, and is stopped after each exercise.
        become_subreaper();
        // Each exercise's process runs one thread: as many at once as
        // there are cores.
        let workers = std::thread::available_parallelism().map_or(1, |n| n.get());
        let results = grade_parallel(
            &exercises,
            workers,
            &|ex| match built.broken.get(&ex.id()) {
                Some(message) => (Outcome::DoesNotCompile(message.clone()), Vec::new()),
                None => run_student(&built.runner, ex, &cli.out, timeout, seed),
            },
            &mut stdout,
            live,
        );
        // The sandbox lets no process start; a sweep all the same.
        kill_orphans();
        results
    };
    // An old failure's images must not be shown as the newest.
    for (ex, outcome, _) in &results {
        if !matches!(outcome, Outcome::Failed(_)) {
            remove_failure_images(ex, &cli.out);
        }
    }
    let passed = results.iter().filter(|r| r.1.is_pass()).count();
    let mut end = format!("{passed} of {} passed\n", results.len());
    if results.iter().any(|r| r.2.contains("images: ")) {
        end += "to compare the newest images side by side: open the terminal UI \
                (`cargo run --release`) and press `g`\n";
    }
    say(&mut stdout, &end);
    // The student's progress over the whole course (raystep's own
    // solutions are not the student's).
    if !cli.reference {
        let states = course::update(&cli.out, &results);
        say(&mut stdout, &course::summary(&catalog, &states));
        let dir = cli.exercises.clone().unwrap_or_else(exercises_dir);
        say(&mut stdout, &predict_line(&dir));
    }
    if let Some(path) = &cli.json {
        let path = path.clone().unwrap_or_else(|| cli.out.join("results.json"));
        if let Err(e) = write_results(&path, &results_json(&results)) {
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

/// `--predict`: the sheet in `dir` marked and explained (the questions of
/// `chapters` only, when some are named); exit 2 when it cannot be read.
fn predict_main(dir: &std::path::Path, chapters: &[String]) -> ExitCode {
    let mut wanted = Vec::new();
    for c in chapters {
        match c.trim_start_matches("ch").parse::<u32>() {
            Ok(n) if (1..=6).contains(&n) => wanted.push(n),
            _ => {
                eprintln!("error: `{c}`: expected a chapter, ch1 to ch6");
                return ExitCode::from(2);
            }
        }
    }
    match predict::read(dir) {
        Ok(mut sheet) => {
            if !wanted.is_empty() {
                sheet.marks.retain(|(q, _)| wanted.contains(&q.chapter));
            }
            print!("{}", predict::explain(&sheet));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// The predict line under the course's progress: the sheet's counts, or
/// why it cannot be read (which does not change the grade).
fn predict_line(dir: &std::path::Path) -> String {
    match predict::read(dir) {
        Ok(sheet) => sheet.summary(),
        Err(e) => format!("predict: {e}\n"),
    }
}

/// Writes `text` to `path` through a temporary file renamed into place,
/// refusing a `path` that exists and is not a regular file (a FIFO would
/// block the write for ever, a link could point anywhere).
pub fn write_results(path: &std::path::Path, text: &str) -> Result<(), String> {
    crate::safe_out::write(path, text.as_bytes())
}

/// `grade --restore chN/name`: the shipped file back in place, the
/// student's kept as `<name>.rs.orig`.
fn restore(id: &str, chapters: &std::path::Path) -> ExitCode {
    let Some(stub) = shipped::find(id) else {
        eprintln!("error: no exercise `{id}`; expected e.g. `ch3/moller_trumbore`");
        return ExitCode::from(2);
    };
    let path = stub.path_in(chapters);
    let result = (|| -> std::io::Result<String> {
        match std::fs::read_to_string(&path) {
            Ok(mine) if mine == stub.text => Ok("is already as shipped".into()),
            Ok(mine) => {
                let kept = path.with_extension("rs.orig");
                std::fs::write(&kept, mine)?;
                std::fs::write(&path, stub.text)?;
                Ok(format!(
                    "is as shipped again; yours is in {}",
                    kept.display()
                ))
            }
            Err(_) => {
                std::fs::write(&path, stub.text)?;
                Ok("is as shipped again".into())
            }
        }
    })();
    match result {
        Ok(what) => {
            println!("{} {what}", path.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: cannot restore {}: {e}", path.display());
            ExitCode::from(2)
        }
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
