//! A random-mutation fuzzer over the scene and OBJ loaders and a 16x16
//! render, on stable Rust (cargo-fuzz needs nightly).
//!
//! Each case starts from one of the repository's scene files (and small
//! OBJ meshes for every `mesh = "..."` it names), applies a few mutations
//! chosen by a seeded random generator (numbers replaced by extreme
//! values, array elements added or dropped, lines duplicated, deleted or
//! spliced from another seed, characters replaced by control codes,
//! quotes and brackets, faces repeated, line endings changed), loads the
//! result and, when it loads, renders it at 16x16 with one chapter. A case
//! ends in one of: a clean error, a success, a panic, or (any of those)
//! slow. Case `i` of seed `s` is the same input on every machine.
//!
//! `cargo run --release --bin fuzz -- --cases 1000000` runs many;
//! `tests/project/fuzz.rs` runs a few thousand in CI. The out-of-process
//! fuzzer that also sees hangs, OOMs and signals: [`tree`], [`process`].

mod obj;
pub mod process;
pub mod tree;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Arc;
use std::time::Instant;

use crate::core::stage::Settings;
use crate::scene::{Limits, Scene};

/// Scene files the mutations start from.
pub const SCENE_SEEDS: &[&str] = &[
    include_str!("../../scenes/cornell-box.toml"),
    include_str!("../../scenes/cornell-glass.toml"),
    include_str!("../../scenes/lights-gallery.toml"),
    include_str!("../../scenes/brdf-row.toml"),
    include_str!("../../scenes/lambert-sphere.toml"),
    include_str!("../../scenes/tetrahedron.toml"),
    include_str!("../../scenes/sdf-shapes.toml"),
    include_str!("../../scenes/sdf-lit.toml"),
    include_str!("../../scenes/sdf-lipschitz.toml"),
    include_str!("../../scenes/interpenetrating.toml"),
    include_str!("../../scenes/railroad.toml"),
];

/// OBJ meshes the mutations start from.
pub const OBJ_SEEDS: &[&str] = &[
    include_str!("../../scenes/meshes/cornell-box/large-box.obj"),
    include_str!("../../scenes/meshes/cornell-box/light.obj"),
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvn 0 0 1\nf 1/1/1 2/2/1 3/2/1 4/1/1\n",
    "o a\nv -1 0 -1\nv 1 0 -1\nv 0 1 1\ng b\nv 0 -1 0\nf 1 2 3\nf -1 -2 -3\nf 1 2 4\n",
];

/// The limits the fuzzer loads with: small enough that every case is a
/// 16x16 render's worth of work (the flags' defaults are far larger).
pub const FUZZ_LIMITS: Limits = Limits {
    max_file_bytes: 1 << 20,
    max_triangles: 100_000,
};

/// A case that takes longer than this (load and render) counts as slow.
pub const SLOW_SECONDS: f64 = 1.0;

/// Numbers a mutation puts in place of a number.
const EXTREMES: &[&str] = &[
    "0",
    "-0",
    "-1",
    "1",
    "2",
    "3",
    "6",
    "7",
    "8",
    "-5",
    "0.5",
    "1e39",
    "-1e39",
    "1e30",
    "-1e30",
    "1e-30",
    "1e-45",
    "1e-50",
    "3.4e38",
    "1e12",
    "1e13",
    "1e18",
    "1e19",
    "nan",
    "inf",
    "-inf",
    "4294967296",
    "-4294967297",
    "180",
    "200",
    "-10",
    "99999999999",
    "1e308",
];

/// Text a mutation inserts or puts in place of a character.
const JUNK: &[&str] = &[
    "\u{1b}[2J",
    "\u{1b}[?1049l",
    "\u{7}",
    "\u{0}",
    "\r",
    "\n",
    "\"",
    "'",
    "[",
    "]",
    "{",
    "}",
    "=",
    ",",
    "#",
    "\\",
    "\u{202e}",
    "é",
    ".",
    "-",
    "[[objects]]\n",
    "[[lights]]\n",
    "junk",
];

/// One generated input: a scene text and the OBJ text every mesh path gets.
#[derive(Clone, Debug)]
pub struct Case {
    /// The (mutated) scene file.
    pub scene: String,
    /// The (mutated) OBJ file served for every `mesh = "..."`.
    pub obj: String,
    /// Which chapter renders it (index into [`crate::chapters::all`]).
    pub chapter: usize,
}

/// How one case ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Loading or rendering returned an error.
    Error,
    /// It loaded and rendered.
    Success,
    /// Something panicked.
    Panic,
}

/// A small deterministic generator (SplitMix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len())]
    }
}

