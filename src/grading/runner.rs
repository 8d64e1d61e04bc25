//! The student's process, `raystep-grade-child` (the crate the grader
//! builds from `src/grading/crates/`): it reads one [`Request`] on its
//! standard input, closes itself into its sandbox, runs the exercise's
//! check with the student's functions in [`bridge::record`] mode, and
//! writes the transcript of their calls to what was its standard output
//! (the student's own prints go to standard error). It decides nothing:
//! the grader replays the check on the transcript ([`replay_check`]).

use std::io::{Read, Write};
use std::process::ExitCode;

use crate::bridge;
use crate::core::warp_test::{self, Drawn};
use crate::exercise::Outcome;
use crate::exercises::images;
use crate::sandbox::Limits;
use crate::students::{self, Replayed, Students};

/// Each chapter's capstone, the exercise that renders the chapter's scene.
pub const CAPSTONES: [(u32, &str); 6] = [
    (1, "draw_edges"),
    (2, "rasterize_triangle"),
    (3, "bvh_traversal"),
    (4, "trace_scene"),
    (5, "direct_light"),
    (6, "path_radiance"),
];

/// Chapter N's capstone exercise.
pub fn capstone(chapter: u32) -> Option<crate::Exercise> {
    let (_, name) = CAPSTONES.iter().find(|(c, _)| *c == chapter)?;
    crate::all()
        .into_iter()
        .find(|e| e.chapter == chapter && e.name == *name)
}

/// What the grader asks of the student's process.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Request {
    /// Run exercise `id`'s check, with the inputs drawn from `seed`.
    Check {
        /// `chN/name`.
        id: String,
        /// The run's seed.
        seed: u64,
    },
    /// Draw `draws` directions with exercise 5.2's routine (the warp view).
    Warp {
        /// How many.
        draws: usize,
        /// The seed of the uniform numbers.
        seed: u64,
    },
    /// Set up the sandbox and say what of it this system cannot enforce,
    /// one phrase a line, instead of a transcript.
    SandboxCheck,
}

impl Request {
    /// The request as one line of text.
    pub fn line(&self) -> String {
        match self {
            Request::Check { id, seed } => format!("check {id} {seed}\n"),
            Request::Warp { draws, seed } => format!("warp {draws} {seed}\n"),
            Request::SandboxCheck => "sandbox-check\n".into(),
        }
    }

    /// Reads a request from its line.
    pub fn parse(line: &str) -> Option<Request> {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["check", id, seed] => Some(Request::Check {
                id: id.to_string(),
                seed: seed.parse().ok()?,
            }),
            ["warp", draws, seed] => Some(Request::Warp {
                draws: draws.parse().ok()?,
                seed: seed.parse().ok()?,
            }),
            ["sandbox-check"] => Some(Request::SandboxCheck),
            _ => None,
        }
    }
}

/// The most directions one warp request draws.
pub const MAX_DRAWS: usize = 1 << 22;

/// The time limit the student's process is given CPU time for, seconds
/// (the grader stops it at its own, shorter limit).
const CPU_SECONDS: f64 = 3600.0;

/// What is standard output now, kept for the transcript, while standard
/// output itself becomes standard error (the student's prints).
#[cfg(unix)]
fn take_stdout() -> std::io::Result<std::fs::File> {
    let kept = nix::unistd::dup(std::io::stdout()).map_err(std::io::Error::from)?;
    nix::unistd::dup2_stdout(std::io::stderr()).map_err(std::io::Error::from)?;
    Ok(std::fs::File::from(kept))
}

#[cfg(not(unix))]
fn take_stdout() -> std::io::Result<std::io::Stdout> {
    Ok(std::io::stdout())
}

