//! Grading a list of exercises and printing each result as soon as it
//! is known: one after the other ([`grade_stream`]), or several at once,
//! each in the student's process of its own ([`grade_parallel`]).

use std::io::Write;
use std::path::PathBuf;

use crate::core::text::escape_keep_newlines;
use crate::exercise::{Check, Exercise, Outcome};

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

/// [`grade_stream`] with up to `workers` exercises graded at once (the
/// results still printed in order, each as soon as it and those before it
/// are known).
pub fn grade_parallel(
    exercises: &[Exercise],
    workers: usize,
    grade: &(dyn Fn(&Exercise) -> (Outcome, Vec<PathBuf>) + Sync),
    w: &mut dyn Write,
    live: bool,
) -> Vec<(Exercise, Outcome, String)> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let width = exercises.iter().map(|e| e.id().len()).max().unwrap_or(0);
    // The capstones, the longest checks, start first; the results are
    // printed in order all the same.
    let mut order: Vec<usize> = (0..exercises.len()).collect();
    order.sort_by_key(|&i| {
        let capstone = crate::runner::CAPSTONES
            .iter()
            .any(|(c, n)| *c == exercises[i].chapter && *n == exercises[i].name);
        !capstone
    });
    let order = &order;
    let next = AtomicUsize::new(0);
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::scope(|scope| {
        for _ in 0..workers.clamp(1, exercises.len().max(1)) {
            let tx = tx.clone();
            let next = &next;
            scope.spawn(move || {
                while let Some(&i) = order.get(next.fetch_add(1, Ordering::Relaxed)) {
                    if tx.send((i, grade(&exercises[i]))).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        let mut done: Vec<Option<(Outcome, Vec<PathBuf>)>> = vec![None; 0];
        done.resize_with(exercises.len(), || None);
        let mut results = Vec::new();
        let announce = |w: &mut dyn Write, k: usize| {
            if live && k < exercises.len() {
                let _ = write!(w, "  {:width$}  ...", exercises[k].id());
                let _ = w.flush();
            }
        };
        announce(w, 0);
        for (i, graded) in rx {
            done[i] = Some(graded);
            while let Some(Some((outcome, images))) = done.get_mut(results.len()).map(Option::take)
            {
                let ex = exercises[results.len()];
                let text = describe(&ex, &outcome, width, &images);
                let _ = write!(w, "{}{text}", if live { "\r" } else { "" });
                let _ = w.flush();
                results.push((ex, outcome, text));
                announce(w, results.len());
            }
        }
        results
    })
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
                c.error,
                c.tolerance,
                escape_keep_newlines(&c.detail)
            );
            let files: Vec<String> = images.iter().map(|f| f.display().to_string()).collect();
            if !files.is_empty() {
                s += &format!("{pad}images: {}\n", files.join(", "));
            }
            s
        }
        Outcome::Panicked(m) => format!("  {id}  FAIL  panicked: {}\n", escape_keep_newlines(m)),
        Outcome::TimedOut { seconds, doing } => format!(
            "  {id}  FAIL  timed out after {seconds} s and was stopped, while {}: does a loop never end?\n",
            if doing.is_empty() {
                format!("running your {} ({})", ex.name, ex.file)
            } else {
                escape_keep_newlines(doing).into_owned()
            }
        ),
        Outcome::DoesNotCompile(m) => {
            let mut s = format!("  {id}  FAIL  does not compile ({}):\n", ex.file);
            for line in m.lines().take(24) {
                s += &format!("{pad}| {}\n", escape_keep_newlines(line));
            }
            // Fix the compiler's complaint first: no hint yet.
            return s;
        }
    };
    match outcome {
        Outcome::Failed(Check {
            symptom: Some(symptom),
            ..
        }) => {
            s += &format!("{pad}symptom: {}\n", symptom.name);
            s += &format!("{pad}hint: {}\n", ex.symptom_hint(symptom));
        }
        _ => s += &format!("{pad}hint: {}\n", ex.hints()[0]),
    }
    s += &format!("{pad}more: cargo grade --hint {}\n", ex.id());
    s
}
