//! Near questions get their own answers: the second probe of
//! [`stateless`](super::stateless). A memo keyed on rounded arguments (a
//! point to the millimetre, directions to 0.01, every number to 10⁻³)
//! answers a question with the answer of an earlier one that rounds the
//! same way; [`changed_answer`](super::stateless::changed_answer) does not
//! see it, because such a memo answers each question the same way every
//! time.
//!
//! The probe asks a question and then its twin: the same question with
//! the numbers of one argument moved by 5 % to 30 % of themselves (a memo
//! may round one argument and key on the others exactly). Where the
//! reference's two answers differ by more than 2 % of their size, a
//! solution within any exercise's tolerance (10⁻⁴ or tighter) must answer
//! the two differently too; the same answer, bit for bit, is a kept one.
//! Questions are also shrunk, their lengths scaled together by 10⁻⁷ to 1
//! (each exercise's contract holds at every scale), so that twins fall
//! in one cell of a fine grid too.
//!
//! A second kind of twin moves two points of the question towards each
//! other by the same step (two corners of a triangle, an eye and its
//! target): their sum stays, so a memo keyed on a centroid or a midpoint
//! answers it with the question's answer.
//!
//! A memo keyed on finely rounded arguments (an albedo to 8 bits, a
//! cosine to 1/4096) answers only near questions alike: fine twins move
//! one number of an argument by 0.2 % to 1 % of itself (the other
//! numbers keep their keys), and must get answers of their
//! own where the reference's differ by more than 0.1 % (ten times the
//! loosest tolerance), at steadier questions (the reference moving by
//! under 0.1 % when the numbers move by 10⁻⁴).
//!
//! And a question's decoys ([`changed_answer`](super::stateless::changed_answer)'s:
//! one argument taken whole from another question) must get answers of
//! their own too: a memo that keeps its entries and leaves one argument
//! out of the key (up beside eye and target) answers a decoy with its
//! question's answer every time it is asked, so no answer changes.
//!
//! Where the answer hangs on its arguments' last digits (a point a hair
//! off a surface, a light seen edge-on), a tolerance can be wider than
//! the answer itself, and two right answers may agree: a question whose
//! reference answer moves by 1 % when its numbers move by 10⁻⁴ is left
//! out, and so is its twin.

use std::fmt::Debug;
use std::ops::Range;

use super::draws::Draws;
use super::stateless::show;

/// How far a twin moves its numbers (a share of each), and whether it
/// moves one number of the argument (drawn) or all of them; how many
/// twins each question gets per argument; how far apart the reference's
/// two answers must be for a right solution to answer them differently,
/// and how little the reference may move when the numbers move by 10⁻⁴
/// (a question that moves more is left out).
struct Reach {
    moves: (f32, f32),
    one: bool,
    times: usize,
    gap: f64,
    steady: f64,
}

/// The twins: moves of 5 % to 30 % of a whole argument, and of 0.2 % to
/// 1 % of one of its numbers (a memo that rounds each number alone then
/// keeps the others' keys).
const COARSE: Reach = Reach {
    moves: (0.05, 0.3),
    one: false,
    times: 2,
    gap: 0.02,
    steady: 1e-2,
};
const FINE: Reach = Reach {
    moves: (2e-3, 1e-2),
    one: true,
    times: 4,
    gap: 1e-3,
    steady: 1e-3,
};

/// Which numbers of a question a twin may change.
pub struct Twins<'a> {
    /// The arguments a twin may move, one at a time: each of its numbers
    /// towards zero by 5 % to 30 % of itself (a number bounded above or
    /// below by zero stays in range).
    pub nudged: &'a [Range<usize>],
    /// Pairs of points (indices into `nudged`) a twin moves towards each
    /// other by the same step, 5 % to 30 % of the way: their sum stays,
    /// so a memo keyed on it (a centroid, a midpoint) answers the twin
    /// with the question's answer.
    pub balanced: &'a [(usize, usize)],
    /// Lengths, scaled together (question and twin alike).
    pub lengths: &'a [Range<usize>],
}

/// A share as a percentage, with the digits a small one needs.
fn percent(share: f64) -> String {
    match share >= 0.01 {
        true => format!("{:.0}%", share * 100.0),
        false => format!("{:.2}%", share * 100.0),
    }
}

/// Whether number `i` of a question is in one of `ranges`.
fn within(ranges: &[Range<usize>], i: usize) -> bool {
    ranges.iter().any(|r| r.contains(&i))
}

/// The numbers in an answer's `Debug` text, and the text around them.
fn numbers(answer: &str) -> (Vec<f64>, String) {
    let (mut nums, mut rest) = (Vec::new(), String::new());
    for token in answer.split(|c: char| " ,()[]{}:;".contains(c)) {
        match token.parse::<f64>() {
            Ok(x) => nums.push(x),
            Err(_) => rest.push_str(token),
        }
        rest.push('|');
    }
    (nums, rest)
}

/// How far apart two answers are, relative to the larger number in them
/// (`None` where they are not the same kind, or not finite).
fn apart(a: &str, b: &str) -> Option<f64> {
    let ((x, skeleton_a), (y, skeleton_b)) = (numbers(a), numbers(b));
    if skeleton_a != skeleton_b || x.len() != y.len() || x.is_empty() {
        return None;
    }
    if !x.iter().chain(&y).all(|v| v.is_finite()) {
        return None;
    }
    let size = x.iter().chain(&y).fold(0.0f64, |m, v| m.max(v.abs()));
    let gap = x
        .iter()
        .zip(&y)
        .fold(0.0f64, |m, (p, q)| m.max((p - q).abs()));
    (size > 0.0).then(|| gap / size)
}