/// The whole `main` of `raystep-grade-child`, with the student's
/// functions `S`.
pub fn child_main<S: Students>() -> ExitCode {
    let mut input = String::new();
    let request = match std::io::stdin().read_to_string(&mut input) {
        Ok(_) => Request::parse(input.trim()),
        Err(_) => None,
    };
    let Some(request) = request else {
        eprintln!(
            "raystep-grade-child is run by the grader (`cargo grade`), which says what to run"
        );
        return ExitCode::from(2);
    };
    let mut out = match take_stdout() {
        Ok(out) => out,
        Err(e) => {
            eprintln!("error: cannot keep standard output for the transcript: {e}");
            return ExitCode::from(2);
        }
    };
    // Where each panic happened, for the transcript.
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if let Some(at) = info.location() {
            *bridge::LAST_PANIC_AT
                .lock()
                .unwrap_or_else(|e| e.into_inner()) =
                Some(crate::short_path(at.file()) + &format!(":{}:{}", at.line(), at.column()));
        }
        default_hook(info);
    }));
    // Everything the checks read from disk, and their one thread, before
    // the sandbox closes the file system and forbids new threads.
    images::preload();
    let pool = match rayon::ThreadPoolBuilder::new().num_threads(1).build() {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: cannot start the check's thread: {e}");
            return ExitCode::from(2);
        }
    };
    bridge::start_grader_pool();
    let missing = Limits::for_timeout(CPU_SECONDS).confine();
    let transcript = match request {
        Request::SandboxCheck => format!("sandbox\n{}", missing.join("\n")).into_bytes(),
        Request::Check { id, seed } => {
            let Some(check) = students::check::<S>(&id) else {
                eprintln!("error: no exercise `{id}`");
                return ExitCode::from(2);
            };
            pool.install(|| {
                crate::set_run_seed(seed);
                bridge::record(|| {
                    let _ = check();
                })
            })
        }
        Request::Warp { draws, seed } => pool.install(|| {
            bridge::record(|| {
                let _ = warp_test::draw(&students::warp_sample::<S>, draws.min(MAX_DRAWS), seed);
            })
        }),
    };
    if out
        .write_all(&transcript)
        .and_then(|_| out.flush())
        .is_err()
    {
        return ExitCode::from(2);
    }
    ExitCode::SUCCESS
}

/// The grader's verdict on exercise `id`: its check, run in this process
/// on the answers of the student's `transcript` (the inputs drawn from
/// `seed`, as in the student's process).
pub fn replay_check(id: &str, transcript: Vec<u8>, seed: u64) -> Outcome {
    let Some(check) = students::check::<Replayed>(id) else {
        return Outcome::Panicked(format!("no exercise `{id}`"));
    };
    let replayed = bridge::sequential(move || {
        crate::set_run_seed(seed);
        bridge::replay(transcript, || crate::run_check_alone(check))
    });
    match replayed {
        Err(e) => Outcome::Panicked(e),
        Ok((Outcome::Passed(_), false)) => Outcome::Panicked(
            "the grader could not replay your code's answers (its process answered a \
             different number of calls)"
                .into(),
        ),
        Ok((outcome, _)) => outcome,
    }
}

/// The directions the student's routine drew, replayed from `transcript`
/// (see [`Request::Warp`]); an error says why there are none.
pub fn replay_warp(transcript: Vec<u8>, draws: usize, seed: u64) -> Result<Drawn, String> {
    let replayed = bridge::sequential(move || {
        bridge::replay(transcript, || {
            std::panic::catch_unwind(|| {
                warp_test::draw(
                    &students::warp_sample::<Replayed>,
                    draws.min(MAX_DRAWS),
                    seed,
                )
            })
        })
    })?;
    match replayed {
        (Ok(drawn), true) => Ok(drawn),
        (Ok(_), false) => Err("the grader could not replay your code's answers".into()),
        (Err(payload), _) => {
            let message = crate::panic_text(&*payload);
            if message.starts_with("not yet implemented") {
                Err("not_implemented".into())
            } else {
                Err(format!("panicked: {}", message.replace('\n', " ")))
            }
        }
    }
}