/// Case `index` of the run seeded `seed`.
pub fn case(seed: u64, index: u64) -> Case {
    let mut rng = Rng(seed ^ index.wrapping_mul(0xd134_2543_de82_ef95));
    let mut scene = SCENE_SEEDS[rng.below(SCENE_SEEDS.len())].to_string();
    let mut obj = OBJ_SEEDS[rng.below(OBJ_SEEDS.len())].to_string();
    // Most cases mutate one of the two, a few both.
    let (scene_edits, obj_edits) = match rng.below(8) {
        0..=4 => (1 + rng.below(3), 0),
        5 | 6 => (0, 1 + rng.below(3)),
        _ => (1 + rng.below(2), 1 + rng.below(2)),
    };
    for _ in 0..scene_edits {
        scene = mutate(&mut rng, &scene, false);
    }
    for _ in 0..obj_edits {
        obj = mutate(&mut rng, &obj, true);
    }
    Case {
        scene,
        obj,
        chapter: rng.below(6),
    }
}

/// Byte offsets of the numbers in `text`.
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit()
            || (bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit));
        if starts && (i == 0 || !bytes[i - 1].is_ascii_alphanumeric()) {
            let mut j = i + 1;
            while j < bytes.len()
                && matches!(bytes[j], b'0'..=b'9' | b'.' | b'e' | b'E' | b'-' | b'+')
            {
                j += 1;
            }
            out.push((i, j));
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

/// A char boundary at or before `i`.
fn boundary(text: &str, mut i: usize) -> usize {
    i = i.min(text.len());
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// One random mutation of `text` (an OBJ file when `obj`).
fn mutate(rng: &mut Rng, text: &str, obj: bool) -> String {
    let lines: Vec<&str> = text.lines().collect();
    match rng.below(10) {
        // A number replaced by an extreme value.
        0..=2 => {
            let nums = numbers(text);
            if nums.is_empty() {
                return text.to_string();
            }
            let (a, b) = nums[rng.below(nums.len())];
            format!("{}{}{}", &text[..a], rng.pick(EXTREMES), &text[b..])
        }
        // An array element added or the last one dropped.
        3 => {
            let closes: Vec<usize> = text.match_indices(']').map(|(i, _)| i).collect();
            if closes.is_empty() || obj {
                // In an OBJ: an extra coordinate or corner.
                let k = rng.below(lines.len());
                let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
                if let Some(l) = out.get_mut(k) {
                    l.push(' ');
                    l.push_str(rng.pick(EXTREMES));
                }
                return out.join("\n");
            }
            let c = closes[rng.below(closes.len())];
            if rng.below(2) == 0 {
                format!("{}, {}{}", &text[..c], rng.pick(EXTREMES), &text[c..])
            } else {
                let open = text[..c].rfind([',', '[']).unwrap_or(c);
                format!("{}{}", &text[..open], &text[c..])
            }
        }
        // A line duplicated (in an OBJ, possibly thousands of times, up to
        // about a megabyte of copies).
        4 => {
            let k = rng.below(lines.len());
            let line = lines.get(k).copied().unwrap_or("");
            let times = if obj {
                [1, 10, 1000, 20_000][rng.below(4)]
            } else {
                1
            };
            let times = times.min((1 << 20) / (line.len() + 1)).max(1);
            let mut out: Vec<&str> = lines.clone();
            let at = k.min(out.len());
            out.splice(at..at, std::iter::repeat_n(line, times));
            out.join("\n")
        }
        // A line deleted.
        5 => {
            let k = rng.below(lines.len());
            let mut out = lines.clone();
            if k < out.len() {
                out.remove(k);
            }
            out.join("\n")
        }
        // A line spliced in from another seed.
        6 => {
            let seeds = if obj { OBJ_SEEDS } else { SCENE_SEEDS };
            let other: Vec<&str> = seeds[rng.below(seeds.len())].lines().collect();
            let line = other.get(rng.below(other.len())).copied().unwrap_or("");
            let mut out = lines.clone();
            out.insert(rng.below(out.len() + 1), line);
            out.join("\n")
        }
        // Junk inserted or put in place of a character.
        7 | 8 => {
            let at = boundary(text, rng.below(text.len() + 1));
            let end = if rng.below(2) == 0 {
                at
            } else {
                boundary(text, at + 1).max(at).min(text.len())
            };
            let end = if end == at && at < text.len() && rng.below(2) == 0 {
                at + text[at..].chars().next().map_or(0, char::len_utf8)
            } else {
                end
            };
            format!("{}{}{}", &text[..at], rng.pick(JUNK), &text[end..])
        }
        // Line endings changed, or (OBJ) one huge polygon.
        _ => {
            if obj && rng.below(2) == 0 {
                let n = [100, 10_000, 100_000][rng.below(3)];
                let mut face = String::from("\nf");
                for k in 0..n {
                    face.push_str([" 1", " 2", " 3", " -1"][k % 4]);
                }
                format!("{text}{face}\n")
            } else if rng.below(2) == 0 {
                text.replace('\n', "\r")
            } else {
                text.replace('\n', "\r\n")
            }
        }
    }
}

/// Loads `case` and, if it loads, renders it at 16x16 with its chapter:
/// `Ok(())` rendered, `Err(message)` a clean error. Panics propagate.
pub fn run_case(case: &Case) -> Result<(), String> {
    render(case, 16, 16, 1)
}

/// [`run_case`] at `width` x `height` and `spp` samples per pixel.
pub fn render(case: &Case, width: u32, height: u32, spp: u32) -> Result<(), String> {
    let obj = case.obj.clone();
    let read = move |rel: &str| -> Result<(String, String), (String, String)> {
        if rel.len() > 200 {
            return Err((rel.chars().take(200).collect(), "path too long".into()));
        }
        // As the file loader does (`read_limited`).
        if obj.len() as u64 > FUZZ_LIMITS.max_file_bytes {
            return Err((rel.to_string(), "larger than the file size limit".into()));
        }
        Ok((rel.to_string(), obj.clone()))
    };
    let scene = Scene::parse_with(&case.scene, "fuzz", "fuzz.toml", &read, &FUZZ_LIMITS)
        .and_then(|s| s.with_resolution(width, height))
        .map_err(|e| e.to_string())?;
    let chapter = crate::chapters::all()[case.chapter];
    let settings = Settings {
        spp,
        ..Settings::default()
    };
    let mut render = chapter
        .start(Arc::new(scene), &settings)
        .map_err(|e| e.to_string())?;
    for _ in 0..256 {
        if render.pass().complete {
            break;
        }
    }
    let snapshot = render.snapshot();
    match snapshot.views.first() {
        Some(film) if film.pixels.iter().all(|p| p.is_finite()) => Ok(()),
        Some(_) => Err("NaN or Inf in a snapshot's view".into()),
        None => Err("a snapshot without views".into()),
    }
}

/// Runs case `index` of `seed`, catching panics: the outcome and seconds.
pub fn run_index(seed: u64, index: u64) -> (Outcome, f64) {
    let start = Instant::now();
    let c = case(seed, index);
    let outcome = match catch_unwind(AssertUnwindSafe(|| run_case(&c))) {
        Ok(Ok(())) => Outcome::Success,
        Ok(Err(_)) => Outcome::Error,
        Err(_) => Outcome::Panic,
    };
    (outcome, start.elapsed().as_secs_f64())
}

/// Counts over a run of cases.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tally {
    /// Cases run.
    pub cases: u64,
    /// Clean errors.
    pub errors: u64,
    /// Loaded and rendered.
    pub successes: u64,
    /// Panicked (must be 0).
    pub panics: u64,
    /// Took longer than [`SLOW_SECONDS`] (must be 0).
    pub slow: u64,
    /// The longest case, in seconds, and its index.
    pub slowest: (f64, u64),
    /// The indices of panicking and slow cases (the first 100).
    pub bad: Vec<u64>,
    /// The indices of every slow case.
    pub slow_cases: Vec<u64>,
}

impl Tally {
    /// Adds one case's outcome.
    pub fn add(&mut self, index: u64, outcome: Outcome, seconds: f64) {
        self.cases += 1;
        match outcome {
            Outcome::Error => self.errors += 1,
            Outcome::Success => self.successes += 1,
            Outcome::Panic => self.panics += 1,
        }
        let slow = seconds > SLOW_SECONDS;
        self.slow += slow as u64;
        if slow {
            self.slow_cases.push(index);
        }
        if (slow || outcome == Outcome::Panic) && self.bad.len() < 100 {
            self.bad.push(index);
        }
        if seconds > self.slowest.0 {
            self.slowest = (seconds, index);
        }
    }

    /// Combines two tallies.
    pub fn merge(mut self, other: Tally) -> Tally {
        self.cases += other.cases;
        self.errors += other.errors;
        self.successes += other.successes;
        self.panics += other.panics;
        self.slow += other.slow;
        if other.slowest.0 > self.slowest.0 {
            self.slowest = other.slowest;
        }
        self.bad.extend(other.bad);
        self.slow_cases.extend(other.slow_cases);
        self.bad.sort_unstable();
        self.bad.truncate(100);
        self
    }
}

/// Runs cases `range` of `seed` on rayon's pool, panics silenced.
pub fn run_range(seed: u64, range: std::ops::Range<u64>) -> Tally {
    use rayon::prelude::*;
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let tally = range
        .into_par_iter()
        .fold(Tally::default, |mut t, i| {
            let (outcome, seconds) = run_index(seed, i);
            t.add(i, outcome, seconds);
            t
        })
        .reduce(Tally::default, Tally::merge);
    std::panic::set_hook(hook);
    tally
}