/// Each of `cases` and two twins of it per argument that may move, at
/// drawn scales: `None` if every twin whose reference answer differs by
/// more than 2 % got an answer of its own, else the first that did not.
/// (Numbers are f32 values held in f64, and stay so.)
pub fn same_for_near<R: Debug>(
    cases: &[Vec<f64>],
    twins: &Twins,
    salt: u64,
    ask: impl Fn(&[f64]) -> R,
    reference: impl Fn(&[f64]) -> R,
) -> Option<String> {
    // A case at a drawn scale (its lengths scaled together).
    let scaled = |case: &[f64], d: &mut Draws| -> Vec<f64> {
        let scale = match twins.lengths.is_empty() {
            true => 1.0,
            false => d.decades(-7.0, 0.0) as f64,
        };
        (0..case.len())
            .map(|i| match within(twins.lengths, i) {
                true => (case[i] * scale) as f32 as f64,
                false => case[i],
            })
            .collect()
    };
    for (reach, salt) in [(&COARSE, salt), (&FINE, salt + 2000)] {
        let mut d = Draws::new(salt);
        let each = (0..reach.times).flat_map(|_| twins.nudged);
        for (case, moved) in cases.iter().flat_map(|c| each.clone().map(move |m| (c, m))) {
            d.next_case();
            let base = scaled(case, &mut d);
            let moved = match reach.one {
                true => {
                    let i = moved.start + (d.unit() * moved.len() as f32) as usize;
                    let i = i.min(moved.end - 1);
                    i..i + 1
                }
                false => moved.clone(),
            };
            let twin: Vec<f64> = (0..base.len())
                .map(|i| match moved.contains(&i) {
                    true => {
                        let share = d.range(reach.moves.0, reach.moves.1) as f64;
                        (base[i] * (1.0 - share)) as f32 as f64
                    }
                    false => base[i],
                })
                .collect();
            if let Some(kept) = kept_for_twin(&base, &twin, twins, reach, &mut d, &ask, &reference)
            {
                return Some(kept);
            }
        }
    }
    // The pairs moved towards each other, from a stream of their own.
    let mut d = Draws::new(salt + 1000);
    let twice = twins.balanced.iter().chain(twins.balanced);
    for (case, &(p, q)) in cases
        .iter()
        .flat_map(|c| twice.clone().map(move |m| (c, m)))
    {
        d.next_case();
        let mut twin = scaled(case, &mut d);
        let base = twin.clone();
        let t = d.range(0.05, 0.3) as f64;
        for (i, j) in twins.nudged[p].clone().zip(twins.nudged[q].clone()) {
            let step = t * (base[j] - base[i]);
            twin[i] = (base[i] + step) as f32 as f64;
            twin[j] = (base[j] - step) as f32 as f64;
        }
        if let Some(kept) = kept_for_twin(&base, &twin, twins, &COARSE, &mut d, &ask, &reference) {
            return Some(kept);
        }
    }
    None
}

/// Each of `decoys` (a question's index, and the question with one
/// argument taken from another) asked right after its question: `None`
/// if every decoy whose reference answer differs from its question's by
/// more than 2 % got an answer of its own, else the first that did not.
pub fn same_for_decoy<R: Debug>(
    cases: &[Vec<f64>],
    decoys: &[(usize, Vec<f64>)],
    twins: &Twins,
    salt: u64,
    ask: impl Fn(&[f64]) -> R,
    reference: impl Fn(&[f64]) -> R,
) -> Option<String> {
    let mut d = Draws::new(salt);
    decoys.iter().find_map(|(k, decoy)| {
        d.next_case();
        kept_for_twin(&cases[*k], decoy, twins, &COARSE, &mut d, &ask, &reference)
    })
}

/// Whether the student's function answered `base` and `twin` alike (bit
/// for bit) where the reference's answers, steady under moves of 10⁻⁴,
/// differ by more than `reach` says: the message saying so.
fn kept_for_twin<R: Debug>(
    base: &[f64],
    twin: &[f64],
    twins: &Twins,
    reach: &Reach,
    d: &mut Draws,
    ask: impl Fn(&[f64]) -> R,
    reference: impl Fn(&[f64]) -> R,
) -> Option<String> {
    let (a, b) = (format!("{:?}", ask(base)), format!("{:?}", ask(twin)));
    if a != b {
        return None;
    }
    let (ra, rb) = (
        format!("{:?}", reference(base)),
        format!("{:?}", reference(twin)),
    );
    // Each of the two, with its numbers moved by 10⁻⁴: steady?
    let steady = |q: &[f64], answer: &str, d: &mut Draws| {
        let moved: Vec<f64> = (0..q.len())
            .map(
                |i| match within(twins.nudged, i) || within(twins.lengths, i) {
                    true => (q[i] * (1.0 + 1e-4 * d.range(-1.0, 1.0) as f64)) as f32 as f64,
                    false => q[i],
                },
            )
            .collect();
        apart(answer, &format!("{:?}", reference(&moved))).is_some_and(|g| g < reach.steady)
    };
    if !steady(base, &ra, d) || !steady(twin, &rb, d) {
        return None;
    }
    if let Some(gap) = apart(&ra, &rb).filter(|gap| *gap > reach.gap) {
        return Some(format!(
            "the arguments {} and then {} both got {a}, though the right answers ({ra} and \
             {rb}) differ by {} of their size: an answer must be worked out from its own \
             arguments, not kept from an earlier question that shares some of them or rounds \
             the same way",
            show(base),
            show(twin),
            percent(gap)
        ));
    }
    None
}
